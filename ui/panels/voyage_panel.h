#pragma once
// The Voyage panel (docs/gui.md, "Route monitoring"): own ship against the active route from the DRKF's
// estimate (MSC.232(82) 11.4): the leg, the cross-track distance with its sd against the limit on that
// side, the course to steer and the bearing and distance to the next waypoint, the wheel-over, time
// to go and the ETA at each waypoint still ahead; the anti-grounding look-ahead (the probability of
// crossing the safety contour, and of passing a danger, within the look-ahead time); track control
// on or off; and the grounding banner.
#include <QLabel>
#include <QWidget>

#include "charts/portrayal/portrayal.h"
#include "ui/bridge/live_frame.h"
#include "ui/common/display_units.h"

class QFormLayout;
class QTableWidget;

namespace reckoner::ui {

class VoyagePanel : public QWidget {
  Q_OBJECT
 public:
  explicit VoyagePanel(QWidget* parent = nullptr);
  void setFrame(const LiveFrame& frame);
  void setUnits(const DisplayUnits& units);
  void setDisplayPalette(charts::Palette p);

  // What tests read.
  [[nodiscard]] QString routeText() const { return route_->text(); }
  [[nodiscard]] QString crossTrackText() const { return xtd_->text(); }
  [[nodiscard]] QString lookAheadText() const { return lookAhead_->text(); }
  [[nodiscard]] QString groundingText() const {
    return aground_->isVisibleTo(this) ? aground_->text() : QString();
  }
  [[nodiscard]] QTableWidget* etaTable() const { return etas_; }

 private:
  QLabel* add(const QString& name);
  /// "T+hh:mm:ss" (simulation) or the UTC clock (live) of a stream time.
  [[nodiscard]] QString timeText(const LiveFrame& f, TimeUs t) const;
  void showLookAhead(const LiveFrame& f);

  DisplayUnits units_;
  charts::Palette palette_ = charts::Palette::Day;
  QFormLayout* form_;
  QLabel* aground_;
  QLabel *route_, *xtd_, *course_, *distance_, *wheelOver_, *lookAhead_, *lookAheadDetail_;
  QTableWidget* etas_;
};

}  // namespace reckoner::ui
