#pragma once
// Own-ship panel: estimated and true position, course and speed, the current, the speedlog and Loran-C
// error estimates against the truth, the active sensors, the NIS of each sensor's last update and the
// dead-reckoning indication.
#include <QLabel>
#include <QWidget>
#include <array>

#include "charts/portrayal/portrayal.h"
#include "geo/local_frame.h"
#include "ui/bridge/live_frame.h"

namespace reckoner::ui {

class OwnShipPanel : public QWidget {
  Q_OBJECT
 public:
  explicit OwnShipPanel(QWidget* parent = nullptr);
  void setFrame(const LiveFrame& frame, const geo::LocalFrame& localFrame);
  /// The dead-reckoning banner (tests read it).
  [[nodiscard]] QString drText() const { return dr_->text(); }
  [[nodiscard]] bool drShown() const { return dr_->isVisibleTo(this); }
  /// The dead-reckoning banner's colours follow the display palette (dim at night).
  void setDisplayPalette(charts::Palette p);

 private:
  QLabel* add(const QString& name);
  QLabel* dr_;
  QLabel *estPos_, *truePos_, *estCog_, *trueCog_, *heading_, *current_, *log_, *loran_, *sensors_, *error_;
  std::array<QLabel*, 2> seed002_{};  ///< error and 95% semi-major axis of seed 002's two filters
  std::array<QLabel*, 5> nis_{};
  QLabel* radarFix_ = nullptr;
  QWidget* form_;
};

}  // namespace reckoner::ui
