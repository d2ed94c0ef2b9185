#include "navigation/lsq_fusion.h"

#include <Eigen/Cholesky>
#include <array>
#include <cmath>
#include <stdexcept>

#include "estimation/ekf.h"

namespace reckoner::nav {

std::optional<est::Gaussian<2>> leastSquares(std::span<const PositionFix> fixes) {
  est::Mat<2> A = est::Mat<2>::Zero();  // H' R^-1 H = sum of R_i^-1
  est::Vec<2> b = est::Vec<2>::Zero();  // H' R^-1 z = sum of R_i^-1 z_i
  for (const PositionFix& f : fixes) {
    if (!f.z.allFinite() || !f.R.allFinite()) return std::nullopt;
    const Eigen::LDLT<est::Mat<2>> r(f.R);
    if (!est::ldltPositiveDefinite(r)) return std::nullopt;
    A += r.solve(est::Mat<2>::Identity());
    b += r.solve(f.z);
  }
  const Eigen::LDLT<est::Mat<2>> a(A);
  if (fixes.empty() || !est::ldltPositiveDefinite(a)) return std::nullopt;
  est::Gaussian<2> g;
  g.x = a.solve(b);
  g.P = a.solve(est::Mat<2>::Identity());
  est::symmetrise(g.P);
  return g;
}

std::string LsqNavigatorConfig::check() const {
  if (!(driftM2PerS >= 0.0) || !std::isfinite(driftM2PerS)) return "drift must be >= 0";
  if (!(minSpeedMps >= 0.0)) return "minimum speed must be >= 0";
  if (!(maxDeadReckoningS > 0.0)) return "dead-reckoning age limit must be positive";
  return {};
}

LsqNavigator::LsqNavigator(const LsqNavigatorConfig& config, const est::Gaussian<2>& position, TimeUs t0)
    : config_(config), position_(position), timeUs_(t0) {
  if (const std::string p = config.check(); !p.empty()) throw std::invalid_argument("LSQ navigator: " + p);
  if (!position.x.allFinite() || !est::isPositiveDefinite(position.P))
    throw std::invalid_argument(
        "LSQ navigator: the start must be finite with a positive definite covariance");
  velocity_.x.setZero();
  velocity_.P = est::Mat<2>::Identity() * 100.0;
}

void LsqNavigator::deadReckonTo(TimeUs t) {
  if (t <= timeUs_) return;
  const double dt = toSeconds(t - timeUs_);
  if (hasVelocity_ && toSeconds(t - velocityUs_) <= config_.maxDeadReckoningS) {
    position_.x += velocity_.x * dt;
    position_.P += velocity_.P * (dt * dt);
  }
  position_.P += est::Mat<2>::Identity() * (config_.driftM2PerS * dt);
  timeUs_ = t;
}

bool LsqNavigator::update(TimeUs t, std::span<const sensors::OwnShipSample> samples,
                          const geo::LocalFrame& frame) {
  deadReckonTo(t);
  const auto [gps, gyro, log] = sensors::epochSamples(samples);
  bool fused = false;
  if (gps) {
    const std::array<PositionFix, 2> fixes{PositionFix{est::Vec<2>(gps->position.xM, gps->position.yM),
                                                       est::Mat<2>::Identity() * gps->positionVarM2},
                                           PositionFix{position_.x, position_.P}};
    if (const auto g = leastSquares(fixes)) {
      position_ = *g;
      fused = true;
    }
  }
  if (gyro && log && std::isfinite(gyro->headingRad) && std::isfinite(log->speedMps)) {
    // Heading and speed are true; the grid velocity turns by the convergence and scales.
    const geo::GridInfo gi = frame.gridInfo({position_.x[0], position_.x[1]});
    const double h = gyro->headingRad - gi.convergenceRad, v = gi.scale * log->speedMps;
    const double sh = std::sin(h), ch = std::cos(h);
    est::Mat<2> J;  // d(vx, vy) / d(speed, heading)
    J << sh, v * ch, ch, -v * sh;
    const double varV = gi.scale * gi.scale * log->varM2PerS2;
    const double varH = v >= config_.minSpeedMps ? gyro->varRad2 : 0.0;
    velocity_.x << v * sh, v * ch;
    velocity_.P = J * est::Vec<2>(varV, varH).asDiagonal() * J.transpose();
    velocity_.P += est::Mat<2>::Identity() * 1e-12;
    hasVelocity_ = true;
    velocityUs_ = t;
  }
  return fused;
}

est::Gaussian<4> LsqNavigator::ground() const {
  est::Gaussian<4> g;
  g.x << position_.x, velocity_.x;
  g.P.setZero();
  g.P.topLeftCorner<2, 2>() = position_.P;
  g.P.bottomRightCorner<2, 2>() = velocity_.P;
  return g;
}

}  // namespace reckoner::nav
