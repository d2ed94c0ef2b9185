#pragma once
// GPS velocity over ground, seed 000 eq. 7b rows 3-4: z = [x2 + x3, x6 + x7] + v (grid m/s).
#include "estimation/models/drkf_state.h"

namespace reckoner::est::drkf {

class GroundVelocityModel {
 public:
  static constexpr int kDim = 2;

  [[nodiscard]] Vec<2> h(const State& x) const { return {groundVx(x), groundVy(x)}; }
  [[nodiscard]] MatRC<2, kStateDim> jacobian(const State&) const {
    MatRC<2, kStateDim> H = MatRC<2, kStateDim>::Zero();
    H(0, kCurX) = H(0, kVelX) = 1.0;
    H(1, kCurY) = H(1, kVelY) = 1.0;
    return H;
  }
  [[nodiscard]] Vec<2> residual(const Vec<2>& z, const Vec<2>& zhat) const { return z - zhat; }
  [[nodiscard]] bool degenerate(const State&) const { return false; }
};

}  // namespace reckoner::est::drkf
