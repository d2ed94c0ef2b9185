#pragma once
// Speedlog speed magnitude with a Gauss-Markov error x11, seed 000 eqs. 7c and 7d:
//   ground-lock (speed over ground):     z = sqrt((x2 + x3)^2 + (x6 + x7)^2) + x11 + v
//   bottom-lock (speed through water):   z = sqrt(x3^2 + x7^2) + x11 + v
// The paper's names are kept; note that a Doppler log's "bottom track" is the over-ground mode.
// |v| is not differentiable at zero speed: below minSpeedMps the model reports itself degenerate.
// With the scale-factor state (withScale): z = (1 + x13) |v| + x11 + v — the IMO log standard allows
// 2% of the speed or 0.2 kn; a change of speed separates the two (docs/drkf.md).
#include <cmath>

#include "estimation/models/drkf_state.h"

namespace reckoner::est::drkf {

class SpeedlogModel {
 public:
  static constexpr int kDim = 1;
  enum class Mode { GroundLock, BottomLock };

  SpeedlogModel(Mode mode, double minSpeedMps, bool withScale = false)
      : mode_(mode), minSpeedMps_(minSpeedMps), withScale_(withScale) {}

  [[nodiscard]] Vec<1> h(const State& x) const {
    const auto [vx, vy] = velocity(x);
    return Vec<1>(scale(x) * std::hypot(vx, vy) + x[kLogBias]);
  }
  [[nodiscard]] MatRC<1, kStateDim> jacobian(const State& x) const {
    const auto [vx, vy] = velocity(x);
    const double r = std::hypot(vx, vy);
    MatRC<1, kStateDim> H = MatRC<1, kStateDim>::Zero();
    const double k = scale(x);
    const double hx = k * vx / r;  // H72 of eq. 7c (or x3 / r of eq. 7d)
    const double hy = k * vy / r;  // H76
    H(0, kVelX) = hx;
    H(0, kVelY) = hy;
    if (mode_ == Mode::GroundLock) {
      H(0, kCurX) = hx;
      H(0, kCurY) = hy;
    }
    H(0, kLogBias) = 1.0;
    if (withScale_) H(0, kLogScale) = r;
    return H;
  }
  [[nodiscard]] Vec<1> residual(const Vec<1>& z, const Vec<1>& zhat) const { return z - zhat; }
  [[nodiscard]] bool degenerate(const State& x) const {
    const auto [vx, vy] = velocity(x);
    return !(std::hypot(vx, vy) >= minSpeedMps_);
  }
  [[nodiscard]] Mode mode() const { return mode_; }

 private:
  [[nodiscard]] std::pair<double, double> velocity(const State& x) const {
    return mode_ == Mode::GroundLock ? std::pair{groundVx(x), groundVy(x)} : std::pair{x[kVelX], x[kVelY]};
  }
  [[nodiscard]] double scale(const State& x) const { return withScale_ ? 1.0 + x[kLogScale] : 1.0; }
  Mode mode_;
  double minSpeedMps_;
  bool withScale_;
};

}  // namespace reckoner::est::drkf
