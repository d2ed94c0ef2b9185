#pragma once
// The turns of a route as they can be sailed (docs/routes.md, "Turns that do not fit"). At waypoint k
// with course change D and turn radius R (the waypoint's, else the route's default) the arc tangent to
// both legs begins R tan(|D| / 2) before the waypoint (the wheel-over distance) and ends as far after
// it. A turn whose wheel-over takes more than half of either leg at k does not fit: it is sailed on the
// largest radius that does, so that consecutive turns never overlap and every leg keeps a straight part
// to monitor. The route monitor sails the turns so; the route check reports the ones that do not fit.
#include <cstddef>
#include <vector>

#include "geo/route.h"

namespace reckoner::geo {

struct TurnFit {
  std::size_t waypoint = 0;        ///< k: 0 < k < waypoints.size() - 1
  double changeRad = 0.0;          ///< the course change at k, (-pi, pi], positive to starboard
  double plannedRadiusM = 0.0;     ///< the waypoint's radius, else the route's default
  double plannedWheelOverM = 0.0;  ///< R tan(|change| / 2) (geo::wheelOverDistanceM)
  double legBeforeM = 0.0;         ///< the leg arriving at k
  double legAfterM = 0.0;          ///< the leg leaving k
  double wheelOverM = 0.0;         ///< as sailed: the planned one, but at most half of either leg
  double radiusM = 0.0;            ///< as sailed: wheelOverM / tan(|change| / 2) (0 for a corner)
  /// Whether the planned turn is sailed as planned.
  [[nodiscard]] bool fits() const { return wheelOverM >= plannedWheelOverM; }
};

/// The turn at waypoint k (0 < k < waypoints.size() - 1; std::out_of_range otherwise). The route must
/// be valid (Route::problems() empty).
TurnFit turnFit(const Route& route, std::size_t k);
/// The turns that do not fit, in waypoint order (none for a route of fewer than three waypoints).
std::vector<TurnFit> turnsThatDoNotFit(const Route& route);

}  // namespace reckoner::geo
