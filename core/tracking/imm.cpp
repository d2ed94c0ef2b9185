#include "tracking/imm.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/angles.h"
#include "estimation/ekf.h"

namespace reckoner::track {
namespace {
using namespace est::ct;

/// Range and bearing of the target from own ship (grid frame).
struct PlotModel {
  static constexpr int kDim = 2;
  double ox = 0.0, oy = 0.0;
  [[nodiscard]] est::Vec<2> h(const State& x) const {
    return est::Vec<2>(bearingOf(x[kX] - ox, x[kY] - oy), std::hypot(x[kX] - ox, x[kY] - oy));
  }
  [[nodiscard]] est::MatRC<2, kStateDim> jacobian(const State& x) const {
    const double dx = x[kX] - ox, dy = x[kY] - oy, r2 = dx * dx + dy * dy, r = std::sqrt(r2);
    est::MatRC<2, kStateDim> H = est::MatRC<2, kStateDim>::Zero();
    H(0, kX) = dy / r2;
    H(0, kY) = -dx / r2;
    H(1, kX) = dx / r;
    H(1, kY) = dy / r;
    return H;
  }
  [[nodiscard]] est::Vec<2> residual(const est::Vec<2>& z, const est::Vec<2>& zhat) const {
    return est::Vec<2>(angleDiff(z[0], zhat[0]), z[1] - zhat[1]);
  }
};

bool positive(double v) {
  return std::isfinite(v) && v > 0.0;
}
}  // namespace

std::string ImmConfig::check() const {
  if (!positive(rangeSdM) || !positive(bearingSdRad)) return "range and bearing sd must be positive";
  if (!positive(cvAccelQ) || !positive(ctAccelQ) || !(ctTurnQ >= 0.0))
    return "process noise must be positive";
  if (!positive(cvSojournS) || !positive(ctSojournS)) return "sojourn times must be positive";
  if (!positive(initialSpeedSdMps) || !positive(initialTurnSdRadPerS)) return "initial sds must be positive";
  if (!(manoeuvreProbability > 0.0 && manoeuvreProbability < 1.0)) return "manoeuvre probability in (0, 1)";
  return {};
}

ImmTracker::ImmTracker(const ImmConfig& config) : config_(config) {
  if (const std::string p = config.check(); !p.empty()) throw std::invalid_argument("IMM: " + p);
  // Start from the stationary mode distribution of the sojourn times.
  const double ct = config.ctSojournS / (config.cvSojournS + config.ctSojournS);
  mu_ = {1.0 - ct, ct};
}

est::Gaussian<kStateDim> ImmTracker::combined() const {
  est::Gaussian<kStateDim> g;
  g.x.setZero();
  for (int j = 0; j < kModes; ++j) g.x += mu_[j] * modes_[j].x;
  g.P.setZero();
  for (int j = 0; j < kModes; ++j) {
    const State d = modes_[j].x - g.x;
    g.P += mu_[j] * (modes_[j].P + d * d.transpose());
  }
  return g;
}

double ImmTracker::update(TimeUs t, double bearingRad, double rangeM, double ownXM, double ownYM) {
  if (!std::isfinite(bearingRad) || !std::isfinite(rangeM) || !(rangeM > 0.0) || !std::isfinite(ownXM) ||
      !std::isfinite(ownYM))
    return std::nan("");
  const est::Mat<2> R =
      est::Vec<2>(config_.bearingSdRad * config_.bearingSdRad, config_.rangeSdM * config_.rangeSdM)
          .asDiagonal();
  const PlotModel model{ownXM, ownYM};
  if (!initialised_) {
    // Position from the plot (polar noise converted to first order), velocity unknown.
    est::Gaussian<kStateDim> g;
    const double s = std::sin(bearingRad), c = std::cos(bearingRad);
    g.x << ownXM + rangeM * s, ownYM + rangeM * c, 0.0, 0.0, 0.0;
    est::MatRC<2, 2> J;
    J << rangeM * c, s, -rangeM * s, c;
    g.P.setZero();
    g.P.block<2, 2>(kX, kX) = J * R * J.transpose();
    g.P(kVx, kVx) = g.P(kVy, kVy) = config_.initialSpeedSdMps * config_.initialSpeedSdMps;
    g.P(kW, kW) = config_.initialTurnSdRadPerS * config_.initialTurnSdRadPerS;
    modes_[kCv] = modes_[kCt] = g;
    modes_[kCv].P(kW, kW) = 0.0;
    modes_[kCv].x[kW] = 0.0;
    initialised_ = true;
    timeUs_ = t;
    return std::nan("");
  }
  const double dt = toSeconds(t - timeUs_);
  if (!(dt > 0.0)) return std::nan("");

  // 1. Mixing probabilities from the mode transition over dt.
  const std::array<double, kModes> stay{std::exp(-dt / config_.cvSojournS),
                                        std::exp(-dt / config_.ctSojournS)};
  double p[kModes][kModes];
  for (int i = 0; i < kModes; ++i)
    for (int j = 0; j < kModes; ++j) p[i][j] = i == j ? stay[i] : 1.0 - stay[i];
  std::array<double, kModes> cbar{};
  for (int j = 0; j < kModes; ++j)
    for (int i = 0; i < kModes; ++i) cbar[j] += p[i][j] * mu_[i];
  // 2. Mixed initial conditions per mode.
  std::array<est::Gaussian<kStateDim>, kModes> mixed{};
  for (int j = 0; j < kModes; ++j) {
    mixed[j].x.setZero();
    for (int i = 0; i < kModes; ++i) mixed[j].x += p[i][j] * mu_[i] / cbar[j] * modes_[i].x;
    mixed[j].P.setZero();
    for (int i = 0; i < kModes; ++i) {
      const State d = modes_[i].x - mixed[j].x;
      mixed[j].P += p[i][j] * mu_[i] / cbar[j] * (modes_[i].P + d * d.transpose());
    }
  }
  // 3. Mode-matched prediction and update; 4. likelihoods.
  std::array<double, kModes> likelihood{};
  std::array<double, kModes> nis{};
  for (int j = 0; j < kModes; ++j) {
    est::Gaussian<kStateDim>& g = mixed[j];
    const bool cv = j == kCv;
    const Covariance F = cv ? cvTransition(dt) : ctTransition(g.x, dt);
    const State x = cv ? cvPredict(g.x, dt) : ctPredict(g.x, dt);
    Covariance P = F * g.P * F.transpose() +
                   noise(cv ? config_.cvAccelQ : config_.ctAccelQ, cv ? 0.0 : config_.ctTurnQ, dt);
    est::symmetrise(P);
    if (!x.allFinite() || !P.allFinite()) return std::nan("");
    g.x = x;
    g.P = P;
    const auto rep = est::update(g, model, est::Vec<2>(bearingRad, rangeM), R, 0.0);
    if (!rep.applied()) return std::nan("");
    nis[j] = rep.nis;
    const double det = rep.S(0, 0) * rep.S(1, 1) - rep.S(0, 1) * rep.S(1, 0);
    likelihood[j] = std::exp(-0.5 * rep.nis) / (2.0 * M_PI * std::sqrt(std::max(det, 1e-300)));
  }
  // 5. Mode probabilities (guarded against underflow of both likelihoods).
  std::array<double, kModes> mu{};
  double total = 0.0;
  for (int j = 0; j < kModes; ++j) total += mu[j] = likelihood[j] * cbar[j];
  if (!(total > 0.0) || !std::isfinite(total)) {
    const int best = nis[kCv] <= nis[kCt] ? kCv : kCt;
    mu = {best == kCv ? 1.0 - 1e-6 : 1e-6, best == kCt ? 1.0 - 1e-6 : 1e-6};
  } else {
    for (int j = 0; j < kModes; ++j) mu[j] = std::clamp(mu[j] / total, 1e-9, 1.0 - 1e-9);
  }
  modes_ = mixed;
  mu_ = mu;
  timeUs_ = t;
  return mu_[kCv] >= mu_[kCt] ? nis[kCv] : nis[kCt];
}

}  // namespace reckoner::track
