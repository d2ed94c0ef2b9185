#include "sim/trial_manoeuvre.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "common/angles.h"
#include "common/units.h"
#include "navigation/drkf.h"
#include "sim/simulation_engine.h"
#include "tracking/ais_fusion.h"
#include "tracking/cpa.h"

namespace reckoner::sim {
namespace {
namespace dk = est::drkf;

double normalCdf(double x) {
  return 0.5 * std::erfc(-x / std::sqrt(2.0));
}

/// Own ship's path under the order, relative to its present position: sampled during the manoeuvre,
/// straight after it.
struct OwnPath {
  double stepS = 0.5;
  std::vector<est::Vec<2>> offset;         ///< own position minus (start + v0 t) at k * stepS
  std::vector<est::Vec<2>> velocity;       ///< own ground velocity at k * stepS
  est::Vec<2> v0 = est::Vec<2>::Zero();    ///< ground velocity now
  est::Vec<2> vEnd = est::Vec<2>::Zero();  ///< ground velocity once the order is reached
  double endS = 0.0;
};

OwnPath ownPathOf(const TrialOwnShip& own, const TrialOrder& order, double stepS) {
  OwnPath p;
  p.stepS = stepS;
  const est::Vec<2> current(own.currentXMps, own.currentYMps);
  const est::Vec<2> water(own.waterVxMps, own.waterVyMps);
  p.v0 = water + current;
  VesselMotionSpec spec;
  spec.initialVelocityMps = {water.x(), water.y()};
  if (water.norm() > 1e-6) spec.initialHeadingRad = bearingOf(water.x(), water.y());
  spec.maxAccelerationMps2 = own.maxAccelerationMps2;
  spec.maxTurnRateRadPerS = own.maxTurnRateRadPerS;
  KinematicEvent e;
  e.timeUs = std::max<TimeUs>(1, fromSeconds(order.delayS));
  e.order = HelmOrder{wrapTwoPi(order.courseRad - own.convergenceRad), order.speedMps, 0.0, 0.0};
  spec.schedule.push_back(e);
  VesselMotionModel model(spec, est::GaussMarkov{0.0, 1.0}, Rng(0, 0), 0);
  // When the order is reached: the delay, the turn at its rate, the speed change at its rate.
  const double heading0 = spec.initialHeadingRad.value_or(e.order->headingRad);
  const double turn = std::abs(angleDiff(e.order->headingRad, heading0));
  const double dv = std::abs(order.speedMps - water.norm());
  p.endS = order.delayS + 2.0;
  if (own.maxTurnRateRadPerS > 0.0) p.endS += turn / own.maxTurnRateRadPerS;
  if (own.maxAccelerationMps2 > 0.0) p.endS += dv / own.maxAccelerationMps2;
  p.endS = std::min(p.endS, 7200.0);
  const int n = static_cast<int>(std::ceil(p.endS / stepS));
  for (int k = 0; k <= n; ++k) {
    const double t = k * stepS;
    model.advanceTo(fromSeconds(t));
    const VesselTruth& s = model.state();
    p.offset.emplace_back(s.position.xM + current.x() * t - p.v0.x() * t,
                          s.position.yM + current.y() * t - p.v0.y() * t);
    p.velocity.emplace_back(s.waterVxMps + current.x(), s.waterVyMps + current.y());
  }
  p.endS = n * stepS;
  p.vEnd = p.velocity.back();
  return p;
}

/// Own ship at t (s from now) relative to where it is now.
est::Vec<2> ownAt(const OwnPath& p, double t) {
  const auto k = static_cast<std::size_t>(std::clamp(t, 0.0, p.endS) / p.stepS);
  est::Vec<2> at = p.v0 * t + p.offset[std::min(k, p.offset.size() - 1)];
  if (t > p.endS) at += (p.vEnd - p.v0) * (t - p.endS);
  return at;
}

/// The covariance of the equivalent straight encounter's (r', u) (trial_manoeuvre.h).
est::Mat<4> equivalentCovariance(const TrialTargetInput& in, const TrialOwnShip& own, double tSwitch) {
  Eigen::Matrix<double, 4, 6> M = Eigen::Matrix<double, 4, 6>::Zero();
  M.block<2, 2>(0, 0).setIdentity();
  M.block<2, 2>(0, 4) = -tSwitch * est::Mat<2>::Identity();
  M.block<2, 2>(2, 2).setIdentity();
  Eigen::Matrix<double, 4, 2> N;
  N << tSwitch * est::Mat<2>::Identity(), -est::Mat<2>::Identity();
  est::Mat<4> P = M * in.covariance * M.transpose() + N * own.currentCovariance * N.transpose();
  est::symmetrise(P);
  return P;
}

TrialTargetResult trialTarget(const TrialTargetInput& in, const TrialOwnShip& own, const OwnPath& path,
                              const TrialOrder& order, const TrialSettings& s) {
  TrialTargetResult r;
  r.trackId = in.trackId;
  r.mmsi = in.mmsi;
  const est::Gaussian<4> rel = in.relative();
  const track::Cpa present = track::cpaOf(rel.x, rel.P);
  r.presentCpaM = present.cpaM;
  r.presentTcpaS = present.tcpaS;
  r.sdPresentCpaM = present.sdCpaM;
  const est::Vec<2> r0 = rel.x.head<2>(), v = rel.x.tail<2>();
  double best = std::numeric_limits<double>::infinity(), tStar = 0.0;
  est::Vec<2> dStar = r0, uStar = v;
  for (std::size_t k = 0; k < path.offset.size(); ++k) {
    const double t = static_cast<double>(k) * path.stepS;
    const est::Vec<2> d = r0 + v * t - path.offset[k];
    if (d.norm() < best) {
      best = d.norm();
      tStar = t;
      dStar = d;
      uStar = v - (path.velocity[k] - path.v0);
    }
  }
  // After the manoeuvre: straight relative motion from the path's end.
  const est::Vec<2> u = v - (path.vEnd - path.v0);
  const est::Vec<2> dEnd = r0 + v * path.endS - path.offset.back();
  const double uu = u.squaredNorm();
  const double tt = uu > 1e-12 ? std::max(0.0, -dEnd.dot(u) / uu) : 0.0;
  if ((dEnd + u * tt).norm() < best) {
    dStar = dEnd + u * tt;
    best = dStar.norm();
    tStar = path.endS + tt;
    uStar = u;
  }
  r.cpaM = best;
  r.tcpaS = tStar;
  // The equivalent straight encounter: start r' = d* - u* t*, velocity u*.
  est::Vec<4> equivalent;
  equivalent << dStar - uStar * tStar, uStar;
  const double tSwitch = std::min(tStar, 0.5 * (order.delayS + path.endS));
  const est::Mat<4> Peq = equivalentCovariance(in, own, tSwitch);
  const track::Cpa eq = track::cpaOf(equivalent, Peq);
  r.sdCpaM = eq.sdCpaM;
  r.sdTcpaS = eq.sdTcpaS;
  double signedMiss = best, sd = eq.sdCpaM;
  if (uStar.norm() > track::kMinRelativeSpeedMps) {
    const est::Vec<2> n(-uStar.y() / uStar.norm(), uStar.x() / uStar.norm());
    signedMiss = dStar.dot(n);
    est::Vec<4> g;
    g << n, tStar * n;
    sd = std::sqrt(std::max(0.0, g.dot(Peq * g)));
    r.sdCpaM = sd;
  }
  const double L = s.cpaLimitM;
  if (sd > 1e-9)
    r.probabilityBelowLimit = normalCdf((L - signedMiss) / sd) - normalCdf((-L - signedMiss) / sd);
  else
    r.probabilityBelowLimit = std::abs(signedMiss) < L ? 1.0 : 0.0;
  r.dangerous = r.cpaM <= L && r.tcpaS <= s.tcpaLimitS;
  return r;
}

DangerSectors dangerSectors(const TrialOwnShip& own, const std::vector<TrialTargetInput>& targets,
                            const TrialOrder& order, const TrialSettings& s) {
  DangerSectors d;
  const est::Vec<2> current(own.currentXMps, own.currentYMps);
  const est::Vec<2> v0 = est::Vec<2>(own.waterVxMps, own.waterVyMps) + current;
  double maxSpeed = s.sectorMaxSpeedMps;
  if (!(maxSpeed > 0.0))
    maxSpeed = std::max(knotsToMps(10.0),
                        1.5 * std::max(order.speedMps, std::hypot(own.waterVxMps, own.waterVyMps)));
  d.courses = std::max(1, s.sectorCourses);
  const int rings = std::max(1, s.sectorSpeeds);
  for (int i = 1; i <= rings; ++i) d.speedsMps.push_back(maxSpeed * i / rings);
  d.danger.assign(d.speedsMps.size() * static_cast<std::size_t>(d.courses), 0);
  for (std::size_t i = 0; i < d.speedsMps.size(); ++i) {
    for (int j = 0; j < d.courses; ++j) {
      const double c = kTwoPi * j / d.courses - own.convergenceRad;
      const est::Vec<2> w = d.speedsMps[i] * est::Vec<2>(std::sin(c), std::cos(c)) + current;
      for (const auto& t : targets) {
        // Own ship holds its velocity through the delay, then sails w.
        const est::Vec<2> r0 = t.state.head<2>() + (t.state.segment<2>(2) - v0) * order.delayS;
        const est::Vec<2> u = t.state.segment<2>(2) - w;
        const double uu = u.squaredNorm();
        const double tt = uu > 1e-12 ? std::max(0.0, -r0.dot(u) / uu) : 0.0;
        if ((r0 + u * tt).norm() <= s.cpaLimitM && order.delayS + tt <= s.tcpaLimitS) {
          d.danger[i * static_cast<std::size_t>(d.courses) + static_cast<std::size_t>(j)] = 1;
          break;
        }
      }
    }
  }
  return d;
}
}  // namespace

std::vector<std::pair<int, int>> DangerSectors::dangerousRuns(std::size_t ring) const {
  std::vector<std::pair<int, int>> runs;
  if (ring >= speedsMps.size()) return runs;
  const auto at = [&](int j) {
    return danger[ring * static_cast<std::size_t>(courses) + static_cast<std::size_t>(j)];
  };
  for (int j = 0; j < courses;) {
    if (!at(j)) {
      ++j;
      continue;
    }
    int k = j;
    while (k + 1 < courses && at(k + 1)) ++k;
    runs.emplace_back(j, k);
    j = k + 1;
  }
  return runs;
}

TrialResult trialManoeuvre(TimeUs timeUs, const TrialOwnShip& own,
                           const std::vector<TrialTargetInput>& targets, const TrialOrder& order,
                           const TrialSettings& settings) {
  TrialResult r;
  r.timeUs = timeUs;
  r.order = order;
  const bool finite = std::isfinite(order.courseRad) && std::isfinite(order.speedMps) &&
                      std::isfinite(order.delayS) && order.speedMps >= 0.0 && order.delayS >= 0.0 &&
                      order.delayS <= 3600.0 && std::isfinite(own.waterVxMps) &&
                      std::isfinite(own.waterVyMps) && std::isfinite(own.currentXMps) &&
                      std::isfinite(own.currentYMps) && settings.stepS > 0.0;
  if (!finite) return r;
  const OwnPath path = ownPathOf(own, order, settings.stepS);
  r.manoeuvreEndS = path.endS;
  for (double t = 0.0; t <= path.endS + 600.0; t += 10.0) {
    const est::Vec<2> at = ownAt(path, t);
    r.ownPath.push_back({own.position.xM + at.x(), own.position.yM + at.y()});
  }
  for (const auto& t : targets) {
    if (!t.state.allFinite() || !t.covariance.allFinite()) continue;
    TrialTargetResult tr = trialTarget(t, own, path, order, settings);
    const est::Vec<2> target =
        est::Vec<2>(own.position.xM, own.position.yM) + t.state.head<2>() + t.state.segment<2>(2) * tr.tcpaS;
    tr.targetAtCpa = {target.x(), target.y()};
    r.targets.push_back(tr);
  }
  for (auto& tr : r.targets) {
    const est::Vec<2> at = ownAt(path, tr.tcpaS);
    tr.ownAtCpa = {own.position.xM + at.x(), own.position.yM + at.y()};
  }
  r.sectors = dangerSectors(own, targets, order, settings);
  return r;
}

est::Gaussian<4> TrialTargetInput::relative() const {
  Eigen::Matrix<double, 4, 6> A = Eigen::Matrix<double, 4, 6>::Zero();
  A.block<2, 2>(0, 0).setIdentity();
  A.block<2, 2>(2, 2).setIdentity();
  A.block<2, 2>(2, 4) = -est::Mat<2>::Identity();
  est::Gaussian<4> g;
  g.x = A * state;
  g.P = A * covariance * A.transpose();
  est::symmetrise(g.P);
  return g;
}

TrialOwnShip trialOwnShipOf(const SimFrame& f, const VesselMotionSpec& vessel, const geo::LocalFrame& frame) {
  TrialOwnShip o;
  const auto& x = f.estimate.x;
  o.position = {x[dk::kPosX], x[dk::kPosY]};
  o.waterVxMps = x[dk::kVelX];
  o.waterVyMps = x[dk::kVelY];
  o.currentXMps = x[dk::kCurX];
  o.currentYMps = x[dk::kCurY];
  const auto& P = f.estimate.P;
  o.currentCovariance << P(dk::kCurX, dk::kCurX), P(dk::kCurX, dk::kCurY), P(dk::kCurY, dk::kCurX),
      P(dk::kCurY, dk::kCurY);
  o.convergenceRad = frame.gridInfo(o.position).convergenceRad;
  o.maxTurnRateRadPerS = vessel.maxTurnRateRadPerS;
  o.maxAccelerationMps2 = vessel.maxAccelerationMps2;
  return o;
}

std::vector<TrialTargetInput> trialTargetsOf(const SimFrame& f, const track::AisErrorModel& errors,
                                             const geo::LocalFrame& frame) {
  std::vector<TrialTargetInput> out;
  namespace tk = est::ttkf;
  // [target - own position, target velocity, own velocity] from the 12-state belief.
  Eigen::Matrix<double, 6, tk::kStateDim> A = Eigen::Matrix<double, 6, tk::kStateDim>::Zero();
  A(0, tk::kTgtX) = A(1, tk::kTgtY) = 1.0;
  A(0, tk::kOwnX) = A(1, tk::kOwnY) = -1.0;
  A(2, tk::kTgtVx) = A(3, tk::kTgtVy) = 1.0;
  A(4, tk::kOwnVx) = A(5, tk::kOwnVy) = 1.0;
  std::set<std::uint32_t> associated;
  for (const auto& t : f.tracks) {
    if (t.status != track::TrackStatus::Confirmed) continue;
    TrialTargetInput in;
    in.trackId = t.trackId;
    in.mmsi = t.aisMmsi;
    in.state = A * t.estimate.x;
    in.covariance = A * t.estimate.P * A.transpose();
    out.push_back(in);
    if (t.aisMmsi) associated.insert(t.aisMmsi);
  }
  if (!f.aisTargets) return out;
  const est::Vec<4> own = nav::groundStateOf(f.estimate);
  const est::Mat<4> ownP = nav::groundCovarianceOf(f.estimate);
  for (const auto& a : *f.aisTargets) {
    if (a.lost || associated.contains(a.mmsi) || !a.hasPosition() || !a.sogKn || !a.cogDeg) continue;
    io::AisMessage m;
    m.type = a.cls == track::AisClass::B ? 18 : 1;
    m.mmsi = a.mmsi;
    m.latDeg = a.latDeg;
    m.lonDeg = a.lonDeg;
    m.sogKn = a.sogKn;
    m.cogDeg = a.cogDeg;
    m.headingDeg = a.headingDeg;
    const auto o = track::aisObservation(m, a.lastPositionUs, a.info, frame, errors, -1);
    if (!o) continue;
    const est::Gaussian<4> g = o->at(f.timeUs, false);
    TrialTargetInput in;
    in.mmsi = a.mmsi;
    in.state << g.x.head<2>() - own.head<2>(), g.x.tail<2>(), own.tail<2>();
    // Target and own ship independent: r = p_t - p_o, the velocities as they are.
    Eigen::Matrix<double, 6, 8> B = Eigen::Matrix<double, 6, 8>::Zero();
    B.block<2, 2>(0, 0).setIdentity();
    B.block<2, 2>(0, 4) = -est::Mat<2>::Identity();
    B.block<2, 2>(2, 2).setIdentity();
    B.block<2, 2>(4, 6).setIdentity();
    Eigen::Matrix<double, 8, 8> joint = Eigen::Matrix<double, 8, 8>::Zero();
    joint.topLeftCorner<4, 4>() = g.P;
    joint.bottomRightCorner<4, 4>() = ownP;
    in.covariance = B * joint * B.transpose();
    out.push_back(in);
  }
  return out;
}

}  // namespace reckoner::sim
