#pragma once
// Seed 003: the alpha-beta-gamma tracking filter of an ARPA, per Cartesian axis of the radar plots:
//   Ps(n)   = Pp(n) + alpha (Po(n) - Pp(n))
//   Vs(n)   = Vs(n-1) + t as(n-1) + (beta / t) (Po(n) - Pp(n))
//   as(n)   = as(n-1) + (2 gamma / t^2) (Po(n) - Pp(n))
//   Pp(n+1) = Ps(n) + t Vs(n) + (t^2 / 2) as(n)
// (o observed, p predicted, s smoothed; t the time since the last plot). The paper bounds alpha by
// 2(2n-1)/(n(n+1)) < alpha <= 0.6 at step n; that lower bound is the growing-memory (least-squares)
// alpha of the alpha-beta filter. Here the start is the alpha-beta-gamma filter's own growing memory,
// the gains of the least-squares quadratic fit to all plots so far (Morrison; Brookner's g-h-k table),
// whose alpha exceeds the paper's bound, used while it is above the chosen alpha; then alpha is fixed
// and beta and gamma follow from it by the relation that makes the gains those of the steady-state
// Kalman filter for a white-jerk (Wiener-process acceleration) target (docs/manoeuvres.md):
//   beta = 2 (2 - alpha) - 4 sqrt(1 - alpha),   gamma = beta^2 / (4 alpha).
#include <array>
#include <string>

#include "common/time.h"

namespace reckoner::track {

struct AbgConfig {
  double alpha = 0.5;          ///< steady-state position gain, (0, 0.6] (the paper's upper bound)
  bool expandingStart = true;  ///< the growing-memory gains while their alpha exceeds alpha
  [[nodiscard]] std::string check() const;  ///< empty when valid, else the problem
};

/// beta and gamma from alpha (the steady-state Kalman relation above).
std::array<double, 2> abgGainsFromAlpha(double alpha);
/// alpha, beta and gamma of the least-squares quadratic fit to plots 1..n (n >= 3; the paper's gain
/// convention): with m = n - 1, alpha = 3(3m^2 + 3m + 2)/d, beta = 18(2m + 1)/d, gamma = 30/d,
/// d = (m + 1)(m + 2)(m + 3).
std::array<double, 3> abgGrowingMemoryGains(int n);

class AlphaBetaGammaFilter {
 public:
  /// Throws std::invalid_argument for an invalid configuration.
  explicit AlphaBetaGammaFilter(const AbgConfig& config);

  struct Estimate {
    std::array<double, 2> smoothedPos{}, smoothedVel{}, smoothedAcc{};  ///< (x, y): m, m/s, m/s^2
    std::array<double, 2> predictedPos{};         ///< Pp at this plot's time (before the plot was used)
    double alpha = 0.0, beta = 0.0, gamma = 0.0;  ///< the gains used for this plot
  };

  /// A plot (x, y metres) at t. The first plot starts the track; the second sets the velocity by
  /// difference; from the third on the filter runs. Returns false (and ignores the plot) if t is not
  /// after the last plot or a coordinate is not finite.
  bool update(TimeUs t, double xM, double yM);

  [[nodiscard]] int plots() const { return n_; }
  [[nodiscard]] const Estimate& estimate() const { return estimate_; }
  /// Position predicted for time t from the last smoothed state.
  [[nodiscard]] std::array<double, 2> predict(TimeUs t) const;

 private:
  AbgConfig config_;
  int n_ = 0;
  TimeUs lastUs_ = 0;
  Estimate estimate_;
};

}  // namespace reckoner::track
