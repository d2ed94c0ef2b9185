#pragma once
// Gyro heading: the direction of the velocity through the water, clockwise from (grid) north:
//   z = atan2(x3, x7) + v,  in [0, 2 pi);  H = [.. dz/dx3 = x7 / r^2 .. dz/dx7 = -x3 / r^2 ..]
// Seed 000's eq. 7b row 8 uses the ground velocity (x2 + x3, x6 + x7); a gyrocompass measures the
// ship's heading, which the current does not turn, so we use the water velocity (docs/drkf.md).
// The innovation is wrapped to (-pi, pi]; below minSpeedMps the heading is undefined (degenerate).
// With the heading-bias state (withBias): z = atan2(x3, x7) + x12 + v, dz/dx12 = 1 — a gyro's
// calibration error or a compass's residual deviation, which only a turn separates from a current
// across the track (docs/drkf.md, "Sensor calibration states").
#include <cmath>

#include "common/angles.h"
#include "estimation/models/drkf_state.h"

namespace reckoner::est::drkf {

class GyroHeadingModel {
 public:
  static constexpr int kDim = 1;

  explicit GyroHeadingModel(double minSpeedMps, bool withBias = false)
      : minSpeedMps_(minSpeedMps), withBias_(withBias) {}

  [[nodiscard]] Vec<1> h(const State& x) const {
    const double b = bearingOf(x[kVelX], x[kVelY]);
    return Vec<1>(withBias_ ? wrapTwoPi(b + x[kHeadingBias]) : b);
  }
  [[nodiscard]] MatRC<1, kStateDim> jacobian(const State& x) const {
    const double vx = x[kVelX], vy = x[kVelY];
    const double r2 = vx * vx + vy * vy;
    MatRC<1, kStateDim> H = MatRC<1, kStateDim>::Zero();
    H(0, kVelX) = vy / r2;
    H(0, kVelY) = -vx / r2;
    if (withBias_) H(0, kHeadingBias) = 1.0;
    return H;
  }
  [[nodiscard]] Vec<1> residual(const Vec<1>& z, const Vec<1>& zhat) const {
    return Vec<1>(angleDiff(z[0], zhat[0]));
  }
  [[nodiscard]] bool degenerate(const State& x) const {
    return !(std::hypot(x[kVelX], x[kVelY]) >= minSpeedMps_);
  }

 private:
  double minSpeedMps_;
  bool withBias_;
};

}  // namespace reckoner::est::drkf
