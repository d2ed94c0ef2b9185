// The engine on the Monte Carlo pool (sim::runMonteCarlo, common/parallel_runs.h): seeds run on three
// threads give, row for row and bit for bit, what the same seeds give one after another. Under
// ThreadSanitizer (label tsan-full, scripts/ci_sanitizers.sh full) this is the check that the engine's
// runs share no unsynchronised state (static caches, lazily built tables). A plain program, not a Qt
// Test: QtTest's watchdog thread is stopped through Qt's own futexes, which TSan cannot see.
#include <cstdio>
#include <string>
#include <vector>

#include "sim/scenario_run.h"
#include "support/drkf_fixtures.h"

using namespace reckoner;

namespace {

bool sameRows(const sim::RunResult& a, const sim::RunResult& b, std::string& why) {
  if (a.rows.size() != b.rows.size()) {
    why = "own-ship row counts differ";
    return false;
  }
  for (std::size_t k = 0; k < a.rows.size(); ++k) {
    const sim::OwnShipRow &x = a.rows[k], &y = b.rows[k];
    if (x.timeUs != y.timeUs || x.estXM != y.estXM || x.estYM != y.estYM || x.estVxMps != y.estVxMps ||
        x.estVyMps != y.estVyMps || x.sdXM != y.sdXM || x.nees != y.nees) {
      why = "own-ship row " + std::to_string(k) + " differs";
      return false;
    }
  }
  if (a.trackRows.size() != b.trackRows.size()) {
    why = "track row counts differ";
    return false;
  }
  return true;
}

}  // namespace

int main() {
  for (const char* name : {"default", "ais-harbour"}) {
    sim::Scenario s = test::builtinScenario(name);
    s.durationUs = std::min<TimeUs>(s.durationUs, 300 * kMicrosPerSecond);
    constexpr int kRuns = 6;
    constexpr std::uint64_t kSeed = 11;
    const std::vector<sim::RunResult> parallel = sim::runMonteCarlo(s, kRuns, 3, kSeed);
    for (int i = 0; i < kRuns; ++i) {
      const sim::RunResult serial = sim::runScenario(s, kSeed + static_cast<std::uint64_t>(i));
      std::string why;
      const sim::RunResult& p = parallel[static_cast<std::size_t>(i)];
      if (p.rows.empty() || !sameRows(serial, p, why)) {
        std::fprintf(stderr, "FAIL %s seed %d: %s\n", name, i, p.rows.empty() ? "no rows" : why.c_str());
        return 1;
      }
    }
    std::printf("PASS %s: %d seeds on three threads match the serial runs\n", name, kRuns);
  }
  return 0;
}
