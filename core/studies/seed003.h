#pragma once
// Seed 003's evaluation: 1000 radar plots of a target every sweep through the alpha-beta-gamma filter,
// and the 2drms (twice the RMS of the radial error) of the observed, smoothed and predicted positions
// against the truth, for the paper's three cases: no noise, varying course, varying course and speed.
// The paper gives no numbers for the target, the sweep or the noise; ours are in docs/manoeuvres.md.
#include <cstdint>

#include "common/angles.h"
#include "common/units.h"
#include "tracking/alpha_beta_gamma.h"

namespace reckoner::studies {

enum class Seed003Case { NoNoise, VaryingCourse, VaryingCourseAndSpeed };
const char* seed003CaseName(Seed003Case c);

struct Seed003Setup {
  int positions = 1000;
  double sweepS = 3.0;
  double plotSdM = 20.0;  ///< plot noise per Cartesian axis (the noisy cases)
  double speedMps = knotsToMps(12.0);
  double legS = 150.0;                     ///< a course (and speed) change every legS seconds
  double turnRateRadPerS = degToRad(1.0);  ///< 1 deg/s
  double accelerationMps2 = 0.05;
};

struct Seed003Result {
  double observed2drmsM = 0.0, smoothed2drmsM = 0.0, predicted2drmsM = 0.0;
};

/// One run of a case; the predicted error counts from the third plot (the first that is predicted by
/// the filter itself).
Seed003Result runSeed003(Seed003Case c, const Seed003Setup& setup, const track::AbgConfig& filter,
                         std::uint64_t seed);

}  // namespace reckoner::studies
