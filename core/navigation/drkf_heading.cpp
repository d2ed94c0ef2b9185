// The DRKF's heading-only update under a ship's motion model (docs/drkf.md, "Ship motion"): a heading
// with no log in its epoch, applied after the stack with a gain that leaves the speed alone, or, when
// the velocity's direction is too uncertain to linearise atan2, re-anchoring the direction.
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "common/angles.h"
#include "estimation/models/drkf_gyro.h"
#include "navigation/drkf.h"

namespace reckoner::nav {
namespace {
using namespace est::drkf;

/// The variance of the velocity through the water across its own direction (m^2/s^2), at speed
/// |(x3, x7)| = speedMps > 0.
double acrossTrackVelocityVariance(const Belief& b, double speedMps) {
  const State& x = b.x;
  const Covariance& P = b.P;
  const double nx = x[kVelY] / speedMps, ny = -x[kVelX] / speedMps;
  return nx * nx * P(kVelX, kVelX) + 2.0 * nx * ny * P(kVelX, kVelY) + ny * ny * P(kVelY, kVelY);
}

/// A heading's Kalman gain with its components along the velocity through the water removed (for the
/// velocity, position and current pairs) and none on the along-track acceleration: the gain of a
/// heading that says nothing about the speed.
est::Vec<kStateDim> speedPreservingGain(est::Vec<kStateDim> K, const State& x, double speedMps) {
  const double ux = x[kVelX] / speedMps, uy = x[kVelY] / speedMps;
  for (const auto& [ix, iy] : {std::pair{kVelX, kVelY}, std::pair{kPosX, kPosY}, std::pair{kCurX, kCurY}}) {
    const double along = K[ix] * ux + K[iy] * uy;
    K[ix] -= along * ux;
    K[iy] -= along * uy;
  }
  K[kAlongAccel] = 0.0;
  return K;
}
}  // namespace

est::BlockReport Drkf::headingOnlyUpdate(TimeUs t, const sensors::GyroSample& s, const geo::GridInfo& g) {
  // The gyro's model (drkf_gyro.h) with the Kalman gain K = P H^T / S projected so that it moves neither
  // the speed through the water (the velocity along its own direction) nor the along-track
  // acceleration: a heading carries no information about the speed, and the full gain's speed
  // component, which comes from the linearisation of atan2 in a Cartesian velocity, drives the speed of
  // a ship with no log away within minutes (docs/drkf.md, "Ship motion"). Any gain is valid in the
  // Joseph form: P stays this estimator's covariance.
  est::BlockReport rep{kGyro,
                       1,
                       std::numeric_limits<double>::quiet_NaN(),
                       gateFor(kGyro, 1, t),
                       false,
                       -1,
                       est::UpdateStatus::Empty};
  const State& x = belief_.x;
  const double speed = std::hypot(x[kVelX], x[kVelY]);
  if (!(speed >= config_.minSpeedMps)) {
    rep.status = est::UpdateStatus::RejectedDegenerate;
    return rep;
  }
  const HeadingFix fix{wrapTwoPi(s.headingRad - g.convergenceRad), s.varRad2,
                       config_.process.headingBias.sigma > 0.0, speed};
  // atan2 is near-linear when the direction is known: the velocity's sd across its own direction, not
  // along it (an uncertain speed of a ship underway does not make its heading ambiguous).
  const double acrossVar = acrossTrackVelocityVariance(belief_, speed);
  if (!(speed >= config_.minSpeedSigmas * std::sqrt(std::max(0.0, acrossVar))))
    return reanchorHeading(fix, rep);
  return speedPreservingHeadingUpdate(fix, rep);
}

est::BlockReport Drkf::reanchorHeading(const HeadingFix& fix, est::BlockReport rep) {
  // The direction is too uncertain for atan2's linearisation (no heading for a minute or more): the
  // heading re-anchors it. The velocity turns to the measured heading (less the estimated bias) at
  // its estimated speed; across it the variance becomes the heading's and the bias's, uncorrelated
  // with the rest (dropping those correlations keeps P positive definite).
  const State& x = belief_.x;
  const Covariance& P = belief_.P;
  const double heading = fix.zRad - (fix.withBias ? x[kHeadingBias] : 0.0);
  const double ux = std::sin(heading), uy = std::cos(heading);
  // Rotate P's velocity block to (along, across) of the new direction, reset the across row.
  Covariance M = Covariance::Identity();
  M(kVelX, kVelX) = ux;
  M(kVelX, kVelY) = uy;  // along = u . v
  M(kVelY, kVelX) = uy;
  M(kVelY, kVelY) = -ux;  // across = n . v, n = (uy, -ux)
  Covariance Pr = M * P * M.transpose();
  const double across =
      fix.speedMps * fix.speedMps * (fix.varRad2 + (fix.withBias ? P(kHeadingBias, kHeadingBias) : 0.0));
  Pr.row(kVelY).setZero();
  Pr.col(kVelY).setZero();
  Pr(kVelY, kVelY) = across;
  Covariance Pn = M.transpose() * Pr * M;  // M is orthogonal and symmetric here
  est::symmetrise(Pn);
  State xn = x;
  xn[kVelX] = fix.speedMps * ux;
  xn[kVelY] = fix.speedMps * uy;
  if (!xn.allFinite() || !Pn.allFinite()) {
    rep.status = est::UpdateStatus::RejectedNumerical;
    return rep;
  }
  belief_.x = xn;
  belief_.P = Pn;
  rep.forced = true;
  rep.status = est::UpdateStatus::AcceptedForced;
  return rep;
}

est::BlockReport Drkf::speedPreservingHeadingUpdate(const HeadingFix& fix, est::BlockReport rep) {
  const State& x = belief_.x;
  const Covariance& P = belief_.P;
  // The innovation and its variance, eq. 7b row 8 (of the water velocity, drkf_gyro.h).
  const GyroHeadingModel model(config_.minSpeedMps, fix.withBias);
  const double y = model.residual(est::Vec<1>(fix.zRad), model.h(x))[0];
  const est::MatRC<1, kStateDim> H = model.jacobian(x);
  const est::Vec<kStateDim> PHt = P * H.transpose();
  const double S = H.dot(PHt) + fix.varRad2;
  if (!std::isfinite(y) || !std::isfinite(S) || !(S > 0.0)) {
    rep.status = est::UpdateStatus::RejectedNumerical;
    return rep;
  }
  // The gate on the NIS y^2 / S.
  rep.nis = y * y / S;
  if (rep.gate > 0.0 && rep.nis > rep.gate) {
    rep.status = est::UpdateStatus::RejectedGate;
    return rep;
  }
  // Joseph form with the projected gain: P = (I - K H) P (I - K H)^T + K R K^T, x += K y.
  const est::Vec<kStateDim> K = speedPreservingGain(PHt / S, x, fix.speedMps);
  const Covariance A = Covariance::Identity() - K * H;
  Covariance Pn = A.lazyProduct(P).lazyProduct(A.transpose()) + (fix.varRad2 * K) * K.transpose();
  est::symmetrise(Pn);
  const State xn = x + K * y;
  if (!xn.allFinite() || !Pn.allFinite()) {
    rep.status = est::UpdateStatus::RejectedNumerical;
    return rep;
  }
  belief_.x = xn;
  belief_.P = Pn;
  rep.status = est::UpdateStatus::Accepted;
  return rep;
}

}  // namespace reckoner::nav
