// The route on the chart (docs/gui.md "Routes"): the legs along their true geometry, the cross-track
// limits to port and starboard (faint), the wheel-over points and turn arcs, the waypoints with their
// names, and the route check's findings as red rings with their kind. The route being planned or
// edited is dashed in orange (S-52's APLRT); the active route, the one the ship follows, solid in
// red-orange (PLRTE). Everything is RouteOverlay's geometry (Mercator), mapped to pixels here.
#include <QLineF>
#include <QPainter>
#include <QPolygonF>
#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "ui/map/ecdis_view.h"

namespace reckoner::ui {
namespace {

constexpr double kWaypointRadiusPx = 5.0;
constexpr double kFindingRadiusPx = 9.0;
/// The look-ahead area is filled and labelled from this crossing probability (the alert's default).
constexpr double kLookAheadShownProbability = 0.05;

QPolygonF polyline(const charts::MercatorToScreen& m, const std::vector<charts::MercatorPoint>& pts) {
  QPolygonF out;
  out.reserve(static_cast<qsizetype>(pts.size()));
  for (const charts::MercatorPoint& q : pts) {
    const charts::ScreenPoint s = m(q.x, q.y);
    out << QPointF(s.x, s.y);
  }
  return out;
}

QPointF pointOf(const charts::MercatorToScreen& m, const charts::MercatorPoint& q) {
  const charts::ScreenPoint s = m(q.x, q.y);
  return {s.x, s.y};
}

/// "land", "safety contour", ... (hazardKindName with spaces).
QString kindText(charts::HazardKind kind) {
  return QString::fromLatin1(charts::hazardKindName(kind)).replace(QLatin1Char('_'), QLatin1Char(' '));
}

}  // namespace

void EcdisView::paintRouteLegs(QPainter& p, const RouteGeometry& g, const QColor& c, bool dashed) {
  const charts::MercatorToScreen m = viewport().mercatorToScreen();
  QColor casing = colour("panel");
  casing.setAlpha(140);
  for (const auto& leg : g.legs) {
    if (leg.size() < 2) continue;
    const QPolygonF line = polyline(m, leg);
    p.setPen(QPen(casing, 4.5, Qt::SolidLine, Qt::RoundCap));
    p.drawPolyline(line);
    QPen pen(c, 2.5, dashed ? Qt::DashLine : Qt::SolidLine, Qt::FlatCap);
    if (dashed) pen.setDashPattern({4.0, 2.5});
    p.setPen(pen);
    p.drawPolyline(line);
  }
}

void EcdisView::paintRouteMarks(QPainter& p, const RouteGeometry& g, const QColor& c) {
  const charts::MercatorToScreen m = viewport().mercatorToScreen();
  p.setBrush(Qt::NoBrush);
  // The cross-track limits, faint: the corridor the route check searches.
  QColor faint = c;
  faint.setAlpha(120);
  p.setPen(QPen(faint, 1.0, Qt::DashDotLine));
  for (const auto* side : {&g.port, &g.starboard})
    for (const auto& line : *side)
      if (line.size() >= 2) p.drawPolyline(polyline(m, line));
  // The turns as sailed: the arc and the wheel-over line across the leg where it begins. A turn whose
  // radius has no room between its legs (sailed on a smaller one, a route check finding) is dashed.
  for (const RouteGeometry::Turn& t : g.turns) {
    p.setPen(QPen(c, 1.5, t.fits ? Qt::SolidLine : Qt::DashLine));
    p.drawPolyline(polyline(m, t.arc));
    const QPointF at = pointOf(m, t.wheelOver);
    QPointF u(m.a * t.direction.x + m.b * t.direction.y, m.c * t.direction.x + m.d * t.direction.y);
    const double len = std::hypot(u.x(), u.y());
    if (!(len > 0.0)) continue;
    u /= len;
    const QPointF across(-u.y(), u.x());
    p.setPen(QPen(c, 2.0));
    p.drawLine(at - 8.0 * across, at + 8.0 * across);
  }
}

void EcdisView::paintRouteWaypoints(QPainter& p, const geo::Route& route, const RouteGeometry& g,
                                    const QColor& c, std::optional<std::size_t> selected) {
  const charts::MercatorToScreen m = viewport().mercatorToScreen();
  for (std::size_t k = 0; k < g.waypoints.size() && k < route.waypoints.size(); ++k) {
    const QPointF at = pointOf(m, g.waypoints[k]);
    const bool sel = selected && *selected == k;
    QColor fill = colour("panel");
    if (sel) fill = c;
    p.setBrush(fill);
    p.setPen(QPen(c, sel ? 2.5 : 1.8));
    const double r = sel ? kWaypointRadiusPx + 2.0 : kWaypointRadiusPx;
    p.drawEllipse(at, r, r);
    labelObstacles_.push_back(QRectF(at - QPointF(r, r), QSizeF(2 * r, 2 * r)));
    // On a light box edged in the route's colour: legible over the legs and any chart colour.
    pendingLabels_.push_back(
        PendingLabel{QString::fromStdString(route.waypoints[k].name), at, r + 1.0, c, 8.0, true});
  }
}

void EcdisView::paintRouteFindings(QPainter& p) {
  const RouteOverlay& r = *routeOverlay_;
  const charts::Viewport view = viewport();
  const QColor danger = colour("danger");
  std::vector<QPointF> drawn;  // findings at one place on screen share a ring and a label
  // The kind is written at the first finding of each kind on a leg and at the selected one: the list
  // has them all, and a dozen labels along one shore would hide the chart.
  std::set<std::pair<std::size_t, charts::HazardKind>> labelled;
  for (std::size_t i = 0; i < r.findings().size(); ++i) {
    const charts::RouteFinding& f = r.findings()[i];
    const charts::ScreenPoint s = view.toScreen(f.position);
    const QPointF at(s.x, s.y);
    const bool sel = r.selectedFinding() && *r.selectedFinding() == i;
    const bool seen = std::any_of(drawn.begin(), drawn.end(),
                                  [&](const QPointF& q) { return QLineF(q, at).length() < 6.0; });
    if (seen && !sel) continue;
    drawn.push_back(at);
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(danger, sel ? 3.0 : 2.0));
    p.drawEllipse(at, kFindingRadiusPx, kFindingRadiusPx);
    if (sel) p.drawEllipse(at, kFindingRadiusPx + 5.0, kFindingRadiusPx + 5.0);
    const double box = kFindingRadiusPx + (sel ? 6.0 : 1.0);
    labelObstacles_.push_back(QRectF(at - QPointF(box, box), QSizeF(2 * box, 2 * box)));
    if (labelled.insert({f.leg, f.kind}).second || sel)
      pendingLabels_.push_back(PendingLabel{kindText(f.kind), at, box, danger, 8.0, false});
  }
}

