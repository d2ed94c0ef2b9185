#include "studies/imo_accuracy.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "common/angles.h"
#include "common/percentile.h"
#include "common/units.h"
#include "sim/scenario_run.h"
#include "sim/simulation_engine.h"
#include "studies/imo_errors.h"

// The studies drive the engine and score its runs: the engine's names unqualified here.
using namespace reckoner::sim;

namespace reckoner::studies {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
using Errors = ImoErrors;
using Truth = ImoTruth;

/// No sample: no bound (infinite error).
double percentile95(std::vector<double> v) {
  return reckoner::percentile95(std::move(v), kInf);
}

struct RunSample {
  std::optional<Errors> at1, at3;
  Truth truth3{};
};
}  // namespace

ImoTruth imoTruthOf(const sim::VesselTruth& o, const sim::VesselTruth& t, double convergence) {
  const double rx = t.position.xM - o.position.xM, ry = t.position.yM - o.position.yM;
  const double vx = t.groundVxMps() - o.groundVxMps(), vy = t.groundVyMps() - o.groundVyMps();
  Truth r{};
  r.relCourseDeg = radToDeg(wrapTwoPi(bearingOf(vx, vy) + convergence));
  r.relSpeedKn = mpsToKnots(std::hypot(vx, vy));
  const double vv = vx * vx + vy * vy;
  const double tcpa = vv > 0.0 ? -(rx * vx + ry * vy) / vv : 0.0;
  r.cpaNm = metresToNm(std::hypot(rx + vx * tcpa, ry + vy * tcpa));
  r.tcpaMin = tcpa / 60.0;
  r.courseDeg = radToDeg(wrapTwoPi(bearingOf(t.groundVxMps(), t.groundVyMps()) + convergence));
  r.speedKn = mpsToKnots(std::hypot(t.groundVxMps(), t.groundVyMps()));
  return r;
}

ImoErrors imoErrorsOf(const track::TrackKinematics& k, const ImoTruth& t) {
  Errors e{};
  e[0] = std::abs(radToDeg(angleDiff(k.relativeCourseRad, degToRad(t.relCourseDeg))));
  e[1] = std::abs(mpsToKnots(k.relativeSpeedMps) - t.relSpeedKn);
  e[2] = std::abs(metresToNm(k.cpa.cpaM) - t.cpaNm);
  e[3] = k.cpa.defined ? std::abs(k.cpa.tcpaS / 60.0 - t.tcpaMin) : kInf;
  e[4] = std::abs(radToDeg(angleDiff(k.trueCourseRad, degToRad(t.courseDeg))));
  e[5] = std::abs(mpsToKnots(k.speedMps) - t.speedKn);
  return e;
}

const char* imoQuantityName(ImoQuantity q) {
  switch (q) {
    case ImoQuantity::RelativeCourse:
      return "relative course";
    case ImoQuantity::RelativeSpeed:
      return "relative speed";
    case ImoQuantity::Cpa:
      return "CPA";
    case ImoQuantity::Tcpa:
      return "TCPA";
    case ImoQuantity::TrueCourse:
      return "true course";
    case ImoQuantity::TrueSpeed:
      return "true speed";
  }
  return "?";
}

const char* imoQuantityUnit(ImoQuantity q) {
  switch (q) {
    case ImoQuantity::RelativeCourse:
    case ImoQuantity::TrueCourse:
      return "deg";
    case ImoQuantity::RelativeSpeed:
    case ImoQuantity::TrueSpeed:
      return "kn";
    case ImoQuantity::Cpa:
      return "NM";
    case ImoQuantity::Tcpa:
      return "min";
  }
  return "?";
}

ImoResult evaluateImo(const sim::Scenario& scenario, int runs, int threads, std::uint64_t seed) {
  if (scenario.targets.empty() || !scenario.radar.fitted)
    throw std::invalid_argument("IMO accuracy test: scenario '" + scenario.name +
                                "' needs a radar and a target");
  if (runs <= 0 || threads <= 0)
    throw std::invalid_argument("IMO accuracy test: runs and threads must be positive");
  const int targetId = scenario.targets.front().id;
  std::vector<RunSample> samples(static_cast<std::size_t>(runs));
  parallelRuns(runs, threads, [&](int i) {
    sim::SimulationEngine engine(scenario, seed + static_cast<std::uint64_t>(i));
    RunSample& out = samples[static_cast<std::size_t>(i)];
    int trackId = -1;
    TimeUs acquiredUs = -1;
    while (!engine.finished() && !out.at3) {
      const sim::SimFrame f = engine.step();
      for (const auto& sw : f.sweeps) {
        const sim::TrackSnapshot* tr = nullptr;
        for (const auto& t : sw.tracks)
          if ((trackId < 0 && t.targetId == targetId) || t.trackId == trackId) tr = &t;
        if (!tr || tr->status == track::TrackStatus::Lost) continue;
        if (trackId < 0) {
          trackId = tr->trackId;
          acquiredUs = tr->initiatedUs;
        }
        const double gamma = engine.frame().gridInfo(sw.ownTruth.position).convergenceRad;
        const Truth truth = imoTruthOf(sw.ownTruth, sw.targets[0], gamma);
        if (!out.at1 && sw.timeUs >= acquiredUs + 60 * kMicrosPerSecond)
          out.at1 = imoErrorsOf(tr->kinematics, truth);
        if (!out.at3 && sw.timeUs >= acquiredUs + 180 * kMicrosPerSecond) {
          out.at3 = imoErrorsOf(tr->kinematics, truth);
          out.truth3 = truth;
        }
      }
    }
  });

  ImoResult r;
  r.scenario = scenario.name;
  r.runs = runs;
  double relSpeed = 0.0, speed = 0.0;
  for (const auto& s : samples) {
    if (!s.at3) continue;
    ++r.tracked;
    relSpeed += s.truth3.relSpeedKn;
    speed += s.truth3.speedKn;
  }
  if (r.tracked > 0) {
    r.trueRelativeSpeedKn = relSpeed / r.tracked;
    r.trueSpeedKn = speed / r.tracked;
  }
  // MSC.192(79) limits (95% probability): 3 min steady state and 1 min trend.
  const std::array<double, kImoQuantityCount> limit3{
      3.0, std::max(0.8, 0.01 * r.trueRelativeSpeedKn), 0.3, 0.5, 5.0, std::max(0.5, 0.01 * r.trueSpeedKn)};
  const std::array<double, kImoQuantityCount> limit1{
      11.0, std::max(1.5, 0.10 * r.trueRelativeSpeedKn), 1.0, kInf, kInf, kInf};
  r.pass = true;
  for (int q = 0; q < kImoQuantityCount; ++q) {
    std::vector<double> e1, e3;
    for (const auto& s : samples) {
      e1.push_back(s.at1 ? (*s.at1)[static_cast<std::size_t>(q)] : kInf);
      e3.push_back(s.at3 ? (*s.at3)[static_cast<std::size_t>(q)] : kInf);
    }
    ImoRow row{static_cast<ImoQuantity>(q), {}, {}};
    const auto qi = static_cast<std::size_t>(q);
    row.at1Min = {std::isfinite(limit1[qi]), percentile95(e1), limit1[qi], false};
    row.at3Min = {true, percentile95(e3), limit3[qi], false};
    row.at1Min.pass = !row.at1Min.required || row.at1Min.p95 <= row.at1Min.limit;
    row.at3Min.pass = row.at3Min.p95 <= row.at3Min.limit;
    r.pass = r.pass && row.at1Min.pass && row.at3Min.pass;
    r.rows.push_back(row);
  }
  return r;
}

}  // namespace reckoner::studies
