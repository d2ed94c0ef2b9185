#pragma once
// First-order Gauss-Markov process (seed 000 eqs. 1-3):
//   da/dt = -beta a + sqrt(2 sigma^2 beta) w(t),  E[w(t) w(s)] = delta(t - s)
// discretised exactly over dt:
//   a(k+1) = Phi a(k) + Gamma w(k),  Phi = exp(-beta dt),  Gamma^2 = sigma^2 (1 - exp(-2 beta dt)).
#include <cmath>

namespace reckoner::est {

struct GaussMarkov {
  double sigma = 0.0;     ///< stationary standard deviation, in the process's units; >= 0
  double betaPerS = 1.0;  ///< inverse correlation time, 1/s; > 0 (T_c = 1 / beta)

  /// Continuous driving-noise gain alpha = sqrt(2 sigma^2 beta) (the G entries of eq. 4d).
  [[nodiscard]] double alpha() const { return std::sqrt(2.0 * sigma * sigma * betaPerS); }
  /// Transition over dtS seconds, eq. 2a.
  [[nodiscard]] double phi(double dtS) const { return std::exp(-betaPerS * dtS); }
  /// Variance of the discrete driving term over dtS, eq. 2b (expm1 keeps small dt accurate).
  [[nodiscard]] double discreteVariance(double dtS) const {
    return sigma * sigma * -std::expm1(-2.0 * betaPerS * dtS);
  }
  [[nodiscard]] bool valid() const {
    return std::isfinite(sigma) && sigma >= 0.0 && std::isfinite(betaPerS) && betaPerS > 0.0;
  }
};

}  // namespace reckoner::est
