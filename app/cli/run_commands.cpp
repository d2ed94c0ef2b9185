// run SCENARIO and montecarlo SCENARIO: the engine on a scenario, once or many times, its rows into
// CSVs under --out DIR, a per-phase table on stdout (--json: summary.json's text instead).
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>

#include "cli/cli_options.h"
#include "cli/commands.h"
#include "cli/nmea_out.h"
#include "cli/voyage_options.h"
#include "common/time.h"
#include "files/own_ship_output.h"
#include "files/track_output.h"
#include "geo/local_frame.h"
#include "io/error_line.h"
#include "io/iso8601.h"
#include "io/text_file.h"
#include "io/text_format.h"
#include "metrics/own_ship_stats.h"
#include "metrics/track_stats.h"
#include "sim/nmea_output.h"
#include "sim/scenario_run.h"
#include "studies/own_ship_filters.h"

namespace reckoner::cli {
namespace {

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

// ---- run -----------------------------------------------------------------------------------------
struct RunArgs {
  std::string scenario;
  std::optional<std::uint64_t> seed;
  std::string filter = "drkf";
  std::string profile;
  std::optional<std::string> nmeaOut;
  std::string date = "2026-01-01";
  std::optional<std::string> enc;
  OutputArgs output;
};

void printRun(const sim::Scenario& s, const sim::RunResult& run, std::uint64_t seed,
              studies::OwnShipFilter filter, const std::vector<metrics::PhaseStats>& phases,
              const std::string& out) {
  const geo::LocalFrame frame(s.origin.latDeg, s.origin.lonDeg);
  std::printf("Reckoner dead-reckoning run: %s (seed %llu, own-ship filter %s%s)\n", s.name.c_str(),
              static_cast<unsigned long long>(seed), studies::ownShipFilterName(filter),
              filter == studies::OwnShipFilter::Drkf ? "" : "; NEES of position and velocity, 4 dof");
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
}

int runCommand(const RunArgs& a) {
  if (a.scenario.empty()) throw UsageError("run needs exactly one SCENARIO");
  const sim::Scenario s = loadProfiled(a.scenario, a.profile);
  const std::uint64_t seed = a.seed.value_or(s.seed);
  const studies::OwnShipFilter filter = *studies::ownShipFilterFromName(a.filter);
  const auto utc0 = io::parseIso8601(a.date + "T00:00:00Z");
  if (!utc0) throw UsageError("--date: expected YYYY-MM-DD, got " + io::quoted(a.date));
  if (a.nmeaOut && filter != studies::OwnShipFilter::Drkf)
    throw UsageError("--nmea-out sends the DRKF's estimate: use it with --own-ship-filter drkf");
  std::unique_ptr<NmeaSink> nmea;
  if (a.nmeaOut) nmea = std::make_unique<NmeaSink>(*a.nmeaOut);
  const std::string out = prepareOutDir(a.output);

  // The DRKF always runs (it feeds the trackers); seed 002's filters beside it when chosen.
  const std::shared_ptr<const sim::ChartGuard> guard = chartGuardFor(s.voyage, a.enc);
  if (guard && filter != studies::OwnShipFilter::Drkf)
    throw UsageError("--enc: the look-ahead and grounding run with --own-ship-filter drkf");
  sim::RunResult run;
  if (nmea) {
    sim::RunNmeaOutput sentences(s, *utc0);
    run = sim::runScenario(
        s, seed,
        [&](const sim::SimFrame& f, const sim::OwnShipRow& row, std::span<const sim::TrackRow> tracks) {
          nmea->write(sentences.frame(f, row, tracks));
        },
        guard);
  } else if (filter == studies::OwnShipFilter::Drkf) {
    run = sim::runScenario(s, seed, sim::FrameObserver{}, guard);
  } else {
    studies::OwnShipFilterRun both = studies::runOwnShipFilters(s, seed);
    run = std::move(both.drkf);
    run.rows = std::move(both.rows[static_cast<std::size_t>(filter)]);
  }
  const auto phases = metrics::summarisePhases(metrics::derivePhases(s), run.rows);
  files::writeOwnShipCsv(out + "/ownship.csv", run.rows);
  const std::string summary = files::runSummaryJson(s, run, phases);
  io::writeTextFile(out + "/summary.json", summary);
  if (s.radar.fitted) files::writeTargetsCsv(out + "/targets.csv", run.trackRows);
  printSummary(a.output, summary);
  if (wantsTable(a.output)) printRun(s, run, seed, filter, phases, out);
  if (run.grounded && !a.output.quiet)
    std::printf("  own ship aground at %.0f s on %s\n", toSeconds(run.grounded->first),
                run.grounded->second.what.c_str());
  if (nmea) {
    const std::string account = nmea->finish();
    if (wantsTable(a.output)) std::printf("  sent %s\n", account.c_str());
  }
  return 0;
}

void addRun(CLI::App& root, Commands& out) {
  auto a = std::make_shared<RunArgs>();
  CLI::App* app = root.add_subcommand("run", "one run of a scenario: ownship.csv, targets.csv, summary.json");
  addScenarioArgument(*app, a->scenario);
  addSeed(*app, a->seed, "the scenario's");
  addChoice(*app, "own-ship-filter", {"drkf", "geodetic", "lsq"}, a->filter,
            "own-ship filter whose rows ownship.csv gets (geodetic, lsq: seed 002's, beside the DRKF)");
  addProfile(*app, a->profile,
             "sensor profile: the sensors' noise and the filter's models (default: the "
             "scenario's own figures)");
  addNmeaOut(*app, a->nmeaOut);
  addValue(*app, "date", "YYYY-MM-DD",
           "the UTC day the run starts at midnight of, for --nmea-out's times (default 2026-01-01)",
           [p = a.get()](const std::string& t) { p->date = t; });
  addText(*app, "enc", a->enc, "PATH",
          "S-57 cells (a .000 file or a folder): the anti-grounding look-ahead and grounding on them");
  addOutputOptions(*app, a->output, Summary::Json, "ownship.csv, summary.json, targets.csv with a radar");
  out.push_back({app, [a] { return runCommand(*a); }, "run needs exactly one SCENARIO"});
}

// ---- montecarlo ----------------------------------------------------------------------------------
struct MonteCarloRunArgs {
  std::string scenario;
  std::optional<int> runs;
  std::optional<int> threads;
  std::optional<std::uint64_t> seed;
  std::string profile;
  OutputArgs output;
};

void printMonteCarlo(const sim::Scenario& s, const metrics::MonteCarloSummary& m, std::uint64_t seed,
                     int runs, int threads, double wall, const std::string& out) {
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
}

int monteCarloCommand(const MonteCarloRunArgs& a) {
  if (a.scenario.empty()) throw UsageError("montecarlo needs exactly one SCENARIO");
  if (!a.runs) throw UsageError("--runs N is required");
  const int threads = a.threads.value_or(hardwareThreads());
  const sim::Scenario s = loadProfiled(a.scenario, a.profile);
  const std::uint64_t seed = a.seed.value_or(s.seed);
  const std::string out = prepareOutDir(a.output);

  const auto start = std::chrono::steady_clock::now();
  const auto results = sim::runMonteCarlo(s, *a.runs, threads, seed);
  const auto m = metrics::summariseMonteCarlo(s, results);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string summary = files::monteCarloSummaryJson(s, m, seed, threads, wall);
  io::writeTextFile(out + "/summary.json", summary);
  files::writeMonteCarloCsv(out + "/montecarlo.csv", m);
  printSummary(a.output, summary);
  if (wantsTable(a.output)) printMonteCarlo(s, m, seed, *a.runs, threads, wall, out);
  return 0;
}

void addMonteCarlo(CLI::App& root, Commands& out) {
  auto a = std::make_shared<MonteCarloRunArgs>();
  CLI::App* app = root.add_subcommand(
      "montecarlo", "Monte Carlo runs of a scenario: average NEES against its chi-square bounds per phase");
  addScenarioArgument(*app, a->scenario);
  addInteger(*app, "runs", a->runs, 1, 100000, "N", "Monte Carlo runs, required");
  addThreads(*app, a->threads, 1024);
  addSeed(*app, a->seed, "the scenario's; run k (from 0) uses seed + k");
  addProfile(*app, a->profile, "sensor profile (default: the scenario's own figures)");
  addOutputOptions(*app, a->output, Summary::Json, "summary.json, montecarlo.csv");
  out.push_back({app, [a] { return monteCarloCommand(*a); }, "montecarlo needs exactly one SCENARIO"});
}

}  // namespace

void addRunCommands(CLI::App& root, Commands& out) {
  addRun(root, out);
  addMonteCarlo(root, out);
}

}  // namespace reckoner::cli
