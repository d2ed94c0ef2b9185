// validate SCENARIO... and scenarios: check scenario files, list the built-in scenarios.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli_options.h"
#include "cli/commands.h"
#include "common/time.h"
#include "files/scenario_json.h"
#include "resources/embedded.h"

namespace reckoner::cli {
namespace {

int validate(const std::vector<std::string>& specs) {
  if (specs.empty()) throw UsageError("validate needs at least one SCENARIO");
  for (const auto& p : specs) {
    const sim::Scenario s = loadScenario(p);
    std::printf("%s: ok (%s, %.0f s)\n", p.c_str(), s.name.c_str(), toSeconds(s.durationUs));
  }
  return 0;
}

int listScenarios() {
  for (const auto& f : resources::scenarios()) {
    const sim::Scenario s = files::parseScenario(f.text, "builtin:" + std::string(f.name));
    std::printf("builtin:%-24s %s\n", std::string(f.name).c_str(), s.name.c_str());
  }
  return 0;
}

}  // namespace

void addScenarioCommands(CLI::App& root, Commands& out) {
  auto specs = std::make_shared<std::vector<std::string>>();
  CLI::App* validateApp = root.add_subcommand("validate", "read and check scenario files: one line each");
  addListArgument(*validateApp, "SCENARIO", *specs, 1,
                  "scenarios: JSON files (docs/scenarios.md) or builtin:NAME");
  addIgnoredQuiet(*validateApp);
  out.push_back({validateApp, [specs] { return validate(*specs); }, ""});

  CLI::App* list = root.add_subcommand("scenarios", "the built-in scenarios: builtin:NAME and title");
  out.push_back({list, [] { return listScenarios(); }, ""});
}

}  // namespace reckoner::cli