void EcdisView::paintLookAhead(QPainter& p) {
  // The anti-grounding look-ahead (docs/routes.md): the area own ship may cover (95%) within the
  // look-ahead time, outlined while the crossing probability is below the alert's and filled in the
  // danger colour above it; the hazards met, ringed; and where the ship is aground, a cross.
  const LiveFrame& live = history_->latest();
  const charts::Viewport view = viewport();
  p.save();
  if (const sim::GroundingOutlook* o = live.lookAhead.get(); o && o->valid && o->area.size() >= 3) {
    QPolygonF area;
    for (const geo::GeoPoint& g : o->area) {
      const charts::ScreenPoint s = view.toScreen({g.latDeg, g.lonDeg});
      area << QPointF(s.x, s.y);
    }
    const double prob = std::max(o->crossingProbability, o->dangerProbability);
    const bool alerting = prob >= kLookAheadShownProbability;
    QColor edge = alerting ? colour("danger") : colour("tool");
    QColor fill = edge;
    fill.setAlpha(alerting ? 60 : 0);
    p.setBrush(alerting ? QBrush(fill) : QBrush(Qt::NoBrush));
    p.setPen(QPen(edge, alerting ? 1.8 : 1.0, Qt::DashLine));
    p.drawPolygon(area);
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(colour("danger"), 1.5));
    for (const sim::HazardAhead& h : o->ahead) {
      if (h.probability <= 0.0) continue;
      const charts::ScreenPoint s = view.toScreen({h.position.latDeg, h.position.lonDeg});
      p.drawEllipse(QPointF(s.x, s.y), 5.0, 5.0);
    }
    if (alerting) {
      const QRectF box = area.boundingRect();
      pendingLabels_.push_back(PendingLabel{
          QStringLiteral("%1% in %2 min").arg(100.0 * prob, 0, 'f', 0).arg(o->horizonS / 60.0, 0, 'f', 0),
          box.center(), 4.0, colour("danger"), 8.0, true});
    }
  }
  if (live.aground) {
    const auto& x = live.frame.estimate.x;
    const Local at = localAt(x[est::drkf::kPosX], x[est::drkf::kPosY]);
    p.setPen(QPen(colour("danger"), 3.0));
    p.drawLine(at.p + QPointF(-12, -12), at.p + QPointF(12, 12));
    p.drawLine(at.p + QPointF(-12, 12), at.p + QPointF(12, -12));
    pendingLabels_.push_back(PendingLabel{tr("AGROUND"), at.p, 14.0, colour("danger"), 9.0, true});
  }
  p.restore();
}

void EcdisView::paintRoute(QPainter& p) {
  const RouteOverlay& r = *routeOverlay_;
  p.save();
  // The active route when another one is shown: solid, with its waypoints.
  if (const auto& g = r.activeGeometry(); g && r.activeRoute()) {
    const QColor c = colour("routeActive");
    paintRouteLegs(p, *g, c, false);
    paintRouteWaypoints(p, *r.activeRoute(), *g, c, std::nullopt);
  }
  if (r.route()) {
    const bool active = r.isActive() && !r.editing();
    const QColor c = colour(active ? "routeActive" : "route");
    paintRouteMarks(p, r.geometry(), c);
    paintRouteLegs(p, r.geometry(), c, !active);
    paintRouteWaypoints(p, *r.route(), r.geometry(), c, r.selectedWaypoint());
    paintRouteFindings(p);
  }
  p.restore();
}

}  // namespace reckoner::ui
