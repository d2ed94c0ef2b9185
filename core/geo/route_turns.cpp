// The turns of a route as they can be sailed: the planned wheel-over against half of each leg.
#include "geo/route_turns.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "common/angles.h"
#include "common/units.h"

namespace reckoner::geo {
namespace {
/// The largest course change geo::wheelOverDistanceM turns on the planned radius (it caps the change there).
constexpr double kMaxFittingChangeDeg = 179.0;
}  // namespace

TurnFit turnFit(const Route& route, std::size_t k) {
  if (k == 0 || k + 1 >= route.waypoints.size())
    throw std::out_of_range("turnFit: waypoint " + std::to_string(k) + " has no turn (route of " +
                            std::to_string(route.waypoints.size()) + " waypoints)");
  TurnFit t;
  t.waypoint = k;
  t.changeRad = courseChangeRad(route, k);
  t.plannedRadiusM = nmToMetres(route.turnRadiusNm(k));
  t.plannedWheelOverM = wheelOverDistanceM(route, k);
  t.legBeforeM = legLengthM(route, k);
  t.legAfterM = legLengthM(route, k + 1);
  t.wheelOverM = std::min({t.plannedWheelOverM, 0.5 * t.legBeforeM, 0.5 * t.legAfterM});
  t.radiusM = t.wheelOverM > 0.0 ? t.wheelOverM / std::tan(std::abs(t.changeRad) / 2.0) : 0.0;
  t.fits = !(t.plannedRadiusM > 0.0) || t.changeRad == 0.0 ||
           (t.wheelOverM >= t.plannedWheelOverM && std::abs(t.changeRad) <= degToRad(kMaxFittingChangeDeg));
  return t;
}

std::vector<TurnFit> turnsThatDoNotFit(const Route& route) {
  std::vector<TurnFit> out;
  for (std::size_t k = 1; k + 1 < route.waypoints.size(); ++k) {
    TurnFit t = turnFit(route, k);
    if (!t.fits) out.push_back(t);
  }
  return out;
}

}  // namespace reckoner::geo
