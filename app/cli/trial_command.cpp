// trial SCENARIO --at T --course C --speed S --delay D: the trial manoeuvre (docs/trial.md). Runs the
// scenario to T, then prints per target (radar track and/or AIS station) the present CPA and TCPA, the
// predicted CPA and TCPA with the manoeuvre and their sd, and the probability that the CPA falls below
// the limit; then the collision-danger sectors at the ordered speed. --verify carries the manoeuvre
// out in the simulation and prints the CPA each vessel really reached; with --runs N over N seeds, the
// summary of (realised - predicted) / sd.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli_options.h"
#include "cli/commands.h"
#include "common/angles.h"
#include "common/units.h"
#include "estimation/chi_square.h"
#include "studies/trial_study.h"

namespace reckoner::cli {
namespace {

struct TrialArgs {
  std::string scenario;
  // Required: NaN until given.
  double atS = std::nan(""), courseDeg = std::nan(""), speedKn = std::nan(""), delayS = 0.0;
  std::optional<double> cpaLimitNm, tcpaLimitMin;
  std::optional<std::uint64_t> seed;
  bool verify = false;
  int runs = 1;
};

std::string label(const sim::TrialTargetResult& t) {
  std::string s = t.trackId ? "track " + std::to_string(t.trackId) : std::string("AIS");
  if (t.mmsi) s += " / " + std::to_string(t.mmsi);
  return s;
}

/// The dangerous courses of the ring nearest to the ordered speed, as ranges "a-b".
std::string dangerousCourses(const sim::DangerSectors& d, double speedMps) {
  if (d.speedsMps.empty()) return "none";
  std::size_t ring = 0;
  for (std::size_t i = 0; i < d.speedsMps.size(); ++i)
    if (std::abs(d.speedsMps[i] - speedMps) < std::abs(d.speedsMps[ring] - speedMps)) ring = i;
  std::string out;
  const double cell = 360.0 / d.courses;
  for (const auto& [j, k] : d.dangerousRuns(ring)) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%s%03.0f-%03.0f", out.empty() ? "" : ", ", j * cell, k * cell);
    out += buf;
  }
  char head[48];
  std::snprintf(head, sizeof head, "at %.1f kn: ", mpsToKnots(d.speedsMps[ring]));
  return head + (out.empty() ? std::string("none") : out);
}

void printTrial(const studies::TrialCheck& c, const sim::TrialSettings& s, bool verified) {
  const auto& r = c.trial;
  std::printf(
      "trial at t = %.0f s: course %.1f deg, speed %.1f kn after %.0f s; order reached after %.0f s\n",
      toSeconds(r.timeUs), radToDeg(r.order.courseRad), mpsToKnots(r.order.speedMps), r.order.delayS,
      r.manoeuvreEndS);
  std::printf("CPA limit %.2f NM, TCPA limit %.1f min\n", metresToNm(s.cpaLimitM), s.tcpaLimitS / 60.0);
  std::printf("%-22s %9s %8s | %9s %8s %9s %8s %8s %-3s%s\n", "target", "CPA now", "TCPA", "CPA trial", "sd",
              "TCPA", "sd", "P<limit", "", verified ? " | realised CPA  (r-p)/sd" : "");
  for (const auto& t : c.targets) {
    const auto& p = t.predicted;
    std::printf("%-22s %7.3fNM %6.1fmn | %7.3fNM %6.3fNM %7.1fmn %6.2fmn %8.3f %-3s", label(p).c_str(),
                metresToNm(p.presentCpaM), p.presentTcpaS / 60.0, metresToNm(p.cpaM), metresToNm(p.sdCpaM),
                p.tcpaS / 60.0, p.sdTcpaS / 60.0, p.probabilityBelowLimit, p.dangerous ? "!" : "");
    if (verified && t.realisedCpaM)
      std::printf(" | %9.3fNM %9.2f", metresToNm(*t.realisedCpaM),
                  p.sdCpaM > 0 ? (*t.realisedCpaM - p.cpaM) / p.sdCpaM : 0.0);
    std::printf("\n");
  }
  std::printf("collision-danger courses %s\n", dangerousCourses(r.sectors, r.order.speedMps).c_str());
}

/// The ranges the help gives, as one usage line each.
void checkRanges(const TrialArgs& a) {
  for (const auto& [v, option] :
       {std::pair{a.atS, "--at"}, {a.courseDeg, "--course"}, {a.speedKn, "--speed"}})
    if (std::isnan(v)) throw UsageError(std::string("option '") + option + "' is required");
  auto within = [](double v, double lo, double hi, const char* option) {
    if (!(v >= lo && v <= hi))
      throw UsageError(std::string("option '") + option + "' must lie in [" + std::to_string(lo) + ", " +
                       std::to_string(hi) + "]");
  };
  within(a.atS, 0.0, 1e7, "--at");
  within(a.courseDeg, 0.0, 360.0, "--course");
  within(a.speedKn, 0.0, 60.0, "--speed");
  within(a.delayS, 0.0, 3600.0, "--delay");
  if (a.cpaLimitNm) within(*a.cpaLimitNm, 0.0, 20.0, "--cpa-limit");
  if (a.tcpaLimitMin) within(*a.tcpaLimitMin, 0.0, 600.0, "--tcpa-limit");
  within(a.runs, 1.0, 10000.0, "--runs");
}

int trialCommand(const TrialArgs& a) {
  checkRanges(a);
  const sim::Scenario s = loadScenario(a.scenario);
  sim::TrialOrder order{wrapTwoPi(degToRad(a.courseDeg)), knotsToMps(a.speedKn), a.delayS};
  sim::TrialSettings settings;
  settings.cpaLimitM = a.cpaLimitNm ? nmToMetres(*a.cpaLimitNm) : s.tracker.dangerCpaM;
  settings.tcpaLimitS = a.tcpaLimitMin ? 60.0 * *a.tcpaLimitMin : s.tracker.dangerTcpaS;
  const std::uint64_t seed = a.seed.value_or(s.seed);
  if (a.runs == 1) {
    printTrial(studies::checkTrial(s, seed, fromSeconds(a.atS), order, settings, a.verify), settings,
               a.verify);
    return 0;
  }
  long n = 0, in1 = 0, in2 = 0, np = 0;
  double z2 = 0.0, zp2 = 0.0;
  for (int i = 0; i < a.runs; ++i) {
    const auto c = studies::checkTrial(s, seed + static_cast<std::uint64_t>(i), fromSeconds(a.atS), order,
                                       settings, true);
    for (const auto& t : c.targets) {
      if (!t.realisedCpaM || !(t.predicted.sdCpaM > 0.0)) continue;
      const double z = (*t.realisedCpaM - t.predicted.cpaM) / t.predicted.sdCpaM;
      ++n;
      in1 += std::abs(z) <= 1.0;
      in2 += std::abs(z) <= 2.0;
      z2 += z * z;
      if (t.truePresentCpaM && t.predicted.presentTcpaS > 0.0) {
        const double zp =
            (*t.truePresentCpaM - t.predicted.presentCpaM) / std::max(1e-9, t.predicted.sdPresentCpaM);
        zp2 += zp * zp;
        ++np;
      }
    }
  }
  const double dn = static_cast<double>(std::max(1L, n));
  std::printf(
      "%d runs, %ld target CPAs: realised within 1 sd of the prediction %.1f%%, within 2 sd %.1f%%; "
      "mean ((r - p) / sd)^2 %.3f (99%% band for %ld samples [%.3f, %.3f])\n",
      a.runs, n, 100.0 * static_cast<double>(in1) / dn, 100.0 * static_cast<double>(in2) / dn, z2 / dn, n,
      est::chiSquareQuantile(0.005, dn) / dn, est::chiSquareQuantile(0.995, dn) / dn);
  std::printf(
      "without the manoeuvre, the present CPA against the truth's: mean ((t - p) / sd)^2 %.3f over %ld\n",
      zp2 / static_cast<double>(std::max(1L, np)), np);
  return 0;
}

}  // namespace

