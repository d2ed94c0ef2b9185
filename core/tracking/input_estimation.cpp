#include "tracking/input_estimation.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "estimation/chi_square.h"
#include "estimation/ekf.h"

namespace reckoner::track {
namespace {
using rp::kRx;
using rp::kRy;
using rp::kVx;
using rp::kVy;

/// Cartesian position (east, north) of a polar measurement and its covariance (first order).
std::pair<est::Vec<2>, est::Mat<2>> toCartesian(double b, double r, double sdB, double sdR) {
  const double s = std::sin(b), c = std::cos(b);
  est::MatRC<2, 2> J;  // d(x, y) / d(b, r)
  J << r * c, s, -r * s, c;
  const est::Mat<2> Rp = est::Vec<2>(sdB * sdB, sdR * sdR).asDiagonal();
  return {est::Vec<2>(r * s, r * c), J * Rp * J.transpose()};
}
}  // namespace

std::string InputEstimationConfig::check() const {
  if (!(bearingSdRad > 0.0) || !std::isfinite(bearingSdRad)) return "bearing sd must be positive";
  if (!(rangeSdM > 0.0) || !std::isfinite(rangeSdM)) return "range sd must be positive";
  if (!(processNoiseQ >= 0.0) || !std::isfinite(processNoiseQ)) return "process noise must be >= 0";
  if (window < 1 || window > 50) return "window must lie in [1, 50]";
  if (!(falseAlarmProbability > 0.0 && falseAlarmProbability < 1.0))
    return "false-alarm probability must lie in (0, 1)";
  if (!(jumpSdMps > 0.0) || !std::isfinite(jumpSdMps)) return "velocity jump sd must be positive";
  return {};
}

InputEstimationEkf::InputEstimationEkf(const InputEstimationConfig& config)
    : config_(config), window_(config.window) {
  if (const std::string p = config.check(); !p.empty()) throw std::invalid_argument("input estimation: " + p);
  threshold_ = est::chiSquareQuantile(1.0 - config.falseAlarmProbability, 2.0);
}

InputEstimationStep InputEstimationEkf::measure(TimeUs t, double bearingRad, double rangeM, double observerXM,
                                                double observerYM) {
  InputEstimationStep step;
  step.timeUs = t;
  if (!std::isfinite(bearingRad) || !std::isfinite(rangeM) || !(rangeM > 0.0) || !std::isfinite(observerXM) ||
      !std::isfinite(observerYM)) {
    step.update.status = est::UpdateStatus::RejectedNonFinite;
    step.manoeuvring = manoeuvring_;
    return step;
  }
  const Sample sample{t, bearingRad, rangeM, observerXM, observerYM};
  if (!belief_) {
    if (!previous_ || t <= previous_->timeUs) {
      previous_ = sample;
      return step;
    }
    belief_ = twoPointInitiation(*previous_, sample);
    previous_ = sample;
    step.manoeuvring = manoeuvring_;
    return step;
  }
  filterSample(step, sample);
  step.manoeuvring = manoeuvring_;
  return step;
}

est::Gaussian<rp::kStateDim> InputEstimationEkf::twoPointInitiation(const Sample& p, const Sample& s) const {
  // Eqs. 30 and 31: position from the second measurement, velocity from the difference of the two
  // (divided by t, the bracket eq. 31 lacks), plus the observer's own velocity: the state holds the
  // target's velocity over ground, and the difference of relative positions is the relative one.
  const double dt = toSeconds(s.timeUs - p.timeUs);
  const auto [r1, P1] = toCartesian(p.bearingRad, p.rangeM, config_.bearingSdRad, config_.rangeSdM);
  const auto [r2, P2] = toCartesian(s.bearingRad, s.rangeM, config_.bearingSdRad, config_.rangeSdM);
  est::Gaussian<rp::kStateDim> g;
  g.x[kRx] = r2[0];
  g.x[kRy] = r2[1];
  g.x[kVx] = (r2[0] - r1[0] + s.observerXM - p.observerXM) / dt;
  g.x[kVy] = (r2[1] - r1[1] + s.observerYM - p.observerYM) / dt;
  g.P.setZero();
  if (config_.paperInitialCovariance) {
    // Eq. 32: each component uniform on +-its value: variance 4 x^2 / 12.
    for (int i = 0; i < rp::kStateDim; ++i) g.P(i, i) = std::max(4.0 * g.x[i] * g.x[i] / 12.0, 1e-6);
  } else {
    g.P.block<2, 2>(kRx, kRx) = P2;
    g.P.block<2, 2>(kVx, kVx) = (P1 + P2) / (dt * dt);
    g.P.block<2, 2>(kVx, kRx) = P2 / dt;
    g.P.block<2, 2>(kRx, kVx) = P2 / dt;
  }
  return g;
}

void InputEstimationEkf::filterSample(InputEstimationStep& step, const Sample& to) {
  // Prediction (eqs. 2 to 4, 10) with the observer's displacement.
  const double dt = toSeconds(to.timeUs - previous_->timeUs);
  if (!(dt > 0.0)) {
    step.update.status = est::UpdateStatus::RejectedNumerical;  // not after the last measurement
    return;
  }
  InputWindow<rp::kStateDim>::Entry entry;
  entry.Phi = rp::transition(dt);
  entry.G = rp::inputGain(dt);
  const Sample from = *previous_;
  est::Gaussian<rp::kStateDim> g = *belief_;
  if (!predict(g, from, to, std::nullopt)) {
    step.update.status = est::UpdateStatus::RejectedNumerical;
    return;
  }
  previous_ = to;

  // Update (eqs. 11 to 13, Joseph form).
  const rp::BearingRangeModel model;
  const est::Mat<2> R =
      est::Vec<2>(config_.bearingSdRad * config_.bearingSdRad, config_.rangeSdM * config_.rangeSdM)
          .asDiagonal();
  entry.H = model.jacobian(g.x);
  const rp::Covariance prior = g.P;
  step.update = est::update(g, model, est::Vec<2>(to.bearingRad, to.rangeM), R, 0.0);
  const est::Gaussian<rp::kStateDim> before = *belief_;
  belief_ = g;  // the prediction, updated when the update was accepted
  if (!step.update.applied()) {
    window_.clear();
    stored_.clear();
    return;
  }
  entry.S = step.update.S;
  entry.innovation = step.update.innovation;
  const Eigen::LDLT<est::Mat<2>> ldlt(entry.S);
  entry.W = ldlt.solve(entry.H * prior).transpose();  // K = P H^T S^-1 (S and P symmetric)
  window_.push(entry);
  stored_.push_back({from, to, before});
  while (static_cast<int>(stored_.size()) > window_.length()) stored_.pop_front();
  estimateInput(step);
}

void InputEstimationEkf::estimateInput(InputEstimationStep& step) {
  // Eqs. 17 to 29 (docs/manoeuvres.md for the exact innovation bias and the S weight).
  const auto e = window_.estimate();
  if (!e.tested) return;
  step.tested = true;
  step.u = e.u;
  step.d = e.d;
  if (e.d < threshold_ || config_.correction == InputEstimationConfig::Correction::None) {
    manoeuvring_ = false;  // the input is no longer significant: the manoeuvre has ended
    return;
  }
  if (config_.correction == InputEstimationConfig::Correction::Refilter) {
    if (!refilterWindow()) return;
  } else {
    est::Gaussian<rp::kStateDim> g = *belief_;
    g.x += e.M * e.u;
    g.P += e.M * e.L * e.M.transpose();
    est::symmetrise(g.P);
    if (!g.x.allFinite() || !g.P.allFinite()) return;
    belief_ = g;
  }
  step.detected = true;
  manoeuvring_ = true;
  window_.clear();  // the stored innovations belong to the uncorrected estimate
  stored_.clear();
}

bool InputEstimationEkf::predict(est::Gaussian<rp::kStateDim>& g, const Sample& from, const Sample& to,
                                 std::optional<double> jumpFraction) const {
  const double dt = toSeconds(to.timeUs - from.timeUs);
  const double f = jumpFraction.value_or(1.0);
  const double dt1 = f * dt, dt2 = dt - dt1;
  if (!est::predictLinear(g, rp::transition(dt1), rp::processNoise(config_.processNoiseQ, dt1))) return false;
  if (jumpFraction) {
    g.P(kVx, kVx) += config_.jumpSdMps * config_.jumpSdMps;
    g.P(kVy, kVy) += config_.jumpSdMps * config_.jumpSdMps;
  }
  if (dt2 > 0.0 && !est::predictLinear(g, rp::transition(dt2), rp::processNoise(config_.processNoiseQ, dt2)))
    return false;
  g.x[kRx] -= to.observerXM - from.observerXM;
  g.x[kRy] -= to.observerYM - from.observerYM;
  return true;
}

bool InputEstimationEkf::refilterWindow() {
  // Every onset: in which of the window's intervals, and where in it (quarters), the velocity jumped.
  // The likeliest (largest summed Gaussian log-likelihood of the window's innovations) is adopted.
  const rp::BearingRangeModel model;
  const est::Mat<2> R =
      est::Vec<2>(config_.bearingSdRad * config_.bearingSdRad, config_.rangeSdM * config_.rangeSdM)
          .asDiagonal();
  std::optional<est::Gaussian<rp::kStateDim>> best;
  double bestLogLik = -std::numeric_limits<double>::infinity();
  bool bestIsJump = false;
  // j == size(): no jump at all, the filter as it ran (marginal likelihoods: a jump must explain the
  // window better than its wide prior costs).
  for (std::size_t j = 0; j <= stored_.size(); ++j) {
    for (const double f : {0.0, 0.25, 0.5, 0.75}) {
      if (j == stored_.size() && f > 0.0) break;
      est::Gaussian<rp::kStateDim> g = stored_.front().before;
      double logLik = 0.0;
      bool ok = true;
      for (std::size_t i = 0; i < stored_.size() && ok; ++i) {
        const Stored& s = stored_[i];
        ok = predict(g, s.from, s.to, i == j ? std::optional(f) : std::nullopt);
        if (!ok) break;
        const auto rep = est::update(g, model, est::Vec<2>(s.to.bearingRad, s.to.rangeM), R, 0.0);
        ok = rep.applied();
        const double det = rep.S(0, 0) * rep.S(1, 1) - rep.S(0, 1) * rep.S(1, 0);
        logLik -= 0.5 * (rep.nis + std::log(std::max(det, 1e-300)));
      }
      if (ok && g.x.allFinite() && logLik > bestLogLik) {
        bestLogLik = logLik;
        best = g;
        bestIsJump = j < stored_.size();
      }
    }
  }
  if (!best || !bestIsJump) return false;
  belief_ = *best;
  return true;
}

}  // namespace reckoner::track
