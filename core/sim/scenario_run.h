#pragma once
// Headless runs: one scenario to completion, or N seeds of it in parallel (Monte Carlo).
#include <cstdint>
#include <functional>
#include <vector>

#include "navigation/drkf.h"
#include "sim/scenario.h"
#include "sim/simulation_engine.h"

namespace reckoner::sim {

/// One output cycle of a run: truth, estimate, standard deviations and NEES (ownship.csv's columns).
/// Velocities are over ground in the grid frame.
struct OwnShipRow {
  TimeUs timeUs = 0;
  double trueXM = 0, trueYM = 0, trueVxMps = 0, trueVyMps = 0;
  double estXM = 0, estYM = 0, estVxMps = 0, estVyMps = 0;
  double sdXM = 0, sdYM = 0, sdVxMps = 0, sdVyMps = 0;
  double estLatDeg = 0, estLonDeg = 0;
  double nees = 0;  ///< full 11-state NEES
  SensorStates sensors;
  int rowsApplied = 0;  ///< measurement rows applied during the cycle

  [[nodiscard]] double positionErrorM() const;
  [[nodiscard]] double velocityErrorMps() const;
  [[nodiscard]] double sdPositionM() const;  ///< sqrt(sd_x^2 + sd_y^2)
  /// Both position errors within k standard deviations of their axis.
  [[nodiscard]] bool positionWithin(double k) const;
};

OwnShipRow makeRow(const SimFrame& frame, const geo::LocalFrame& geo,
                   const est::drkf::ProcessParams& process);
/// The row of any estimate of position and velocity over ground [x, y, vx, vy] (grid) with covariance;
/// nees is that of those 4 states, rowsApplied 0.
OwnShipRow groundRow(const SimFrame& frame, const est::Gaussian<4>& estimate, const geo::LocalFrame& geo);

/// A DRKF estimate as output columns: position and velocity over ground, their sds, latitude/longitude.
struct GroundEstimate {
  double xM = 0, yM = 0, vxMps = 0, vyMps = 0;
  double sdXM = 0, sdYM = 0, sdVxMps = 0, sdVyMps = 0;
  double latDeg = 0, lonDeg = 0;
};
GroundEstimate groundEstimateOf(const est::drkf::Belief& b, const geo::LocalFrame& geo);

/// One track at the end of one radar sweep (targets.csv's columns). Truth columns are filled when the
/// track's plots came mostly from a real target (hasTruth).
struct TrackRow {
  TimeUs timeUs = 0;
  int trackId = 0;
  int targetId = -1;
  track::TrackStatus status = track::TrackStatus::Tentative;
  bool dangerous = false;
  bool hasTruth = false;
  double trueXM = 0, trueYM = 0, trueVxMps = 0, trueVyMps = 0;
  double estXM = 0, estYM = 0, estVxMps = 0, estVyMps = 0;
  double sdXM = 0, sdYM = 0, sdVxMps = 0, sdVyMps = 0;
  double estLatDeg = 0, estLonDeg = 0;
  double courseDeg = 0, speedKn = 0;
  double cpaNm = 0, tcpaMin = 0;  ///< NaN when there is no relative motion
  double nees = 0;                ///< all 12 TTKF states (own ship and target); NaN without truth
  double nis = 0;                 ///< of the last radar update
  bool manoeuvring = false;       ///< the track's manoeuvre flag (ekf-ie, imm)

  [[nodiscard]] double positionErrorM() const;
  [[nodiscard]] double velocityErrorMps() const;
};

/// A TrackRow's estimate columns from a track's belief and kinematics (no truth; nees NaN).
TrackRow trackEstimateRow(TimeUs t, int trackId, int targetId, track::TrackStatus status, bool dangerous,
                          const est::ttkf::Belief& b, const track::TrackKinematics& k, double nis,
                          const geo::LocalFrame& geo);

/// One target at the end of one radar sweep: where it truly is and whether the radar can see it.
struct TargetSweepRow {
  TimeUs timeUs = 0;
  int targetId = 0;
  bool inRange = false;
  double xM = 0, yM = 0;
};

/// Rows of every track and every target of each sweep that ended in the frame.
void appendSweepRows(const SimFrame& frame, const Scenario& scenario, const geo::LocalFrame& geo,
                     std::vector<TrackRow>& tracks, std::vector<TargetSweepRow>& targets);

struct RunResult {
  std::uint64_t seed = 0;
  std::vector<OwnShipRow> rows;
  std::vector<TrackRow> trackRows;
  std::vector<TargetSweepRow> targetRows;
  nav::DrkfCounters counters;
  track::TrackCounters trackCounters;
  double wallTimeS = 0.0;
};

/// Runs the scenario to its end with the given seed. Throws std::invalid_argument for a bad scenario.
RunResult runScenario(const Scenario& scenario, std::uint64_t seed);

/// Calls fn(i) for i in [0, runs) on `threads` worker threads (>= 1); rethrows the first exception
/// (by index) after all have finished.
void parallelRuns(int runs, int threads, const std::function<void(int)>& fn);

/// Runs seeds baseSeed, baseSeed + 1, ... on `threads` worker threads (>= 1). Results are in seed order
/// and identical whatever the thread count.
std::vector<RunResult> runMonteCarlo(const Scenario& scenario, int runs, int threads, std::uint64_t baseSeed);

}  // namespace reckoner::sim
