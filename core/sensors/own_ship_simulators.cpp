#include "sensors/own_ship_simulators.h"

#include "common/angles.h"

namespace reckoner::sensors {

GpsSample GpsSimulator::measure(TimeUs t, const geo::GridPoint& truePos, double groundVxGrid,
                                double groundVyGrid, const geo::GridInfo& grid) {
  GpsSample s;
  s.timeUs = t;
  const double sdPos = std::sqrt(spec_.positionVarM2);
  s.position = {truePos.xM + rng_.normal(0.0, sdPos), truePos.yM + rng_.normal(0.0, sdPos)};
  s.positionVarM2 = spec_.positionVarM2;
  // Grid velocity to true east/north: rotate by +convergence (true bearing = grid bearing + gamma),
  // divide by the point scale.
  const double c = std::cos(grid.convergenceRad), sn = std::sin(grid.convergenceRad);
  const double east = (groundVxGrid * c + groundVyGrid * sn) / grid.scale;
  const double north = (-groundVxGrid * sn + groundVyGrid * c) / grid.scale;
  const double sdVel = std::sqrt(spec_.velocityVarM2PerS2);
  s.hasVelocity = true;
  s.velEastMps = east + rng_.normal(0.0, sdVel);
  s.velNorthMps = north + rng_.normal(0.0, sdVel);
  s.velocityVarM2PerS2 = spec_.velocityVarM2PerS2;
  return s;
}

LoranSample LoranSimulator::measure(TimeUs t, const geo::GridPoint& truePos) {
  advanceTo(t);
  const double sd = std::sqrt(spec_.whiteVarM2);
  LoranSample s;
  s.timeUs = t;
  s.position = {truePos.xM + ex_.value() + rng_.normal(0.0, sd),
                truePos.yM + ey_.value() + rng_.normal(0.0, sd)};
  s.positionVarM2 = spec_.whiteVarM2;
  return s;
}

SpeedlogSample SpeedlogSimulator::measure(TimeUs t, double speedOverGroundGrid, double speedThroughWaterGrid,
                                          SpeedlogMode mode, const geo::GridInfo& grid) {
  advanceTo(t);
  SpeedlogSample s;
  s.timeUs = t;
  s.mode = mode;
  const double gridSpeed = s.mode == SpeedlogMode::GroundLock ? speedOverGroundGrid : speedThroughWaterGrid;
  // The Gauss-Markov error is defined on the filter's (grid) speed; report true length.
  const double scaled = spec_.scaleError.sigma > 0.0 ? (1.0 + scale_.value()) * gridSpeed : gridSpeed;
  s.speedMps = (scaled + error_.value()) / grid.scale + rng_.normal(0.0, std::sqrt(spec_.whiteVarM2PerS2));
  s.varM2PerS2 = spec_.whiteVarM2PerS2;
  return s;
}

GyroSample GyroSimulator::measure(TimeUs t, double headingGridRad, const geo::GridInfo& grid) {
  advanceTo(t);
  GyroSample s;
  s.timeUs = t;
  const double bias = spec_.bias.sigma > 0.0 ? bias_.value() : 0.0;
  s.headingRad = wrapTwoPi(headingGridRad + bias + grid.convergenceRad + rng_.normal(0.0, spec_.sdRad));
  s.varRad2 = spec_.sdRad * spec_.sdRad;
  return s;
}

}  // namespace reckoner::sensors
