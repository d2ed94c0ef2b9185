#include "sensors/radar.h"

#include <cmath>

#include "common/angles.h"

namespace reckoner::sensors {

TimeUs RadarSimulator::beamTime(TimeUs sweepStartUs, double trueBearingRad) const {
  return sweepStartUs + fromSeconds(wrapTwoPi(trueBearingRad) / kTwoPi * spec_.sweepPeriodS);
}

std::optional<RadarPlot> RadarSimulator::measure(TimeUs t, double dxGridM, double dyGridM,
                                                 const geo::GridInfo& grid) {
  const double rangeTrue = std::hypot(dxGridM, dyGridM) / grid.scale;
  const double u =
      rng_.uniform();  // drawn whatever happens, so one target's fate never shifts another's noise
  const double nr = rng_.normal(), nb = rng_.normal();
  if (rangeTrue > spec_.maxRangeM || u >= spec_.detectionProbability) return std::nullopt;
  RadarPlot p;
  p.timeUs = t;
  p.rangeM = rangeTrue + spec_.rangeSdM * nr;
  p.bearingRad = wrapTwoPi(bearingOf(dxGridM, dyGridM) + grid.convergenceRad + spec_.bearingSdRad * nb);
  p.rangeVarM2 = spec_.rangeSdM * spec_.rangeSdM;
  p.bearingVarRad2 = spec_.bearingSdRad * spec_.bearingSdRad;
  return p;
}

}  // namespace reckoner::sensors
