#include "tracking/alpha_beta_gamma.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace reckoner::track {

std::string AbgConfig::check() const {
  if (!(alpha > 0.0 && alpha <= 0.6)) return "alpha must lie in (0, 0.6] (seed 003's bound)";
  return {};
}

std::array<double, 2> abgGainsFromAlpha(double alpha) {
  const double beta = 2.0 * (2.0 - alpha) - 4.0 * std::sqrt(std::max(0.0, 1.0 - alpha));
  return {beta, beta * beta / (4.0 * alpha)};
}

std::array<double, 3> abgGrowingMemoryGains(int n) {
  const double m = n - 1.0;  // Brookner's index, from 0
  const double d = (m + 1.0) * (m + 2.0) * (m + 3.0);
  return {3.0 * (3.0 * m * m + 3.0 * m + 2.0) / d, 18.0 * (2.0 * m + 1.0) / d, 30.0 / d};
}

AlphaBetaGammaFilter::AlphaBetaGammaFilter(const AbgConfig& config) : config_(config) {
  if (const std::string p = config.check(); !p.empty()) throw std::invalid_argument("alpha-beta-gamma: " + p);
}

bool AlphaBetaGammaFilter::update(TimeUs t, double xM, double yM) {
  if (!std::isfinite(xM) || !std::isfinite(yM) || (n_ > 0 && t <= lastUs_)) return false;
  const std::array<double, 2> z{xM, yM};
  Estimate& e = estimate_;
  if (n_ == 0) {
    e = Estimate{};
    e.smoothedPos = e.predictedPos = z;
    e.alpha = 1.0;
  } else if (n_ == 1) {
    const double dt = toSeconds(t - lastUs_);
    for (int a = 0; a < 2; ++a) {
      e.predictedPos[a] = e.smoothedPos[a];
      e.smoothedVel[a] = (z[a] - e.smoothedPos[a]) / dt;
      e.smoothedPos[a] = z[a];
    }
    e.alpha = 1.0;
    e.beta = 1.0;
  } else {
    const int n = n_ + 1;  // this plot's number
    const double dt = toSeconds(t - lastUs_);
    double alpha = config_.alpha;
    auto [beta, gamma] = abgGainsFromAlpha(alpha);
    if (config_.expandingStart) {
      const auto g = abgGrowingMemoryGains(n);
      if (g[0] > alpha) {
        alpha = g[0];
        beta = g[1];
        gamma = g[2];
      }
    }
    for (int a = 0; a < 2; ++a) {
      const double pp = e.smoothedPos[a] + dt * e.smoothedVel[a] + 0.5 * dt * dt * e.smoothedAcc[a];
      const double r = z[a] - pp;
      e.predictedPos[a] = pp;
      e.smoothedPos[a] = pp + alpha * r;
      e.smoothedVel[a] = e.smoothedVel[a] + dt * e.smoothedAcc[a] + beta / dt * r;
      e.smoothedAcc[a] = e.smoothedAcc[a] + 2.0 * gamma / (dt * dt) * r;
    }
    e.alpha = alpha;
    e.beta = beta;
    e.gamma = gamma;
  }
  lastUs_ = t;
  ++n_;
  return true;
}

std::array<double, 2> AlphaBetaGammaFilter::predict(TimeUs t) const {
  const double dt = toSeconds(t - lastUs_);
  const Estimate& e = estimate_;
  return {e.smoothedPos[0] + dt * e.smoothedVel[0] + 0.5 * dt * dt * e.smoothedAcc[0],
          e.smoothedPos[1] + dt * e.smoothedVel[1] + 0.5 * dt * dt * e.smoothedAcc[1]};
}

}  // namespace reckoner::track
