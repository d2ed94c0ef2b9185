// reckoner-cli: headless runs of the Reckoner engine.
//   reckoner-cli run SCENARIO [--seed N] [--own-ship-filter drkf|geodetic|lsq] [--profile P] --out DIR
//   [--quiet] reckoner-cli montecarlo SCENARIO --runs N [--threads K] [--seed N] [--profile P] --out DIR
//   [--quiet] reckoner-cli chart info PATH... reckoner-cli replay --nmea FILE [--radar FILE.csv] [--config
//   SCENARIO] [--assume-association]
//                       [--max-gap S] [--date YYYY-MM-DD] [--variation DEG] [--profile P]
//                       [--adaptive-gnss on|off] --out DIR
//   reckoner-cli export SCENARIO [--seed N] [--date YYYY-MM-DD] --out DIR
//   reckoner-cli compare SCENARIO [--runs N] [--targets LIST] [--threads K] [--seed N] --out DIR [--quiet]
//   reckoner-cli imo [SCENARIO...] [--runs N] [--threads K] [--seed N]   (exit 1 if a cell fails)
//   reckoner-cli validate SCENARIO...
//   reckoner-cli scenarios
// SCENARIO is a file path or builtin:NAME (see `reckoner-cli scenarios`).
// Exit codes: 0 success, 2 bad input or usage (one line on stderr), 1 any other failure.
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <QGuiApplication>
#include <QImage>

#include "charts/pick/pick_report.h"
#include "charts/portrayal/portrayal.h"
#include "charts/radar/radar_contours.h"
#include "charts/render/chart_renderer.h"
#include "charts/s57/s57_loader.h"
#include "common/angles.h"
#include "estimation/chi_square.h"
#include "estimation/ekf.h"
#include "files/own_ship_output.h"
#include "files/scenario_json.h"
#include "files/track_output.h"
#include "io/error_line.h"
#include "io/input_error.h"
#include "io/iso8601.h"
#include "io/json.h"
#include "io/text_format.h"
#include "metrics/own_ship_stats.h"
#include "metrics/track_stats.h"
#include "resources/embedded.h"
#include "sim/nmea_export.h"
#include "sim/replay.h"
#include "sim/scenario_run.h"
#include "sim/sensor_profile.h"
#include "studies/comparison.h"
#include "studies/imo_accuracy.h"
#include "studies/manoeuvre_trial.h"
#include "studies/own_ship_filters.h"
#include "studies/radar_fix_study.h"
#include "studies/seed001.h"
#include "studies/seed003.h"

namespace {

using namespace reckoner;

constexpr const char* kUsage =
    "usage:\n"
    "  reckoner-cli run SCENARIO [--seed N] [--own-ship-filter drkf|geodetic|lsq] [--profile P] --out DIR\n"
    "               [--quiet]\n"
    "  reckoner-cli montecarlo SCENARIO --runs N [--threads K] [--seed N] [--profile P] --out DIR [--quiet]\n"
    "  (P, a sensor profile: paper, imo or realistic; sets the sensors' noise and the filter's models)\n"
    "  reckoner-cli chart info PATH...   (S-57 cells or folders: metadata and feature counts as JSON)\n"
    "  reckoner-cli chart render PATH... --center LAT,LON --scale N --size WxH [--palette day|dusk|night]\n"
    "               [--category base|standard|all] [--safety-contour M] --out FILE.png [--repeat K]\n"
    "  reckoner-cli chart pick PATH... --at LAT,LON [--scale N] [--tolerance PX]   (pick report as JSON)\n"
    "  (PATH builtin:default is the embedded fictional chart)\n"
    "  reckoner-cli replay --nmea FILE [--radar FILE.csv] [--config SCENARIO] [--assume-association]\n"
    "               [--max-gap S] [--date YYYY-MM-DD] [--variation DEG] [--profile P] [--adaptive-gnss "
    "on|off]\n"
    "               --out DIR\n"
    "               (S: no data longer than this restarts the DRKF, default 120; --date: for a log without\n"
    "               dates; --variation: magnetic variation, east positive, when the file gives none;\n"
    "               --profile: default realistic, or the --config scenario's own sensor figures;\n"
    "               --adaptive-gnss: scale the receiver's position noise by a variational-Bayes estimate)\n"
    "  reckoner-cli export SCENARIO [--seed N] [--date YYYY-MM-DD] --out DIR   (NMEA + radar CSV of a run)\n"
    "  reckoner-cli compare SCENARIO [--runs N] [--targets 1,2,5,10,20] [--threads K] [--seed N] --out DIR\n"
    "  reckoner-cli own-ship-compare SCENARIO [--runs N] [--threads K] [--seed N]   (DRKF, seed 002 geodetic "
    "KF "
    "and least squares)\n"
    "  reckoner-cli radar-fix SCENARIO [--enc PATH] [--runs N] [--threads K] [--seed N]   (seed 004: dead "
    "reckoning against radar fixes)\n"
    "  reckoner-cli imo [SCENARIO...] [--runs N] [--threads K] [--seed N]\n"
    "  reckoner-cli seed001 [--runs N] [--turn] [--seed N] [--window S] [--pfa P] [--q Q] [--bearing-sd "
    "DEG]\n"
    "               [--init paper|two-point] [--correction none|paper|refilter] [--jump-sd M/S]   (seed 001: "
    "input-estimation "
    "EKF, Monte Carlo per sample)\n"
    "  reckoner-cli seed003 [--runs N] [--alpha A] [--sweep S] [--noise M] [--seed N]   (alpha-beta-gamma "
    "2drms)\n"
    "  reckoner-cli manoeuvre-report [--runs N] [--turn DEG | --speed-change KN] [--seed N]\n"
    "               (four trackers at radar rates: detection delay, false alarms, RMSE, PCRB ratio, p95 "
    "errors)\n"
    "  reckoner-cli validate SCENARIO...\n"
    "  reckoner-cli scenarios\n"
    "SCENARIO is a JSON file (docs/scenarios.md) or builtin:NAME.\n";

/// Bad input or usage: one line on stderr, exit code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Args {
  std::vector<std::string> positional;
  std::map<std::string, std::string> options;  // --name value
  bool quiet = false;
  bool assumeAssociation = false;
};

Args parseArgs(int argc, char** argv, int first, const std::vector<std::string>& valued) {
  Args a;
  for (int i = first; i < argc; ++i) {
    const std::string s = argv[i];
    if (s == "--quiet") {
      a.quiet = true;
    } else if (s == "--assume-association" &&
               std::find(valued.begin(), valued.end(), "assume-association") != valued.end()) {
      a.assumeAssociation = true;
    } else if (s.rfind("--", 0) == 0) {
      const std::string name = s.substr(2);
      if (std::find(valued.begin(), valued.end(), name) == valued.end())
        throw UsageError("unknown option " + io::quoted(s));
      if (i + 1 >= argc) throw UsageError("option " + io::quoted(s) + " needs a value");
      if (a.options.count(name)) throw UsageError("option " + io::quoted(s) + " given twice");
      a.options[name] = argv[++i];
    } else {
      a.positional.push_back(s);
    }
  }
  return a;
}

