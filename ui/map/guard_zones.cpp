#include "ui/map/guard_zones.h"

#include <QLineF>
#include <algorithm>
#include <cmath>

#include "common/angles.h"

namespace reckoner::ui {
namespace {

const double kArcStepRad = degToRad(2.0);

double spanOf(const track::AcquisitionZone& z) {
  const double s = wrapTwoPi(z.toBearingRad - z.fromBearingRad);
  return s == 0.0 ? kTwoPi : s;
}

/// Distance in pixels from p to the arc of radius rangeM over the zone's bearings.
double arcDistancePx(const track::AcquisitionZone& z, double rangeM, QPointF p, const PolarMap& m) {
  const auto [r, b] = m.fromWidget(p);
  if (z.contains(z.minRangeM, b) || wholeRing(z)) return std::abs(r - rangeM) * m.pxPerMetre;
  return std::min(QLineF(p, m.toWidget(rangeM, z.fromBearingRad)).length(),
                  QLineF(p, m.toWidget(rangeM, z.toBearingRad)).length());
}

/// Distance in pixels from p to the side at bearing b (from the inner to the outer range).
double sideDistancePx(const track::AcquisitionZone& z, double b, QPointF p, const PolarMap& m) {
  const QPointF a = m.toWidget(z.minRangeM, b), c = m.toWidget(z.maxRangeM, b);
  const QPointF d = c - a;
  const double len2 = QPointF::dotProduct(d, d);
  const double t = len2 > 0.0 ? std::clamp(QPointF::dotProduct(p - a, d) / len2, 0.0, 1.0) : 0.0;
  return QLineF(p, a + t * d).length();
}

}  // namespace

bool wholeRing(const track::AcquisitionZone& z) {
  return wrapTwoPi(z.toBearingRad - z.fromBearingRad) == 0.0;
}

QPainterPath zoneOutline(const track::AcquisitionZone& z, const PolarMap& m) {
  const double span = spanOf(z);
  const int n = std::max(2, static_cast<int>(std::ceil(span / kArcStepRad)) + 1);
  QPainterPath path;
  const auto arc = [&](double rangeM, bool clockwise, bool start) {
    for (int i = 0; i < n; ++i) {
      const double f = static_cast<double>(i) / (n - 1);
      const double b = z.fromBearingRad + span * (clockwise ? f : 1.0 - f);
      const QPointF q = m.toWidget(rangeM, b);
      if (start && i == 0)
        path.moveTo(q);
      else
        path.lineTo(q);
    }
  };
  if (wholeRing(z)) {
    arc(z.maxRangeM, true, true);
    path.closeSubpath();
    if (z.minRangeM > 0.0) {
      arc(z.minRangeM, false, true);
      path.closeSubpath();
    }
    return path;
  }
  arc(z.maxRangeM, true, true);
  arc(z.minRangeM, false, false);
  path.closeSubpath();
  return path;
}

ZoneHit hitZone(const std::vector<track::AcquisitionZone>& zones, QPointF p, const PolarMap& m,
                double tolPx) {
  for (int i = static_cast<int>(zones.size()) - 1; i >= 0; --i) {
    const auto& z = zones[static_cast<std::size_t>(i)];
    if (arcDistancePx(z, z.maxRangeM, p, m) <= tolPx) return {i, ZoneEdge::Outer};
    if (z.minRangeM > 0.0 && arcDistancePx(z, z.minRangeM, p, m) <= tolPx) return {i, ZoneEdge::Inner};
    if (!wholeRing(z)) {
      if (sideDistancePx(z, z.fromBearingRad, p, m) <= tolPx) return {i, ZoneEdge::From};
      if (sideDistancePx(z, z.toBearingRad, p, m) <= tolPx) return {i, ZoneEdge::To};
    }
  }
  for (int i = static_cast<int>(zones.size()) - 1; i >= 0; --i) {
    const auto [r, b] = m.fromWidget(p);
    if (zones[static_cast<std::size_t>(i)].contains(r, b)) return {i, ZoneEdge::Inside};
  }
  return {};
}

track::AcquisitionZone movedZone(track::AcquisitionZone z, ZoneEdge edge, double rangeM, double bearingRad,
                                 double grabBearingRad, double minSpanM) {
  switch (edge) {
    case ZoneEdge::Outer:
      z.maxRangeM = std::max(rangeM, z.minRangeM + minSpanM);
      break;
    case ZoneEdge::Inner:
      z.minRangeM = std::clamp(rangeM, 0.0, z.maxRangeM - minSpanM);
      if (z.minRangeM < minSpanM) z.minRangeM = 0.0;  // dragged to own ship: the sector starts there
      break;
    case ZoneEdge::From:
      z.fromBearingRad = wrapTwoPi(bearingRad);
      break;
    case ZoneEdge::To:
      z.toBearingRad = wrapTwoPi(bearingRad);
      break;
    case ZoneEdge::Inside: {
      const double turn = wrapPi(bearingRad - grabBearingRad);
      z.fromBearingRad = wrapTwoPi(z.fromBearingRad + turn);
      z.toBearingRad = wrapTwoPi(z.toBearingRad + turn);
      break;
    }
    case ZoneEdge::None:
      break;
  }
  return z;
}

track::AcquisitionZone zoneAt(double rangeM, double bearingRad, double minSpanM) {
  const double half = degToRad(22.5);
  track::AcquisitionZone z;
  z.minRangeM = std::max(0.0, 0.8 * rangeM);
  z.maxRangeM = std::max(1.2 * rangeM, z.minRangeM + minSpanM);
  z.fromBearingRad = wrapTwoPi(bearingRad - half);
  z.toBearingRad = wrapTwoPi(bearingRad + half);
  return z;
}

bool GuardZoneEditor::press(const std::vector<track::AcquisitionZone>& zones, QPointF p, const PolarMap& m) {
  const ZoneHit hit = hitZone(zones, p, m);
  if (hit.zone < 0) return false;
  drag_ = Drag{zones, zones[static_cast<std::size_t>(hit.zone)], hit.zone, hit.edge, m.fromWidget(p).second};
  return true;
}

bool GuardZoneEditor::move(QPointF p, const PolarMap& m) {
  if (!drag_) return false;
  const auto [r, b] = m.fromWidget(p);
  // At least 10 px deep on screen, so the inner and outer arcs stay apart enough to grab.
  const double minSpanM = 10.0 / std::max(m.pxPerMetre, 1e-9);
  drag_->zones[static_cast<std::size_t>(drag_->zone)] =
      movedZone(drag_->start, drag_->edge, r, b, drag_->grabBearingRad, minSpanM);
  return true;
}

std::optional<std::vector<track::AcquisitionZone>> GuardZoneEditor::release(QPointF p, const PolarMap& m) {
  if (!move(p, m)) return std::nullopt;
  std::vector<track::AcquisitionZone> zones = std::move(drag_->zones);
  drag_.reset();
  return zones;
}

}  // namespace reckoner::ui
