#include "sim/manoeuvre_trial.h"

#include <algorithm>
#include <cmath>

#include "common/angles.h"
#include "common/rng.h"

namespace reckoner::sim {

ManoeuvreOutcome runManoeuvreTrial(const ManoeuvreTrial& m, const track::InputEstimationConfig& ieConfig,
                                   const track::ImmConfig& immConfig, std::uint64_t seed) {
  track::InputEstimationEkf ie(ieConfig);
  track::ImmTracker imm(immConfig);
  Rng rng(seed, 6);
  const bool manoeuvres = m.turnRad != 0.0 || m.speedChangeMps != 0.0;
  ManoeuvreOutcome out;
  out.straightS = manoeuvres ? m.manoeuvreStartS : m.durationS;
  // Target truth integrated in 0.1 s steps.
  double tx = m.targetRangeM * std::sin(m.targetBearingRad),
         ty = m.targetRangeM * std::cos(m.targetBearingRad);
  double course = m.targetCourseRad, speed = m.targetSpeedMps;
  const double finalCourse = wrapTwoPi(m.targetCourseRad + m.turnRad);
  const double finalSpeed = m.targetSpeedMps + m.speedChangeMps;
  constexpr double kDt = 0.1;
  double t = 0.0;
  bool ieFlag = false, immFlag = false;
  for (int k = 0; k * m.sweepS <= m.durationS + 1e-9; ++k) {
    const double tPlot = k * m.sweepS;
    while (t < tPlot - 1e-9) {
      if (manoeuvres && t >= m.manoeuvreStartS) {
        course = wrapTwoPi(course + std::clamp(angleDiff(finalCourse, course), -m.turnRateRadPerS * kDt,
                                               m.turnRateRadPerS * kDt));
        speed += std::clamp(finalSpeed - speed, -m.accelerationMps2 * kDt, m.accelerationMps2 * kDt);
      }
      tx += speed * kDt * std::sin(course);
      ty += speed * kDt * std::cos(course);
      t += kDt;
    }
    const double ox = m.ownSpeedMps * tPlot * std::sin(m.ownCourseRad);
    const double oy = m.ownSpeedMps * tPlot * std::cos(m.ownCourseRad);
    const double b = wrapTwoPi(bearingOf(tx - ox, ty - oy) + rng.normal(0.0, m.bearingSdRad));
    const double r = std::hypot(tx - ox, ty - oy) + rng.normal(0.0, m.rangeSdM);
    const auto step = ie.measure(fromSeconds(tPlot), b, r, ox, oy);
    imm.update(fromSeconds(tPlot), b, r, ox, oy);
    const bool ieNow = step.manoeuvring, immNow = imm.initialised() && imm.manoeuvring();
    const bool before = !manoeuvres || tPlot < m.manoeuvreStartS;
    if (before) {
      out.ieFalseAlarms += ieNow && !ieFlag ? 1 : 0;
      out.immFalseAlarms += immNow && !immFlag ? 1 : 0;
    } else {
      if (ieNow && !out.ieDelayS) out.ieDelayS = tPlot - m.manoeuvreStartS;
      if (immNow && !out.immDelayS) out.immDelayS = tPlot - m.manoeuvreStartS;
    }
    ieFlag = ieNow;
    immFlag = immNow;
  }
  return out;
}

}  // namespace reckoner::sim