std::uint64_t parseCount(const std::string& option, const std::string& text, std::uint64_t min,
                         std::uint64_t max) {
  std::size_t used = 0;
  unsigned long long v = 0;
  try {
    if (text.empty() || text[0] == '-') throw std::invalid_argument("negative");
    v = std::stoull(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || used == 0 || v < min || v > max)
    throw UsageError("--" + option + ": expected an integer in [" + std::to_string(min) + ", " +
                     std::to_string(max) + "], got " + io::quoted(text));
  return v;
}

sim::Scenario loadScenario(const std::string& spec) {
  if (spec.rfind("builtin:", 0) == 0) {
    const std::string name = spec.substr(8);
    const auto* f = resources::findScenario(name);
    if (!f)
      throw UsageError("unknown built-in scenario " + io::quoted(name) + " (see `reckoner-cli scenarios`)");
    return io::parseScenario(f->text, spec);
  }
  return io::loadScenarioFile(spec);
}

std::string prepareOutDir(const Args& a) {
  const auto it = a.options.find("out");
  if (it == a.options.end()) throw UsageError("--out DIR is required");
  std::error_code ec;
  std::filesystem::create_directories(it->second, ec);
  if (ec || !std::filesystem::is_directory(it->second))
    throw UsageError("--out " + it->second + ": cannot create directory" + (ec ? ": " + ec.message() : ""));
  return it->second;
}

void printPhaseTable(const std::vector<metrics::PhaseStats>& phases) {
  std::printf("  %-2s %-13s %-30s %10s %11s %9s %6s %10s\n", "#", "time (s)", "sensors", "pos RMSE",
              "vel RMSE", "mean NEES", "<=3sd", "sd at end");
  for (const auto& p : phases) {
    char span[32];
    std::snprintf(span, sizeof span, "%.0f-%.0f", toSeconds(p.phase.startUs), toSeconds(p.phase.endUs));
    std::printf("  %-2d %-13s %-30s %8.1f m %7.3f m/s %9.2f %5.0f%% %8.1f m\n", p.phase.index + 1, span,
                p.phase.label.c_str(), p.rmsePositionM, p.rmseVelocityMps, p.meanNees,
                100.0 * p.fractionWithin3Sd, p.sdPositionEndM);
  }
}

void printTracking(const metrics::TrackingStats& t, const sim::RunResult& run) {
  const auto& c = run.trackCounters;
  std::printf(
      "\n  radar tracking: %ld plots, %ld associated; %ld tracks started, %ld confirmed, %ld lost, %ld "
      "dropped\n",
      c.plots, c.plotsAssociated, c.tracksStarted, c.tracksConfirmed, c.tracksLost, c.tracksDropped);
  std::printf(
      "  continuity %.2f%% over %zu targets (%d never held), %d breaks, %d swaps (%d between targets > 500 m "
      "apart), %d false tracks\n",
      100.0 * t.continuity, t.targets.size(), t.targetsNeverHeld, t.breaks, t.swaps, t.farSwaps,
      t.falseTracks);
  if (t.targets.size() > 12) return;
  std::printf("  %-6s %10s %7s %12s %12s %9s\n", "target", "continuity", "breaks", "pos RMSE", "vel RMSE",
              "mean NEES");
  for (const auto& s : t.targets)
    std::printf("  %-6d %9.1f%% %7d %10.1f m %8.3f m/s %9.2f\n", s.targetId, 100.0 * s.continuity, s.breaks,
                s.rmsePositionM, s.rmseVelocityMps, s.meanNees);
}

/// --profile NAME, when given.
std::optional<sim::SensorProfile> profileOption(const Args& a) {
  if (!a.options.count("profile")) return std::nullopt;
  const auto p = sim::sensorProfileFromName(a.options.at("profile"));
  if (!p)
    throw UsageError("--profile: expected paper, imo or realistic, got " +
                     io::quoted(a.options.at("profile")));
  return p;
}

/// The scenario, with --profile's sensor figures when given.
sim::Scenario loadProfiled(const Args& a, const std::string& spec) {
  sim::Scenario s = loadScenario(spec);
  if (const auto p = profileOption(a)) sim::applySensorProfile(s, *p);
  return s;
}

int cmdRun(int argc, char** argv) {
  const Args a = parseArgs(argc, argv, 2, {"seed", "out", "own-ship-filter", "profile"});
  if (a.positional.size() != 1) throw UsageError("run needs exactly one SCENARIO");
  const sim::Scenario s = loadProfiled(a, a.positional[0]);
  const std::uint64_t seed =
      a.options.count("seed") ? parseCount("seed", a.options.at("seed"), 0, UINT64_MAX) : s.seed;
  sim::OwnShipFilter filter = sim::OwnShipFilter::Drkf;
  if (a.options.count("own-ship-filter")) {
    const auto f = sim::ownShipFilterFromName(a.options.at("own-ship-filter"));
    if (!f)
      throw UsageError("--own-ship-filter: expected drkf, geodetic or lsq, got " +
                       io::quoted(a.options.at("own-ship-filter")));
    filter = *f;
  }
  const std::string out = prepareOutDir(a);

  // The DRKF always runs (it feeds the trackers); seed 002's filters beside it when chosen.
  sim::RunResult run;
  if (filter == sim::OwnShipFilter::Drkf) {
    run = sim::runScenario(s, seed);
  } else {
    sim::OwnShipFilterRun both = sim::runOwnShipFilters(s, seed);
    run = std::move(both.drkf);
    run.rows = std::move(both.rows[static_cast<std::size_t>(filter)]);
  }
  const auto phases = metrics::summarisePhases(metrics::derivePhases(s), run.rows);
  io::writeOwnShipCsv(out + "/ownship.csv", run.rows);
  io::writeTextFile(out + "/summary.json", io::runSummaryJson(s, run, phases));
  if (s.radar.fitted) io::writeTargetsCsv(out + "/targets.csv", run.trackRows);
  if (a.quiet) return 0;

  const geo::LocalFrame frame(s.origin.latDeg, s.origin.lonDeg);
  std::printf("Reckoner dead-reckoning run: %s (seed %llu, own-ship filter %s%s)\n", s.name.c_str(),
              static_cast<unsigned long long>(seed), sim::ownShipFilterName(filter),
              filter == sim::OwnShipFilter::Drkf ? "" : "; NEES of position and velocity, 4 dof");
  if (!s.description.empty()) std::printf("  %s\n", s.description.c_str());
  std::printf("  origin %s %s (UTM zone %d), %.0f s, %zu filter cycles in %.3f s wall time\n\n",
              io::formatLatitude(s.origin.latDeg).c_str(), io::formatLongitude(s.origin.lonDeg).c_str(),
              frame.utmZone(), toSeconds(s.durationUs), run.rows.size(), run.wallTimeS);
  printPhaseTable(phases);
  if (!run.rows.empty()) {
    const auto& last = run.rows.back();
    std::printf("\n  final estimate %s %s, position sd %.1f m, true error %.1f m\n",
                io::formatLatitude(last.estLatDeg).c_str(), io::formatLongitude(last.estLonDeg).c_str(),
                last.sdPositionM(), last.positionErrorM());
  }
  if (s.radar.fitted) printTracking(metrics::summariseTracking(run.trackRows, run.targetRows), run);
  std::printf("  wrote %s/ownship.csv%s and %s/summary.json\n", out.c_str(),
              s.radar.fitted ? (", " + out + "/targets.csv").c_str() : "", out.c_str());
  return 0;
}

/// --runs (default given), --threads (default: the machine's) and --seed (default: the scenario's).
struct MonteCarloOptions {
  int runs;
  int threads;
  std::uint64_t seed;
};
MonteCarloOptions monteCarloOptions(const Args& a, int defaultRuns, std::uint64_t defaultSeed) {
  const auto opt = [&a](const std::string& k) { return a.options.count(k) > 0; };
  const int hw = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return {opt("runs") ? static_cast<int>(parseCount("runs", a.options.at("runs"), 1, 100000)) : defaultRuns,
          opt("threads") ? static_cast<int>(parseCount("threads", a.options.at("threads"), 1, 256)) : hw,
          opt("seed") ? parseCount("seed", a.options.at("seed"), 0, UINT64_MAX) : defaultSeed};
}

int cmdRadarFix(int argc, char** argv) {
  const Args a = parseArgs(argc, argv, 2, {"enc", "runs", "threads", "seed"});
  if (a.positional.size() != 1) throw UsageError("radar-fix needs exactly one SCENARIO");
  sim::Scenario s = loadScenario(a.positional[0]);
  const auto [runs, threads, seed] = monteCarloOptions(a, 20, s.seed);
  const std::string enc =
      a.options.count("enc") ? a.options.at("enc") : std::string(charts::kDefaultChartPath);
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
      s.name.c_str(), enc.c_str(), coast->segments().size(), runs);
  const auto study = [&](bool matching) {
    const sim::RadarFixStudy r = sim::runRadarFixStudy(s, coast, land, matching, runs, threads, seed);
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
  };
  study(false);
  study(true);
  return 0;
}

