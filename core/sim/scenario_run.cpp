#include "sim/scenario_run.h"

#include <chrono>
#include <stdexcept>

#include "io/error_line.h"

namespace reckoner::sim {

RunResult runScenario(const Scenario& scenario, std::uint64_t seed) {
  return runScenario(scenario, seed, FrameObserver{});
}

RunResult runScenario(const Scenario& scenario, std::uint64_t seed, const FrameObserver& observer) {
  return runScenario(scenario, seed, observer, nullptr);
}

RunResult runScenario(const Scenario& scenario, std::uint64_t seed, const FrameObserver& observer,
                      std::shared_ptr<const ChartGuard> guard) {
  const auto start = std::chrono::steady_clock::now();
  SimulationEngine engine(scenario, seed);
  engine.setChartGuard(std::move(guard));
  RunResult result;
  result.seed = seed;
  result.rows.reserve(static_cast<std::size_t>(scenario.durationUs / scenario.stepUs + 1));
  while (!engine.finished()) {
    const SimFrame f = engine.step();
    result.rows.push_back(makeRow(f, engine.frame(), engine.drkf().config().process));
    const std::size_t tracksBefore = result.trackRows.size();
    appendSweepRows(f, scenario, engine.frame(), result.trackRows, result.targetRows);
    if (f.grounded) result.grounded.emplace(f.timeUs, *f.grounded);
    if (observer)
      observer(f, result.rows.back(), std::span<const TrackRow>(result.trackRows).subspan(tracksBefore));
  }
  result.counters = engine.drkf().counters();
  result.trackCounters = engine.trackers().counters();
  result.deadReckoning = engine.deadReckoning().intervals();
  result.wallTimeS = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::vector<RunResult> runMonteCarlo(const Scenario& scenario, int runs, int threads,
                                     std::uint64_t baseSeed) {
  if (runs <= 0) throw std::invalid_argument("Monte Carlo: runs must be positive");
  if (threads <= 0) throw std::invalid_argument("Monte Carlo: threads must be positive");
  if (const std::string problem = checkScenarioForRows(scenario); !problem.empty())
    throw std::invalid_argument("scenario " + io::quoted(scenario.name) + ": " + problem);
  std::vector<RunResult> results(static_cast<std::size_t>(runs));
  parallelRuns(runs, threads, [&](int i) {
    results[static_cast<std::size_t>(i)] = runScenario(scenario, baseSeed + static_cast<std::uint64_t>(i));
  });
  return results;
}

}  // namespace reckoner::sim
