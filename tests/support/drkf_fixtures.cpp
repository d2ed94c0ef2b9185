#include "support/drkf_fixtures.h"

#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>

#include "files/scenario_json.h"
#include "resources/embedded.h"

namespace reckoner::test {

sim::Scenario builtinScenario(const std::string& name) {
  const auto* f = resources::findScenario(name);
  if (!f) {
    std::fprintf(stderr, "test support: no built-in scenario '%s'\n", name.c_str());
    std::abort();
  }
  return files::parseScenario(f->text, "builtin:" + name);
}

est::drkf::ProcessParams tableOneProcess() {
  est::drkf::ProcessParams p;
  p.current = {std::sqrt(0.3), 0.17};
  p.acceleration = {0.5, 1.0};
  p.loranError = {std::sqrt(500.0), 0.25};
  p.speedlogError = {std::sqrt(0.5), 0.5};
  return p;
}

const MonteCarloStudy& monteCarlo(const std::string& name, int runs) {
  static std::map<std::pair<std::string, int>, std::unique_ptr<MonteCarloStudy>> cache;
  auto& slot = cache[{name, runs}];
  if (!slot) {
    slot = std::make_unique<MonteCarloStudy>();
    slot->scenario = builtinScenario(name);
    slot->runs = sim::runMonteCarlo(slot->scenario, runs, 2, slot->scenario.seed);
    slot->summary = metrics::summariseMonteCarlo(slot->scenario, slot->runs);
  }
  return *slot;
}

}  // namespace reckoner::test