int cmdOwnShipCompare(int argc, char** argv) {
  const Args a = parseArgs(argc, argv, 2, {"runs", "threads", "seed"});
  if (a.positional.size() != 1) throw UsageError("own-ship-compare needs exactly one SCENARIO");
  const sim::Scenario s = loadScenario(a.positional[0]);
  const auto [runs, threads, seed] = monteCarloOptions(a, 20, s.seed);
  const auto all = sim::runOwnShipFiltersMonteCarlo(s, runs, threads, seed);
  const auto bounds = est::averageNeesBounds(4, runs);
  const auto stats = sim::summariseOwnShipFilters(all, fromSeconds(60.0), bounds);
  std::printf("own-ship filters on %s, %d runs: with GPS / without GPS (rows after the first 60 s)\n",
              s.name.c_str(), runs);
  std::printf(
      "  mean NEES: position and velocity over ground, 4 dof, averaged over the runs at each time; band "
      "[%.2f, %.2f] is its 95%% interval for one time\n",
      bounds.lower, bounds.upper);
  std::printf("  %-9s %21s %21s %17s %17s %21s\n", "filter", "pos RMSE m", "vel RMSE m/s", "mean NEES",
              "times in band", "p95 pos error m");
  for (int k = 0; k < sim::kOwnShipFilterCount; ++k) {
    const auto& on = stats[static_cast<std::size_t>(k)][0];
    const auto& off = stats[static_cast<std::size_t>(k)][1];
    std::printf("  %-9s %10.2f %10.2f %10.3f %10.3f %8.2f %8.2f %7.0f%% %7.0f%% %10.1f %10.1f\n",
                sim::ownShipFilterName(static_cast<sim::OwnShipFilter>(k)), on.positionRmseM,
                off.positionRmseM, on.velocityRmseMps, off.velocityRmseMps, on.meanNees, off.meanNees,
                100.0 * on.shareInBand, 100.0 * off.shareInBand, on.p95PositionErrorM, off.p95PositionErrorM);
  }
  return 0;
}

int cmdMonteCarlo(int argc, char** argv) {
  const Args a = parseArgs(argc, argv, 2, {"runs", "threads", "seed", "out", "profile"});
  if (a.positional.size() != 1) throw UsageError("montecarlo needs exactly one SCENARIO");
  if (!a.options.count("runs")) throw UsageError("--runs N is required");
  const int runs = static_cast<int>(parseCount("runs", a.options.at("runs"), 1, 100000));
  const int hw = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int threads = a.options.count("threads")
                          ? static_cast<int>(parseCount("threads", a.options.at("threads"), 1, 1024))
                          : hw;
  const sim::Scenario s = loadProfiled(a, a.positional[0]);
  const std::uint64_t seed =
      a.options.count("seed") ? parseCount("seed", a.options.at("seed"), 0, UINT64_MAX) : s.seed;
  const std::string out = prepareOutDir(a);

  const auto start = std::chrono::steady_clock::now();
  const auto results = sim::runMonteCarlo(s, runs, threads, seed);
  const auto m = metrics::summariseMonteCarlo(s, results);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  io::writeTextFile(out + "/summary.json", io::monteCarloSummaryJson(s, m, seed, threads, wall));
  io::writeMonteCarloCsv(out + "/montecarlo.csv", m);
  if (a.quiet) return 0;

  std::printf("Reckoner Monte Carlo: %s, %d runs (seeds %llu-%llu) on %d threads in %.2f s\n", s.name.c_str(),
              runs, static_cast<unsigned long long>(seed),
              static_cast<unsigned long long>(seed + static_cast<std::uint64_t>(runs) - 1), threads, wall);
  std::printf("  average NEES (%d states) %.0f%% bounds: [%.2f, %.2f]\n\n", m.neesDof, 100.0 * m.confidence,
              m.bounds.lower, m.bounds.upper);
  std::printf("  %-2s %-13s %-30s %9s %9s %8s %10s %11s %6s\n", "#", "time (s)", "sensors", "mean NEES",
              "max", "inside", "pos RMSE", "vel RMSE", "<=3sd");
  for (const auto& p : m.phases) {
    char span[32];
    std::snprintf(span, sizeof span, "%.0f-%.0f", toSeconds(p.stats.phase.startUs),
                  toSeconds(p.stats.phase.endUs));
    std::printf("  %-2d %-13s %-30s %9.2f %9.2f %8s %8.1f m %7.3f m/s %5.1f%%\n", p.stats.phase.index + 1,
                span, p.stats.phase.label.c_str(), p.stats.meanNees, p.maxMeanNees, p.inside ? "yes" : "NO",
                p.stats.rmsePositionM, p.stats.rmseVelocityMps, 100.0 * p.stats.fractionWithin3Sd);
  }
  std::printf("\n  %s; wrote %s/summary.json and %s/montecarlo.csv\n",
              m.allPhasesInside ? "every phase inside its bounds" : "SOME PHASES OUTSIDE their bounds",
              out.c_str(), out.c_str());
  return 0;
}

int cmdImo(int argc, char** argv) {
  const Args a = parseArgs(argc, argv, 2, {"runs", "threads", "seed"});
  const int runs =
      a.options.count("runs") ? static_cast<int>(parseCount("runs", a.options.at("runs"), 1, 100000)) : 100;
  const int hw = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int threads = a.options.count("threads")
                          ? static_cast<int>(parseCount("threads", a.options.at("threads"), 1, 1024))
                          : hw;
  std::vector<std::string> specs = a.positional;
  if (specs.empty()) specs = {"builtin:imo-1", "builtin:imo-2", "builtin:imo-3", "builtin:imo-4"};
  std::vector<sim::Scenario> scenarios;
  for (const auto& spec : specs) scenarios.push_back(loadScenario(spec));
  bool all = true;
  std::printf("ARPA accuracy (IMO MSC.192(79)): 95th percentile of the error over %d runs\n", runs);
  for (const auto& s : scenarios) {
    const std::uint64_t seed =
        a.options.count("seed") ? parseCount("seed", a.options.at("seed"), 0, UINT64_MAX) : s.seed;
    const auto r = metrics::evaluateImo(s, runs, threads, seed);
    all = all && r.pass;
    std::printf(
        "\n%s: target tracked at 3 min in %d of %d runs; true relative speed %.1f kn, true speed %.1f kn\n",
        r.scenario.c_str(), r.tracked, r.runs, r.trueRelativeSpeedKn, r.trueSpeedKn);
    std::printf("  %-16s %-5s %10s %8s %-5s %10s %8s %-5s\n", "quantity", "unit", "1 min p95", "limit", "",
                "3 min p95", "limit", "");
    for (const auto& row : r.rows) {
      const auto cell = [](const metrics::ImoCell& c, char* buf, std::size_t n) {
        if (!c.required)
          std::snprintf(buf, n, "%10s %8s %-5s", "-", "-", "");
        else
          std::snprintf(buf, n, "%10.3f %8.3f %-5s", c.p95, c.limit, c.pass ? "pass" : "FAIL");
      };
      char c1[64], c3[64];
      cell(row.at1Min, c1, sizeof c1);
      cell(row.at3Min, c3, sizeof c3);
      std::printf("  %-16s %-5s %s %s\n", metrics::imoQuantityName(row.quantity),
                  metrics::imoQuantityUnit(row.quantity), c1, c3);
    }
  }
  std::printf("\n%s\n", all ? "all cells pass" : "SOME CELLS FAIL");
  return all ? 0 : 1;
}

double parseReal(const std::string& option, const std::string& text, double min, double max) {
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || used == 0 || !std::isfinite(v) || v < min || v > max)
    throw UsageError("--" + option + ": expected a number in [" + std::to_string(min) + ", " +
                     std::to_string(max) + "], got " + io::quoted(text));
  return v;
}

