// seed001 and seed003: the papers' own experiments, Monte Carlo tables on stdout. seed001: the
// input-estimation EKF with range and bearing (docs/manoeuvres.md); seed003: the alpha-beta-gamma
// tracker's 2drms.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli_options.h"
#include "cli/commands.h"
#include "common/angles.h"
#include "studies/seed001.h"
#include "studies/seed003.h"
#include "tracking/alpha_beta_gamma.h"
#include "tracking/input_estimation.h"

namespace reckoner::cli {
namespace {

// ---- seed001 -------------------------------------------------------------------------------------
struct Seed001Args {
  int runs = 100;
  std::uint64_t seed = 1;
  bool turn = false;
  track::InputEstimationConfig cfg;
  std::string init = "two-point";
  std::string correction = "refilter";
};

void printSeed001(const Seed001Args& a, const track::InputEstimationConfig& cfg,
                  const std::vector<studies::Seed001SampleStats>& stats) {
  std::printf(
      "seed 001: %d runs, bearing sd %.2f deg, range sd %.0f m, window %d, Pfa %.3g (threshold %.2f), q "
      "%.3g, "
      "init %s%s\n",
      a.runs, radToDeg(cfg.bearingSdRad), cfg.rangeSdM, cfg.window, cfg.falseAlarmProbability,
      track::InputEstimationEkf(cfg).threshold(), cfg.processNoiseQ,
      cfg.paperInitialCovariance ? "paper (eq. 32)" : "two-point",
      a.turn ? ", target turns 100->180 deg at 540 s" : "");
  std::printf("  %-3s %7s %16s %16s %16s %7s %8s %8s %6s\n", "k", "t (s)", "range err % m/r",
              "course deg m/r", "speed m/s m/r", "within", "mean d", "max d", "det");
  for (const auto& s : stats)
    std::printf("  %-3d %7.0f %7.2f %8.2f %7.2f %8.2f %7.2f %8.2f %6.0f%% %8.2f %8.2f %6d\n", s.index,
                s.meanTS, s.meanRangeErrorPct, s.rmsRangeErrorPct, s.meanCourseErrorDeg, s.rmsCourseErrorDeg,
                s.meanSpeedErrorMps, s.rmsSpeedErrorMps, 100.0 * s.withinLimits, s.meanD, s.maxD,
                s.detections);
}

int seed001Command(const Seed001Args& a) {
  track::InputEstimationConfig cfg = a.cfg;
  using C = track::InputEstimationConfig::Correction;
  cfg.correction = a.correction == "none" ? C::None : a.correction == "paper" ? C::Paper : C::Refilter;
  cfg.paperInitialCovariance = a.init == "paper";
  studies::Seed001Scenario sc;
  if (a.turn) sc.turn = studies::Seed001Scenario::Turn{};
  std::vector<std::vector<studies::Seed001Sample>> all;
  all.reserve(static_cast<std::size_t>(std::max(a.runs, 0)));
  for (int r = 0; r < a.runs; ++r)
    all.push_back(studies::runSeed001(sc, cfg, a.seed + static_cast<std::uint64_t>(r)));
  printSeed001(a, cfg, studies::summariseSeed001(all));
  if (a.turn) {
    const auto first = studies::firstDetections(all, sc.turn->startS);
    std::map<int, int> hist;
    for (int f : first) ++hist[f];
    std::printf("  first detection at or after 540 s, by sample (0: never):");
    for (const auto& [k, n] : hist) std::printf(" %d:%d", k, n);
    std::printf("\n");
  }
  return 0;
}

void addSeed001(CLI::App& root, Commands& out) {
  auto a = std::make_shared<Seed001Args>();
  CLI::App* app = root.add_subcommand(
      "seed001", "seed 001: the input-estimation EKF (range and bearing), Monte Carlo per sample");
  auto& cfg = a->cfg;
  addInteger(*app, "runs", a->runs, 1, 100000, "N", "Monte Carlo runs");
  addFlag(*app, "turn", a->turn, "the target turns 100 -> 180 deg at 540 s (default: a straight course)");
  addInteger(*app, "seed", a->seed, 0, UINT64_MAX, "N", "first run's random seed");
  addInteger(*app, "window", cfg.window, 1, 50, "S", "input-estimation window, seconds");
  addReal(*app, "pfa", cfg.falseAlarmProbability, 1e-12, 0.5, "P", "false-alarm probability of the test");
  addReal(*app, "q", cfg.processNoiseQ, 0.0, 100.0, "Q", "target's white-acceleration density, m^2/s^3");
  addValue(
      *app, "bearing-sd", "DEG",
      "bearing noise sd, degrees" + rangeText(1e-6, 30.0, numberText(radToDeg(cfg.bearingSdRad))),
      [&cfg](const std::string& t) { cfg.bearingSdRad = degToRad(parseReal("bearing-sd", t, 1e-6, 30.0)); });
  addChoice(*app, "init", {"paper", "two-point"}, a->init,
            "initial covariance: the paper's eq. 32 or the two-point difference's");
  addChoice(*app, "correction", {"none", "paper", "refilter"}, a->correction,
            "after a detection: nothing, the paper's eqs. 28-29, or the window filtered again with a jump");
  addReal(*app, "jump-sd", cfg.jumpSdMps, 1e-3, 100.0, "M/S", "refilter: velocity jump sd per axis, m/s");
  addIgnoredQuiet(*app);
  out.push_back({app, [a] { return seed001Command(*a); }, ""});
}

// ---- seed003 -------------------------------------------------------------------------------------
struct Seed003Args {
  int runs = 50;
  std::uint64_t seed = 1;
  track::AbgConfig cfg;
  studies::Seed003Setup setup;
};

int seed003Command(const Seed003Args& a) {
  const auto& cfg = a.cfg;
  const auto& setup = a.setup;
  const int runs = a.runs;
  const auto [beta, gamma] = track::abgGainsFromAlpha(cfg.alpha);
  std::printf(
      "seed 003: alpha %.3f (beta %.4f, gamma %.5f), %d positions every %.1f s, plot noise %.0f m per axis, "
      "mean over %d runs\n",
      cfg.alpha, beta, gamma, setup.positions, setup.sweepS, setup.plotSdM, runs);
  std::printf("  %-26s %14s %14s %14s\n", "case", "observed 2drms", "smoothed 2drms", "predicted 2drms");
  for (const auto c : {studies::Seed003Case::NoNoise, studies::Seed003Case::VaryingCourse,
                       studies::Seed003Case::VaryingCourseAndSpeed}) {
    studies::Seed003Result sum;
    for (int r = 0; r < runs; ++r) {
      const auto one = studies::runSeed003(c, setup, cfg, a.seed + static_cast<std::uint64_t>(r));
      sum.observed2drmsM += one.observed2drmsM / runs;
      sum.smoothed2drmsM += one.smoothed2drmsM / runs;
      sum.predicted2drmsM += one.predicted2drmsM / runs;
    }
    std::printf("  %-26s %12.1f m %12.1f m %12.1f m\n", studies::seed003CaseName(c), sum.observed2drmsM,
                sum.smoothed2drmsM, sum.predicted2drmsM);
  }
  return 0;
}

void addSeed003(CLI::App& root, Commands& out) {
  auto a = std::make_shared<Seed003Args>();
  CLI::App* app =
      root.add_subcommand("seed003", "seed 003: the alpha-beta-gamma tracker's 2drms, three cases");
  addInteger(*app, "runs", a->runs, 1, 100000, "N", "Monte Carlo runs");
  addReal(*app, "alpha", a->cfg.alpha, 1e-6, 0.6, "A", "steady-state position gain (beta, gamma follow)");
  addReal(*app, "sweep", a->setup.sweepS, 0.1, 600.0, "S", "time between positions, seconds");
  addReal(*app, "noise", a->setup.plotSdM, 0.0, 10000.0, "M", "plot noise sd per axis, metres");
  addInteger(*app, "seed", a->seed, 0, UINT64_MAX, "N", "first run's random seed");
  addIgnoredQuiet(*app);
  out.push_back({app, [a] { return seed003Command(*a); }, ""});
}

}  // namespace

void addSeedCommands(CLI::App& root, Commands& out) {
  addSeed001(root, out);
  addSeed003(root, out);
}

}  // namespace reckoner::cli
