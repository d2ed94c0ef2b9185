#pragma once
// Navigation radar: one sweep every sweep period; a target is seen when the beam passes its bearing.
// Plots carry range, true bearing and time, never the target's identity. Errors (docs/ttkf.md):
//  - Gaussian range and bearing noise per plot (Table III: 10 m, 1 degree; A.823(19): pulse shape
//    20 m, beam shape 0.05 degree and encoder 0.03 degree combined);
//  - antenna backlash, uniform in +-bearingBacklashRad (A.823: 0.05 degree);
//  - quantisation to rangeQuantumM and bearingQuantumRad (A.823: 0.02 NM and 0.2 degree steps, i.e.
//    +-0.01 NM and +-0.1 degree);
//  - the gyro's error in the true bearing: a fixed calibration error (A.823: 0.5 degree) plus a
//    Gaussian scatter drawn once per sweep (A.823: 0.12 degree);
//  - Poisson clutter: false plots uniform in area out to the clutter range.
#include <optional>
#include <string>
#include <vector>

#include "common/angles.h"
#include "common/rng.h"
#include "common/step_schedule.h"
#include "geo/local_frame.h"

namespace reckoner::sensors {

struct RadarSpec {
  bool fitted = false;
  double sweepPeriodS = 2.0;            ///< antenna revolution, s
  double rangeSdM = 10.0;               ///< Table III: 10 m
  double bearingSdRad = degToRad(1.0);  ///< Table III: 1 degree
  double bearingBacklashRad = 0.0;      ///< uniform bearing error half-width
  double rangeQuantumM = 0.0;           ///< 0: none
  double bearingQuantumRad = 0.0;       ///< 0: none
  double gyroCalibrationRad = 0.0;      ///< fixed bearing error from the gyro
  double gyroScatterSdRad = 0.0;        ///< per-sweep bearing error from the gyro
  double maxRangeM = 24.0 * 1852.0;     ///< instrumented range
  double minRangeM = 0.0;               ///< blind range around the antenna
  double detectionProbability = 1.0;    ///< per target per sweep
  double clutterPerKm2 = 0.0;           ///< expected false plots per km^2 per sweep
  double clutterMaxRangeM = 0.0;        ///< 0: clutter out to maxRangeM
  StepSchedule<bool> power{true};

  /// The plot variances a tracker should assume: every zero-mean error above (the fixed gyro
  /// calibration error is a bias that no per-plot variance can describe).
  [[nodiscard]] double plotRangeVarM2() const;
  [[nodiscard]] double plotBearingVarRad2() const;
  /// Empty if valid, else the first problem (JSON field names).
  [[nodiscard]] std::string check() const;
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
  /// rng draws target plots; clutterRng the false plots, so that clutter never shifts target noise.
  RadarSimulator(const RadarSpec& spec, Rng rng, Rng clutterRng)
      : spec_(spec), rng_(rng), clutterRng_(clutterRng) {}

  /// When the beam of the sweep starting at sweepStartUs points at trueBearingRad (clockwise sweep
  /// from north).
  [[nodiscard]] TimeUs beamTime(TimeUs sweepStartUs, double trueBearingRad) const;
  /// Starts a sweep: draws the sweep's gyro scatter and its clutter plots (in time order).
  std::vector<RadarPlot> beginSweep(TimeUs sweepStartUs);
  /// A plot of a target at the grid offset (dx, dy) from own ship, or nothing when it is outside the
  /// instrumented ranges or not detected this sweep.
  std::optional<RadarPlot> measure(TimeUs t, double dxGridM, double dyGridM, const geo::GridInfo& grid);
  [[nodiscard]] const RadarSpec& spec() const { return spec_; }

 private:
  [[nodiscard]] RadarPlot finish(TimeUs t, double rangeM, double bearingRad) const;
  RadarSpec spec_;
  Rng rng_;
  Rng clutterRng_;
  double sweepGyroErrorRad_ = 0.0;
};

/// Poisson variate with the given mean (>= 0), exact for any mean.
int poisson(Rng& rng, double mean);

}  // namespace reckoner::sensors
