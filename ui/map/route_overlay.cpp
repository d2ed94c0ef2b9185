// RouteOverlay: the route's state, geometry and mouse input on the chart (route_overlay.h); the
// painting is EcdisView's (ecdis_route.cpp).
#include "ui/map/route_overlay.h"

#include <QLineF>
#include <QMenu>
#include <algorithm>
#include <cmath>

#include "common/angles.h"
#include "geo/route_turns.h"
#include "ui/common/route_text.h"

namespace reckoner::ui {
namespace {

constexpr double kMaxLegPieceM = 500.0;
constexpr int kArcSteps = 24;

charts::MercatorPoint mercatorOf(const geo::GeoPoint& p) {
  return charts::toMercator({p.latDeg, p.lonDeg});
}

QPointF screenOf(const charts::MercatorToScreen& m, const charts::MercatorPoint& q) {
  const charts::ScreenPoint s = m(q.x, q.y);
  return {s.x, s.y};
}

geo::GeoPoint geoPointAt(QPointF p, const charts::Viewport& v) {
  const charts::LatLon ll = v.toLatLon({p.x(), p.y()});
  return {ll.latDeg, std::remainder(ll.lonDeg, 360.0)};
}

double distanceToSegment(QPointF p, QPointF a, QPointF b) {
  const QPointF ab = b - a;
  const double len2 = QPointF::dotProduct(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(QPointF::dotProduct(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return QLineF(p, a + t * ab).length();
}

/// The turn at waypoint k as the route monitor sails it (geo::turnFit: a radius that does not fit is
/// reduced until it does): the arc tangent to the arriving leg at the wheel-over point and ending on the
/// departing leg, constructed in Mercator (conformal, so a small circle stays a circle).
std::optional<RouteGeometry::Turn> turnAt(const geo::Route& route, std::size_t k) {
  const geo::TurnFit fit = geo::turnFit(route, k);
  const double d = fit.wheelOverM;
  if (!(d > 0.0) || !std::isfinite(d)) return std::nullopt;
  const double lenIn = fit.legBeforeM;
  const charts::MercatorPoint p = mercatorOf(geo::legPoint(route, k, lenIn - d));
  const charts::MercatorPoint back = mercatorOf(geo::legPoint(route, k, lenIn - d - 1.0));
  const charts::MercatorPoint q = mercatorOf(geo::legPoint(route, k + 1, d));
  double tx = p.x - back.x, ty = p.y - back.y;
  const double tl = std::hypot(tx, ty);
  if (!(tl > 0.0) || !std::isfinite(q.x) || !std::isfinite(q.y)) return std::nullopt;
  tx /= tl;
  ty /= tl;
  const double wx = q.x - p.x, wy = q.y - p.y;
  double nx = -ty, ny = tx;  // the normal towards the turn's side
  if (wx * nx + wy * ny < 0.0) {
    nx = -nx;
    ny = -ny;
  }
  const double across = wx * nx + wy * ny;
  if (!(across > 0.0)) return std::nullopt;
  const double r = (wx * wx + wy * wy) / (2.0 * across);
  const double cx = p.x + r * nx, cy = p.y + r * ny;
  const double a0 = std::atan2(p.y - cy, p.x - cx);
  const double sweep = wrapPi(std::atan2(q.y - cy, q.x - cx) - a0);
  RouteGeometry::Turn t{k, p, {tx, ty}, {}, fit.fits};
  for (int s = 0; s <= kArcSteps; ++s) {
    const double a = a0 + sweep * s / kArcSteps;
    t.arc.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
  }
  return t;
}

}  // namespace

RouteGeometry routeGeometry(const geo::Route& route) {
  RouteGeometry g;
  const std::size_t n = route.waypoints.size();
  for (const geo::Waypoint& w : route.waypoints) g.waypoints.push_back(mercatorOf(w.position));
  g.legs.resize(n);
  g.port.resize(n);
  g.starboard.resize(n);
  for (std::size_t to = 1; to < n; ++to) {
    const double len = geo::legLengthM(route, to);
    if (!(len > 0.0) || !std::isfinite(len)) continue;  // a leg of length 0 (refused as an edit)
    for (const geo::GeoPoint& p : geo::legPoints(route, to, std::max(kMaxLegPieceM, len / 256.0)))
      g.legs[to].push_back(mercatorOf(p));
    // The cross-track limits are the edges of the corridor the route check uses.
    const std::vector<std::vector<charts::MercatorPoint>> pieces = charts::legCorridor(route, to);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      if (i == 0) {
        g.starboard[to].push_back(pieces[i][1]);
        g.port[to].push_back(pieces[i][4]);
      }
      g.starboard[to].push_back(pieces[i][2]);
      g.port[to].push_back(pieces[i][3]);
    }
  }
  for (std::size_t k = 1; k + 1 < n; ++k)
    if (auto t = turnAt(route, k)) g.turns.push_back(std::move(*t));
  return g;
}

RouteOverlay::RouteOverlay(QObject* parent) : QObject(parent) {}

void RouteOverlay::rebuild() {
  geometry_ = shown_ ? routeGeometry(*shown_) : RouteGeometry{};
}

void RouteOverlay::setRoute(const geo::Route& route, bool active) {
  route_ = route;
  shown_ = route;
  active_ = active;
  drag_.reset();
  if (selectedWaypoint_ && *selectedWaypoint_ >= route.waypoints.size()) selectedWaypoint_.reset();
  rebuild();
  emit changed();
}

void RouteOverlay::clearRoute() {
  route_.reset();
  shown_.reset();
  active_ = false;
  drag_.reset();
  selectedWaypoint_.reset();
  findings_.clear();
  selectedFinding_.reset();
  rebuild();
  emit changed();
}

void RouteOverlay::setActiveRoute(const std::optional<geo::Route>& route) {
  activeRoute_ = route;
  activeGeometry_ = route ? std::optional<RouteGeometry>(routeGeometry(*route)) : std::nullopt;
  emit changed();
}

void RouteOverlay::setFindings(std::vector<charts::RouteFinding> findings) {
  findings_ = std::move(findings);
  selectedFinding_.reset();
  emit changed();
}

void RouteOverlay::setSelectedWaypoint(std::optional<std::size_t> index) {
  if (index && (!route_ || *index >= route_->waypoints.size())) index.reset();
  if (selectedWaypoint_ == index) return;
  selectedWaypoint_ = index;
  emit changed();
}

void RouteOverlay::setSelectedFinding(std::optional<std::size_t> index) {
  if (index && *index >= findings_.size()) index.reset();
  selectedFinding_ = index;
  emit changed();
}

void RouteOverlay::setEditing(bool on) {
  if (editing_ == on) return;
  editing_ = on;
  if (drag_) {
    drag_.reset();
    shown_ = route_;
    rebuild();
  }
  emit editingChanged(on);
  emit changed();
}

std::optional<std::size_t> RouteOverlay::waypointAt(QPointF p, const charts::Viewport& v,
                                                    double tolPx) const {
  const charts::MercatorToScreen m = v.mercatorToScreen();
  std::optional<std::size_t> best;
  double bestD = tolPx;
  for (std::size_t k = 0; k < geometry_.waypoints.size(); ++k) {
    const double d = QLineF(p, screenOf(m, geometry_.waypoints[k])).length();
    if (d <= bestD) {
      bestD = d;
      best = k;
    }
  }
  return best;
}

std::optional<std::size_t> RouteOverlay::legAt(QPointF p, const charts::Viewport& v, double tolPx) const {
  const charts::MercatorToScreen m = v.mercatorToScreen();
  std::optional<std::size_t> best;
  double bestD = tolPx;
  for (std::size_t to = 1; to < geometry_.legs.size(); ++to) {
    const auto& leg = geometry_.legs[to];
    for (std::size_t i = 1; i < leg.size(); ++i) {
      const double d = distanceToSegment(p, screenOf(m, leg[i - 1]), screenOf(m, leg[i]));
      if (d <= bestD) {
        bestD = d;
        best = to;
      }
    }
  }
  return best;
}

bool RouteOverlay::press(QPointF p, const charts::Viewport& v) {
  if (!route_) return false;
  const std::optional<std::size_t> k = waypointAt(p, v);
  if (!k) return false;
  setSelectedWaypoint(k);
  emit waypointSelected(static_cast<int>(*k));
  if (!editing_) return false;  // selected; the chart pans or picks as it would
  drag_ = Drag{*k, p, route_->waypoints[*k].position, false};
  return true;
}

bool RouteOverlay::move(QPointF p, const charts::Viewport& v) {
  if (!drag_) return false;
  if (!drag_->moved && QLineF(p, drag_->from).length() < 3.0) return true;  // a click, not yet a drag
  drag_->moved = true;
  drag_->at = geoPointAt(p, v);
  shown_ = moved(drag_->index, drag_->at);
  rebuild();
  emit changed();
  return true;
}

bool RouteOverlay::release(QPointF p, const charts::Viewport& v) {
  if (!drag_) return false;
  const Drag d = *drag_;
  drag_.reset();
  shown_ = route_;
  rebuild();
  emit changed();
  if (d.moved) {
    const QString name = QString::fromStdString(route_->waypoints[d.index].name);
    emit routeEdited(moved(d.index, geoPointAt(p, v)), tr("Move %1").arg(name));
  }
  return true;
}

bool RouteOverlay::click(QPointF p, const charts::Viewport& v) {
  if (!editing_ || !route_) return false;
  const geo::Route after = appended(geoPointAt(p, v));
  emit routeEdited(after, tr("Add %1").arg(QString::fromStdString(after.waypoints.back().name)));
  return true;
}

bool RouteOverlay::key(int key) {
  if (!editing_) return false;
  if (key == Qt::Key_Escape) {
    setEditing(false);
    return true;
  }
  if (key == Qt::Key_Delete && selectedWaypoint_ && route_) {
    const std::size_t k = *selectedWaypoint_;
    emit routeEdited(removed(k), tr("Delete %1").arg(QString::fromStdString(route_->waypoints[k].name)));
    return true;
  }
  return false;
}

void RouteOverlay::addContextActions(QMenu* menu, QPointF p, const charts::Viewport& v) {
  if (!editing_ || !route_) return;
  // The edits are made now, from the route the operator sees.
  const geo::GeoPoint at = geoPointAt(p, v);
  if (const auto k = waypointAt(p, v)) {
    const QString name = QString::fromStdString(route_->waypoints[*k].name);
    const geo::Route after = removed(*k);
    menu->addAction(tr("Delete waypoint %1").arg(name), this,
                    [this, after, name] { emit routeEdited(after, tr("Delete %1").arg(name)); })
        ->setObjectName(QStringLiteral("routeDeleteWaypoint"));
    menu->addAction(tr("Rename waypoint %1…").arg(name), this,
                    [this, index = static_cast<int>(*k)] { emit renameRequested(index); })
        ->setObjectName(QStringLiteral("routeRenameWaypoint"));
  } else if (const auto to = legAt(p, v)) {
    const geo::Route after = inserted(*to, at);
    const QString name = QString::fromStdString(after.waypoints[*to].name);
    menu->addAction(tr("Insert waypoint here"), this,
                    [this, after, name] { emit routeEdited(after, tr("Insert %1").arg(name)); })
        ->setObjectName(QStringLiteral("routeInsertWaypoint"));
  }
  const geo::Route after = appended(at);
  const QString name = QString::fromStdString(after.waypoints.back().name);
  menu->addAction(tr("Add waypoint here (end of the route)"), this,
                  [this, after, name] { emit routeEdited(after, tr("Add %1").arg(name)); })
      ->setObjectName(QStringLiteral("routeAppendWaypoint"));
  menu->addAction(tr("Leave route edit (Esc)"), this, [this] { setEditing(false); })
      ->setObjectName(QStringLiteral("routeLeaveEdit"));
  menu->addSeparator();
}

geo::Route RouteOverlay::appended(const geo::GeoPoint& at) const {
  geo::Route r = route_.value_or(geo::Route{});
  geo::Waypoint w;
  w.id = nextWaypointId(r);
  w.name = nextWaypointName(r);
  w.position = at;
  if (r.waypoints.size() >= 2) w.leg = r.waypoints.back().leg;  // the limits and speed of the leg before
  r.waypoints.push_back(w);
  return r;
}

geo::Route RouteOverlay::inserted(std::size_t to, const geo::GeoPoint& at) const {
  geo::Route r = route_.value_or(geo::Route{});
  if (to == 0 || to >= r.waypoints.size()) return r;
  const double len = geo::legLengthM(r, to);
  const geo::LegFix fix = geo::legFix(r, to, at);
  const double along =
      std::isfinite(fix.alongTrackM) ? std::clamp(fix.alongTrackM, 0.1 * len, 0.9 * len) : 0.5 * len;
  geo::Waypoint w;
  w.id = nextWaypointId(r);
  w.name = nextWaypointName(r);
  w.position = geo::legPoint(r, to, along);
  w.leg = r.waypoints[to].leg;  // both halves keep the leg's plan
  r.waypoints.insert(r.waypoints.begin() + static_cast<std::ptrdiff_t>(to), w);
  return r;
}

geo::Route RouteOverlay::removed(std::size_t k) const {
  geo::Route r = route_.value_or(geo::Route{});
  if (k < r.waypoints.size()) r.waypoints.erase(r.waypoints.begin() + static_cast<std::ptrdiff_t>(k));
  return r;
}

geo::Route RouteOverlay::moved(std::size_t k, const geo::GeoPoint& at) const {
  geo::Route r = route_.value_or(geo::Route{});
  if (k < r.waypoints.size()) r.waypoints[k].position = at;
  return r;
}

}  // namespace reckoner::ui
