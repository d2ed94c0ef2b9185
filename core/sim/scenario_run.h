#pragma once
// Headless runs: one scenario to completion, or N seeds of it in parallel (Monte Carlo).
#include <cstdint>
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

OwnShipRow makeRow(const SimFrame& frame, const geo::LocalFrame& geo);

/// One track at one output cycle: its target's truth and the TTKF estimate (target part).
struct TrackRow {
  TimeUs timeUs = 0;
  int trackId = 0;
  int targetId = -1;
  double trueXM = 0, trueYM = 0, trueVxMps = 0, trueVyMps = 0;
  double estXM = 0, estYM = 0, estVxMps = 0, estVyMps = 0;
  double sdXM = 0, sdYM = 0, sdVxMps = 0, sdVyMps = 0;
  double nees = 0;  ///< all 12 TTKF states (own ship and target)
};

/// Rows of every track whose target is in the frame.
void appendTrackRows(const SimFrame& frame, const Scenario& scenario, std::vector<TrackRow>& out);

struct RunResult {
  std::uint64_t seed = 0;
  std::vector<OwnShipRow> rows;
  std::vector<TrackRow> trackRows;
  nav::DrkfCounters counters;
  double wallTimeS = 0.0;
};

/// Runs the scenario to its end with the given seed. Throws std::invalid_argument for a bad scenario.
RunResult runScenario(const Scenario& scenario, std::uint64_t seed);

/// Runs seeds baseSeed, baseSeed + 1, ... on `threads` worker threads (>= 1). Results are in seed order
/// and identical whatever the thread count.
std::vector<RunResult> runMonteCarlo(const Scenario& scenario, int runs, int threads, std::uint64_t baseSeed);

}  // namespace reckoner::sim
