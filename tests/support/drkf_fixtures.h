#pragma once
// Shared helpers for the tests: built-in scenarios and cached Monte Carlo studies.
#include <string>
#include <vector>

#include "metrics/own_ship_stats.h"
#include "sim/scenario.h"
#include "sim/scenario_run.h"

namespace reckoner::test {

/// A scenario from resources/scenarios by name (fails the test run with a message if missing).
sim::Scenario builtinScenario(const std::string& name);

/// The DRKF process parameters of seed 000 Table I test 1 (used where a model needs realistic numbers).
est::drkf::ProcessParams tableOneProcess();

struct MonteCarloStudy {
  sim::Scenario scenario;
  std::vector<sim::RunResult> runs;
  metrics::MonteCarloSummary summary;
};

/// Runs (once per process, then cached) `runs` seeds of a built-in scenario on two threads.
const MonteCarloStudy& monteCarlo(const std::string& name, int runs = 50);

}  // namespace reckoner::test

// QTest printers (found by argument-dependent lookup) so QCOMPARE shows names, not numbers.
#include <QByteArray>
namespace reckoner::est {
inline char* toString(UpdateStatus s) {
  return qstrdup(std::string(statusName(s)).c_str());
}
}  // namespace reckoner::est
namespace reckoner::sensors {
inline char* toString(SpeedlogMode m) {
  return qstrdup(std::string(modeName(m)).c_str());
}
}  // namespace reckoner::sensors
