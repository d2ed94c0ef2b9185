// The Monte Carlo comparisons of a scenario: compare (seed 000: decoupled against coupled filter),
// own-ship-compare (seed 002: DRKF, geodetic KF, least squares) and radar-fix (seed 004: dead reckoning
// against radar fixes on the chart). Tables on stdout; compare also writes compare.csv under --out.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "charts/radar/radar_contours.h"
#include "charts/s57/s57_loader.h"
#include "cli/cli_options.h"
#include "cli/commands.h"
#include "common/time.h"
#include "estimation/chi_square.h"
#include "geo/local_frame.h"
#include "io/text_file.h"
#include "studies/comparison.h"
#include "studies/own_ship_filters.h"
#include "studies/radar_fix_study.h"

namespace reckoner::cli {
namespace {

// ---- compare -------------------------------------------------------------------------------------
struct CompareArgs {
  std::string scenario;
  MonteCarloArgs mc;
  std::vector<int> targets{1, 2, 5, 10, 20};
  OutputArgs output;
};

std::vector<int> parseTargetCounts(const std::string& text) {
  std::vector<int> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::string item =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    out.push_back(static_cast<int>(parseCount("targets", item, 1, 200)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

std::string compareCsv(const std::vector<studies::ComparisonRow>& rows) {
  std::string csv =
      "targets,coupled_states,runs,decoupled_rmse_position_m,coupled_rmse_position_m,decoupled_rmse_velocity_"
      "mps,"
      "coupled_rmse_velocity_mps,decoupled_mean_nees4,coupled_mean_nees4,decoupled_us_per_cycle,"
      "coupled_us_per_cycle,cycle_ratio,decoupled_propagation_us,coupled_propagation_us,propagation_ratio,"
      "eq10_ratio,eq10_saving_pct\n";
  for (const auto& r : rows) {
    char buf[512];
    std::snprintf(
        buf, sizeof buf, "%d,%d,%d,%.4f,%.4f,%.5f,%.5f,%.4f,%.4f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f\n",
        r.targets, r.coupledDim, r.runs, r.decoupledRmsePositionM, r.coupledRmsePositionM,
        r.decoupledRmseVelocityMps, r.coupledRmseVelocityMps, r.decoupledMeanNees, r.coupledMeanNees,
        r.decoupledUsPerCycle, r.coupledUsPerCycle, r.cycleRatio(), r.decoupledPropagationUs,
        r.coupledPropagationUs, r.propagationRatio(), r.eq10Ratio, r.eq10SavingPct);
    csv += buf;
  }
  return csv;
}

void printCompare(const sim::Scenario& s, const std::vector<studies::ComparisonRow>& rows, int runs,
                  const std::string& out) {
  std::printf("Decoupled (DRKF + TTKF bank) vs coupled (11 + 6n states): %s, %d runs, known association\n",
              s.name.c_str(), runs);
  std::printf("  %3s %4s | %-17s | %-17s | %-11s | %-17s | %-23s | %s\n", "n", "N", "pos RMSE dec/cpl m",
              "vel RMSE dec/cpl", "NEES(4)", "us/cycle dec/cpl", "propagation us dec/cpl",
              "ratio: cycle, prop, eq.10");
  for (const auto& r : rows)
    std::printf(
        "  %3d %4d | %7.2f / %7.2f | %6.3f / %6.3f | %4.2f/%4.2f | %7.1f / %7.1f | %9.2f / %9.2f | %6.1f "
        "%6.1f %6.1f (%.1f%%)\n",
        r.targets, r.coupledDim, r.decoupledRmsePositionM, r.coupledRmsePositionM, r.decoupledRmseVelocityMps,
        r.coupledRmseVelocityMps, r.decoupledMeanNees, r.coupledMeanNees, r.decoupledUsPerCycle,
        r.coupledUsPerCycle, r.decoupledPropagationUs, r.coupledPropagationUs, r.cycleRatio(),
        r.propagationRatio(), r.eq10Ratio, r.eq10SavingPct);
  std::printf("  wrote %s/compare.csv\n", out.c_str());
}

int compareCommand(const CompareArgs& a) {
  if (a.scenario.empty()) throw UsageError("compare needs exactly one SCENARIO");
  const sim::Scenario s = loadScenario(a.scenario);
  const std::uint64_t seed = a.mc.seed.value_or(s.seed);
  const std::string out = prepareOutDir(a.output);
  const auto rows = studies::compareCoupled(s, a.targets, a.mc.runs, a.mc.threadCount(), seed);
  io::writeTextFile(out + "/compare.csv", compareCsv(rows));
  if (wantsTable(a.output)) printCompare(s, rows, a.mc.runs, out);
  return 0;
}

void addCompare(CLI::App& root, Commands& out) {
  auto a = std::make_shared<CompareArgs>();
  a->mc.runs = 10;
  CLI::App* app = root.add_subcommand(
      "compare", "seed 000: the decoupled DRKF + TTKF bank against the coupled 11 + 6n state filter");
  addScenarioArgument(*app, a->scenario);
  addMonteCarloOptions(*app, a->mc, 10000, 1024, "the scenario's");
  addValue(*app, "targets", "LIST", "target counts, comma-separated, each 1 to 200 (default 1,2,5,10,20)",
           [p = a.get()](const std::string& t) { p->targets = parseTargetCounts(t); });
  addOutputOptions(*app, a->output, Summary::None, "compare.csv");
  out.push_back({app, [a] { return compareCommand(*a); }, "compare needs exactly one SCENARIO"});
}

// ---- own-ship-compare ----------------------------------------------------------------------------
struct StudyArgs {
  std::string scenario;
  MonteCarloArgs mc;
  std::optional<std::string> enc;  // radar-fix only
};

int ownShipCompareCommand(const StudyArgs& a) {
  if (a.scenario.empty()) throw UsageError("own-ship-compare needs exactly one SCENARIO");
  const sim::Scenario s = loadScenario(a.scenario);
  const int runs = a.mc.runs;
  const auto all =
      studies::runOwnShipFiltersMonteCarlo(s, runs, a.mc.threadCount(), a.mc.seed.value_or(s.seed));
  const auto bounds = est::averageNeesBounds(4, runs);
  const auto stats = studies::summariseOwnShipFilters(all, fromSeconds(60.0), bounds);
  std::printf("own-ship filters on %s, %d runs: with GPS / without GPS (rows after the first 60 s)\n",
              s.name.c_str(), runs);
  std::printf(
      "  mean NEES: position and velocity over ground, 4 dof, averaged over the runs at each time; band "
      "[%.2f, %.2f] is its 95%% interval for one time\n",
      bounds.lower, bounds.upper);
  std::printf("  %-9s %21s %21s %17s %17s %21s\n", "filter", "pos RMSE m", "vel RMSE m/s", "mean NEES",
              "times in band", "p95 pos error m");
  for (int k = 0; k < studies::kOwnShipFilterCount; ++k) {
    const auto& on = stats[static_cast<std::size_t>(k)][0];
    const auto& off = stats[static_cast<std::size_t>(k)][1];
    std::printf("  %-9s %10.2f %10.2f %10.3f %10.3f %8.2f %8.2f %7.0f%% %7.0f%% %10.1f %10.1f\n",
                studies::ownShipFilterName(static_cast<studies::OwnShipFilter>(k)), on.positionRmseM,
                off.positionRmseM, on.velocityRmseMps, off.velocityRmseMps, on.meanNees, off.meanNees,
                100.0 * on.shareInBand, 100.0 * off.shareInBand, on.p95PositionErrorM, off.p95PositionErrorM);
  }
  return 0;
}

// ---- radar-fix -----------------------------------------------------------------------------------
void printRadarFixStudy(const studies::RadarFixStudy& r, bool matching) {
  std::printf(
      "  %-22s without GPS: position p95 %7.1f m, RMS %7.1f m, heading p95 %6.3f deg, mean NEES (11) "
      "%6.2f\n",
      matching ? "with radar matching" : "dead reckoning alone", r.positionP95M, r.positionRmsM,
      r.headingP95Deg, r.meanNees);
  if (!matching) return;
  std::printf(
      "    %ld pictures, %ld fixes applied, %.0f echoes per picture, %.0f matched; echoes from vessels "
      "%ld, "
      "from clutter and noise %ld: %.1f%% of them rejected\n"
      "    the fixes (less the DRKF's motion error they carry): position p95 %.1f m, heading p95 %.3f deg, "
      "mean NEES %.2f (3 dof; position %.2f of 2, heading %.2f of 1)\n",
      r.pictures, r.applied, r.echoesPerPicture, r.matchedPerPicture, r.vesselEchoes, r.clutterEchoes,
      100.0 * r.spuriousRejectedFraction(), r.fixPositionP95M, r.fixHeadingP95Deg, r.fixNees,
      r.fixPositionNees, r.fixHeadingNees);
}

int radarFixCommand(const StudyArgs& a) {
  if (a.scenario.empty()) throw UsageError("radar-fix needs exactly one SCENARIO");
  const sim::Scenario s = loadScenario(a.scenario);
  const std::uint64_t seed = a.mc.seed.value_or(s.seed);
  const std::string enc = a.enc.value_or(std::string(charts::kDefaultChartPath));
  const charts::LoadResult loaded = charts::loadCharts({enc});
  for (const auto& f : loaded.failures)
    std::fprintf(stderr, "reckoner-cli: %s: %s\n", f.file.c_str(), f.reason.c_str());
  if (loaded.cells.empty()) throw UsageError(enc + ": no chart cell could be loaded");
  const geo::LocalFrame frame(s.origin.latDeg, s.origin.lonDeg);
  const auto coast = std::make_shared<const radar::Coastline>(
      charts::radarContours(loaded.cells, frame, {0.0, 0.0}, 100000.0));
  const auto land =
      std::make_shared<const radar::LandMask>(charts::landMask(loaded.cells, frame, {0.0, 0.0}, 100000.0));
  std::printf(
      "radar fixes on %s with %s (%zu contour segments), %d runs: dead reckoning alone against radar "
      "matching\n",
      s.name.c_str(), enc.c_str(), coast->segments().size(), a.mc.runs);
  for (const bool matching : {false, true})
    printRadarFixStudy(
        studies::runRadarFixStudy(s, coast, land, matching, a.mc.runs, a.mc.threadCount(), seed), matching);
  return 0;
}

void addOwnShipStudies(CLI::App& root, Commands& out) {
  auto o = std::make_shared<StudyArgs>();
  o->mc.runs = 20;
  CLI::App* app =
      root.add_subcommand("own-ship-compare",
                          "seed 002: the DRKF, the geodetic Kalman filter and least squares, with and "
                          "without GPS");
  addScenarioArgument(*app, o->scenario);
  addMonteCarloOptions(*app, o->mc, 100000, 256, "the scenario's");
  addIgnoredQuiet(*app);
  out.push_back(
      {app, [o] { return ownShipCompareCommand(*o); }, "own-ship-compare needs exactly one SCENARIO"});

  auto r = std::make_shared<StudyArgs>();
  r->mc.runs = 20;
  app = root.add_subcommand("radar-fix",
                            "seed 004: dead reckoning through a GPS outage, alone and with radar fixes");
  addScenarioArgument(*app, r->scenario);
  addText(*app, "enc", r->enc, "PATH",
          "S-57 cells or a folder, default builtin:default (the embedded chart)");
  addMonteCarloOptions(*app, r->mc, 100000, 256, "the scenario's");
  addIgnoredQuiet(*app);
  out.push_back({app, [r] { return radarFixCommand(*r); }, "radar-fix needs exactly one SCENARIO"});
}

}  // namespace

void addStudyCommands(CLI::App& root, Commands& out) {
  addCompare(root, out);
  addOwnShipStudies(root, out);
}

}  // namespace reckoner::cli
