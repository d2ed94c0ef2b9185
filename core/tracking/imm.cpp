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

est::Gaussian<kStateDim> ImmTracker::combine(const std::array<est::Gaussian<kStateDim>, kModes>& m,
                                             const std::array<double, kModes>& w) {
  est::Gaussian<kStateDim> g;
  g.x.setZero();
  for (int j = 0; j < kModes; ++j) g.x += w[j] * m[j].x;
  g.P.setZero();
  for (int j = 0; j < kModes; ++j) {
    const State d = m[j].x - g.x;
    g.P += w[j] * (m[j].P + d * d.transpose());
  }
  return g;
}

est::Gaussian<kStateDim> ImmTracker::combined() const {
  return combine(modes_, mu_);
}

void ImmTracker::initialise(TimeUs t, const est::Vec<2>& position, const est::Mat<2>& positionCov) {
  est::Gaussian<kStateDim> g;
  g.x << position[0], position[1], 0.0, 0.0, 0.0;
  g.P.setZero();
  g.P.block<2, 2>(kX, kX) = positionCov;
  g.P(kVx, kVx) = g.P(kVy, kVy) = config_.initialSpeedSdMps * config_.initialSpeedSdMps;
  g.P(kW, kW) = config_.initialTurnSdRadPerS * config_.initialTurnSdRadPerS;
  modes_[kCv] = modes_[kCt] = g;
  modes_[kCv].P(kW, kW) = 0.0;
  modes_[kCv].x[kW] = 0.0;
  initialised_ = true;
  timeUs_ = t;
}

double ImmTracker::update(TimeUs t, double bearingRad, double rangeM, double ownXM, double ownYM) {
  if (!std::isfinite(bearingRad) || !std::isfinite(rangeM) || !(rangeM > 0.0) || !std::isfinite(ownXM) ||
      !std::isfinite(ownYM))
    return std::nan("");
  const est::Mat<2> R =
      est::Vec<2>(config_.bearingSdRad * config_.bearingSdRad, config_.rangeSdM * config_.rangeSdM)
          .asDiagonal();
  if (!initialised_) {
    // Position from the plot (polar noise converted to first order), velocity unknown.
    const double s = std::sin(bearingRad), c = std::cos(bearingRad);
    est::MatRC<2, 2> J;
    J << rangeM * c, s, -rangeM * s, c;
    initialise(t, est::Vec<2>(ownXM + rangeM * s, ownYM + rangeM * c), J * R * J.transpose());
    return std::nan("");
  }
  const auto rep = updatePlot(t, bearingRad, rangeM, ownXM, ownYM, R, 0.0);
  return rep.applied() ? rep.nis : std::nan("");
}

ImmTracker::Prediction ImmTracker::predictModes(double dt) const {
  Prediction out;
  // 1. Mixing probabilities from the mode transition over dt.
  const std::array<double, kModes> stay{std::exp(-dt / config_.cvSojournS),
                                        std::exp(-dt / config_.ctSojournS)};
  double p[kModes][kModes];
  for (int i = 0; i < kModes; ++i)
    for (int j = 0; j < kModes; ++j) p[i][j] = i == j ? stay[i] : 1.0 - stay[i];
  for (int j = 0; j < kModes; ++j)
    for (int i = 0; i < kModes; ++i) out.cbar[j] += p[i][j] * mu_[i];
  // 2. Mixed initial conditions per mode; 3. mode-matched prediction.
  for (int j = 0; j < kModes; ++j) {
    est::Gaussian<kStateDim>& g = out.modes[j];
    g.x.setZero();
    for (int i = 0; i < kModes; ++i) g.x += p[i][j] * mu_[i] / out.cbar[j] * modes_[i].x;
    g.P.setZero();
    for (int i = 0; i < kModes; ++i) {
      const State d = modes_[i].x - g.x;
      g.P += p[i][j] * mu_[i] / out.cbar[j] * (modes_[i].P + d * d.transpose());
    }
    const bool cv = j == kCv;
    const Covariance F = cv ? cvTransition(dt) : ctTransition(g.x, dt);
    const State x = cv ? cvPredict(g.x, dt) : ctPredict(g.x, dt);
    Covariance P = F * g.P * F.transpose() +
                   noise(cv ? config_.cvAccelQ : config_.ctAccelQ, cv ? 0.0 : config_.ctTurnQ, dt);
    est::symmetrise(P);
    if (!x.allFinite() || !P.allFinite()) return out;
    g.x = x;
    g.P = P;
  }
  out.ok = true;
  return out;
}