int cmdSeed001(int argc, char** argv) {
  // --turn is a flag: taken out before the valued options are parsed.
  bool turn = false;
  std::vector<char*> rest;
  for (int i = 0; i < argc; ++i) {
    if (i >= 2 && std::string(argv[i]) == "--turn")
      turn = true;
    else
      rest.push_back(argv[i]);
  }
  const Args a =
      parseArgs(static_cast<int>(rest.size()), rest.data(), 2,
                {"runs", "seed", "window", "pfa", "q", "bearing-sd", "init", "correction", "jump-sd"});
  if (!a.positional.empty())
    throw UsageError("seed001: unexpected argument " + io::quoted(a.positional.front()));
  const auto opt = [&a](const std::string& k) { return a.options.count(k) > 0; };
  const int runs = opt("runs") ? static_cast<int>(parseCount("runs", a.options.at("runs"), 1, 100000)) : 100;
  const std::uint64_t seed = opt("seed") ? parseCount("seed", a.options.at("seed"), 0, UINT64_MAX) : 1;
  track::InputEstimationConfig cfg;
  if (opt("window")) cfg.window = static_cast<int>(parseCount("window", a.options.at("window"), 1, 50));
  if (opt("pfa")) cfg.falseAlarmProbability = parseReal("pfa", a.options.at("pfa"), 1e-12, 0.5);
  if (opt("q")) cfg.processNoiseQ = parseReal("q", a.options.at("q"), 0.0, 100.0);
  if (opt("bearing-sd"))
    cfg.bearingSdRad = degToRad(parseReal("bearing-sd", a.options.at("bearing-sd"), 1e-6, 30.0));
  if (opt("jump-sd")) cfg.jumpSdMps = parseReal("jump-sd", a.options.at("jump-sd"), 1e-3, 100.0);
  if (opt("correction")) {
    const std::string& c = a.options.at("correction");
    using C = track::InputEstimationConfig::Correction;
    if (c != "paper" && c != "refilter" && c != "none")
      throw UsageError("--correction: expected none, paper or refilter, got " + io::quoted(c));
    cfg.correction = c == "none" ? C::None : c == "paper" ? C::Paper : C::Refilter;
  }
  if (opt("init")) {
    const std::string& i = a.options.at("init");
    if (i != "paper" && i != "two-point")
      throw UsageError("--init: expected paper or two-point, got " + io::quoted(i));
    cfg.paperInitialCovariance = i == "paper";
  }
  sim::Seed001Scenario sc;
  if (turn) sc.turn = sim::Seed001Scenario::Turn{};
  std::vector<std::vector<sim::Seed001Sample>> all;
  for (int r = 0; r < runs; ++r)
    all.push_back(sim::runSeed001(sc, cfg, seed + static_cast<std::uint64_t>(r)));
  const auto stats = sim::summariseSeed001(all);
  std::printf(
      "seed 001: %d runs, bearing sd %.2f deg, range sd %.0f m, window %d, Pfa %.3g (threshold %.2f), q "
      "%.3g, "
      "init %s%s\n",
      runs, radToDeg(cfg.bearingSdRad), cfg.rangeSdM, cfg.window, cfg.falseAlarmProbability,
      track::InputEstimationEkf(cfg).threshold(), cfg.processNoiseQ,
      cfg.paperInitialCovariance ? "paper (eq. 32)" : "two-point",
      turn ? ", target turns 100->180 deg at 540 s" : "");
  std::printf("  %-3s %7s %16s %16s %16s %7s %8s %8s %6s\n", "k", "t (s)", "range err % m/r",
              "course deg m/r", "speed m/s m/r", "within", "mean d", "max d", "det");
  for (const auto& s : stats)
    std::printf("  %-3d %7.0f %7.2f %8.2f %7.2f %8.2f %7.2f %8.2f %6.0f%% %8.2f %8.2f %6d\n", s.index,
                s.meanTS, s.meanRangeErrorPct, s.rmsRangeErrorPct, s.meanCourseErrorDeg, s.rmsCourseErrorDeg,
                s.meanSpeedErrorMps, s.rmsSpeedErrorMps, 100.0 * s.withinLimits, s.meanD, s.maxD,
                s.detections);
  if (turn) {
    const auto first = sim::firstDetections(all, sc.turn->startS);
    std::map<int, int> hist;
    for (int f : first) ++hist[f];
    std::printf("  first detection at or after 540 s, by sample (0: never):");
    for (const auto& [k, n] : hist) std::printf(" %d:%d", k, n);
    std::printf("\n");
  }
  return 0;
}

int cmdSeed003(int argc, char** argv) {
  const Args a = parseArgs(argc, argv, 2, {"runs", "alpha", "sweep", "noise", "seed"});
  if (!a.positional.empty())
    throw UsageError("seed003: unexpected argument " + io::quoted(a.positional.front()));
  const auto opt = [&a](const std::string& k) { return a.options.count(k) > 0; };
  const int runs = opt("runs") ? static_cast<int>(parseCount("runs", a.options.at("runs"), 1, 100000)) : 50;
  const std::uint64_t seed = opt("seed") ? parseCount("seed", a.options.at("seed"), 0, UINT64_MAX) : 1;
  track::AbgConfig cfg;
  if (opt("alpha")) cfg.alpha = parseReal("alpha", a.options.at("alpha"), 1e-6, 0.6);
  sim::Seed003Setup setup;
  if (opt("sweep")) setup.sweepS = parseReal("sweep", a.options.at("sweep"), 0.1, 600.0);
  if (opt("noise")) setup.plotSdM = parseReal("noise", a.options.at("noise"), 0.0, 10000.0);
  const auto [beta, gamma] = track::abgGainsFromAlpha(cfg.alpha);
  std::printf(
      "seed 003: alpha %.3f (beta %.4f, gamma %.5f), %d positions every %.1f s, plot noise %.0f m per axis, "
      "mean over %d runs\n",
      cfg.alpha, beta, gamma, setup.positions, setup.sweepS, setup.plotSdM, runs);
  std::printf("  %-26s %14s %14s %14s\n", "case", "observed 2drms", "smoothed 2drms", "predicted 2drms");
  for (const auto c : {sim::Seed003Case::NoNoise, sim::Seed003Case::VaryingCourse,
                       sim::Seed003Case::VaryingCourseAndSpeed}) {
    sim::Seed003Result sum;
    for (int r = 0; r < runs; ++r) {
      const auto one = sim::runSeed003(c, setup, cfg, seed + static_cast<std::uint64_t>(r));
      sum.observed2drmsM += one.observed2drmsM / runs;
      sum.smoothed2drmsM += one.smoothed2drmsM / runs;
      sum.predicted2drmsM += one.predicted2drmsM / runs;
    }
    std::printf("  %-26s %12.1f m %12.1f m %12.1f m\n", sim::seed003CaseName(c), sum.observed2drmsM,
                sum.smoothed2drmsM, sum.predicted2drmsM);
  }
  return 0;
}

/// Root mean square of the finite values of v at the indices where keep(t) holds.
template <class Keep>
double rmsWhere(const std::vector<std::vector<double>>& runs, const std::vector<double>& tS, Keep keep) {
  double sum = 0.0;
  long n = 0;
  for (const auto& v : runs)
    for (std::size_t i = 0; i < v.size() && i < tS.size(); ++i)
      if (keep(tS[i]) && std::isfinite(v[i])) {
        sum += v[i] * v[i];
        ++n;
      }
  return n ? std::sqrt(sum / static_cast<double>(n)) : std::nan("");
}

/// 95th percentile over the runs of v at the sweep nearest to time t.
double p95At(const std::vector<std::vector<double>>& runs, const std::vector<double>& tS, double t) {
  std::size_t k = 0;
  while (k + 1 < tS.size() && tS[k] < t) ++k;
  std::vector<double> x;
  for (const auto& v : runs)
    if (k < v.size() && std::isfinite(v[k])) x.push_back(v[k]);
  if (x.empty()) return std::nan("");
  std::sort(x.begin(), x.end());
  return x[std::min(x.size() - 1,
                    static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(x.size()))) - 1)];
}

