#include "sim/own_ship_truth.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/angles.h"
#include "estimation/discretize.h"

namespace reckoner::sim {
namespace {
constexpr double kHeadingMinSpeedMps = 0.05;  // below this the ship keeps its last heading

double initialHeading(const OwnShipSpec& spec) {
  if (spec.initialHeadingRad) return wrapTwoPi(*spec.initialHeadingRad);
  const auto& v0 = spec.initialVelocityMps;
  if (std::hypot(v0[0], v0[1]) > 0.0) return bearingOf(v0[0], v0[1]);
  for (const auto& e : spec.schedule) {
    if (e.setVelocityMps && std::hypot((*e.setVelocityMps)[0], (*e.setVelocityMps)[1]) > 0.0)
      return bearingOf((*e.setVelocityMps)[0], (*e.setVelocityMps)[1]);
  }
  return 0.0;
}
}  // namespace

OwnShipTruthModel::OwnShipTruthModel(const OwnShipSpec& spec, const est::GaussMarkov& current, Rng rng)
    : spec_(spec),
      current_(current),
      randomAccel_(spec.randomAcceleration.value_or(est::GaussMarkov{0.0, 1.0})),
      rng_(rng) {
  if (!current_.valid() || !randomAccel_.valid())
    throw std::invalid_argument("own-ship truth: Gauss-Markov sigma must be >= 0 and beta > 0");
  commanded_ = spec.initialVelocityMps;
  scheduledVel_ = spec.initialVelocityMps;
  for (auto& r : random_) {
    r.setZero();
    r[1] = rng_.normal(0.0, current_.sigma);      // current from its stationary distribution
    r[3] = rng_.normal(0.0, randomAccel_.sigma);  // so is the random acceleration
  }
  truth_.headingRad = initialHeading(spec);
  while (nextEvent_ < spec_.schedule.size() && spec_.schedule[nextEvent_].timeUs <= 0)
    applyEvent(spec_.schedule[nextEvent_++]);
  refreshOutputs();
}

const OwnShipTruthModel::AxisDiscretisation& OwnShipTruthModel::discretisation(TimeUs dtUs) {
  for (const auto& c : cache_)
    if (c.dtUs == dtUs) return c;
  // Per-axis block of the DRKF model (seed 000 eq. 4c): [position, current, velocity, acceleration].
  est::Mat<4> F = est::Mat<4>::Zero();
  F(0, 1) = F(0, 2) = 1.0;
  F(1, 1) = -current_.betaPerS;
  F(2, 3) = 1.0;
  F(3, 3) = -randomAccel_.betaPerS;
  est::MatRC<4, 2> G = est::MatRC<4, 2>::Zero();
  G(1, 0) = current_.alpha();
  G(3, 1) = randomAccel_.alpha();
  const auto d = est::discretiseVanLoan<4, 2>(F, G, toSeconds(dtUs));
  const Eigen::SelfAdjointEigenSolver<est::Mat<4>> eig(d.Q);
  AxisDiscretisation& slot = cache_[cacheNext_];
  cacheNext_ = (cacheNext_ + 1) % cache_.size();
  slot.dtUs = dtUs;
  slot.Phi = d.Phi;
  slot.sqrtQ = eig.eigenvectors() * eig.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();
  return slot;
}

void OwnShipTruthModel::applyEvent(const KinematicEvent& e) {
  if (e.setVelocityMps) commanded_ = *e.setVelocityMps;
  if (e.turnRateRadPerS) turnRateRadPerS_ = *e.turnRateRadPerS;
  if (spec_.maxAccelerationMps2 <= 0.0) scheduledVel_ = commanded_;
}

void OwnShipTruthModel::substep(TimeUs dtUs) {
  const double dt = toSeconds(dtUs);
  const std::array<double, 2> before = scheduledVel_;
  if (turnRateRadPerS_ != 0.0) {
    // Table II footnote: Vx' = cos(w dt) Vx + sin(w dt) Vy, Vy' = cos(w dt) Vy - sin(w dt) Vx.
    const double c = std::cos(turnRateRadPerS_ * dt), s = std::sin(turnRateRadPerS_ * dt);
    for (auto* v : {&commanded_, &scheduledVel_}) *v = {c * (*v)[0] + s * (*v)[1], c * (*v)[1] - s * (*v)[0]};
  }
  rampAccel_ = {0.0, 0.0};
  auto& rampAccel = rampAccel_;
  if (spec_.maxAccelerationMps2 > 0.0) {
    const double dx = commanded_[0] - scheduledVel_[0], dy = commanded_[1] - scheduledVel_[1];
    const double gap = std::hypot(dx, dy);
    const double reach = spec_.maxAccelerationMps2 * dt;
    if (gap <= reach) {
      scheduledVel_ = commanded_;
    } else {
      rampAccel = {spec_.maxAccelerationMps2 * dx / gap, spec_.maxAccelerationMps2 * dy / gap};
      scheduledVel_ = {scheduledVel_[0] + rampAccel[0] * dt, scheduledVel_[1] + rampAccel[1] * dt};
    }
  } else {
    scheduledVel_ = commanded_;
  }
  for (int i = 0; i < 2; ++i) scheduledDisplacement_[i] += 0.5 * (before[i] + scheduledVel_[i]) * dt;

  const AxisDiscretisation& d = discretisation(dtUs);
  for (auto& r : random_) {
    const est::Vec<4> w(rng_.normal(), rng_.normal(), rng_.normal(), rng_.normal());
    r = (d.Phi * r + d.sqrtQ * w).eval();
  }
  truth_.timeUs += dtUs;
}

void OwnShipTruthModel::advanceTo(TimeUs t) {
  const auto& events = spec_.schedule;
  while (truth_.timeUs < t) {
    while (nextEvent_ < events.size() && events[nextEvent_].timeUs <= truth_.timeUs)
      applyEvent(events[nextEvent_++]);
    TimeUs end = std::min(t, truth_.timeUs + kMaxSubstepUs);
    if (nextEvent_ < events.size()) end = std::min(end, events[nextEvent_].timeUs);
    substep(end - truth_.timeUs);
  }
  while (nextEvent_ < events.size() && events[nextEvent_].timeUs <= truth_.timeUs)
    applyEvent(events[nextEvent_++]);
  refreshOutputs();
}

void OwnShipTruthModel::refreshOutputs() {
  truth_.position = {spec_.initialPosition.xM + scheduledDisplacement_[0] + random_[0][0],
                     spec_.initialPosition.yM + scheduledDisplacement_[1] + random_[1][0]};
  truth_.currentXMps = random_[0][1];
  truth_.currentYMps = random_[1][1];
  truth_.waterVxMps = scheduledVel_[0] + random_[0][2];
  truth_.waterVyMps = scheduledVel_[1] + random_[1][2];
  // Scheduled acceleration: the turn (d/dt of the Table II rotation) plus any speed ramp.
  truth_.accelXMps2 = turnRateRadPerS_ * scheduledVel_[1] + rampAccel_[0] + random_[0][3];
  truth_.accelYMps2 = -turnRateRadPerS_ * scheduledVel_[0] + rampAccel_[1] + random_[1][3];
  if (std::hypot(truth_.waterVxMps, truth_.waterVyMps) > kHeadingMinSpeedMps)
    truth_.headingRad = bearingOf(truth_.waterVxMps, truth_.waterVyMps);
}

}  // namespace reckoner::sim