est::Gaussian<kStateDim> ImmTracker::predicted(TimeUs t) const {
  if (!initialised_ || t <= timeUs_) return combined();
  const Prediction pr = predictModes(toSeconds(t - timeUs_));
  return pr.ok ? combine(pr.modes, pr.cbar) : combined();
}

est::UpdateReport<2> ImmTracker::updatePlot(TimeUs t, double bearingRad, double rangeM, double ownXM,
                                            double ownYM, const est::Mat<2>& R, double gate) {
  est::UpdateReport<2> out;
  out.dim = 2;
  out.gate = gate;
  if (!std::isfinite(bearingRad) || !std::isfinite(rangeM) || !(rangeM > 0.0) || !std::isfinite(ownXM) ||
      !std::isfinite(ownYM) || !R.allFinite()) {
    out.status = est::UpdateStatus::RejectedNonFinite;
    return out;
  }
  if (!initialised_ || t <= timeUs_) {
    out.status = est::UpdateStatus::RejectedStale;
    return out;
  }
  const double dt = toSeconds(t - timeUs_);
  Prediction pr = predictModes(dt);
  if (!pr.ok) {
    out.status = est::UpdateStatus::RejectedNumerical;
    return out;
  }
  const PlotModel model{ownXM, ownYM};
  const est::Vec<2> z(bearingRad, rangeM);
  // The gate and the report: the combined prediction.
  {
    const est::Gaussian<kStateDim> c = combine(pr.modes, pr.cbar);
    if (std::hypot(c.x[kX] - ownXM, c.x[kY] - ownYM) < 1.0) {
      out.status = est::UpdateStatus::RejectedDegenerate;
      return out;
    }
    const auto H = model.jacobian(c.x);
    out.innovation = model.residual(z, model.h(c.x));
    out.S = H * c.P * H.transpose() + R;
    const Eigen::LDLT<est::Mat<2>> ldlt(out.S);
    if (!est::ldltPositiveDefinite(ldlt)) {
      out.status = est::UpdateStatus::RejectedNumerical;
      return out;
    }
    out.nis = out.innovation.dot(ldlt.solve(out.innovation));
    if (gate > 0.0 && out.nis > gate) {
      out.status = est::UpdateStatus::RejectedGate;
      return out;
    }
  }
  // 4. Mode-matched updates and likelihoods.
  std::array<double, kModes> likelihood{};
  std::array<double, kModes> nis{};
  for (int j = 0; j < kModes; ++j) {
    const auto rep = est::update(pr.modes[j], model, z, R, 0.0);
    if (!rep.applied()) {
      out.status = rep.status;
      return out;
    }
    nis[j] = rep.nis;
    const double det = rep.S(0, 0) * rep.S(1, 1) - rep.S(0, 1) * rep.S(1, 0);
    likelihood[j] = std::exp(-0.5 * rep.nis) / (kTwoPi * std::sqrt(std::max(det, 1e-300)));
  }
  // 5. Mode probabilities (guarded against underflow of both likelihoods).
  std::array<double, kModes> mu{};
  double total = 0.0;
  for (int j = 0; j < kModes; ++j) total += mu[j] = likelihood[j] * pr.cbar[j];
  if (!(total > 0.0) || !std::isfinite(total)) {
    const int best = nis[kCv] <= nis[kCt] ? kCv : kCt;
    mu = {best == kCv ? 1.0 - 1e-6 : 1e-6, best == kCt ? 1.0 - 1e-6 : 1e-6};
  } else {
    for (int j = 0; j < kModes; ++j) mu[j] = std::clamp(mu[j] / total, 1e-9, 1.0 - 1e-9);
  }
  modes_ = pr.modes;
  mu_ = mu;
  timeUs_ = t;
  out.status = est::UpdateStatus::Accepted;
  return out;
}

}  // namespace reckoner::track
