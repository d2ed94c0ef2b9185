#pragma once
// Radar range and azimuth to the target, seed 000 eqs. 9a-9c (rows 5-6), grid frame:
//   z5 = sqrt(dx^2 + dy^2),  z6 = atan2(dx, dy) in [0, 2 pi)  (clockwise from north),
//   dx = x7 - x1, dy = x8 - x2.  H51 = dx/r, H52 = dy/r, H61 = dx/r^2, H62 = dy/r^2:
//   d z5 / d(x7, x8) = (H51, H52), d z6 / d(x7, x8) = (H62, -H61), own position with opposite sign.
// The azimuth innovation is wrapped to (-pi, pi]; below minRangeM the geometry is degenerate.
#include <cmath>

#include "common/angles.h"
#include "estimation/models/ttkf_state.h"

namespace reckoner::est::ttkf {

class RadarModel {
 public:
  static constexpr int kDim = 2;

  explicit RadarModel(double minRangeM) : minRangeM_(minRangeM) {}

  [[nodiscard]] Vec<2> h(const State& x) const {
    const double dx = x[kTgtX] - x[kOwnX], dy = x[kTgtY] - x[kOwnY];
    return {std::hypot(dx, dy), bearingOf(dx, dy)};
  }
  [[nodiscard]] MatRC<2, kStateDim> jacobian(const State& x) const {
    const double dx = x[kTgtX] - x[kOwnX], dy = x[kTgtY] - x[kOwnY];
    const double r2 = dx * dx + dy * dy, r = std::sqrt(r2);
    MatRC<2, kStateDim> H = MatRC<2, kStateDim>::Zero();
    H(0, kTgtX) = dx / r;
    H(0, kTgtY) = dy / r;
    H(0, kOwnX) = -dx / r;
    H(0, kOwnY) = -dy / r;
    H(1, kTgtX) = dy / r2;
    H(1, kTgtY) = -dx / r2;
    H(1, kOwnX) = -dy / r2;
    H(1, kOwnY) = dx / r2;
    return H;
  }
  [[nodiscard]] Vec<2> residual(const Vec<2>& z, const Vec<2>& zhat) const {
    return {z[0] - zhat[0], angleDiff(z[1], zhat[1])};
  }
  [[nodiscard]] bool degenerate(const State& x) const {
    return !(std::hypot(x[kTgtX] - x[kOwnX], x[kTgtY] - x[kOwnY]) >= minRangeM_);
  }

 private:
  double minRangeM_;
};

/// The DRKF's own-ship position and velocity as a measurement (seed 000 eq. 9a rows 1-4).
class OwnShipModel {
 public:
  static constexpr int kDim = kOwnDim;
  [[nodiscard]] Vec<kOwnDim> h(const State& x) const { return x.head<kOwnDim>(); }
  [[nodiscard]] MatRC<kOwnDim, kStateDim> jacobian(const State&) const {
    MatRC<kOwnDim, kStateDim> H = MatRC<kOwnDim, kStateDim>::Zero();
    H.leftCols<kOwnDim>().setIdentity();
    return H;
  }
  [[nodiscard]] Vec<kOwnDim> residual(const Vec<kOwnDim>& z, const Vec<kOwnDim>& zhat) const {
    return z - zhat;
  }
  [[nodiscard]] bool degenerate(const State&) const { return false; }
};

}  // namespace reckoner::est::ttkf
