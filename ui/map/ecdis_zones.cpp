// EcdisView's guard zones (guard_zones.h): own ship's polar frame on screen, the zones drawn, and the
// context menu's zone actions.
#include <QMenu>
#include <QPainter>
#include <cmath>

#include "common/angles.h"
#include "estimation/models/drkf_state.h"
#include "ui/map/ecdis_view.h"

namespace reckoner::ui {

std::optional<PolarMap> EcdisView::polarMap() const {
  if (!history_ || history_->empty() || !frame_) return std::nullopt;
  const auto& x = history_->latest().frame.estimate.x;
  const geo::GridPoint own{x[est::drkf::kPosX], x[est::drkf::kPosY]};
  const geo::GridInfo gi = frame_->gridInfo(own);
  const Local local = localAt(own.xM, own.yM);
  PolarMap m;
  m.toWidget = [local, gi](double rangeM, double bearingRad) {
    const double g = bearingRad - gi.convergenceRad, r = rangeM * gi.scale;
    return local.offset(r * std::sin(g), r * std::cos(g));
  };
  m.fromWidget = [this, own, gi](QPointF p) {
    const geo::GridPoint q = widgetToGrid(p);
    const double dx = q.xM - own.xM, dy = q.yM - own.yM;
    return std::pair{std::hypot(dx, dy) / gi.scale, wrapTwoPi(bearingOf(dx, dy) + gi.convergenceRad)};
  };
  m.pxPerMetre = local.pxPerMetre() * gi.scale;
  return m;
}

std::vector<track::AcquisitionZone> EcdisView::shownZones() const {
  if (const auto* dragged = zoneEditor_.preview()) return *dragged;
  if (pendingZones_) return *pendingZones_;
  if (!history_ || history_->empty()) return {};
  return history_->latest().frame.zones;
}

void EcdisView::editZones(const std::vector<track::AcquisitionZone>& zones) {
  pendingZones_ = zones;
  emit zonesEdited(zones);
  update();
}

void EcdisView::paintZones(QPainter& p) {
  const auto m = polarMap();
  const std::vector<track::AcquisitionZone> zones = shownZones();
  if (!m || zones.empty()) return;
  QColor line = colour("zone");
  QColor fill = line;
  fill.setAlpha(settings().palette == charts::Palette::Day ? 28 : 40);
  p.save();
  for (std::size_t i = 0; i < zones.size(); ++i) {
    const auto& z = zones[i];
    const bool editing = zoneEditor_.preview() != nullptr;
    p.setPen(QPen(line, editing ? 2.0 : 1.5, Qt::DashLine));
    p.setBrush(fill);
    QPainterPath path = zoneOutline(z, *m);
    path.setFillRule(Qt::OddEvenFill);
    p.drawPath(path);
    // Its number just outside the outer arc, in the middle of its bearings.
    const double span = wholeRing(z) ? 0.0 : wrapTwoPi(z.toBearingRad - z.fromBearingRad);
    const QPointF at =
        m->toWidget(z.maxRangeM + 12.0 / std::max(m->pxPerMetre, 1e-9), z.fromBearingRad + 0.5 * span);
    p.setPen(line);
    p.drawText(QRectF(at.x() - 20, at.y() - 9, 40, 18), Qt::AlignCenter, tr("GZ%1").arg(i + 1));
  }
  p.restore();
}

void EcdisView::addZoneActions(QMenu* menu, QPointF at) {
  const auto m = polarMap();
  if (!m) return;
  const std::vector<track::AcquisitionZone> zones = shownZones();
  const std::pair<double, double> polar = m->fromWidget(at);
  const double rangeM = polar.first, bearing = polar.second;
  menu->addSeparator();
  menu->addAction(tr("New guard zone here"), this,
                  [this, zones, rangeM, bearing, px = m->pxPerMetre] {
                    std::vector<track::AcquisitionZone> z = zones;
                    z.push_back(zoneAt(rangeM, bearing, 20.0 / std::max(px, 1e-9)));
                    editZones(z);
                  })
      ->setObjectName(QStringLiteral("newZone"));
  const ZoneHit hit = hitZone(zones, at, *m);
  if (hit.zone >= 0) {
    const int i = hit.zone;
    menu->addAction(tr("Delete guard zone GZ%1").arg(i + 1), this,
                    [this, zones, i] {
                      std::vector<track::AcquisitionZone> z = zones;
                      z.erase(z.begin() + i);
                      editZones(z);
                    })
        ->setObjectName(QStringLiteral("deleteZone"));
  }
  if (!zones.empty())
    menu->addAction(tr("Remove all guard zones (acquire everywhere)"), this, [this] { editZones({}); })
        ->setObjectName(QStringLiteral("clearZones"));
}

}  // namespace reckoner::ui
