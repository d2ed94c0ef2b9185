// fusion [SCENARIO...]: the AIS-radar association and fusion evaluation (docs/fusion.md): association
// correctness (correct, missed, false, swaps) and the fused, radar-only and AIS-only errors of every
// AIS-carrying vessel at 1 and 3 minutes, 95th percentiles. Default: builtin:ais-harbour; the IMO
// scenarios with --add-ais A (a transponder on every target without one). Exit code 1 when the
// acceptance fails: fewer than --min-correct of the eligible station-cycles correct, a swap between
// vessels more than 500 m apart, or a fused 3-minute CPA or true-speed p95 above the better single source.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli_options.h"
#include "cli/commands.h"
#include "studies/ais_fusion_study.h"
#include "studies/imo_accuracy.h"

namespace reckoner::cli {
namespace {

struct FusionArgs {
  std::vector<std::string> scenarios;
  MonteCarloArgs mc;
  std::string addAis;
  double minCorrect = 0.99;
};

void printAccuracy(const studies::FusionStudyResult& r) {
  std::printf("  %-16s %-4s | %28s | %28s\n", "", "", "1 min p95", "3 min p95");
  std::printf("  %-16s %-4s | %8s %9s %9s | %8s %9s %9s\n", "quantity", "unit", "fused", "radar", "AIS",
              "fused", "radar", "AIS");
  for (int q = 0; q < studies::kImoErrorCount; ++q) {
    const auto qq = static_cast<studies::ImoQuantity>(q);
    std::printf("  %-16s %-4s | %8.3f %9.3f %9.3f | %8.3f %9.3f %9.3f\n", studies::imoQuantityName(qq),
                studies::imoQuantityUnit(qq), r.accuracy[0].p95At1[q], r.accuracy[1].p95At1[q],
                r.accuracy[2].p95At1[q], r.accuracy[0].p95At3[q], r.accuracy[1].p95At3[q],
                r.accuracy[2].p95At3[q]);
  }
  std::printf(
      "  samples: %d at 1 min, %d at 3 min; mean NEES at 3 min (4 dof): fused %.2f, radar %.2f, AIS %.2f\n",
      r.accuracy[0].samplesAt1, r.accuracy[0].samplesAt3, r.accuracy[0].meanNeesAt3,
      r.accuracy[1].meanNeesAt3, r.accuracy[2].meanNeesAt3);
}

bool report(const studies::FusionStudyResult& r, double minCorrect) {
  std::printf("\n%s: %d runs, %d vessels with AIS\n", r.scenario.c_str(), r.runs, r.aisVessels);
  const double e = static_cast<double>(std::max(1L, r.eligible));
  std::printf(
      "  association: %ld eligible station-cycles: correct %.2f%%, missed %.2f%%, false %.2f%%; "
      "swaps %ld (near) %ld (> 500 m apart)\n",
      r.eligible, 100.0 * static_cast<double>(r.correct) / e, 100.0 * static_cast<double>(r.missed) / e,
      100.0 * static_cast<double>(r.falseAssociations) / e, r.swapsNear, r.swapsFar);
  std::printf("  events: %ld associations, %ld dissociations; %ld reports fused, %ld rejected by the gate\n",
              r.associationEvents, r.dissociationEvents, r.fusedReports, r.rejectedReports);
  printAccuracy(r);
  const int cpa = static_cast<int>(studies::ImoQuantity::Cpa),
            speed = static_cast<int>(studies::ImoQuantity::TrueSpeed);
  bool ok = r.correctFraction() >= minCorrect && r.swapsFar == 0;
  for (int q : {cpa, speed}) {
    const double best = std::min(r.accuracy[1].p95At3[q], r.accuracy[2].p95At3[q]);
    const double fused = r.accuracy[0].p95At3[q];
    std::printf("  3 min %s p95: fused %.4f against the better single source %.4f (%+.1f%%)\n",
                studies::imoQuantityName(static_cast<studies::ImoQuantity>(q)), fused, best,
                best > 0.0 ? 100.0 * (fused - best) / best : 0.0);
    ok = ok && fused <= best;
  }
  std::printf("  %s\n", ok ? "pass" : "FAIL");
  return ok;
}

int fusionCommand(const FusionArgs& a) {
  std::vector<std::string> specs = a.scenarios;
  if (specs.empty()) specs = {"builtin:ais-harbour"};
  if (!a.addAis.empty() && a.addAis != "A" && a.addAis != "B")
    throw UsageError("option '--add-ais' must be A or B");
  if (!(a.minCorrect >= 0.0 && a.minCorrect <= 1.0))
    throw UsageError("option '--min-correct' must lie in [0, 1]");
  bool all = true;
  for (const auto& spec : specs) {
    sim::Scenario s = loadScenario(spec);
    if (!a.addAis.empty())
      s = studies::withAis(std::move(s),
                           a.addAis == "A" ? sensors::AisStationClass::A : sensors::AisStationClass::B);
    studies::FusionStudyOptions o;
    o.runs = a.mc.runs;
    o.threads = a.mc.threadCount();
    o.seed = a.mc.seed.value_or(s.seed);
    all = report(studies::evaluateFusion(s, o), a.minCorrect) && all;
  }
  std::printf("\n%s\n", all ? "all pass" : "SOME FAIL");
  return all ? 0 : 1;
}

}  // namespace

void addFusionCommand(CLI::App& root, Commands& out) {
  auto a = std::make_shared<FusionArgs>();
  a->mc.runs = 10;
  CLI::App* app = root.add_subcommand(
      "fusion",
      "AIS and radar: association correctness, fused vs radar-only vs AIS-only errors (exit 1 on failure)");
  addListArgument(*app, "SCENARIO", a->scenarios, 0,
                  "scenarios with a radar and targets carrying AIS (default builtin:ais-harbour)");
  addMonteCarloOptions(*app, a->mc, 100000, 1024, "each scenario's");
  app->add_option("--add-ais", a->addAis, "a transponder of this class on every target without one")
      ->type_name("A|B");
  app->add_option("--min-correct", a->minCorrect,
                  "required fraction of correct station-cycles (0 to 1, default 0.99)")
      ->type_name("F");
  addIgnoredQuiet(*app);
  out.push_back({app, [a] { return fusionCommand(*a); }, ""});
}

}  // namespace reckoner::cli
