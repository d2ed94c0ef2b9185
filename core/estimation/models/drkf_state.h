#pragma once
// The dead-reckoning filter state: the 11 states of seed 000 eq. 4a (grid frame, x east, y north, SI
// units) and two sensor-calibration states real sensors need (docs/drkf.md, "Sensor calibration
// states"). Under the paper's profile their Gauss-Markov sigma is 0: they stay exactly zero and no
// measurement sees them, so the filter is the paper's.
#include "estimation/gaussian.h"

namespace reckoner::est::drkf {

inline constexpr int kStateDim = 13;
/// The paper's state dimension (x1..x11).
inline constexpr int kPaperStateDim = 11;

/// State indices (paper x1..x11 are kPosX..kLogBias).
enum Index : int {
  kPosX = 0,          ///< x1  vessel x position, m
  kCurX = 1,          ///< x2  ocean current x velocity, m/s (Gauss-Markov)
  kVelX = 2,          ///< x3  vessel x velocity through the water, m/s
  kAccX = 3,          ///< x4  vessel x acceleration, m/s^2 (Gauss-Markov)
  kPosY = 4,          ///< x5  vessel y position, m
  kCurY = 5,          ///< x6  ocean current y velocity, m/s
  kVelY = 6,          ///< x7  vessel y velocity through the water, m/s
  kAccY = 7,          ///< x8  vessel y acceleration, m/s^2
  kLoranX = 8,        ///< x9  Loran-C x position error, m (Gauss-Markov)
  kLoranY = 9,        ///< x10 Loran-C y position error, m (Gauss-Markov)
  kLogBias = 10,      ///< x11 speedlog error, m/s (Gauss-Markov): the log's offset
  kHeadingBias = 11,  ///< heading sensor's error, rad (Gauss-Markov, slow): gyro error or residual deviation
  kLogScale = 12,     ///< speedlog scale-factor error, dimensionless (Gauss-Markov, slow)
};

/// Under a ship's motion model (ProcessParams::ship, docs/drkf.md "Ship motion") x4 and x8 are not the
/// Cartesian acceleration but the acceleration along the velocity through the water and its turn rate.
inline constexpr int kAlongAccel = kAccX;  ///< m/s^2, along the velocity through the water
inline constexpr int kTurnRate = kAccY;    ///< rad/s, clockwise (the heading's rate)

using State = Vec<kStateDim>;
using Covariance = Mat<kStateDim>;
using Belief = Gaussian<kStateDim>;

/// Velocity over ground (x, y) = current + velocity through water.
inline double groundVx(const State& x) {
  return x[kCurX] + x[kVelX];
}
inline double groundVy(const State& x) {
  return x[kCurY] + x[kVelY];
}

}  // namespace reckoner::est::drkf
