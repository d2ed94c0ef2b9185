#include "estimation/models/drkf_process.h"

#include <algorithm>
#include <array>
#include <cmath>
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

  const ShipMotionParams& ship = params.ship;
  if (ship.enabled) {
    check(ship.alongAcceleration, "along-track acceleration");
    check(ship.turnRate, "turn rate");
    if (!(ship.whiteAccelerationQ >= 0.0 && std::isfinite(ship.whiteAccelerationQ)) ||
        !(ship.minSpeedMps > 0.0 && std::isfinite(ship.minSpeedMps)))
      throw std::invalid_argument(
          "DRKF process model: ship motion needs a finite white acceleration >= 0 and a minimum speed > 0");
  }
  shipF_ = F_;
  shipF_(kVelX, kAccX) = 0.0;  // the velocity rows are the nonlinear part (jacobianAt)
  shipF_(kVelY, kAccY) = 0.0;
  shipF_(kAlongAccel, kAlongAccel) = -ship.alongAcceleration.betaPerS;
  shipF_(kTurnRate, kTurnRate) = -ship.turnRate.betaPerS;
  shipG_.setZero();
  shipG_(kCurX, 0) = params.current.alpha();
  shipG_(kCurY, 1) = params.current.alpha();
  shipG_(kAlongAccel, 2) = ship.alongAcceleration.alpha();
  shipG_(kTurnRate, 3) = ship.turnRate.alpha();
  shipG_(kVelX, 4) = std::sqrt(std::max(0.0, ship.whiteAccelerationQ));
  shipG_(kVelY, 5) = std::sqrt(std::max(0.0, ship.whiteAccelerationQ));
  shipG_(kLoranX, 6) = params.loranError.alpha();
  shipG_(kLoranY, 7) = params.loranError.alpha();
  shipG_(kLogBias, 8) = params.speedlogError.alpha();
  shipG_(kHeadingBias, 9) = params.headingBias.alpha();
  shipG_(kLogScale, 10) = params.logScale.alpha();
}

State ProcessModel::derivative(const State& x) const {
  State d = shipF_ * x;
  const double vx = x[kVelX], vy = x[kVelY];
  const double r = std::max(std::hypot(vx, vy), params_.ship.minSpeedMps);
  const double a = x[kAlongAccel], w = x[kTurnRate];
  d[kVelX] += a * vx / r + w * vy;
  d[kVelY] += a * vy / r - w * vx;
  return d;
}

Mat<kStateDim> ProcessModel::jacobianAt(const State& x) const {
  Mat<kStateDim> J = shipF_;
  const double vx = x[kVelX], vy = x[kVelY], speed = std::hypot(vx, vy);
  const double a = x[kAlongAccel], w = x[kTurnRate];
  if (speed > params_.ship.minSpeedMps) {  // a v / |v|: a (I - u u^T) / |v|
    const double ux = vx / speed, uy = vy / speed;
    J(kVelX, kVelX) = a * (1.0 - ux * ux) / speed;
    J(kVelX, kVelY) = -a * ux * uy / speed;
    J(kVelY, kVelX) = -a * ux * uy / speed;
    J(kVelY, kVelY) = a * (1.0 - uy * uy) / speed;
    J(kVelX, kAlongAccel) = ux;
    J(kVelY, kAlongAccel) = uy;
  } else {  // a v / minSpeed
    const double m = params_.ship.minSpeedMps;
    J(kVelX, kVelX) = a / m;
    J(kVelY, kVelY) = a / m;
    J(kVelX, kAlongAccel) = vx / m;
    J(kVelY, kAlongAccel) = vy / m;
  }
  J(kVelX, kVelY) += w;  // omega (vy, -vx)
  J(kVelY, kVelX) -= w;
  J(kVelX, kTurnRate) = vy;
  J(kVelY, kTurnRate) = -vx;
  return J;
}

State ProcessModel::propagate(const State& x, double dtS) const {
  constexpr double kMaxStepS = 0.25;
  const int n = std::max(1, static_cast<int>(std::ceil(dtS / kMaxStepS)));
  const double h = dtS / n;
  State y = x;
  for (int i = 0; i < n; ++i) {
    const State k1 = derivative(y);
    const State k2 = derivative(y + 0.5 * h * k1);
    const State k3 = derivative(y + 0.5 * h * k2);
    const State k4 = derivative(y + h * k3);
    y += (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  return y;
}

Discretised<kStateDim> ProcessModel::discretiseAt(const State& x, double dtS) const {
  // Only position, current, velocity, along-track acceleration and turn rate are coupled; Loran-C,
  // log offset, heading bias and log scale are independent Gauss-Markov states with exact scalar
  // steps. Van Loan on the coupled 8 (a 16 x 16 exponential rather than 26 x 26: a quarter of the work).
  static constexpr std::array<int, 8> kCoupled{kPosX, kPosY, kCurX,       kCurY,
                                               kVelX, kVelY, kAlongAccel, kTurnRate};
  static constexpr std::array<int, 6> kCoupledNoise{0, 1, 2, 3, 4, 5};  // current, a, omega, white
  const Mat<kStateDim> J = jacobianAt(x);
  Mat<8> F8;
  MatRC<8, 6> G8;
  for (std::size_t i = 0; i < 8; ++i) {
    for (std::size_t j = 0; j < 8; ++j)
      F8(static_cast<int>(i), static_cast<int>(j)) = J(kCoupled[i], kCoupled[j]);
    for (std::size_t k = 0; k < 6; ++k)
      G8(static_cast<int>(i), static_cast<int>(k)) = shipG_(kCoupled[i], kCoupledNoise[k]);
  }
  const auto d8 = discretiseVanLoan<8, 6>(F8, G8, dtS);
  Discretised<kStateDim> d;
  d.Phi.setZero();
  d.Q.setZero();
  for (std::size_t i = 0; i < 8; ++i)
    for (std::size_t j = 0; j < 8; ++j) {
      d.Phi(kCoupled[i], kCoupled[j]) = d8.Phi(static_cast<int>(i), static_cast<int>(j));
      d.Q(kCoupled[i], kCoupled[j]) = d8.Q(static_cast<int>(i), static_cast<int>(j));
    }
  for (const int i : {kLoranX, kLoranY, kLogBias, kHeadingBias, kLogScale}) {
    const double f = shipF_(i, i), g = shipG_.row(i).squaredNorm();  // dx = f x dt + g^(1/2) dw
    const double phi = std::exp(f * dtS);
    d.Phi(i, i) = phi;
    d.Q(i, i) = f != 0.0 ? g * std::expm1(2.0 * f * dtS) / (2.0 * f) : g * dtS;
  }
  return d;
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
