#pragma once
// A radar fix (seed 004's matching, docs/radar_matching.md): own ship's position and heading as the
// radar picture matched to the chart gives them, with their joint 3 x 3 covariance:
//   z = (x1, x5, atan2(x3, x7)) + v
// The heading is the gyro's quantity, the direction of the velocity through the water
// (drkf_gyro.h); below minSpeedMps it is undefined and the fix is used for position only.
#include <cmath>

#include "common/angles.h"
#include "estimation/models/drkf_state.h"

namespace reckoner::est::drkf {

class RadarFixModel {
 public:
  static constexpr int kDim = 3;

  [[nodiscard]] Vec<3> h(const State& x) const {
    return Vec<3>(x[kPosX], x[kPosY], bearingOf(x[kVelX], x[kVelY]));
  }
  [[nodiscard]] MatRC<3, kStateDim> jacobian(const State& x) const {
    const double vx = x[kVelX], vy = x[kVelY], r2 = vx * vx + vy * vy;
    MatRC<3, kStateDim> H = MatRC<3, kStateDim>::Zero();
    H(0, kPosX) = 1.0;
    H(1, kPosY) = 1.0;
    H(2, kVelX) = vy / r2;
    H(2, kVelY) = -vx / r2;
    return H;
  }
  [[nodiscard]] Vec<3> residual(const Vec<3>& z, const Vec<3>& zhat) const {
    return Vec<3>(z[0] - zhat[0], z[1] - zhat[1], angleDiff(z[2], zhat[2]));
  }
};

/// The position part alone (slow ship).
class RadarPositionModel {
 public:
  static constexpr int kDim = 2;
  [[nodiscard]] Vec<2> h(const State& x) const { return Vec<2>(x[kPosX], x[kPosY]); }
  [[nodiscard]] MatRC<2, kStateDim> jacobian(const State&) const {
    MatRC<2, kStateDim> H = MatRC<2, kStateDim>::Zero();
    H(0, kPosX) = 1.0;
    H(1, kPosY) = 1.0;
    return H;
  }
  [[nodiscard]] Vec<2> residual(const Vec<2>& z, const Vec<2>& zhat) const { return z - zhat; }
};

}  // namespace reckoner::est::drkf
