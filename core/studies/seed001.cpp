#include "studies/seed001.h"

#include <algorithm>
#include <cmath>

#include "common/angles.h"
#include "common/rng.h"

namespace reckoner::studies {
namespace {

struct Kinematics {
  double x, y, course, speed;
};

/// Target at time t (s): straight, or turning at a constant rate from the turn's start to its new course.
Kinematics targetAt(const Seed001Scenario& s, double t) {
  const double x0 = s.initialRangeM * std::sin(s.initialBearingRad);
  const double y0 = s.initialRangeM * std::cos(s.initialBearingRad);
  const double v = s.targetSpeedMps;
  const auto straight = [v](double x, double y, double c, double dt) {
    return Kinematics{x + v * dt * std::sin(c), y + v * dt * std::cos(c), c, v};
  };
  if (!s.turn || t <= s.turn->startS) return straight(x0, y0, s.targetCourseRad, t);
  const Kinematics k0 = straight(x0, y0, s.targetCourseRad, s.turn->startS);
  const double delta = angleDiff(s.turn->newCourseRad, s.targetCourseRad);
  const double w = std::copysign(s.turn->rateRadPerS, delta);
  const double turnS = std::abs(delta) / s.turn->rateRadPerS;
  const double tt = std::min(t - s.turn->startS, turnS);
  // Arc: d/dt (x, y) = v (sin c, cos c) with c = c0 + w t.
  const double c1 = s.targetCourseRad + w * tt;
  const Kinematics k1{k0.x + v / w * (std::cos(s.targetCourseRad) - std::cos(c1)),
                      k0.y + v / w * (std::sin(c1) - std::sin(s.targetCourseRad)), c1, v};
  if (t - s.turn->startS <= turnS) return k1;
  return straight(k1.x, k1.y, s.turn->newCourseRad, t - s.turn->startS - turnS);
}

Kinematics observerAt(const Seed001Scenario& s, double t) {
  return {s.observerSpeedMps * t * std::sin(s.observerCourseRad),
          s.observerSpeedMps * t * std::cos(s.observerCourseRad), s.observerCourseRad, s.observerSpeedMps};
}

}  // namespace

double pingIntervalS(double rangeM) {
  if (rangeM < 5000.0) return 10.0;
  if (rangeM < 10000.0) return 20.0;
  if (rangeM < 20000.0) return 40.0;
  return 80.0;
}

std::vector<Seed001Ping> seed001Pings(const Seed001Scenario& s, double bearingSdRad, double rangeSdM,
                                      std::uint64_t seed) {
  Rng rng(seed, 1);
  std::vector<Seed001Ping> out;
  double ping = 0.0;
  for (int index = 1;; ++index) {
    // The reflection time: ping time plus the one-way travel time (fixed point, converges in a few steps).
    double tr = ping;
    for (int it = 0; it < 5; ++it) {
      const Kinematics o = observerAt(s, tr), g = targetAt(s, tr);
      tr = ping + std::hypot(g.x - o.x, g.y - o.y) / s.soundSpeedMps;
    }
    if (tr > s.durationS) break;
    const Kinematics o = observerAt(s, tr), g = targetAt(s, tr);
    Seed001Ping p;
    p.index = index;
    p.tS = tr;
    p.trueRangeM = std::hypot(g.x - o.x, g.y - o.y);
    p.trueXM = g.x;
    p.trueYM = g.y;
    p.trueCourseRad = g.course;
    p.trueSpeedMps = g.speed;
    p.bearingRad = wrapTwoPi(bearingOf(g.x - o.x, g.y - o.y) + rng.normal(0.0, bearingSdRad));
    p.rangeM = p.trueRangeM + rng.normal(0.0, rangeSdM);
    // The filter stamps the echo with the measured range (as the paper recalculates its times).
    p.stampS = ping + p.rangeM / s.soundSpeedMps;
    const Kinematics os = observerAt(s, p.stampS);
    p.observerXM = os.x;
    p.observerYM = os.y;
    out.push_back(p);
    ping += pingIntervalS(p.rangeM);
  }
  return out;
}

std::vector<Seed001Sample> runSeed001(const Seed001Scenario& s, const track::InputEstimationConfig& filter,
                                      std::uint64_t seed) {
  track::InputEstimationEkf ekf(filter);
  std::vector<Seed001Sample> out;
  for (const Seed001Ping& p : seed001Pings(s, filter.bearingSdRad, filter.rangeSdM, seed)) {
    const track::InputEstimationStep step =
        ekf.measure(fromSeconds(p.stampS), p.bearingRad, p.rangeM, p.observerXM, p.observerYM);
    if (!ekf.initialised() || p.index < 2) continue;
    const auto& x = ekf.belief().x;
    namespace rp = est::relpolar;
    Seed001Sample r;
    r.index = p.index;
    r.tS = p.tS;
    r.trueRangeM = p.trueRangeM;
    r.rangeErrorPct = 100.0 * std::abs(std::hypot(x[rp::kRx], x[rp::kRy]) - p.trueRangeM) / p.trueRangeM;
    r.courseErrorDeg = std::abs(radToDeg(angleDiff(bearingOf(x[rp::kVx], x[rp::kVy]), p.trueCourseRad)));
    r.speedErrorMps = std::abs(std::hypot(x[rp::kVx], x[rp::kVy]) - p.trueSpeedMps);
    r.tested = step.tested;
    r.d = step.d;
    r.detected = step.detected;
    r.manoeuvring = step.manoeuvring;
    out.push_back(r);
  }
  return out;
}

std::vector<Seed001SampleStats> summariseSeed001(const std::vector<std::vector<Seed001Sample>>& runs) {
  std::vector<Seed001SampleStats> out;
  for (const auto& run : runs) {
    for (const Seed001Sample& r : run) {
      if (static_cast<int>(out.size()) < r.index - 1) out.resize(static_cast<std::size_t>(r.index - 1));
      Seed001SampleStats& s = out[static_cast<std::size_t>(r.index - 2)];
      s.index = r.index;
      ++s.runs;
      s.meanTS += r.tS;
      s.meanRangeErrorPct += r.rangeErrorPct;
      s.rmsRangeErrorPct += r.rangeErrorPct * r.rangeErrorPct;
      s.meanCourseErrorDeg += r.courseErrorDeg;
      s.rmsCourseErrorDeg += r.courseErrorDeg * r.courseErrorDeg;
      s.meanSpeedErrorMps += r.speedErrorMps;
      s.rmsSpeedErrorMps += r.speedErrorMps * r.speedErrorMps;
      s.withinLimits +=
          (r.rangeErrorPct < 8.0 && r.courseErrorDeg < 3.0 && r.speedErrorMps < 3.0) ? 1.0 : 0.0;
      if (r.tested) {
        ++s.tested;
        s.meanD += r.d;
        s.maxD = std::max(s.maxD, r.d);
      }
      s.detections += r.detected ? 1 : 0;
    }
  }
  for (auto& s : out) {
    if (s.runs == 0) continue;
    const double n = s.runs;
    s.meanTS /= n;
    s.meanRangeErrorPct /= n;
    s.rmsRangeErrorPct = std::sqrt(s.rmsRangeErrorPct / n);
    s.meanCourseErrorDeg /= n;
    s.rmsCourseErrorDeg = std::sqrt(s.rmsCourseErrorDeg / n);
    s.meanSpeedErrorMps /= n;
    s.rmsSpeedErrorMps = std::sqrt(s.rmsSpeedErrorMps / n);
    s.withinLimits /= n;
    if (s.tested > 0) s.meanD /= s.tested;
  }
  return out;
}

std::vector<int> firstDetections(const std::vector<std::vector<Seed001Sample>>& runs, double fromS) {
  std::vector<int> out;
  for (const auto& run : runs) {
    int first = 0;
    for (const Seed001Sample& r : run)
      if (r.detected && r.tS >= fromS) {
        first = r.index;
        break;
      }
    out.push_back(first);
  }
  return out;
}

}  // namespace reckoner::studies
