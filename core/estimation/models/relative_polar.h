#pragma once
// Seed 001 section II.A: the relative-state model of a target seen from a moving observer (active sonar
// or radar), state X = [vx, vy, Rx, Ry]: the target's velocity over ground (east, north; m/s) and the
// target's position relative to the observer (east, north; m). True-north convention.
//   Transition, eq. 3 and 4 (with the sign of eq. 4 corrected, docs/manoeuvres.md):
//     v(k+1) = v(k),  R(k+1) = R(k) + t v(k) - [o(k+1) - o(k)]   (o: observer position)
//   Measurement, eqs. 5 to 9: bearing B = atan2(Rx, Ry) in [0, 2 pi), range R = |(Rx, Ry)|.
//   H = [0 0 cos B / R  -sin B / R; 0 0 sin B  cos B]; the bearing innovation is wrapped.
#include <cmath>

#include "common/angles.h"
#include "estimation/gaussian.h"

namespace reckoner::est::relpolar {

enum Index : int { kVx = 0, kVy = 1, kRx = 2, kRy = 3, kStateDim = 4 };
using State = Vec<kStateDim>;
using Covariance = Mat<kStateDim>;

/// Eq. 3: the transition over dtS seconds.
inline Covariance transition(double dtS) {
  Covariance F = Covariance::Identity();
  F(kRx, kVx) = dtS;
  F(kRy, kVy) = dtS;
  return F;
}

/// How a constant target acceleration u = (ax, ay) over dtS enters the state (the F of eq. 14).
inline MatRC<kStateDim, 2> inputGain(double dtS) {
  MatRC<kStateDim, 2> G = MatRC<kStateDim, 2>::Zero();
  G(kVx, 0) = G(kVy, 1) = dtS;
  G(kRx, 0) = G(kRy, 1) = 0.5 * dtS * dtS;
  return G;
}

/// Process noise: white acceleration of spectral density q (m^2/s^3) on each axis of the target.
inline Covariance processNoise(double qM2PerS3, double dtS) {
  Covariance Q = Covariance::Zero();
  for (int a = 0; a < 2; ++a) {
    const int v = kVx + a, r = kRx + a;
    Q(v, v) = qM2PerS3 * dtS;
    Q(v, r) = Q(r, v) = qM2PerS3 * dtS * dtS / 2.0;
    Q(r, r) = qM2PerS3 * dtS * dtS * dtS / 3.0;
  }
  return Q;
}

/// Bearing and range, eqs. 5 to 9.
class BearingRangeModel {
 public:
  static constexpr int kDim = 2;
  [[nodiscard]] Vec<2> h(const State& x) const {
    return Vec<2>(bearingOf(x[kRx], x[kRy]), std::hypot(x[kRx], x[kRy]));
  }
  [[nodiscard]] MatRC<2, kStateDim> jacobian(const State& x) const {
    const double r = std::hypot(x[kRx], x[kRy]);
    const double s = x[kRx] / r, c = x[kRy] / r;  // sin B, cos B
    MatRC<2, kStateDim> H = MatRC<2, kStateDim>::Zero();
    H(0, kRx) = c / r;
    H(0, kRy) = -s / r;
    H(1, kRx) = s;
    H(1, kRy) = c;
    return H;
  }
  [[nodiscard]] Vec<2> residual(const Vec<2>& z, const Vec<2>& zhat) const {
    return Vec<2>(angleDiff(z[0], zhat[0]), z[1] - zhat[1]);
  }
};

}  // namespace reckoner::est::relpolar
