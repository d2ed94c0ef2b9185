#include "sim/vessel_motion.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/angles.h"
#include "estimation/discretize.h"
#include "estimation/singer.h"

namespace reckoner::sim {
namespace {
constexpr double kHeadingMinSpeedMps = 0.05;  // below this the ship keeps its last heading

double initialHeading(const VesselMotionSpec& spec) {
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

VesselMotionModel::VesselMotionModel(const VesselMotionSpec& spec, const est::GaussMarkov& current, Rng rng,
                                     TimeUs startUs)
    : spec_(spec),
      current_(current),
      randomAccel_(spec.randomAcceleration.value_or(est::GaussMarkov{0.0, 1.0})),
      rng_(rng) {
  if (!current_.valid() || !randomAccel_.valid())
    throw std::invalid_argument("vessel motion: Gauss-Markov sigma must be >= 0 and beta > 0");
  if (spec.randomShipMotion) {
    const auto& sm = *spec.randomShipMotion;
    if (spec.randomAcceleration)
      throw std::invalid_argument(
          "vessel motion: a random acceleration and a random ship motion exclude each other");
    if (!sm.alongAcceleration.valid() || !sm.turnRate.valid() || !(sm.whiteAccelerationQ >= 0.0) ||
        !(sm.minSpeedMps > 0.0))
      throw std::invalid_argument("vessel motion: invalid random ship motion");
  }
  committed_.commanded = spec.initialVelocityMps;
  committed_.scheduledVel = spec.initialVelocityMps;
  for (auto& r : committed_.random) {
    r.setZero();
    r[1] = rng_.normal(0.0, current_.sigma);      // current from its stationary distribution
    r[3] = rng_.normal(0.0, randomAccel_.sigma);  // so is the random acceleration
  }
  if (spec.randomShipMotion) {  // from their stationary distributions
    committed_.shipAlong = rng_.normal(0.0, spec.randomShipMotion->alongAcceleration.sigma);
    committed_.shipTurn = rng_.normal(0.0, spec.randomShipMotion->turnRate.sigma);
  }
  committed_.headingRad = initialHeading(spec);
  committed_.timeUs = startUs;
  while (committed_.nextEvent < spec_.schedule.size() &&
         spec_.schedule[committed_.nextEvent].timeUs < startUs)
    ++committed_.nextEvent;  // events before the motion starts do not apply
  applyDueEvents(committed_);
  refreshOutputs(committed_);
}

est::Mat<4> VesselMotionModel::transition(TimeUs dtUs) const {
  // Per-axis block [p, c, v, a] of exp(F dt): the current and the Singer velocity/acceleration chain.
  const double dt = toSeconds(dtUs);
  const est::Mat<3> s = est::singerTransition(randomAccel_, dt);  // [p, v, a]
  est::Mat<4> Phi = est::Mat<4>::Identity();
  Phi(0, 1) = -std::expm1(-current_.betaPerS * dt) / current_.betaPerS;
  Phi(1, 1) = current_.phi(dt);
  Phi(0, 2) = s(0, 1);
  Phi(0, 3) = s(0, 2);
  Phi(2, 3) = s(1, 2);
  Phi(3, 3) = s(2, 2);
  return Phi;
}

const VesselMotionModel::AxisDiscretisation& VesselMotionModel::discretisation(TimeUs dtUs) {
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

void VesselMotionModel::applyDueEvents(Motion& m) const {
  const auto& events = spec_.schedule;
  while (m.nextEvent < events.size() && events[m.nextEvent].timeUs <= m.timeUs) {
    const KinematicEvent& e = events[m.nextEvent++];
    m.order = e.order;  // an order holds until the next event
    if (e.order) {
      m.turnRateRadPerS = 0.0;
      continue;
    }
    if (e.setVelocityMps) m.commanded = *e.setVelocityMps;
    if (e.turnRateRadPerS) m.turnRateRadPerS = *e.turnRateRadPerS;
    if (spec_.maxAccelerationMps2 <= 0.0) m.scheduledVel = m.commanded;
  }
}

void VesselMotionModel::substep(Motion& m, TimeUs dtUs, bool noisy) {
  const double dt = toSeconds(dtUs);
  const std::array<double, 2> before = m.scheduledVel;
  if (m.turnRateRadPerS != 0.0) {
    // Table II footnote: Vx' = cos(w dt) Vx + sin(w dt) Vy, Vy' = cos(w dt) Vy - sin(w dt) Vx.
    const double c = std::cos(m.turnRateRadPerS * dt), s = std::sin(m.turnRateRadPerS * dt);
    for (auto* v : {&m.commanded, &m.scheduledVel})
      *v = {c * (*v)[0] + s * (*v)[1], c * (*v)[1] - s * (*v)[0]};
  }
  m.rampAccel = {0.0, 0.0};
  if (m.order) {
    // Helm order: turn towards the ordered heading at the turn-rate limit, change speed at the
    // acceleration limit (either instantly when its limit is 0). The ramp acceleration is the exact
    // mean acceleration of the substep, so the truth's acceleration output stays consistent.
    const double speed = std::hypot(m.scheduledVel[0], m.scheduledVel[1]);
    const double heading =
        speed > kHeadingMinSpeedMps ? bearingOf(m.scheduledVel[0], m.scheduledVel[1]) : m.headingRad;
    const double turn = angleDiff(m.order->headingRad, heading);
    const double rate = m.order->turnRateRadPerS > 0.0 ? m.order->turnRateRadPerS : spec_.maxTurnRateRadPerS;
    const double accel =
        m.order->accelerationMps2 > 0.0 ? m.order->accelerationMps2 : spec_.maxAccelerationMps2;
    const double maxTurn = rate * dt;
    const double newHeading = heading + (rate > 0.0 ? std::clamp(turn, -maxTurn, maxTurn) : turn);
    const double dv = m.order->speedMps - speed;
    const double maxDv = accel * dt;
    const double newSpeed = speed + (accel > 0.0 ? std::clamp(dv, -maxDv, maxDv) : dv);
    const std::array<double, 2> next{newSpeed * std::sin(newHeading), newSpeed * std::cos(newHeading)};
    if (dt > 0.0) m.rampAccel = {(next[0] - before[0]) / dt, (next[1] - before[1]) / dt};
    m.scheduledVel = m.commanded = next;
  } else if (spec_.maxAccelerationMps2 > 0.0) {
    const double dx = m.commanded[0] - m.scheduledVel[0], dy = m.commanded[1] - m.scheduledVel[1];
    const double gap = std::hypot(dx, dy);
    const double reach = spec_.maxAccelerationMps2 * dt;
    if (gap <= reach) {
      m.scheduledVel = m.commanded;
    } else {
      m.rampAccel = {spec_.maxAccelerationMps2 * dx / gap, spec_.maxAccelerationMps2 * dy / gap};
      m.scheduledVel = {m.scheduledVel[0] + m.rampAccel[0] * dt, m.scheduledVel[1] + m.rampAccel[1] * dt};
    }
  } else {
    m.scheduledVel = m.commanded;
  }
  for (int i = 0; i < 2; ++i) m.scheduledDisplacement[i] += 0.5 * (before[i] + m.scheduledVel[i]) * dt;

  if (noisy) {
    const AxisDiscretisation& d = discretisation(dtUs);
    for (auto& r : m.random) {
      const est::Vec<4> w(rng_.normal(), rng_.normal(), rng_.normal(), rng_.normal());
      r = (d.Phi * r + d.sqrtQ * w).eval();
    }
  } else {
    const est::Mat<4> Phi = transition(dtUs);
    for (auto& r : m.random) r = (Phi * r).eval();
  }
  if (spec_.randomShipMotion) shipSubstep(m, dt, noisy);
  m.timeUs += dtUs;
  const double vx = m.scheduledVel[0] + m.random[0][2] + m.shipVel[0],
               vy = m.scheduledVel[1] + m.random[1][2] + m.shipVel[1];
  if (std::hypot(vx, vy) > kHeadingMinSpeedMps) m.headingRad = bearingOf(vx, vy);
}

void VesselMotionModel::shipSubstep(Motion& m, double dt, bool noisy) {
  // dv/dt = a v / max(|v|, minSpeed) + omega (v_y, -v_x) + w for the whole velocity through the water
  // (schedule + ship part), the ship part carrying it (Euler-Maruyama on the 0.1 s grid: the mean
  // rotation error over a step is ~(omega dt)^2 / 2, 1e-7 at a degree a second); a and omega exact
  // Gauss-Markov steps.
  const auto& sm = *spec_.randomShipMotion;
  const double vx = m.scheduledVel[0] + m.shipVel[0], vy = m.scheduledVel[1] + m.shipVel[1];
  const double r = std::max(std::hypot(vx, vy), sm.minSpeedMps);
  const std::array<double, 2> before = m.shipVel;
  m.shipVel[0] += (m.shipAlong * vx / r + m.shipTurn * vy) * dt;
  m.shipVel[1] += (m.shipAlong * vy / r - m.shipTurn * vx) * dt;
  if (noisy) {
    const double w = std::sqrt(sm.whiteAccelerationQ * dt);
    m.shipVel[0] += w * rng_.normal();
    m.shipVel[1] += w * rng_.normal();
    m.shipAlong = sm.alongAcceleration.phi(dt) * m.shipAlong +
                  std::sqrt(sm.alongAcceleration.discreteVariance(dt)) * rng_.normal();
    m.shipTurn =
        sm.turnRate.phi(dt) * m.shipTurn + std::sqrt(sm.turnRate.discreteVariance(dt)) * rng_.normal();
  } else {
    m.shipAlong *= sm.alongAcceleration.phi(dt);
    m.shipTurn *= sm.turnRate.phi(dt);
  }
  for (int i = 0; i < 2; ++i) m.scheduledDisplacement[i] += 0.5 * (before[i] + m.shipVel[i]) * dt;
}

void VesselMotionModel::advanceTo(TimeUs t) {
  const auto& events = spec_.schedule;
  // Commit the random path on the grid and at scheduled events, never at the times asked for.
  while (true) {
    applyDueEvents(committed_);
    TimeUs next = (committed_.timeUs / kGridUs + 1) * kGridUs;
    if (committed_.nextEvent < events.size()) next = std::min(next, events[committed_.nextEvent].timeUs);
    if (next > t) break;
    substep(committed_, next - committed_.timeUs, true);
  }
  applyDueEvents(committed_);
  if (t <= committed_.timeUs) {
    refreshOutputs(committed_);
    return;
  }
  Motion view = committed_;
  substep(view, t - view.timeUs, false);
  refreshOutputs(view);
}

void VesselMotionModel::refreshOutputs(const Motion& m) {
  truth_.timeUs = m.timeUs;
  truth_.position = {spec_.initialPosition.xM + m.scheduledDisplacement[0] + m.random[0][0],
                     spec_.initialPosition.yM + m.scheduledDisplacement[1] + m.random[1][0]};
  truth_.currentXMps = m.random[0][1];
  truth_.currentYMps = m.random[1][1];
  truth_.waterVxMps = m.scheduledVel[0] + m.random[0][2] + m.shipVel[0];
  truth_.waterVyMps = m.scheduledVel[1] + m.random[1][2] + m.shipVel[1];
  // Scheduled acceleration: the turn (d/dt of the Table II rotation) plus any speed ramp.
  truth_.accelXMps2 = m.turnRateRadPerS * m.scheduledVel[1] + m.rampAccel[0] + m.random[0][3];
  truth_.accelYMps2 = -m.turnRateRadPerS * m.scheduledVel[0] + m.rampAccel[1] + m.random[1][3];
  if (spec_.randomShipMotion) {  // the ship part's (its white acceleration has no value to show)
    const double vx = truth_.waterVxMps, vy = truth_.waterVyMps;
    const double r = std::max(std::hypot(vx, vy), spec_.randomShipMotion->minSpeedMps);
    truth_.accelXMps2 += m.shipAlong * vx / r + m.shipTurn * vy;
    truth_.accelYMps2 += m.shipAlong * vy / r - m.shipTurn * vx;
  }
  truth_.headingRad = m.headingRad;
  order_ = m.order;
  if (aground_) {
    truth_.position = *aground_;
    truth_.waterVxMps = -truth_.currentXMps;
    truth_.waterVyMps = -truth_.currentYMps;
    truth_.accelXMps2 = truth_.accelYMps2 = 0.0;
  }
}

void VesselMotionModel::runAground() {
  if (aground_) return;
  aground_ = truth_.position;
  truth_.waterVxMps = -truth_.currentXMps;
  truth_.waterVyMps = -truth_.currentYMps;
  truth_.accelXMps2 = truth_.accelYMps2 = 0.0;
}

bool VesselMotionModel::overrideFrom(const KinematicEvent& e) {
  if (e.timeUs <= committed_.timeUs) return false;
  auto& events = spec_.schedule;
  // Events before the committed one are spent (their effect is in committed_, a view starts from it):
  // drop them once there are many, so that an autopilot's orders over days do not pile up.
  if (committed_.nextEvent >= kSpentEventsKept) {
    events.erase(events.begin(), events.begin() + static_cast<std::ptrdiff_t>(committed_.nextEvent));
    committed_.nextEvent = 0;
  }
  while (events.size() > committed_.nextEvent && events.back().timeUs >= e.timeUs) events.pop_back();
  events.push_back(e);
  return true;
}

}  // namespace reckoner::sim
