#include "tracking/input_estimation.h"

#include <Eigen/Cholesky>
#include <cmath>
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
  return {};
}

InputEstimationEkf::InputEstimationEkf(const InputEstimationConfig& config) : config_(config) {
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
  if (!belief_) {
    if (!previous_ || t <= previous_->timeUs) {
      previous_ = Previous{t, bearingRad, rangeM, observerXM, observerYM};
      return step;
    }
    // Eqs. 30 and 31: position from the second measurement, velocity from the difference of the two
    // (divided by t, the bracket eq. 31 lacks), plus the observer's own velocity: the state holds the
    // target's velocity over ground, and the difference of relative positions is the relative one.
    const Previous& p = *previous_;
    const double dt = toSeconds(t - p.timeUs);
    const auto [r1, P1] = toCartesian(p.bearingRad, p.rangeM, config_.bearingSdRad, config_.rangeSdM);
    const auto [r2, P2] = toCartesian(bearingRad, rangeM, config_.bearingSdRad, config_.rangeSdM);
    est::Gaussian<rp::kStateDim> g;
    g.x[kRx] = r2[0];
    g.x[kRy] = r2[1];
    g.x[kVx] = (r2[0] - r1[0] + observerXM - p.observerXM) / dt;
    g.x[kVy] = (r2[1] - r1[1] + observerYM - p.observerYM) / dt;
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
    belief_ = g;
    previous_ = Previous{t, bearingRad, rangeM, observerXM, observerYM};
    step.manoeuvring = manoeuvring_;
    return step;
  }

  // Prediction (eqs. 2 to 4, 10) with the observer's displacement.
  const double dt = toSeconds(t - previous_->timeUs);
  if (!(dt > 0.0)) {
    step.update.status = est::UpdateStatus::RejectedNumerical;  // not after the last measurement
    step.manoeuvring = manoeuvring_;
    return step;
  }
  WindowEntry entry;
  entry.Phi = rp::transition(dt);
  entry.G = rp::inputGain(dt);
  est::Gaussian<rp::kStateDim> g = *belief_;
  if (!est::predictLinear(g, entry.Phi, rp::processNoise(config_.processNoiseQ, dt))) {
    step.update.status = est::UpdateStatus::RejectedNumerical;
    step.manoeuvring = manoeuvring_;
    return step;
  }
  g.x[kRx] -= observerXM - previous_->observerXM;
  g.x[kRy] -= observerYM - previous_->observerYM;
  previous_ = Previous{t, bearingRad, rangeM, observerXM, observerYM};

  // Update (eqs. 11 to 13, Joseph form).
  const rp::BearingRangeModel model;
  const est::Mat<2> R =
      est::Vec<2>(config_.bearingSdRad * config_.bearingSdRad, config_.rangeSdM * config_.rangeSdM)
          .asDiagonal();
  entry.H = model.jacobian(g.x);
  const rp::Covariance prior = g.P;
  step.update = est::update(g, model, est::Vec<2>(bearingRad, rangeM), R, 0.0);
  belief_ = g;  // the prediction, updated when the update was accepted
  if (!step.update.applied()) {
    window_.clear();
    step.manoeuvring = manoeuvring_;
    return step;
  }
  entry.S = step.update.S;
  entry.innovation = step.update.innovation;
  const Eigen::LDLT<est::Mat<2>> ldlt(entry.S);
  entry.W = ldlt.solve(entry.H * prior).transpose();  // K = P H^T S^-1 (S and P symmetric)
  window_.push_back(entry);
  while (static_cast<int>(window_.size()) > config_.window) window_.pop_front();
  estimateInput(step);
  step.manoeuvring = manoeuvring_;
  return step;
}

void InputEstimationEkf::estimateInput(InputEstimationStep& step) {
  if (static_cast<int>(window_.size()) < config_.window) return;
  // Eqs. 17 to 19 with the filter's own response to the input: C(i) is d(predicted state error)/du at
  // step i of the window, C(first) = G(first), C(i+1) = Phi(i+1) (I - W(i) H(i)) C(i) + G(i+1); the
  // innovation bias is Psi(i) u with Psi(i) = H(i) C(i).
  const rp::Covariance I = rp::Covariance::Identity();
  est::MatRC<rp::kStateDim, 2> C = window_.front().G;
  est::Mat<2> A = est::Mat<2>::Zero();  // Psi^T S^-1 Psi
  est::Vec<2> b = est::Vec<2>::Zero();  // Psi^T S^-1 y
  for (std::size_t i = 0; i < window_.size(); ++i) {
    const WindowEntry& e = window_[i];
    if (i > 0) C = (e.Phi * (I - window_[i - 1].W * window_[i - 1].H) * C + e.G).eval();
    const est::MatRC<2, 2> Psi = e.H * C;
    const Eigen::LDLT<est::Mat<2>> Sldlt(e.S);  // eq. 23: weighted by the inverse innovation covariance
    A += Psi.transpose() * Sldlt.solve(Psi);
    b += Psi.transpose() * Sldlt.solve(e.innovation);
  }
  const Eigen::LDLT<est::Mat<2>> Aldlt(A);
  if (!est::ldltPositiveDefinite(Aldlt)) return;
  const est::Vec<2> u = Aldlt.solve(b);                        // eq. 23
  const est::Mat<2> L = Aldlt.solve(est::Mat<2>::Identity());  // eq. 24
  step.tested = true;
  step.u = u;
  step.d = u.dot(A * u);  // eq. 25: u^T L^-1 u
  if (!std::isfinite(step.d)) return;
  if (step.d < threshold_) {
    manoeuvring_ = false;  // the input is no longer significant: the manoeuvre has ended
    return;
  }
  // Eqs. 28 and 29: the filtered state at the end of the window carries (I - W H) C u of the input.
  const WindowEntry& last = window_.back();
  const est::MatRC<rp::kStateDim, 2> M = (I - last.W * last.H) * C;
  est::Gaussian<rp::kStateDim> g = *belief_;
  g.x += M * u;
  g.P += M * L * M.transpose();
  est::symmetrise(g.P);
  if (!g.x.allFinite() || !g.P.allFinite()) return;
  belief_ = g;
  step.detected = true;
  manoeuvring_ = true;
  window_.clear();  // the stored innovations belong to the uncorrected estimate
}

}  // namespace reckoner::track