int cmdManoeuvreReport(int argc, char** argv) {
  const Args a = parseArgs(argc, argv, 2, {"runs", "turn", "speed-change", "seed", "imo-runs"});
  if (!a.positional.empty())
    throw UsageError("manoeuvre-report: unexpected argument " + io::quoted(a.positional.front()));
  const auto opt = [&a](const std::string& k) { return a.options.count(k) > 0; };
  const int runs = opt("runs") ? static_cast<int>(parseCount("runs", a.options.at("runs"), 1, 100000)) : 100;
  const std::uint64_t seed = opt("seed") ? parseCount("seed", a.options.at("seed"), 0, UINT64_MAX) : 1;
  std::vector<sim::ManoeuvreTrial> cases;
  if (opt("turn") || opt("speed-change")) {
    sim::ManoeuvreTrial c;
    if (opt("turn")) c.turnRad = degToRad(parseReal("turn", a.options.at("turn"), -180.0, 180.0));
    if (opt("speed-change"))
      c.speedChangeMps =
          parseReal("speed-change", a.options.at("speed-change"), -30.0, 30.0) * 1852.0 / 3600.0;
    cases.push_back(c);
  } else {
    for (const double turn : {10.0, 30.0, 90.0}) {
      sim::ManoeuvreTrial c;
      c.turnRad = degToRad(turn);
      cases.push_back(c);
    }
    for (const double dv : {5.0, -5.0}) {
      sim::ManoeuvreTrial c;
      c.speedChangeMps = dv * 1852.0 / 3600.0;
      cases.push_back(c);
    }
    sim::ManoeuvreTrial straight;
    straight.durationS = 3600.0;
    cases.push_back(straight);
  }
  const sim::ManoeuvreTrial base;
  std::printf(
      "manoeuvre report: %d runs per case; radar every %.1f s, range sd %.0f m, bearing sd %.2f deg; target "
      "at 3 NM, 12 kn; manoeuvres from %.0f s (turns at 1 deg/s, speed at 0.1 m/s^2)\n",
      runs, base.sweepS, base.rangeSdM, radToDeg(base.bearingSdRad), base.manoeuvreStartS);
  std::printf(
      "  flag: first rise within 60 s of the start (STCW: 10 deg or 5 kn noticed within a minute); RMSE of "
      "position before (60 s to start), during, and 2 min after; /PCRB: RMSE over the bound's sd along the "
      "truth; p95 course and speed errors 1 and 3 min after the end (IMO MSC.192(79) times)\n");
  for (const auto& c : cases) {
    const sim::TrackerConfigs cfg = sim::radarRateTrackers(c);
    std::array<std::vector<std::vector<double>>, sim::kTrackerKinds> pos, crs, spd;
    std::array<int, sim::kTrackerKinds> within{}, falseAlarms{};
    std::array<double, sim::kTrackerKinds> delaySum{};
    std::vector<std::vector<double>> bound;
    std::vector<double> tS;
    double straightS = 0.0;
    for (int r = 0; r < runs; ++r) {
      const auto run = sim::runManoeuvreTrial(c, cfg, seed + static_cast<std::uint64_t>(r));
      tS = run.tS;
      bound.push_back(run.pcrbPosM);
      straightS += run.straightS;
      for (int k = 0; k < sim::kTrackerKinds; ++k) {
        const auto& s = run.trackers[static_cast<std::size_t>(k)];
        pos[k].push_back(s.posErrM);
        crs[k].push_back(s.courseErrRad);
        spd[k].push_back(s.speedErrMps);
        falseAlarms[k] += s.falseAlarms;
        if (s.delayS && *s.delayS <= 60.0) {
          ++within[k];
          delaySum[k] += *s.delayS;
        }
      }
    }
    const double start = c.manoeuvreStartS, end = c.manoeuvreEndS();
    if (c.manoeuvres())
      std::printf("\n%s %+.0f%s (ends at %.0f s)\n", c.turnRad != 0.0 ? "turn" : "speed change",
                  c.turnRad != 0.0 ? radToDeg(c.turnRad) : c.speedChangeMps * 3600.0 / 1852.0,
                  c.turnRad != 0.0 ? " deg" : " kn", end);
    else
      std::printf("\nstraight (%.0f h in all)\n", straightS / 3600.0);
    std::printf("  %-24s %8s %8s %8s %9s %9s %9s %8s %8s %9s %9s %9s %9s\n", "tracker", "flag<=60", "delay",
                "FA/h", "RMSE bef", "RMSE dur", "RMSE aft", "/PCRB b", "/PCRB a", "crs95 1m", "spd95 1m",
                "crs95 3m", "spd95 3m");
    const auto before = [&](double t) { return t >= 60.0 && (!c.manoeuvres() || t < start); };
    const auto during = [&](double t) { return c.manoeuvres() && t >= start && t <= end; };
    const auto after = [&](double t) { return c.manoeuvres() && t > end && t <= end + 120.0; };
    const double pcrbBefore = rmsWhere(bound, tS, before), pcrbAfter = rmsWhere(bound, tS, after);
    for (int k = 0; k < sim::kTrackerKinds; ++k) {
      const bool flags = k == sim::kEkfIe || k == sim::kImm;
      char flag[16] = "-", delay[16] = "-";
      if (flags && c.manoeuvres()) {
        std::snprintf(flag, sizeof flag, "%.0f%%", 100.0 * within[k] / runs);
        if (within[k]) std::snprintf(delay, sizeof delay, "%.1f s", delaySum[k] / within[k]);
      }
      char fa[16] = "-";
      if (flags) std::snprintf(fa, sizeof fa, "%.2f", falseAlarms[k] / (straightS / 3600.0));
      const double rb = rmsWhere(pos[k], tS, before), rd = rmsWhere(pos[k], tS, during),
                   ra = rmsWhere(pos[k], tS, after);
      std::printf(
          "  %-24s %8s %8s %8s %7.1f m %7.1f m %7.1f m %8.2f %8.2f %7.2f d %6.2f kn %7.2f d %6.2f kn\n",
          sim::trackerName(static_cast<sim::TrackerKind>(k)), flag, delay, fa, rb, rd, ra, rb / pcrbBefore,
          ra / pcrbAfter, radToDeg(p95At(crs[k], tS, end + 60.0)),
          p95At(spd[k], tS, end + 60.0) * 3600.0 / 1852.0, radToDeg(p95At(crs[k], tS, end + 180.0)),
          p95At(spd[k], tS, end + 180.0) * 3600.0 / 1852.0);
    }
  }

  // Seed 001's sonar scenario (pings every 10 to 80 s) through the same four trackers.
  if (!opt("turn") && !opt("speed-change")) {
    const sim::TrackerConfigs cfg = sim::sonarTrackers();
    std::printf(
        "\nseed 001 sonar scenario, %d runs (pings every 10-80 s, 1 deg, 20 m; EKF s = 2, Pfa 0.01, q 1e-6; "
        "abg "
        "alpha %.1f)\n",
        runs, cfg.abg.alpha);
    std::printf(
        "  straight: mean errors from the 6th sample (paper: range < 8%%, course < 3 deg, speed < 3 m/s), "
        "share "
        "of samples inside all three, flags per run\n");
    std::printf(
        "  turn 100 -> 180 deg at 540 s: runs flagged by the 9th sample (the paper's), mean course and speed "
        "errors at samples 10, 13 and 20, position RMSE from sample 10 and its ratio to the PCRB\n");
    std::printf("  %-24s %7s %7s %7s %6s %7s %7s %5s | %6s %14s %14s %14s %7s %7s\n", "tracker", "range%",
                "crs deg", "spd m/s", "inside", "RMSE m", "/PCRB", "flags", "by 9th", "crs/spd @10",
                "crs/spd @13", "crs/spd @20", "RMSE m", "/PCRB");
    sim::Seed001Scenario straight;
    sim::Seed001Scenario turning;
    turning.turn = sim::Seed001Scenario::Turn{};
    struct Acc {
      double range = 0, crs = 0, spd = 0, inside = 0, se = 0, bound2 = 0, seTurn = 0, bound2Turn = 0;
      long n = 0, flags = 0, byNinth = 0, nTurn = 0;
      std::map<int, std::pair<double, double>> at;  // sample -> sums
      std::map<int, int> atN;
    };
    std::array<Acc, sim::kTrackerKinds> acc;
    for (int r = 0; r < runs; ++r) {
      const auto s0 = sim::runSeed001Trackers(straight, cfg, seed + static_cast<std::uint64_t>(r)).trackers;
      const auto s1 = sim::runSeed001Trackers(turning, cfg, seed + static_cast<std::uint64_t>(r)).trackers;
      for (int k = 0; k < sim::kTrackerKinds; ++k) {
        Acc& q = acc[static_cast<std::size_t>(k)];
        bool was = false;
        for (const auto& x : s0[static_cast<std::size_t>(k)]) {
          q.flags += x.manoeuvring && !was ? 1 : 0;
          was = x.manoeuvring;
          if (x.index < 6) continue;
          q.range += x.rangeErrorPct;
          q.crs += x.courseErrorDeg;
          q.spd += x.speedErrorMps;
          q.inside += x.rangeErrorPct < 8.0 && x.courseErrorDeg < 3.0 && x.speedErrorMps < 3.0 ? 1 : 0;
          q.se += x.positionErrorM * x.positionErrorM;
          q.bound2 += x.pcrbPositionM * x.pcrbPositionM;
          ++q.n;
        }
        bool flagged = false;
        for (const auto& x : s1[static_cast<std::size_t>(k)]) {
          flagged = flagged || (x.manoeuvring && x.tS >= 540.0 && x.index <= 9);
          if (x.index >= 10) {
            q.seTurn += x.positionErrorM * x.positionErrorM;
            q.bound2Turn += x.pcrbPositionM * x.pcrbPositionM;
            ++q.nTurn;
          }
          for (const int at : {10, 13, 20}) {
            if (x.index != at) continue;
            q.at[at].first += x.courseErrorDeg;
            q.at[at].second += x.speedErrorMps;
            ++q.atN[at];
          }
        }
        q.byNinth += flagged ? 1 : 0;
      }
    }
    for (int k = 0; k < sim::kTrackerKinds; ++k) {
      const Acc& q = acc[static_cast<std::size_t>(k)];
      const double n = static_cast<double>(std::max(1L, q.n));
      const bool flags = k == sim::kEkfIe || k == sim::kImm;
      char by9[16], cell[3][24];
      std::snprintf(by9, sizeof by9, "%s",
                    flags ? (std::to_string(100 * q.byNinth / runs) + "%").c_str() : "-");
      int c = 0;
      for (const int at : {10, 13, 20}) {
        const auto it = q.at.find(at);
        const int m = q.atN.count(at) ? q.atN.at(at) : 0;
        if (it == q.at.end() || m == 0)
          std::snprintf(cell[c++], sizeof cell[0], "-");
        else
          std::snprintf(cell[c++], sizeof cell[0], "%.1f / %.2f", it->second.first / m,
                        it->second.second / m);
      }
      const double nt = static_cast<double>(std::max(1L, q.nTurn));
      std::printf("  %-24s %7.2f %7.2f %7.2f %5.0f%% %7.1f %7.2f %5s | %6s %14s %14s %14s %7.1f %7.2f\n",
                  sim::trackerName(static_cast<sim::TrackerKind>(k)), q.range / n, q.crs / n, q.spd / n,
                  100.0 * q.inside / n, std::sqrt(q.se / n), std::sqrt(q.se / q.bound2),
                  flags ? std::to_string(static_cast<double>(q.flags) / runs).substr(0, 4).c_str() : "-", by9,
                  cell[0], cell[1], cell[2], std::sqrt(q.seTurn / nt), std::sqrt(q.seTurn / q.bound2Turn));
    }
  }

  // The IMO A.823 scenarios through the ARPA tracks with each of the four filters (track_filter.h).
  const int imoRuns =
      opt("imo-runs") ? static_cast<int>(parseCount("imo-runs", a.options.at("imo-runs"), 0, 100000)) : 100;
  if (imoRuns > 0 && !opt("turn") && !opt("speed-change")) {
    std::printf(
        "\nIMO A.823 scenarios through the ARPA tracks, %d runs per filter: 95th-percentile errors at 1 / 3 "
        "min "
        "(* over the MSC.192(79) limit)\n",
        imoRuns);
    const int hw = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    for (const char* name : {"imo-1", "imo-2", "imo-3", "imo-4"}) {
      sim::Scenario sc = loadScenario(std::string("builtin:") + name);
      for (int k = 0; k < track::kTrackerKindCount; ++k) {
        sc.tracker.kind = static_cast<track::TrackerKind>(k);
        const auto r = metrics::evaluateImo(sc, imoRuns, hw, sc.seed);
        std::printf("  %s %-7s", name, track::trackerKindName(sc.tracker.kind));
        for (const auto& row : r.rows) {
          std::printf("  %s ", metrics::imoQuantityName(row.quantity));
          if (row.at1Min.required) std::printf("%.2f%s/", row.at1Min.p95, row.at1Min.pass ? "" : "*");
          std::printf("%.2f%s", row.at3Min.p95, !row.at3Min.required || row.at3Min.pass ? "" : "*");
        }
        std::printf("  %s\n", r.pass ? "pass" : "FAIL");
      }
    }
  }
  return 0;
}

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

