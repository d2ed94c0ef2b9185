#pragma once
// Navigation radar: one sweep every sweep period; a target is seen when the beam passes its bearing.
// Plots carry range, true bearing and time, never the target's identity.
#include <optional>

#include "common/rng.h"
#include "common/step_schedule.h"
#include "geo/local_frame.h"

namespace reckoner::sensors {

struct RadarSpec {
  bool fitted = false;
  double sweepPeriodS = 2.0;                   ///< antenna revolution, s
  double rangeSdM = 10.0;                      ///< Table III: 10 m
  double bearingSdRad = 0.017453292519943295;  ///< Table III: 1 degree
  double maxRangeM = 24.0 * 1852.0;            ///< instrumented range
  double detectionProbability = 1.0;           ///< per target per sweep
  StepSchedule<bool> power{true};
};

/// A radar plot as the radar reports it (true bearing; the range is a true length).
struct RadarPlot {
  TimeUs timeUs = 0;
  double rangeM = 0.0;
  double bearingRad = 0.0;  ///< true, clockwise from true north, [0, 2 pi)
  double rangeVarM2 = 0.0;
  double bearingVarRad2 = 0.0;
};

class RadarSimulator {
 public:
  RadarSimulator(const RadarSpec& spec, Rng rng) : spec_(spec), rng_(rng) {}

  /// When the beam of the sweep starting at sweepStartUs points at trueBearingRad (clockwise sweep
  /// from north).
  [[nodiscard]] TimeUs beamTime(TimeUs sweepStartUs, double trueBearingRad) const;
  /// A plot of a target at the grid offset (dx, dy) from own ship, or nothing when it is beyond the
  /// instrumented range or not detected this sweep.
  std::optional<RadarPlot> measure(TimeUs t, double dxGridM, double dyGridM, const geo::GridInfo& grid);
  [[nodiscard]] const RadarSpec& spec() const { return spec_; }

 private:
  RadarSpec spec_;
  Rng rng_;
};

}  // namespace reckoner::sensors
