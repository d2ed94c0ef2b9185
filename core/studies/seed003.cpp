#include "studies/seed003.h"
#include "common/units.h"

#include <algorithm>
#include <cmath>

#include "common/angles.h"
#include "common/rng.h"
#include "sim/vessel_motion.h"

// The studies drive the engine and score its runs: the engine's names unqualified here.
using namespace reckoner::sim;

namespace reckoner::studies {

const char* seed003CaseName(Seed003Case c) {
  switch (c) {
    case Seed003Case::NoNoise:
      return "no noise";
    case Seed003Case::VaryingCourse:
      return "varying course";
    case Seed003Case::VaryingCourseAndSpeed:
      return "varying course and speed";
  }
  return "?";
}

Seed003Result runSeed003(Seed003Case c, const Seed003Setup& s, const track::AbgConfig& filter,
                         std::uint64_t seed) {
  track::AlphaBetaGammaFilter abg(filter);
  Rng rng(seed, 3);
  const bool noisy = c != Seed003Case::NoNoise;
  // Truth: the simulator's vessel model. Every legS seconds a helm order: a course change of 20 to 60
  // deg either way, and in the third case also a new speed between 6 and 18 kn, drawn in advance.
  VesselMotionSpec spec;
  const double course0 = degToRad(200.0);
  spec.initialVelocityMps = {s.speedMps * std::sin(course0), s.speedMps * std::cos(course0)};
  const double durationS = (s.positions - 1) * s.sweepS;
  double orderedCourse = course0, orderedSpeed = s.speedMps;
  for (double t = s.legS; c != Seed003Case::NoNoise && t <= durationS; t += s.legS) {
    const double change = degToRad(20.0 + 40.0 * rng.uniform()) * (rng.uniform() < 0.5 ? -1.0 : 1.0);
    orderedCourse = wrapTwoPi(orderedCourse + change);
    if (c == Seed003Case::VaryingCourseAndSpeed) orderedSpeed = knotsToMps(6.0 + 12.0 * rng.uniform());
    KinematicEvent e;
    e.timeUs = fromSeconds(t);
    e.order = HelmOrder{orderedCourse, orderedSpeed, s.turnRateRadPerS, s.accelerationMps2};
    spec.schedule.push_back(e);
  }
  VesselMotionModel target(spec, est::GaussMarkov{0.0, 1.0}, Rng(seed, kStreamTargetBase));
  double sumObs = 0.0, sumSmooth = 0.0, sumPred = 0.0;
  int nPred = 0;
  for (int n = 1; n <= s.positions; ++n) {
    const double tPlot = (n - 1) * s.sweepS;
    target.advanceTo(fromSeconds(tPlot));
    const double x = target.state().position.xM, y = target.state().position.yM;
    const double ox = x + (noisy ? rng.normal(0.0, s.plotSdM) : 0.0);
    const double oy = y + (noisy ? rng.normal(0.0, s.plotSdM) : 0.0);
    abg.update(fromSeconds(tPlot), ox, oy);
    const auto& e = abg.estimate();
    sumObs += (ox - x) * (ox - x) + (oy - y) * (oy - y);
    sumSmooth += std::pow(e.smoothedPos[0] - x, 2) + std::pow(e.smoothedPos[1] - y, 2);
    if (n >= 3) {
      sumPred += std::pow(e.predictedPos[0] - x, 2) + std::pow(e.predictedPos[1] - y, 2);
      ++nPred;
    }
  }
  Seed003Result r;
  r.observed2drmsM = 2.0 * std::sqrt(sumObs / s.positions);
  r.smoothed2drmsM = 2.0 * std::sqrt(sumSmooth / s.positions);
  r.predicted2drmsM = nPred > 0 ? 2.0 * std::sqrt(sumPred / nPred) : 0.0;
  return r;
}

}  // namespace reckoner::studies