int cmdCompare(int argc, char** argv) {
  const Args a = parseArgs(argc, argv, 2, {"runs", "threads", "seed", "out", "targets"});
  if (a.positional.size() != 1) throw UsageError("compare needs exactly one SCENARIO");
  const int runs =
      a.options.count("runs") ? static_cast<int>(parseCount("runs", a.options.at("runs"), 1, 10000)) : 10;
  const int hw = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int threads = a.options.count("threads")
                          ? static_cast<int>(parseCount("threads", a.options.at("threads"), 1, 1024))
                          : hw;
  const std::vector<int> counts = a.options.count("targets") ? parseTargetCounts(a.options.at("targets"))
                                                             : std::vector<int>{1, 2, 5, 10, 20};
  const sim::Scenario s = loadScenario(a.positional[0]);
  const std::uint64_t seed =
      a.options.count("seed") ? parseCount("seed", a.options.at("seed"), 0, UINT64_MAX) : s.seed;
  const std::string out = prepareOutDir(a);
  const auto rows = sim::compareCoupled(s, counts, runs, threads, seed);
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
  io::writeTextFile(out + "/compare.csv", csv);
  if (a.quiet) return 0;
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
  return 0;
}

int cmdReplay(int argc, char** argv) {
  const Args a = parseArgs(argc, argv, 2,
                           {"nmea", "radar", "config", "out", "assume-association", "max-gap", "date",
                            "variation", "profile", "adaptive-gnss"});
  if (!a.positional.empty()) throw UsageError("replay takes no positional arguments (use --nmea FILE)");
  if (!a.options.count("nmea")) throw UsageError("--nmea FILE is required");
  sim::ReplayOptions o;
  if (a.options.count("config")) {
    o.settings = loadScenario(a.options.at("config"));
    o.settingsName = a.options.at("config");
    o.originFromSettings = true;
  } else {
    o.settings = loadScenario("builtin:default");
    // Recorded data come from real sensors: the realistic profile unless asked otherwise (paper: the
    // default scenario's figures, seed 000's Table I).
    sim::applySensorProfile(o.settings, profileOption(a).value_or(sim::SensorProfile::Realistic));
    o.sweepFromPlots = true;  // no radar configured: the antenna's rotation as the plots show it
  }
  if (const auto p = profileOption(a); p && a.options.count("config"))
    sim::applySensorProfile(o.settings, *p);
  if (!o.settings.radar.fitted) {  // the radar noise a replay assumes without a configured radar
    o.settings.radar.fitted = true;
    o.settings.radar.rangeSdM = 20.0;
    o.settings.radar.bearingSdRad = degToRad(0.5);
  }
  o.assumeAssociation = a.assumeAssociation;
  if (a.options.count("adaptive-gnss")) {
    const std::string& v = a.options.at("adaptive-gnss");
    if (v != "on" && v != "off")
      throw UsageError("--adaptive-gnss: expected on or off, got " + io::quoted(v));
    o.settings.filter.adaptiveGnssNoise = v == "on";
  }
  if (a.options.count("max-gap")) o.maxGapS = parseReal("max-gap", a.options.at("max-gap"), 1.0, 1e7);
  if (a.options.count("variation"))
    o.variationDeg = parseReal("variation", a.options.at("variation"), -180.0, 180.0);
  if (a.options.count("date")) {
    const std::string& date = a.options.at("date");
    const auto day = io::parseIso8601(date + "T00:00:00Z");
    if (!day || date.size() != 10) throw UsageError("--date: expected YYYY-MM-DD, got " + io::quoted(date));
    o.date = std::array<int, 3>{std::stoi(date.substr(0, 4)), std::stoi(date.substr(5, 2)),
                                std::stoi(date.substr(8, 2))};
  }
  const std::string out = prepareOutDir(a);
  const std::string nmeaPath = a.options.at("nmea");
  const std::string nmea = io::readTextFile(nmeaPath);
  std::optional<std::string> radar;
  if (a.options.count("radar")) radar = io::readTextFile(a.options.at("radar"));
  const sim::ReplayResult r = sim::replay(nmea, nmeaPath, radar ? &*radar : nullptr,
                                          a.options.count("radar") ? a.options.at("radar") : "", o);
  for (const auto& w : r.warnings) std::fprintf(stderr, "reckoner-cli: warning: %s\n", w.c_str());
  io::writeReplayOwnShipCsv(out + "/ownship.csv", r);
  if (radar) io::writeReplayTargetsCsv(out + "/targets.csv", r);
  io::writeTextFile(out + "/summary.json", io::replaySummaryJson(r, nmeaPath));
  if (a.quiet) return 0;
  const auto& st = r.stats;
  std::printf("Reckoner replay of %s%s%s from %s\n", nmeaPath.c_str(), radar ? " and " : "",
              radar ? a.options.at("radar").c_str() : "", io::formatIso8601(r.utc0).c_str());
  std::printf(
      "  NMEA: %ld lines, %ld sentences used, %ld skipped (%ld comments, %ld bad checksum, %ld unknown, %ld "
      "proprietary, "
      "%ld malformed, %ld untimed, %ld time jumps, %ld unusable, %ld not GNSS fixes, %ld implausible, %ld "
      "without variation); %ld standby, %ld repeated, %ld not used; %ld replayed out of file order\n",
      st.nmeaLines, st.sentencesUsed, st.nmeaSkipped(), st.comments, st.badChecksum, st.unknownSentences,
      st.proprietary, st.malformed, st.untimed, st.timeJumps, st.unusable, st.notGnss, st.implausible,
      st.noVariation, st.standby, st.repeated, st.notUsed, st.reordered);
  const double span = r.own.empty() ? 0.0 : toSeconds(r.own.back().timeUs - r.own.front().timeUs);
  for (const auto& src : r.sources) {
    if (src.used + src.standby + src.repeated == 0) continue;
    std::printf("    %-14s %-9s %6ld used %6ld standby, active %3.0f%%, clock %+.2f s%s\n",
                src.source.c_str(), src.quantity.c_str(), src.used, src.standby,
                span > 0 ? 100.0 * std::min(1.0, src.activeS / span) : 0.0, src.clockOffsetS,
                src.clockCorrected ? " (corrected)" : "");
  }
  std::printf("  %ld own-ship epochs (%ld before the first fix), origin %s %s\n", st.epochs,
              st.epochsBeforeFix, io::formatLatitude(r.origin.latDeg).c_str(),
              io::formatLongitude(r.origin.lonDeg).c_str());
  std::printf("  DRKF updates accepted/gated/failed:");
  for (int b = 0; b < nav::kDrkfBlockCount; ++b) {
    const auto& c = r.updates[static_cast<std::size_t>(b)];
    std::printf(" %s %ld/%ld/%ld", nav::blockName(static_cast<nav::DrkfBlock>(b)), c.accepted, c.gated,
                c.failed);
  }
  std::printf("; restarts: %ld after a gap, %ld after failures\n", st.restartsAfterGap,
              st.restartsAfterFailure);
  if (radar)
    std::printf(
        "  radar: %ld lines, %ld plots, %ld bad, %ld duplicates, %ld time jumps; %ld tracks started, %ld "
        "confirmed (%s)\n",
        st.radarLines, st.radarPlots, st.radarBad, st.radarDuplicates, st.radarTimeJumps,
        r.tracking.tracksStarted, r.tracking.tracksConfirmed,
        o.assumeAssociation ? "association by target_id" : "nearest neighbour");
  if (!r.own.empty()) {
    const auto& last = r.own.back();
    std::printf("  final estimate %s %s, position sd %.1f m\n",
                io::formatLatitude(last.estimate.latDeg).c_str(),
                io::formatLongitude(last.estimate.lonDeg).c_str(),
                std::hypot(last.estimate.sdXM, last.estimate.sdYM));
  }
  std::printf("  wrote %s/ownship.csv%s and %s/summary.json\n", out.c_str(),
              radar ? (", " + out + "/targets.csv").c_str() : "", out.c_str());
  return 0;
}

