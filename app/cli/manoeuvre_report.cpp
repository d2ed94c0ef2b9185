// manoeuvre-report: four trackers (EKF, EKF + input estimation, alpha-beta-gamma, IMM) on the same
// plots (docs/manoeuvres.md): radar-rate turns and speed changes (detection delay, false alarms, RMSE
// against the PCRB, p95 course and speed errors), seed 001's sonar scenario, and the IMO A.823
// scenarios through the ARPA tracks with each filter. One --turn or --speed-change: that case alone.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "cli/cli_options.h"
#include "cli/commands.h"
#include "common/angles.h"
#include "common/percentile.h"
#include "common/units.h"
#include "studies/imo_accuracy.h"
#include "studies/manoeuvre_trial.h"
#include "tracking/track_filter.h"

namespace reckoner::cli {
namespace {

struct ManoeuvreArgs {
  int runs = 100;
  std::uint64_t seed = 1;
  std::optional<double> turnDeg, speedChangeKn;
  int imoRuns = 100;
  bool oneCase() const { return turnDeg || speedChangeKn; }
};

using Series = std::vector<std::vector<double>>;  // per run, per sweep

/// Root mean square of the finite values of v at the indices where keep(t) holds.
template <class Keep>
double rmsWhere(const Series& runs, const std::vector<double>& tS, Keep keep) {
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

/// 95th percentile (nearest rank) over the runs of the finite values at the sweep nearest to time t.
double p95At(const Series& runs, const std::vector<double>& tS, double t) {
  std::size_t k = 0;
  while (k + 1 < tS.size() && tS[k] < t) ++k;
  std::vector<double> x;
  for (const auto& v : runs)
    if (k < v.size() && std::isfinite(v[k])) x.push_back(v[k]);
  return percentile95(std::move(x));
}

std::vector<studies::ManoeuvreTrial> trialCases(const ManoeuvreArgs& a) {
  std::vector<studies::ManoeuvreTrial> cases;
  if (a.oneCase()) {
    studies::ManoeuvreTrial c;
    if (a.turnDeg) c.turnRad = degToRad(*a.turnDeg);
    if (a.speedChangeKn) c.speedChangeMps = knotsToMps(*a.speedChangeKn);
    return {c};
  }
  for (const double turn : {10.0, 30.0, 90.0}) {
    studies::ManoeuvreTrial c;
    c.turnRad = degToRad(turn);
    cases.push_back(c);
  }
  for (const double dv : {5.0, -5.0}) {
    studies::ManoeuvreTrial c;
    c.speedChangeMps = knotsToMps(dv);
    cases.push_back(c);
  }
  studies::ManoeuvreTrial straight;
  straight.durationS = 3600.0;
  cases.push_back(straight);
  return cases;
}

// ---- radar-rate cases ----------------------------------------------------------------------------
struct TrialStats {
  std::array<Series, studies::kTrackerKinds> pos, crs, spd;
  std::array<int, studies::kTrackerKinds> within{}, falseAlarms{};
  std::array<double, studies::kTrackerKinds> delaySum{};
  Series bound;
  std::vector<double> tS;
  double straightS = 0.0;
};

TrialStats runTrial(const studies::ManoeuvreTrial& c, int runs, std::uint64_t seed) {
  const studies::TrackerConfigs cfg = studies::radarRateTrackers(c);
  TrialStats t;
  for (int r = 0; r < runs; ++r) {
    const auto run = studies::runManoeuvreTrial(c, cfg, seed + static_cast<std::uint64_t>(r));
    t.tS = run.tS;
    t.bound.push_back(run.pcrbPosM);
    t.straightS += run.straightS;
    for (int k = 0; k < studies::kTrackerKinds; ++k) {
      const auto& s = run.trackers[static_cast<std::size_t>(k)];
      t.pos[k].push_back(s.posErrM);
      t.crs[k].push_back(s.courseErrRad);
      t.spd[k].push_back(s.speedErrMps);
      t.falseAlarms[k] += s.falseAlarms;
      if (s.delayS && *s.delayS <= 60.0) {
        ++t.within[k];
        t.delaySum[k] += *s.delayS;
      }
    }
  }
  return t;
}

void printTrialHeading(const studies::ManoeuvreTrial& c, const TrialStats& t) {
  if (c.manoeuvres())
    std::printf("\n%s %+.0f%s (ends at %.0f s)\n", c.turnRad != 0.0 ? "turn" : "speed change",
                c.turnRad != 0.0 ? radToDeg(c.turnRad) : mpsToKnots(c.speedChangeMps),
                c.turnRad != 0.0 ? " deg" : " kn", c.manoeuvreEndS());
  else
    std::printf("\nstraight (%.0f h in all)\n", t.straightS / 3600.0);
  std::printf("  %-24s %8s %8s %8s %9s %9s %9s %8s %8s %9s %9s %9s %9s\n", "tracker", "flag<=60", "delay",
              "FA/h", "RMSE bef", "RMSE dur", "RMSE aft", "/PCRB b", "/PCRB a", "crs95 1m", "spd95 1m",
              "crs95 3m", "spd95 3m");
}

void printTrial(const studies::ManoeuvreTrial& c, const TrialStats& t, int runs) {
  printTrialHeading(c, t);
  const double start = c.manoeuvreStartS, end = c.manoeuvreEndS();
  const auto before = [&](double s) { return s >= 60.0 && (!c.manoeuvres() || s < start); };
  const auto during = [&](double s) { return c.manoeuvres() && s >= start && s <= end; };
  const auto after = [&](double s) { return c.manoeuvres() && s > end && s <= end + 120.0; };
  const double pcrbBefore = rmsWhere(t.bound, t.tS, before), pcrbAfter = rmsWhere(t.bound, t.tS, after);
  for (int k = 0; k < studies::kTrackerKinds; ++k) {
    const bool flags = k == studies::kEkfIe || k == studies::kImm;
    char flag[16] = "-", delay[16] = "-";
    if (flags && c.manoeuvres()) {
      std::snprintf(flag, sizeof flag, "%.0f%%", 100.0 * t.within[k] / runs);
      if (t.within[k]) std::snprintf(delay, sizeof delay, "%.1f s", t.delaySum[k] / t.within[k]);
    }
    char fa[16] = "-";
    if (flags) std::snprintf(fa, sizeof fa, "%.2f", t.falseAlarms[k] / (t.straightS / 3600.0));
    const double rb = rmsWhere(t.pos[k], t.tS, before), rd = rmsWhere(t.pos[k], t.tS, during),
                 ra = rmsWhere(t.pos[k], t.tS, after);
    std::printf("  %-24s %8s %8s %8s %7.1f m %7.1f m %7.1f m %8.2f %8.2f %7.2f d %6.2f kn %7.2f d %6.2f kn\n",
                studies::trackerName(static_cast<studies::TrackerKind>(k)), flag, delay, fa, rb, rd, ra,
                rb / pcrbBefore, ra / pcrbAfter, radToDeg(p95At(t.crs[k], t.tS, end + 60.0)),
                mpsToKnots(p95At(t.spd[k], t.tS, end + 60.0)), radToDeg(p95At(t.crs[k], t.tS, end + 180.0)),
                mpsToKnots(p95At(t.spd[k], t.tS, end + 180.0)));
  }
}

// ---- seed 001's sonar scenario -------------------------------------------------------------------
struct SonarStats {
  double range = 0, crs = 0, spd = 0, inside = 0, se = 0, bound2 = 0, seTurn = 0, bound2Turn = 0;
  long n = 0, flags = 0, byNinth = 0, nTurn = 0;
  std::map<int, std::pair<double, double>> at;  // sample -> sums of course and speed errors
  std::map<int, int> atN;
};

void addStraight(SonarStats& q, const std::vector<studies::Seed001TrackerSample>& samples) {
  bool was = false;
  for (const auto& x : samples) {
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
}

void addTurning(SonarStats& q, const std::vector<studies::Seed001TrackerSample>& samples) {
  bool flagged = false;
  for (const auto& x : samples) {
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

std::array<SonarStats, studies::kTrackerKinds> runSonar(const studies::TrackerConfigs& cfg, int runs,
                                                        std::uint64_t seed) {
  studies::Seed001Scenario straight;
  studies::Seed001Scenario turning;
  turning.turn = studies::Seed001Scenario::Turn{};
  std::array<SonarStats, studies::kTrackerKinds> acc;
  for (int r = 0; r < runs; ++r) {
    const auto s0 = studies::runSeed001Trackers(straight, cfg, seed + static_cast<std::uint64_t>(r)).trackers;
    const auto s1 = studies::runSeed001Trackers(turning, cfg, seed + static_cast<std::uint64_t>(r)).trackers;
    for (std::size_t k = 0; k < acc.size(); ++k) {
      addStraight(acc[k], s0[k]);
      addTurning(acc[k], s1[k]);
    }
  }
  return acc;
}

void printSonarRow(int k, const SonarStats& q, int runs) {
  const double n = static_cast<double>(std::max(1L, q.n));
  const bool flags = k == studies::kEkfIe || k == studies::kImm;
  char by9[16], cell[3][24];
  std::snprintf(by9, sizeof by9, "%s", flags ? (std::to_string(100 * q.byNinth / runs) + "%").c_str() : "-");
  int c = 0;
  for (const int at : {10, 13, 20}) {
    const auto it = q.at.find(at);
    const int m = q.atN.count(at) ? q.atN.at(at) : 0;
    if (it == q.at.end() || m == 0)
      std::snprintf(cell[c++], sizeof cell[0], "-");
    else
      std::snprintf(cell[c++], sizeof cell[0], "%.1f / %.2f", it->second.first / m, it->second.second / m);
  }
  const double nt = static_cast<double>(std::max(1L, q.nTurn));
  std::printf("  %-24s %7.2f %7.2f %7.2f %5.0f%% %7.1f %7.2f %5s | %6s %14s %14s %14s %7.1f %7.2f\n",
              studies::trackerName(static_cast<studies::TrackerKind>(k)), q.range / n, q.crs / n, q.spd / n,
              100.0 * q.inside / n, std::sqrt(q.se / n), std::sqrt(q.se / q.bound2),
              flags ? std::to_string(static_cast<double>(q.flags) / runs).substr(0, 4).c_str() : "-", by9,
              cell[0], cell[1], cell[2], std::sqrt(q.seTurn / nt), std::sqrt(q.seTurn / q.bound2Turn));
}

void printSonar(int runs, std::uint64_t seed) {
  const studies::TrackerConfigs cfg = studies::sonarTrackers();
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
  const auto acc = runSonar(cfg, runs, seed);
  for (int k = 0; k < studies::kTrackerKinds; ++k) printSonarRow(k, acc[static_cast<std::size_t>(k)], runs);
}

// ---- the IMO A.823 scenarios through the ARPA tracks with each of the four filters ----------------
void printImoFilters(int imoRuns) {
  std::printf(
      "\nIMO A.823 scenarios through the ARPA tracks, %d runs per filter: 95th-percentile errors at 1 / 3 "
      "min "
      "(* over the MSC.192(79) limit)\n",
      imoRuns);
  for (const char* name : {"imo-1", "imo-2", "imo-3", "imo-4"}) {
    sim::Scenario sc = loadScenario(std::string("builtin:") + name);
    for (int k = 0; k < track::kTrackerKindCount; ++k) {
      sc.tracker.kind = static_cast<track::TrackerKind>(k);
      const auto r = studies::evaluateImo(sc, imoRuns, hardwareThreads(), sc.seed);
      std::printf("  %s %-7s", name, track::trackerKindName(sc.tracker.kind));
      for (const auto& row : r.rows) {
        std::printf("  %s ", studies::imoQuantityName(row.quantity));
        if (row.at1Min.required) std::printf("%.2f%s/", row.at1Min.p95, row.at1Min.pass ? "" : "*");
        std::printf("%.2f%s", row.at3Min.p95, !row.at3Min.required || row.at3Min.pass ? "" : "*");
      }
      std::printf("  %s\n", r.pass ? "pass" : "FAIL");
    }
  }
}

int manoeuvreReport(const ManoeuvreArgs& a) {
  const studies::ManoeuvreTrial base;
  std::printf(
      "manoeuvre report: %d runs per case; radar every %.1f s, range sd %.0f m, bearing sd %.2f deg; target "
      "at 3 NM, 12 kn; manoeuvres from %.0f s (turns at 1 deg/s, speed at 0.1 m/s^2)\n",
      a.runs, base.sweepS, base.rangeSdM, radToDeg(base.bearingSdRad), base.manoeuvreStartS);
  std::printf(
      "  flag: first rise within 60 s of the start (STCW: 10 deg or 5 kn noticed within a minute); RMSE of "
      "position before (60 s to start), during, and 2 min after; /PCRB: RMSE over the bound's sd along the "
      "truth; p95 course and speed errors 1 and 3 min after the end (IMO MSC.192(79) times)\n");
  for (const auto& c : trialCases(a)) printTrial(c, runTrial(c, a.runs, a.seed), a.runs);
  if (a.oneCase()) return 0;
  printSonar(a.runs, a.seed);
  if (a.imoRuns > 0) printImoFilters(a.imoRuns);
  return 0;
}

}  // namespace

void addManoeuvreCommand(CLI::App& root, Commands& out) {
  auto a = std::make_shared<ManoeuvreArgs>();
  CLI::App* app =
      root.add_subcommand("manoeuvre-report",
                          "four trackers at radar and sonar rates: detection delay, false alarms, RMSE "
                          "against the PCRB, p95 errors; the IMO scenarios per filter");
  addInteger(*app, "runs", a->runs, 1, 100000, "N", "Monte Carlo runs per case");
  addReal(*app, "turn", a->turnDeg, -180.0, 180.0, "DEG",
          "only this case: the target turns by this much, degrees clockwise");
  addReal(*app, "speed-change", a->speedChangeKn, -30.0, 30.0, "KN",
          "only this case: the target changes speed by this much, knots");
  addInteger(*app, "seed", a->seed, 0, UINT64_MAX, "N", "first run's random seed");
  addInteger(*app, "imo-runs", a->imoRuns, 0, 100000, "N",
             "runs per filter of the IMO scenarios, 0: none (not with --turn or --speed-change)");
  addIgnoredQuiet(*app);
  out.push_back({app, [a] { return manoeuvreReport(*a); }, ""});
}

}  // namespace reckoner::cli
