#pragma once
// The 12-state target-tracking filter state of seed 000 eq. 8a: own vessel and one target, each with
// position, velocity over ground and Gauss-Markov acceleration (grid frame, SI units).
#include "estimation/gaussian.h"

namespace reckoner::est::ttkf {

inline constexpr int kStateDim = 12;
inline constexpr int kOwnDim = 4;  ///< the own-ship states the DRKF provides: position and velocity

enum Index : int {
  kOwnX = 0,    ///< x1  own position x, m
  kOwnY = 1,    ///< x2  own position y, m
  kOwnVx = 2,   ///< x3  own velocity over ground x, m/s
  kOwnVy = 3,   ///< x4  own velocity over ground y, m/s
  kOwnAx = 4,   ///< x5  own acceleration x, m/s^2
  kOwnAy = 5,   ///< x6  own acceleration y, m/s^2
  kTgtX = 6,    ///< x7  target position x, m
  kTgtY = 7,    ///< x8  target position y, m
  kTgtVx = 8,   ///< x9  target velocity over ground x, m/s
  kTgtVy = 9,   ///< x10 target velocity over ground y, m/s
  kTgtAx = 10,  ///< x11 target acceleration x, m/s^2
  kTgtAy = 11,  ///< x12 target acceleration y, m/s^2
};

using State = Vec<kStateDim>;
using Covariance = Mat<kStateDim>;
using Belief = Gaussian<kStateDim>;

}  // namespace reckoner::est::ttkf