int cmdExport(int argc, char** argv) {
  const Args a = parseArgs(argc, argv, 2, {"seed", "out", "date"});
  if (a.positional.size() != 1) throw UsageError("export needs exactly one SCENARIO");
  const sim::Scenario s = loadScenario(a.positional[0]);
  const std::uint64_t seed =
      a.options.count("seed") ? parseCount("seed", a.options.at("seed"), 0, UINT64_MAX) : s.seed;
  const std::string date = a.options.count("date") ? a.options.at("date") : "2026-01-01";
  const auto utc0 = io::parseIso8601(date + "T00:00:00Z");
  if (!utc0) throw UsageError("--date: expected YYYY-MM-DD, got " + io::quoted(date));
  const std::string out = prepareOutDir(a);
  const auto e = sim::exportRun(s, seed, *utc0);
  io::writeTextFile(out + "/ownship.nmea", e.nmea);
  io::writeTextFile(out + "/radar.csv", e.radarCsv);
  if (!a.quiet)
    std::printf("wrote %s/ownship.nmea and %s/radar.csv (%s, seed %llu, from %sT00:00:00Z)\n", out.c_str(),
                out.c_str(), s.name.c_str(), static_cast<unsigned long long>(seed), date.c_str());
  return 0;
}

void writeCellJson(io::JsonWriter& w, const charts::ChartCell& c) {
  const charts::CellInfo& i = c.info();
  w.beginObject();
  w.key("name").value(i.name);
  w.key("path").value(i.path);
  w.key("edition").value(i.edition);
  w.key("update_number").value(i.updateNumber);
  w.key("updates_applied").beginArray();
  for (const auto& u : i.updatesApplied) w.value(u);
  w.endArray();
  w.key("issue_date").value(i.issueDate);
  w.key("update_date").value(i.updateDate);
  w.key("agency").value(i.agency);
  w.key("intended_usage").value(i.intendedUsage);
  w.key("compilation_scale").value(i.compilationScale);
  w.key("comment").value(i.comment);
  const charts::Bounds& b = c.bounds();
  w.key("bounds").beginObject();
  w.key("min_lat_deg").value(b.minLatDeg, 9).key("max_lat_deg").value(b.maxLatDeg, 9);
  w.key("min_lon_deg").value(b.minLonDeg, 9).key("max_lon_deg").value(b.maxLonDeg, 9);
  w.endObject();
  w.key("coverage_areas").value(static_cast<std::int64_t>(c.coverage().size()));
  w.key("features").value(static_cast<std::int64_t>(c.features().size()));
  w.key("soundings").value(static_cast<std::int64_t>(c.soundingCount()));
  w.key("feature_counts").beginObject();
  for (const auto& [cls, n] : c.countsByClass()) w.key(cls).value(static_cast<std::int64_t>(n));
  w.endObject();
  w.endObject();
}

/// chart info PATH...: JSON with every cell's metadata and feature counts; failures listed, exit 2
/// when nothing loaded.
std::pair<double, double> parsePair(const std::string& option, const std::string& text, char sep) {
  const auto at = text.find(sep);
  try {
    if (at == std::string::npos) throw std::invalid_argument("no separator");
    std::size_t u1 = 0, u2 = 0;
    const double a = std::stod(text.substr(0, at), &u1), b = std::stod(text.substr(at + 1), &u2);
    if (u1 != at || u2 != text.size() - at - 1 || !std::isfinite(a) || !std::isfinite(b))
      throw std::invalid_argument("trailing");
    return {a, b};
  } catch (const std::exception&) {
    throw UsageError("--" + option + ": expected two numbers separated by '" + std::string(1, sep) +
                     "', got " + io::quoted(text));
  }
}

/// chart pick PATH... --at LAT,LON [--scale N] [--tolerance PX]: the features there, in plain words.
int cmdChartPick(int argc, char** argv) {
  const Args a = parseArgs(argc, argv, 3, {"at", "scale", "tolerance"});
  if (a.positional.empty()) throw UsageError("chart pick needs at least one PATH");
  if (!a.options.count("at")) throw UsageError("--at is required");
  const auto [lat, lon] = parsePair("at", a.options.at("at"), ',');
  if (!(std::abs(lat) <= 85.0) || !(std::abs(lon) <= 180.0))
    throw UsageError("--at: latitude within +-85 and longitude within +-180 degrees");
  const double scale = a.options.count("scale")
                           ? static_cast<double>(parseCount("scale", a.options.at("scale"), 100, 100000000))
                           : 10000.0;
  const double tolerance =
      a.options.count("tolerance")
          ? static_cast<double>(parseCount("tolerance", a.options.at("tolerance"), 1, 200))
          : 8.0;
  const charts::LoadResult r = charts::loadCharts(a.positional);
  for (const auto& f : r.failures)
    std::fprintf(stderr, "reckoner-cli: error: %s: %s\n", f.file.c_str(), f.reason.c_str());
  if (r.cells.empty()) return 2;
  const charts::Viewport view({lat, lon}, scale, 101, 101);
  const auto picked = charts::pickFeatures(r.cells, view, {50.5, 50.5}, tolerance);
  io::JsonWriter jw;
  jw.beginObject();
  jw.key("at").beginObject();
  jw.key("lat_deg").value(lat, 7);
  jw.key("lon_deg").value(lon, 7);
  jw.endObject();
  jw.key("features").beginArray();
  for (const auto& f : picked) {
    jw.beginObject();
    jw.key("cell").value(f.cell);
    jw.key("class").value(f.objectClass);
    jw.key("class_name").value(f.className);
    jw.key("primitive").value(f.primitive);
    jw.key("distance_px").value(f.distancePx, 3);
    jw.key("attributes").beginArray();
    for (const auto& at : f.attributes) {
      jw.beginObject();
      jw.key("acronym").value(at.acronym);
      jw.key("name").value(at.name);
      jw.key("value").value(at.value);
      jw.endObject();
    }
    jw.endArray();
    jw.endObject();
  }
  jw.endArray();
  jw.endObject();
  std::printf("%s\n", jw.str().c_str());
  return 0;
}

