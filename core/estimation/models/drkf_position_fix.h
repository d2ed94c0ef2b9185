#pragma once
// Position fixes, seed 000 eq. 7a/7b rows 1-2 and 5-6:
//   GPS:      z = [x1, x5] + v
//   Loran-C:  z = [x1 + x9, x5 + x10] + v   (x9, x10: the Gauss-Markov Loran-C error)
#include "estimation/models/drkf_state.h"

namespace reckoner::est::drkf {

class PositionFixModel {
 public:
  static constexpr int kDim = 2;
  enum class Source { Gps, LoranC };

  explicit PositionFixModel(Source source) : loran_(source == Source::LoranC) {}

  [[nodiscard]] Vec<2> h(const State& x) const {
    Vec<2> z(x[kPosX], x[kPosY]);
    if (loran_) z += Vec<2>(x[kLoranX], x[kLoranY]);
    return z;
  }
  [[nodiscard]] MatRC<2, kStateDim> jacobian(const State&) const {
    MatRC<2, kStateDim> H = MatRC<2, kStateDim>::Zero();
    H(0, kPosX) = 1.0;
    H(1, kPosY) = 1.0;
    if (loran_) {
      H(0, kLoranX) = 1.0;
      H(1, kLoranY) = 1.0;
    }
    return H;
  }
  [[nodiscard]] Vec<2> residual(const Vec<2>& z, const Vec<2>& zhat) const { return z - zhat; }
  [[nodiscard]] bool degenerate(const State&) const { return false; }

 private:
  bool loran_;
};

}  // namespace reckoner::est::drkf
