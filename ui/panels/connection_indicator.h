#pragma once
// The connections in the status bar (docs/connections.md, "The window"): per source a coloured dot,
// its name and its sentences per second, from ConnectionHub::status() once a second. Green: connected
// and lines arrived in the last kSilentAfterS seconds; amber: connecting, waiting to retry, or
// connected but silent (a UDP port is "connected" as soon as it is bound, whether anybody sends or
// not); red: error; grey: disabled, stopped or a file played to its end. The tooltip has the state and
// the last error of each.
#include <QColor>
#include <QString>
#include <QWidget>
#include <vector>

#include "connections/connection_hub.h"

class QTimer;

namespace reckoner::ui {

enum class IndicatorLight { Green, Amber, Red, Grey };

/// A connected source with no bytes for this long is shown amber ("silent").
constexpr double kSilentAfterS = 5.0;

/// The light of a source's status at the system time nowUtc.
IndicatorLight indicatorLight(const conn::SourceStatus& s, UtcUs nowUtc);
QColor indicatorColour(IndicatorLight light);
const char* indicatorLightName(IndicatorLight light);

class ConnectionIndicator : public QWidget {
  Q_OBJECT
 public:
  struct Entry {
    QString name;
    IndicatorLight light = IndicatorLight::Grey;
    QString text;  ///< "name 12.0/s"
  };

  explicit ConnectionIndicator(conn::ConnectionHub& hub, QWidget* parent = nullptr);
  /// Reads the hub's status again (the timer calls it).
  void refresh();
  [[nodiscard]] const std::vector<Entry>& entries() const { return entries_; }

  QSize sizeHint() const override;
  QSize minimumSizeHint() const override { return sizeHint(); }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  conn::ConnectionHub& hub_;
  QTimer* timer_;
  std::vector<Entry> entries_;
};

}  // namespace reckoner::ui
