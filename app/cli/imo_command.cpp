// imo [SCENARIO...]: the ARPA accuracy of IMO MSC.192(79), 95th percentiles of the errors at 1 and
// 3 minutes against the limits, per scenario (default the four IMO A.823 scenarios). Exit code 1 when
// a cell fails.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli_options.h"
#include "cli/commands.h"
#include "studies/imo_accuracy.h"

namespace reckoner::cli {
namespace {

struct ImoArgs {
  std::vector<std::string> scenarios;
  MonteCarloArgs mc;
};

std::string imoCell(const studies::ImoCell& c) {
  char buf[64];
  if (!c.required)
    std::snprintf(buf, sizeof buf, "%10s %8s %-5s", "-", "-", "");
  else
    std::snprintf(buf, sizeof buf, "%10.3f %8.3f %-5s", c.p95, c.limit, c.pass ? "pass" : "FAIL");
  return buf;
}

void printImo(const studies::ImoResult& r) {
  std::printf(
      "\n%s: target tracked at 3 min in %d of %d runs; true relative speed %.1f kn, true speed %.1f kn\n",
      r.scenario.c_str(), r.tracked, r.runs, r.trueRelativeSpeedKn, r.trueSpeedKn);
  std::printf("  %-16s %-5s %10s %8s %-5s %10s %8s %-5s\n", "quantity", "unit", "1 min p95", "limit", "",
              "3 min p95", "limit", "");
  for (const auto& row : r.rows)
    std::printf("  %-16s %-5s %s %s\n", studies::imoQuantityName(row.quantity),
                studies::imoQuantityUnit(row.quantity), imoCell(row.at1Min).c_str(),
                imoCell(row.at3Min).c_str());
}

int imoCommand(const ImoArgs& a) {
  std::vector<std::string> specs = a.scenarios;
  if (specs.empty()) specs = {"builtin:imo-1", "builtin:imo-2", "builtin:imo-3", "builtin:imo-4"};
  std::vector<sim::Scenario> scenarios;
  scenarios.reserve(specs.size());
  for (const auto& spec : specs) scenarios.push_back(loadScenario(spec));
  bool all = true;
  std::printf("ARPA accuracy (IMO MSC.192(79)): 95th percentile of the error over %d runs\n", a.mc.runs);
  for (const auto& s : scenarios) {
    const auto r = studies::evaluateImo(s, a.mc.runs, a.mc.threadCount(), a.mc.seed.value_or(s.seed));
    all = all && r.pass;
    printImo(r);
  }
  std::printf("\n%s\n", all ? "all cells pass" : "SOME CELLS FAIL");
  return all ? 0 : 1;
}

}  // namespace

void addImoCommand(CLI::App& root, Commands& out) {
  auto a = std::make_shared<ImoArgs>();
  a->mc.runs = 100;
  CLI::App* app = root.add_subcommand(
      "imo", "ARPA accuracy of IMO MSC.192(79) per scenario (exit code 1 when a cell fails)");
  addListArgument(*app, "SCENARIO", a->scenarios, 0,
                  "scenarios with a radar and a target (default builtin:imo-1 to builtin:imo-4)");
  addMonteCarloOptions(*app, a->mc, 100000, 1024, "each scenario's");
  addIgnoredQuiet(*app);
  out.push_back({app, [a] { return imoCommand(*a); }, ""});
}

}  // namespace reckoner::cli
