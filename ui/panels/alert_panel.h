#pragma once
// The alert list (docs/alerts.md, docs/gui.md): the alerts now, most urgent first, each with its
// priority, state and time; "Acknowledge" for the selected alert (or, with none selected, the most
// urgent one that waits), "Silence" for every audible alert (30 s); and the history of the run. The
// decisions are the worker's alerts::AlertManager's; this panel shows them and asks.
#include <QListWidget>
#include <QPushButton>
#include <QTabWidget>
#include <QWidget>
#include <optional>

#include "charts/portrayal/portrayal.h"
#include "ui/bridge/sim_history.h"

Q_DECLARE_METATYPE(reckoner::alerts::AlertId)

namespace reckoner::ui {

class AlertPanel : public QWidget {
  Q_OBJECT
 public:
  explicit AlertPanel(QWidget* parent = nullptr);
  /// Shows the alerts and the history of `h` (call when a frame arrived).
  void refresh(const SimHistory& h);
  /// The alert "Acknowledge" would act on now.
  [[nodiscard]] std::optional<alerts::AlertId> acknowledgeTarget() const;
  [[nodiscard]] QListWidget* list() const { return list_; }
  [[nodiscard]] QListWidget* historyList() const { return history_; }
  /// The display palette: the priorities' colours dim at dusk and night (shown from the next refresh).
  void setDisplayPalette(charts::Palette p) { palette_ = p; }

 signals:
  void acknowledgeRequested(reckoner::alerts::AlertId id);
  void silenceRequested();

 private:
  void updateButtons();

  QTabWidget* tabs_;
  QListWidget* list_;
  QListWidget* history_;
  QPushButton* acknowledge_;
  QPushButton* silence_;
  std::vector<alerts::Alert> shown_;
  std::uint64_t historyShown_ = 0;  ///< SimHistory::alertHistoryCount() shown
  bool anyAudible_ = false;
  charts::Palette palette_ = charts::Palette::Day;
};

/// The colour of a priority on the alert list and banner, dimmed for dusk and night (a bright red on a
/// near-black screen would blind the officer of the watch).
QColor alertColour(alerts::Priority p, charts::Palette palette = charts::Palette::Day);
/// The style sheet of a label that shows an alert of priority p (the banner, the DR indication).
QString alertLabelStyle(alerts::Priority p, charts::Palette palette, int paddingPx);

}  // namespace reckoner::ui
