#include "ui/panels/voyage_panel.h"

#include <QFormLayout>
#include <QHeaderView>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>

#include "common/time.h"
#include "io/iso8601.h"
#include "ui/panels/alert_panel.h"

namespace reckoner::ui {
namespace {
/// hh:mm:ss of a span of seconds ("–" when it is not finite).
QString span(double s) {
  if (!std::isfinite(s) || s < 0.0) return QStringLiteral("–");
  if (s >= 100.0 * 3600.0) return QStringLiteral("> 99 h");
  const auto t = static_cast<long long>(std::llround(s));
  return QStringLiteral("%1:%2:%3")
      .arg(t / 3600, 2, 10, QChar('0'))
      .arg(t / 60 % 60, 2, 10, QChar('0'))
      .arg(t % 60, 2, 10, QChar('0'));
}

QString percent(double p) {
  if (p <= 0.0) return QStringLiteral("0%");
  if (p < 0.01) return QStringLiteral("< 1%");
  return QStringLiteral("%1%").arg(100.0 * p, 0, 'f', 0);
}

QString waypointName(const geo::Route& r, std::size_t i) {
  if (i >= r.waypoints.size()) return QStringLiteral("?");
  const std::string& n = r.waypoints[i].name;
  return n.empty() ? QStringLiteral("WP%1").arg(i + 1) : QString::fromStdString(n);
}
}  // namespace

VoyagePanel::VoyagePanel(QWidget* parent) : QWidget(parent) {
  auto* v = new QVBoxLayout(this);
  aground_ = new QLabel(this);
  aground_->setObjectName(QStringLiteral("groundingBanner"));
  aground_->setWordWrap(true);
  aground_->hide();
  v->addWidget(aground_);
  auto* form = new QWidget(this);
  form_ = new QFormLayout(form);
  form_->setContentsMargins(0, 0, 0, 0);
  v->addWidget(form);
  route_ = add(tr("Route"));
  xtd_ = add(tr("Cross-track"));
  course_ = add(tr("Course to steer"));
  distance_ = add(tr("Next waypoint"));
  wheelOver_ = add(tr("Wheel-over"));
  lookAhead_ = add(tr("Look-ahead"));
  lookAheadDetail_ = add(QString());
  lookAhead_->setObjectName(QStringLiteral("lookAheadText"));
  xtd_->setObjectName(QStringLiteral("crossTrackText"));
  etas_ = new QTableWidget(0, 4, this);
  etas_->setObjectName(QStringLiteral("etaTable"));
  etas_->setHorizontalHeaderLabels({tr("Waypoint"), tr("Distance"), tr("Time to go"), tr("ETA")});
  etas_->verticalHeader()->hide();
  etas_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  etas_->horizontalHeader()->setStretchLastSection(true);
  etas_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  etas_->setSelectionMode(QAbstractItemView::NoSelection);
  etas_->setMinimumHeight(120);
  v->addWidget(etas_, 1);
  setDisplayPalette(charts::Palette::Day);
}

QLabel* VoyagePanel::add(const QString& name) {
  auto* l = new QLabel(this);
  l->setTextInteractionFlags(Qt::TextSelectableByMouse);
  l->setWordWrap(true);
  form_->addRow(name.isEmpty() ? QString() : name + ':', l);
  return l;
}

void VoyagePanel::setUnits(const DisplayUnits& units) {
  units_ = units;
}

void VoyagePanel::setDisplayPalette(charts::Palette p) {
  palette_ = p;
  aground_->setStyleSheet(alertLabelStyle(alerts::Priority::Alarm, p, 4));
}

QString VoyagePanel::timeText(const LiveFrame& f, TimeUs t) const {
  if (f.live)
    return QString::fromStdString(io::formatIso8601(f.liveUtc0 + t)).mid(11, 8) + QStringLiteral(" UTC");
  return QStringLiteral("T+") + span(toSeconds(t));
}

void VoyagePanel::setFrame(const LiveFrame& live) {
  if (live.aground) {
    aground_->setText(tr("AGROUND on %1").arg(QString::fromStdString(live.aground->what)));
    aground_->show();
  } else {
    aground_->hide();
  }
  showLookAhead(live);
  const auto& status = live.frame.route;
  if (!live.route || !status) {
    route_->setText(live.route
                        ? tr("%1: waiting for a position").arg(QString::fromStdString(live.route->name))
                        : tr("no active route (Route ▸ Activate route)"));
    for (QLabel* l : {xtd_, course_, distance_, wheelOver_}) l->setText(QStringLiteral("–"));
    xtd_->setStyleSheet({});
    etas_->setRowCount(0);
    return;
  }
  const geo::Route& r = *live.route;
  const nav::RouteStatus& s = *status;
  QString part;
  if (s.trackPart == nav::TrackPart::Turn) part = tr(", in the turn");
  if (s.trackPart == nav::TrackPart::PreviousLeg) part = tr(", before the wheel-over of the leg");
  route_->setText(tr("%1, leg %2 → %3%4%5")
                      .arg(QString::fromStdString(r.name), waypointName(r, s.to - 1), waypointName(r, s.to),
                           part, live.followingRoute ? tr(" · track control") : QString()));
  if (s.arrived) {
    route_->setText(route_->text() + tr(" · ARRIVED"));
  }
  if (!s.valid) {
    xtd_->setText(tr("no usable position"));
    xtd_->setStyleSheet({});
  } else {
    // In metres whatever the distance unit: a cross-track distance is tens of metres, which 0.01 NM
    // cannot show.
    const QString side = s.side == nav::TrackSide::Port ? tr("port") : tr("starboard");
    const QString sd =
        std::isfinite(s.crossTrackSdM) ? tr(" ± %1 m").arg(s.crossTrackSdM, 0, 'f', 1) : QString();
    xtd_->setText(tr("%1 m %2%3 (limit %4 m)%5")
                      .arg(std::abs(s.crossTrackM), 0, 'f', 1)
                      .arg(side, sd)
                      .arg(s.crossTrackLimitM, 0, 'f', 0)
                      .arg(s.offTrack ? tr(" · OFF TRACK") : QString()));
    xtd_->setStyleSheet(s.offTrack ? alertLabelStyle(alerts::Priority::Warning, palette_, 2) : QString());
  }
  course_->setText(tr("%1 (leg %2) · COG %3 SOG %4")
                       .arg(formatBearing(s.trackCourseRad), formatBearing(s.legCourseRad),
                            formatBearing(s.cogRad), formatSpeed(s.sogMps, units_, 1)));
  distance_->setText(tr("%1 bearing %2, %3, time to go %4")
                         .arg(waypointName(r, s.to), formatBearing(s.bearingToWaypointRad),
                              formatDistance(s.distanceToWaypointM, units_, 2), span(s.timeToWaypointS)) +
                     (s.arrivalCircleEntered ? tr(" · in the arrival circle") : QString()));
  if (s.to + 1 >= r.waypoints.size())
    wheelOver_->setText(tr("none (the last waypoint)"));
  else if (s.distanceToWheelOverM < 0.0)
    wheelOver_->setText(tr("passed: turn now"));
  else
    wheelOver_->setText(
        tr("in %1 (%2)").arg(formatDistance(s.distanceToWheelOverM, units_, 2), span(s.timeToWheelOverS)));
  etas_->setRowCount(static_cast<int>(s.etas.size()));
  for (std::size_t i = 0; i < s.etas.size(); ++i) {
    const nav::WaypointEta& e = s.etas[i];
    const int row = static_cast<int>(i);
    const auto set = [&](int col, const QString& text) {
      auto* item = etas_->item(row, col);
      if (!item) etas_->setItem(row, col, item = new QTableWidgetItem);
      item->setText(text);
    };
    set(0, waypointName(r, e.waypoint));
    set(1, formatDistance(e.distanceM, units_, 2));
    set(2, span(e.timeS) + (std::isfinite(e.timeSdS) && e.timeSdS >= 1.0
                                ? tr(" ± %1 s").arg(e.timeSdS, 0, 'f', 0)
                                : QString()));
    set(3, e.etaUs ? timeText(live, *e.etaUs) : QStringLiteral("–"));
  }
}

void VoyagePanel::showLookAhead(const LiveFrame& live) {
  const sim::GroundingOutlook* o = live.lookAhead.get();
  if (!o || !o->valid) {
    lookAhead_->setText(o ? tr("no usable estimate") : tr("off (no chart open)"));
    lookAhead_->setStyleSheet({});
    lookAheadDetail_->clear();
    return;
  }
  const double minutes = o->horizonS / 60.0;
  lookAhead_->setText(tr("safety contour %1, dangers %2 within %3 min")
                          .arg(percent(o->crossingProbability), percent(o->dangerProbability))
                          .arg(minutes, 0, 'f', 0));
  const double p = std::max(o->crossingProbability, o->dangerProbability);
  lookAhead_->setStyleSheet(p >= 0.05 ? alertLabelStyle(alerts::Priority::Warning, palette_, 2) : QString());
  QStringList ahead;
  for (std::size_t i = 0; i < o->ahead.size() && i < 3; ++i) {
    const sim::HazardAhead& h = o->ahead[i];
    QString what = QString::fromStdString(h.kind).replace(QLatin1Char('_'), QLatin1Char(' '));
    if (h.depthM) what += tr(" %1 m").arg(*h.depthM, 0, 'f', 1);
    ahead << tr("%1 (%2)%3")
                 .arg(what, QString::fromStdString(h.objectClass),
                      h.probability > 0.0 ? QStringLiteral(" ") + percent(h.probability) : QString());
  }
  QString detail = ahead.isEmpty() ? tr("nothing charted in the area")
                                   : tr("in the area: %1").arg(ahead.join(QStringLiteral(", ")));
  if (std::isfinite(o->medianCrossingS))
    detail += tr(" · median crossing in %1").arg(span(o->medianCrossingS));
  lookAheadDetail_->setText(detail);
}

}  // namespace reckoner::ui
