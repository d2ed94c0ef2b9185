#pragma once
// A radar fix (seed 004's matching, docs/radar_matching.md): own ship's position and heading at the
// sweep's end as the radar picture matched to the chart gives them, with their joint 3 x 3 covariance.
// The picture was placed along the sweep with the filter's own velocity over ground and turn rate,
// r^ = (vgx, vgy, omega) at the linearisation point; the matcher reports how its answer moves with an
// error in them (S, MatchResult::motionSensitivity). So
//   z = (x1, x5, atan2(x3, x7)) + S (r(x) - r^) + v,
//   r(x) = (x2 + x3, x6 + x7, omega(x)),  omega = (x7 x4 - x3 x8) / (x3^2 + x7^2)
// (omega: the rate at which the acceleration turns the velocity through the water). With S = 0 it is
// a plain position-and-heading fix. The heading is the gyro's quantity, the direction of the velocity
// through the water (drkf_gyro.h); below minSpeedMps it is undefined and the fix is used for position
// only.
#include <cmath>

#include "common/angles.h"
#include "estimation/models/drkf_state.h"

namespace reckoner::est::drkf {

/// Velocity over ground and the turn rate of the velocity through the water; with a ship's motion
/// model (turnRateState) the turn rate is the state x8 itself.
inline Vec<3> sweepMotionOf(const State& x, bool turnRateState = false) {
  if (turnRateState) return {groundVx(x), groundVy(x), x[kTurnRate]};
  const double vx = x[kVelX], vy = x[kVelY], v2 = vx * vx + vy * vy;
  return {groundVx(x), groundVy(x), v2 > 0.0 ? (vy * x[kAccX] - vx * x[kAccY]) / v2 : 0.0};
}

class RadarFixModel {
 public:
  static constexpr int kDim = 3;

  RadarFixModel() = default;
  RadarFixModel(const Mat<3>& sensitivity, const Vec<3>& assumedMotion, bool turnRateState = false)
      : S_(sensitivity), assumed_(assumedMotion), turnRateState_(turnRateState) {}

  [[nodiscard]] Vec<3> h(const State& x) const {
    const Vec<3> base(x[kPosX], x[kPosY], bearingOf(x[kVelX], x[kVelY]));
    Vec<3> z = base + S_ * (sweepMotionOf(x, turnRateState_) - assumed_);
    z[2] = wrapTwoPi(z[2]);
    return z;
  }
  [[nodiscard]] MatRC<3, kStateDim> jacobian(const State& x) const {
    const double vx = x[kVelX], vy = x[kVelY], r2 = vx * vx + vy * vy;
    MatRC<3, kStateDim> H = MatRC<3, kStateDim>::Zero();
    H(0, kPosX) = 1.0;
    H(1, kPosY) = 1.0;
    H(2, kVelX) = vy / r2;
    H(2, kVelY) = -vx / r2;
    // d r / d x: ground velocity, and omega = (vy ax - vx ay) / r2.
    const double w = (vy * x[kAccX] - vx * x[kAccY]) / r2;
    MatRC<3, kStateDim> R = MatRC<3, kStateDim>::Zero();
    R(0, kCurX) = R(0, kVelX) = 1.0;
    R(1, kCurY) = R(1, kVelY) = 1.0;
    if (turnRateState_) {
      R(2, kTurnRate) = 1.0;
    } else {
      R(2, kAccX) = vy / r2;
      R(2, kAccY) = -vx / r2;
      R(2, kVelX) = (-x[kAccY] - 2.0 * vx * w) / r2;
      R(2, kVelY) = (x[kAccX] - 2.0 * vy * w) / r2;
    }
    H += S_ * R;
    return H;
  }
  [[nodiscard]] Vec<3> residual(const Vec<3>& z, const Vec<3>& zhat) const {
    return Vec<3>(z[0] - zhat[0], z[1] - zhat[1], angleDiff(z[2], zhat[2]));
  }

 private:
  Mat<3> S_ = Mat<3>::Zero();
  Vec<3> assumed_ = Vec<3>::Zero();
  bool turnRateState_ = false;
};

/// The position part alone (slow ship: no heading, no turn rate), with its sensitivity to the velocity
/// over ground.
class RadarPositionModel {
 public:
  static constexpr int kDim = 2;
  RadarPositionModel() = default;
  RadarPositionModel(const Mat<2>& sensitivity, const Vec<2>& assumedVelocity)
      : S_(sensitivity), assumed_(assumedVelocity) {}
  [[nodiscard]] Vec<2> h(const State& x) const {
    return Vec<2>(x[kPosX], x[kPosY]) + S_ * (Vec<2>(groundVx(x), groundVy(x)) - assumed_);
  }
  [[nodiscard]] MatRC<2, kStateDim> jacobian(const State&) const {
    MatRC<2, kStateDim> H = MatRC<2, kStateDim>::Zero();
    H(0, kPosX) = 1.0;
    H(1, kPosY) = 1.0;
    for (int r = 0; r < 2; ++r) {
      H(r, kCurX) = H(r, kVelX) = S_(r, 0);
      H(r, kCurY) = H(r, kVelY) = S_(r, 1);
    }
    return H;
  }
  [[nodiscard]] Vec<2> residual(const Vec<2>& z, const Vec<2>& zhat) const { return z - zhat; }

 private:
  Mat<2> S_ = Mat<2>::Zero();
  Vec<2> assumed_ = Vec<2>::Zero();
};

}  // namespace reckoner::est::drkf