/// chart render PATH... --center LAT,LON --scale N --size WxH [--palette] [--category] [--safety-contour M]
/// --out FILE.png [--repeat K]: PNG and JSON with load and median render times.
int cmdChartRender(int argc, char** argv) {
  const Args a = parseArgs(
      argc, argv, 3, {"center", "scale", "size", "palette", "category", "safety-contour", "out", "repeat"});
  if (a.positional.empty()) throw UsageError("chart render needs at least one PATH");
  for (const char* required : {"center", "scale", "size", "out"})
    if (!a.options.count(required)) throw UsageError(std::string("--") + required + " is required");
  const auto [lat, lon] = parsePair("center", a.options.at("center"), ',');
  const double scale = static_cast<double>(parseCount("scale", a.options.at("scale"), 100, 100000000));
  const auto [w, h] = parsePair("size", a.options.at("size"), 'x');
  if (w < 16 || h < 16 || w > 16384 || h > 16384 || w != std::floor(w) || h != std::floor(h))
    throw UsageError("--size: width and height must be integers in [16, 16384]");
  charts::MarinerSettings ms;
  if (a.options.count("palette")) {
    const auto p = charts::paletteFromName(a.options.at("palette"));
    if (!p) throw UsageError("--palette: day, dusk or night");
    ms.palette = *p;
  }
  if (a.options.count("category")) {
    const auto c = charts::categoryFromName(a.options.at("category"));
    if (!c) throw UsageError("--category: base, standard or all");
    ms.category = *c;
  }
  if (a.options.count("safety-contour")) {
    std::size_t used = 0;
    const std::string& t = a.options.at("safety-contour");
    double v = -1;
    try {
      v = std::stod(t, &used);
    } catch (const std::exception&) {
    }
    if (used != t.size() || !(v >= 0.0) || v > 12000.0)
      throw UsageError("--safety-contour: metres in [0, 12000]");
    ms.safetyContourM = v;
    ms.safetyDepthM = v;
  }
  const int repeat =
      a.options.count("repeat") ? static_cast<int>(parseCount("repeat", a.options.at("repeat"), 1, 1000)) : 1;
  if (!qEnvironmentVariableIsSet("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  int qargc = 1;
  char name[] = "reckoner-cli";
  char* qargv[] = {name, nullptr};
  QGuiApplication app(qargc, qargv);  // fonts for the chart text
  const auto t0 = std::chrono::steady_clock::now();
  const charts::LoadResult r = charts::loadCharts(a.positional);
  const double loadS = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (const auto& f : r.failures)
    std::fprintf(stderr, "reckoner-cli: error: %s: %s\n", f.file.c_str(), f.reason.c_str());
  if (r.cells.empty()) return 2;
  const charts::Viewport view({lat, lon}, scale, static_cast<int>(w), static_cast<int>(h));
  QImage image(static_cast<int>(w), static_cast<int>(h), QImage::Format_ARGB32_Premultiplied);
  // One renderer for all the repeats, as a chart view keeps one: the first render also projects the
  // cells to Mercator (reported apart), the others are full redraws from the prepared cells.
  charts::ChartRenderer renderer;
  const auto p0 = std::chrono::steady_clock::now();
  for (const auto& cell : r.cells) renderer.prepare(cell);
  const double prepareMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - p0).count();
  std::vector<double> times;
  charts::RenderStats stats;
  for (int k = 0; k < repeat; ++k) {
    const auto s0 = std::chrono::steady_clock::now();
    stats = renderer.render(image, r.cells, view, ms);
    times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - s0).count());
  }
  std::sort(times.begin(), times.end());
  if (!image.save(QString::fromStdString(a.options.at("out")), "PNG"))
    throw io::InputError(a.options.at("out"), 0, "", "cannot write the PNG");
  io::JsonWriter jw;
  jw.beginObject();
  jw.key("out").value(a.options.at("out"));
  jw.key("cells_loaded").value(static_cast<std::int64_t>(r.cells.size()));
  jw.key("cells_drawn").value(stats.cellsDrawn);
  jw.key("features_drawn").value(stats.featuresDrawn);
  jw.key("overscale").value(stats.overscale, 4);
  jw.key("load_time_s").value(loadS, 6);
  jw.key("prepare_ms").value(prepareMs, 5);
  jw.key("render_ms_median").value(times[times.size() / 2], 5);
  jw.key("renders").value(repeat);
  jw.endObject();
  std::printf("%s\n", jw.str().c_str());
  return 0;
}

int cmdChart(int argc, char** argv) {
  if (argc < 3) throw UsageError("chart needs a subcommand: info or render");
  const std::string sub = argv[2];
  if (sub == "render") return cmdChartRender(argc, argv);
  if (sub == "pick") return cmdChartPick(argc, argv);
  if (sub != "info")
    throw UsageError("unknown chart subcommand " + io::quoted(sub) + " (known: info, render, pick)");
  const Args a = parseArgs(argc, argv, 3, {});
  if (a.positional.empty()) throw UsageError("chart info needs at least one PATH (a .000 cell or a folder)");
  const auto start = std::chrono::steady_clock::now();
  const charts::LoadResult r = charts::loadCharts(a.positional);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  io::JsonWriter w;
  w.beginObject();
  w.key("load_time_s").value(wall, 6);
  w.key("cells").beginArray();
  for (const auto& c : r.cells) writeCellJson(w, *c);
  w.endArray();
  w.key("failures").beginArray();
  for (const auto& f : r.failures)
    w.beginObject().key("file").value(f.file).key("reason").value(f.reason).endObject();
  w.endArray();
  w.endObject();
  std::printf("%s\n", w.str().c_str());
  for (const auto& f : r.failures)
    std::fprintf(stderr, "reckoner-cli: error: %s: %s\n", f.file.c_str(), f.reason.c_str());
  if (r.cells.empty()) return 2;
  return 0;
}

int cmdValidate(int argc, char** argv) {
  const Args a = parseArgs(argc, argv, 2, {});
  if (a.positional.empty()) throw UsageError("validate needs at least one SCENARIO");
  for (const auto& p : a.positional) {
    const sim::Scenario s = loadScenario(p);
    std::printf("%s: ok (%s, %.0f s)\n", p.c_str(), s.name.c_str(), toSeconds(s.durationUs));
  }
  return 0;
}

int cmdScenarios() {
  for (const auto& f : resources::scenarios()) {
    const sim::Scenario s = io::parseScenario(f.text, "builtin:" + std::string(f.name));
    std::printf("builtin:%-24s %s\n", std::string(f.name).c_str(), s.name.c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc < 2) throw UsageError("no command given");
    const std::string cmd = argv[1];
    if (cmd == "--help" || cmd == "-h" || cmd == "help") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (cmd == "run") return cmdRun(argc, argv);
    if (cmd == "montecarlo") return cmdMonteCarlo(argc, argv);
    if (cmd == "validate") return cmdValidate(argc, argv);
    if (cmd == "imo") return cmdImo(argc, argv);
    if (cmd == "compare") return cmdCompare(argc, argv);
    if (cmd == "own-ship-compare") return cmdOwnShipCompare(argc, argv);
    if (cmd == "radar-fix") return cmdRadarFix(argc, argv);
    if (cmd == "replay") return cmdReplay(argc, argv);
    if (cmd == "export") return cmdExport(argc, argv);
    if (cmd == "chart") return cmdChart(argc, argv);
    if (cmd == "scenarios") return cmdScenarios();
    if (cmd == "seed001") return cmdSeed001(argc, argv);
    if (cmd == "seed003") return cmdSeed003(argc, argv);
    if (cmd == "manoeuvre-report") return cmdManoeuvreReport(argc, argv);
    throw UsageError("unknown command " + io::quoted(cmd));
  } catch (const UsageError& e) {
    std::fprintf(stderr, "reckoner-cli: error: %s\n", io::oneLine(e.what()).c_str());
    if (std::string(e.what()).find("usage") == std::string::npos && argc < 2) std::fputs(kUsage, stderr);
    return 2;
  } catch (const io::InputError& e) {
    std::fprintf(stderr, "reckoner-cli: error: %s\n", e.what());
    return 2;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "reckoner-cli: error: %s\n", io::oneLine(e.what()).c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "reckoner-cli: failed: %s\n", io::oneLine(e.what()).c_str());
    return 1;
  }
}