void addTrialCommand(CLI::App& root, Commands& out) {
  auto a = std::make_shared<TrialArgs>();
  CLI::App* app = root.add_subcommand(
      "trial",
      "trial manoeuvre: predicted CPA, TCPA and P(CPA < limit) per target for a proposed course and speed");
  addScenarioArgument(*app, a->scenario);
  app->add_option("--at", a->atS, "when to try it, seconds into the run (0 to the duration; required)")
      ->type_name("S");
  app->add_option("--course", a->courseDeg, "ordered heading, degrees true (0 to 360; required)")
      ->type_name("DEG");
  app->add_option("--speed", a->speedKn, "ordered speed through the water, knots (0 to 60; required)")
      ->type_name("KN");
  app->add_option("--delay", a->delayS, "seconds before the order is given (0 to 3600, default 0)")
      ->type_name("S");
  app->add_option("--cpa-limit", a->cpaLimitNm, "CPA limit, NM (default the scenario's danger CPA)")
      ->type_name("NM");
  app->add_option("--tcpa-limit", a->tcpaLimitMin, "TCPA limit, minutes (default the scenario's)")
      ->type_name("MIN");
  addSeed(*app, a->seed, "the scenario's");
  app->add_flag("--verify", a->verify, "carry the manoeuvre out in the simulation and print the CPA reached");
  app->add_option("--runs", a->runs,
                  "with --verify: over this many seeds (1 to 10000), the consistency summary")
      ->type_name("N");
  addIgnoredQuiet(*app);
  out.push_back({app, [a] { return trialCommand(*a); }, ""});
}

}  // namespace reckoner::cli
