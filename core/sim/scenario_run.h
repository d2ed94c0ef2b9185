#pragma once
// Headless runs: one scenario to completion, or N seeds of it in parallel (Monte Carlo). The rows they
// collect are built in sim/run_rows.h.
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "common/parallel_runs.h"
#include "navigation/dead_reckoning_monitor.h"
#include "navigation/drkf.h"
#include "sim/run_rows.h"
#include "sim/scenario.h"
#include "sim/simulation_engine.h"

namespace reckoner::sim {

struct RunResult {
  std::uint64_t seed = 0;
  std::vector<OwnShipRow> rows;
  std::vector<TrackRow> trackRows;
  std::vector<TargetSweepRow> targetRows;
  nav::DrkfCounters counters;
  track::TrackCounters trackCounters;
  /// The stretches without a recent position fix (nav::DeadReckoningMonitor, the window's DR rule).
  std::vector<nav::DeadReckoningInterval> deadReckoning;
  /// Own ship ran aground (charts given): when and on what.
  std::optional<std::pair<TimeUs, Grounding>> grounded;
  double wallTimeS = 0.0;
};

/// Runs the scenario to its end with the given seed. Throws std::invalid_argument for a bad scenario.
RunResult runScenario(const Scenario& scenario, std::uint64_t seed);
/// Called after each frame with its own-ship row and the track rows of the sweeps that ended in it.
using FrameObserver = std::function<void(const SimFrame&, const OwnShipRow&, std::span<const TrackRow>)>;
/// The same run, with every frame shown to `observer` as it is made (e.g. sim::RunNmeaOutput).
RunResult runScenario(const Scenario& scenario, std::uint64_t seed, const FrameObserver& observer);
/// The same with the charts' answers (the look-ahead and grounding; sim/chart_guard.h); null: none.
RunResult runScenario(const Scenario& scenario, std::uint64_t seed, const FrameObserver& observer,
                      std::shared_ptr<const ChartGuard> guard);

/// Runs seeds baseSeed, baseSeed + 1, ... on `threads` worker threads (>= 1). Results are in seed order
/// and identical whatever the thread count.
std::vector<RunResult> runMonteCarlo(const Scenario& scenario, int runs, int threads, std::uint64_t baseSeed);

}  // namespace reckoner::sim
