#pragma once
// Seed 001's evaluation (section IV): an active sonar on an observer at 065 deg, 30 kn; a target at
// 100 deg, 10 kn, first on bearing 000 at 30 km; range scales 5/10/20/40 km with pings every
// 10/20/40/80 s; bearing noise 1 deg and range noise 20 m; 30 minutes; optionally the target turns to
// 180 deg at 3 deg/s from 540 s. Each echo is stamped at its reflection time, ping time plus range over
// the sound speed (1500 m/s), as the paper recalculates its measurement times. Monte Carlo runs of the
// input-estimation EKF give the errors per sample (docs/manoeuvres.md).
#include <cstdint>
#include <optional>
#include <vector>

#include "common/units.h"
#include "tracking/input_estimation.h"

namespace reckoner::studies {

struct Seed001Scenario {
  double observerCourseRad = 1.1344640137963142;  ///< 065 deg
  double observerSpeedMps = knotsToMps(30.0);
  double targetCourseRad = 1.7453292519943295;  ///< 100 deg
  double targetSpeedMps = knotsToMps(10.0);
  double initialBearingRad = 0.0;
  double initialRangeM = 30000.0;
  double durationS = 1800.0;
  double soundSpeedMps = 1500.0;
  struct Turn {
    double startS = 540.0;
    double newCourseRad = 3.141592653589793;   ///< 180 deg
    double rateRadPerS = 0.05235987755982988;  ///< 3 deg/s
  };
  std::optional<Turn> turn;
};

/// One sonar measurement's outcome in one run.
struct Seed001Sample {
  int index = 0;  ///< 1-based measurement number (the filter starts at 2)
  double tS = 0.0;
  double trueRangeM = 0.0;
  double rangeErrorPct = 0.0, courseErrorDeg = 0.0, speedErrorMps = 0.0;  ///< absolute errors
  bool tested = false;
  double d = 0.0;
  bool detected = false;
  bool manoeuvring = false;
};

/// Ping interval for a range, seed 001 section IV: 10, 20, 40 or 80 s below 5, 10, 20 km and beyond.
double pingIntervalS(double rangeM);

/// One sonar echo of one run: when it was reflected and when the filter stamps it (ping time plus the
/// measured range over the sound speed), the measurement, the observer at the stamp, and the truth.
struct Seed001Ping {
  int index = 0;  ///< 1-based
  double tS = 0.0, stampS = 0.0;
  double bearingRad = 0.0, rangeM = 0.0;
  double observerXM = 0.0, observerYM = 0.0;
  double trueRangeM = 0.0, trueXM = 0.0, trueYM = 0.0, trueCourseRad = 0.0, trueSpeedMps = 0.0;
};
/// The echoes of one run (the next ping follows the interval of the measured range).
std::vector<Seed001Ping> seed001Pings(const Seed001Scenario& scenario, double bearingSdRad, double rangeSdM,
                                      std::uint64_t seed);

/// One run; the filter is configured by `filter` (bearing and range noise are also the sensor's).
std::vector<Seed001Sample> runSeed001(const Seed001Scenario& scenario,
                                      const track::InputEstimationConfig& filter, std::uint64_t seed);

/// Monte Carlo statistics of one measurement number over the runs that reached it.
struct Seed001SampleStats {
  int index = 0;
  int runs = 0;
  double meanTS = 0.0;
  double meanRangeErrorPct = 0.0, rmsRangeErrorPct = 0.0;
  double meanCourseErrorDeg = 0.0, rmsCourseErrorDeg = 0.0;
  double meanSpeedErrorMps = 0.0, rmsSpeedErrorMps = 0.0;
  double withinLimits = 0.0;  ///< fraction of runs with range < 8%, course < 3 deg and speed < 3 m/s
  int tested = 0;
  double meanD = 0.0, maxD = 0.0;
  int detections = 0;  ///< runs that declared a manoeuvre at this sample
};

std::vector<Seed001SampleStats> summariseSeed001(const std::vector<std::vector<Seed001Sample>>& runs);

/// The first sample at which each run declared a manoeuvre at or after fromS (0 when it never did).
std::vector<int> firstDetections(const std::vector<std::vector<Seed001Sample>>& runs, double fromS);

}  // namespace reckoner::studies
