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
  std::size_t waypoint = 0;     ///< k: 0 < k < waypoints.size() - 1
  double changeRad = 0.0;       ///< the course change at k, (-pi, pi], positive to starboard
  double plannedRadiusM = 0.0;  ///< the waypoint's radius, else the route's default
  double plannedWheelOverM =
      0.0;                  ///< geo::wheelOverDistanceM: R tan(|change| / 2), the change capped at 179°
  double legBeforeM = 0.0;  ///< the leg arriving at k
  double legAfterM = 0.0;   ///< the leg leaving k
  double wheelOverM = 0.0;  ///< as sailed: the planned one, but at most half of either leg
  double radiusM = 0.0;     ///< as sailed: wheelOverM / tan(|change| / 2) (0 for a corner or no change)
  /// Whether the turn is sailed on its planned radius: a radius of 0 (a corner) always is; otherwise the
  /// planned wheel-over must have room (at most half of either leg) and the change be at most 179° (a
  /// turn of more, such as a reversal, has no arc tangent to both legs on that radius: its wheel-over is
  /// capped at the 179° one and it is sailed on a smaller radius).
  bool fits = true;
};

/// The turn at waypoint k (0 < k < waypoints.size() - 1; std::out_of_range otherwise). Never throws for
/// such k, whatever the route: on one being drawn (a leg of length 0, a position not finite) the figures
/// may be 0 or NaN, so callers that report turns check Route::problems() first.
TurnFit turnFit(const Route& route, std::size_t k);
/// The turns that do not fit, in waypoint order (none for a route of fewer than three waypoints).
std::vector<TurnFit> turnsThatDoNotFit(const Route& route);

}  // namespace reckoner::geo
