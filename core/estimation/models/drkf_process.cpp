#include "estimation/models/drkf_process.h"

#include <stdexcept>
#include <string>

namespace reckoner::est::drkf {
namespace {
void check(const GaussMarkov& gm, const char* name) {
  if (!gm.valid()) {
    throw std::invalid_argument(std::string("DRKF process model: ") + name +
                                " Gauss-Markov parameters need sigma >= 0 and beta > 0");
  }
}
}  // namespace

ProcessModel::ProcessModel(const ProcessParams& params) : params_(params) {
  check(params.current, "current");
  check(params.acceleration, "acceleration");
  check(params.loranError, "Loran-C error");
  check(params.speedlogError, "speedlog error");
  check(params.headingBias, "heading bias");
  check(params.logScale, "log scale");

  // eq. 4c
  F_.setZero();
  for (const auto [pos, cur, vel, acc] :
       {std::array{kPosX, kCurX, kVelX, kAccX}, std::array{kPosY, kCurY, kVelY, kAccY}}) {
    F_(pos, cur) = 1.0;
    F_(pos, vel) = 1.0;
    F_(cur, cur) = -params.current.betaPerS;
    F_(vel, acc) = 1.0;
    F_(acc, acc) = -params.acceleration.betaPerS;
  }
  F_(kLoranX, kLoranX) = -params.loranError.betaPerS;
  F_(kLoranY, kLoranY) = -params.loranError.betaPerS;
  F_(kLogBias, kLogBias) = -params.speedlogError.betaPerS;
  // An unmodelled calibration state (sigma 0) is held, not decayed: its variance stays at the floor of
  // initialCovariance() however long the prediction (a decayed one underflows to a singular P).
  F_(kHeadingBias, kHeadingBias) = params.headingBias.sigma > 0.0 ? -params.headingBias.betaPerS : 0.0;
  F_(kLogScale, kLogScale) = params.logScale.sigma > 0.0 ? -params.logScale.betaPerS : 0.0;

  // eq. 4d, alpha = sqrt(2 sigma^2 beta) (eq. 1)
  G_.setZero();
  G_(kCurX, 0) = params.current.alpha();
  G_(kAccX, 1) = params.acceleration.alpha();
  G_(kCurY, 2) = params.current.alpha();
  G_(kAccY, 3) = params.acceleration.alpha();
  G_(kLoranX, 4) = params.loranError.alpha();
  G_(kLoranY, 5) = params.loranError.alpha();
  G_(kLogBias, 6) = params.speedlogError.alpha();
  G_(kHeadingBias, 7) = params.headingBias.alpha();
  G_(kLogScale, 8) = params.logScale.alpha();
}

Discretised<kStateDim> ProcessModel::discretise(double dtS) const {
  return discretiseVanLoan<kStateDim, kNoiseDim>(F_, G_, dtS);
}

Mat<kStateDim> ProcessModel::printedTransition(double dt) const {
  Mat<kStateDim> Phi = Mat<kStateDim>::Identity();
  for (const auto [pos, cur, vel, acc] :
       {std::array{kPosX, kCurX, kVelX, kAccX}, std::array{kPosY, kCurY, kVelY, kAccY}}) {
    Phi(pos, cur) = dt;
    Phi(pos, vel) = dt;
    Phi(pos, acc) = 0.5 * dt * dt;
    Phi(cur, cur) = params_.current.phi(dt);
    Phi(vel, acc) = dt;
    Phi(acc, acc) = params_.acceleration.phi(dt);
  }
  Phi(kLoranX, kLoranX) = params_.loranError.phi(dt);
  Phi(kLoranY, kLoranY) = params_.loranError.phi(dt);
  Phi(kLogBias, kLogBias) = params_.speedlogError.phi(dt);
  Phi(kHeadingBias, kHeadingBias) = params_.headingBias.sigma > 0.0 ? params_.headingBias.phi(dt) : 1.0;
  Phi(kLogScale, kLogScale) = params_.logScale.sigma > 0.0 ? params_.logScale.phi(dt) : 1.0;
  return Phi;
}

}  // namespace reckoner::est::drkf
