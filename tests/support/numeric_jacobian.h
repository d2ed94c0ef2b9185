#pragma once
// Central-difference Jacobian, the reference every analytic Jacobian is tested against.
#include <algorithm>
#include <cmath>

#include "estimation/gaussian.h"

namespace reckoner::est {

/// d h / d x at x by central differences with step relStep * max(1, |x_i|). diff(a, b) returns a - b
/// in measurement space (wrap angles there), so a heading near north differentiates correctly.
template <int M, int N, class Fn, class Diff>
MatRC<M, N> numericJacobian(const Fn& h, const Vec<N>& x, const Diff& diff, double relStep = 1e-6) {
  MatRC<M, N> J;
  for (int j = 0; j < N; ++j) {
    const double step = relStep * std::max(1.0, std::abs(x[j]));
    Vec<N> xp = x, xm = x;
    xp[j] += step;
    xm[j] -= step;
    J.col(j) = diff(h(xp), h(xm)) / (2.0 * step);
  }
  return J;
}

template <int M, int N, class Fn>
MatRC<M, N> numericJacobian(const Fn& h, const Vec<N>& x, double relStep = 1e-6) {
  return numericJacobian<M, N>(
      h, x, [](const Vec<M>& a, const Vec<M>& b) -> Vec<M> { return a - b; }, relStep);
}

}  // namespace reckoner::est
