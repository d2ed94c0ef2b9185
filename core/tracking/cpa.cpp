#include "tracking/cpa.h"

#include <cmath>

#include "common/angles.h"

namespace reckoner::track {
namespace tk = est::ttkf;

est::MatRC<2, 4> cpaJacobian(const est::Vec<4>& rel) {
  const est::Vec<2> r = rel.head<2>(), v = rel.tail<2>();
  const double vv = v.squaredNorm(), rv = r.dot(v);
  const double tau = -rv / vv;
  // d tau / d r = -v / |v|^2;  d tau / d v = -r / |v|^2 + 2 (r . v) v / |v|^4
  const est::Vec<2> dTauDr = -v / vv;
  const est::Vec<2> dTauDv = -r / vv + 2.0 * rv * v / (vv * vv);
  // d = r + v tau;  d cpa = u^T dd with u = d / |d|;  dd/dr = I + v dTauDr^T, dd/dv = tau I + v dTauDv^T
  const est::Vec<2> d = r + v * tau;
  const double cpa = d.norm();
  est::MatRC<2, 4> J;
  J.row(1) << dTauDr.transpose(), dTauDv.transpose();
  if (cpa > 1e-9) {
    const est::Vec<2> u = d / cpa;
    const est::Mat<2> ddr = est::Mat<2>::Identity() + v * dTauDr.transpose();
    const est::Mat<2> ddv = tau * est::Mat<2>::Identity() + v * dTauDv.transpose();
    J.block<1, 2>(0, 0) = u.transpose() * ddr;
    J.block<1, 2>(0, 2) = u.transpose() * ddv;
  } else {
    J.row(0).setZero();  // |d| is not differentiable at a collision course; first order gives 0
  }
  return J;
}

Cpa cpaOf(const est::Vec<4>& rel, const est::Mat<4>& P) {
  Cpa c;
  const est::Vec<2> r = rel.head<2>(), v = rel.tail<2>();
  if (!rel.allFinite()) return c;
  if (v.norm() < kMinRelativeSpeedMps) {
    c.cpaM = r.norm();
    const est::Vec<2> u = c.cpaM > 0.0 ? est::Vec<2>(r / c.cpaM) : est::Vec<2>::Zero();
    c.sdCpaM = std::sqrt(std::max(0.0, u.dot(P.topLeftCorner<2, 2>() * u)));
    return c;
  }
  c.defined = true;
  c.tcpaS = -r.dot(v) / v.squaredNorm();
  const est::Vec<2> d = r + v * c.tcpaS;
  c.cpaM = d.norm();
  const est::MatRC<2, 4> J = cpaJacobian(rel);
  c.sdTcpaS = std::sqrt(std::max(0.0, J.row(1).dot(P * J.row(1).transpose())));
  // Covariance of the CPA point d = r + v TCPA. Far from a collision course CPA = |d| is near-linear
  // and its sd is that of d along d; near one it is not (|d| has a kink at 0), and the honest figure
  // is the RMS distance of the estimated CPA point from the true one, sqrt(trace C_d).
  const est::Vec<2> dTauDr = -v / v.squaredNorm();
  const est::Vec<2> dTauDv = -r / v.squaredNorm() + 2.0 * r.dot(v) * v / (v.squaredNorm() * v.squaredNorm());
  est::MatRC<2, 4> Jd;
  Jd.leftCols<2>() = est::Mat<2>::Identity() + v * dTauDr.transpose();
  Jd.rightCols<2>() = c.tcpaS * est::Mat<2>::Identity() + v * dTauDv.transpose();
  const est::Mat<2> Cd = Jd * P * Jd.transpose();
  const double spread = std::sqrt(std::max(0.0, Cd.trace()));
  c.sdCpaM =
      c.cpaM > 3.0 * spread ? std::sqrt(std::max(0.0, J.row(0).dot(P * J.row(0).transpose()))) : spread;
  return c;
}

TrackKinematics kinematicsOf(const tk::Belief& b, double convergenceRad) {
  TrackKinematics k;
  const auto& x = b.x;
  // rel = A x with A picking target minus own position and velocity.
  Eigen::Matrix<double, 4, tk::kStateDim> A = Eigen::Matrix<double, 4, tk::kStateDim>::Zero();
  const int own[4] = {tk::kOwnX, tk::kOwnY, tk::kOwnVx, tk::kOwnVy};
  const int tgt[4] = {tk::kTgtX, tk::kTgtY, tk::kTgtVx, tk::kTgtVy};
  for (int i = 0; i < 4; ++i) {
    A(i, tgt[i]) = 1.0;
    A(i, own[i]) = -1.0;
  }
  const est::Vec<4> rel = A * x;
  const est::Mat<4> Prel = A.lazyProduct(b.P).lazyProduct(A.transpose());
  k.rangeM = rel.head<2>().norm();
  k.trueBearingRad = wrapTwoPi(bearingOf(rel[0], rel[1]) + convergenceRad);
  const double vx = x[tk::kTgtVx], vy = x[tk::kTgtVy];
  k.speedMps = std::hypot(vx, vy);
  k.trueCourseRad = wrapTwoPi(bearingOf(vx, vy) + convergenceRad);
  if (k.speedMps > 1e-9) {
    // speed = |v|, course = atan2(vx, vy): gradients along and across the velocity
    const est::Vec<2> along(vx / k.speedMps, vy / k.speedMps);
    const est::Vec<2> across(vy / (k.speedMps * k.speedMps), -vx / (k.speedMps * k.speedMps));
    const est::Mat<2> Pv = b.P.block<2, 2>(tk::kTgtVx, tk::kTgtVx);
    k.sdSpeedMps = std::sqrt(std::max(0.0, along.dot(Pv * along)));
    k.sdCourseRad = std::sqrt(std::max(0.0, across.dot(Pv * across)));
  } else {
    k.sdSpeedMps = std::sqrt(std::max(0.0, b.P.block<2, 2>(tk::kTgtVx, tk::kTgtVx).trace() / 2.0));
    k.sdCourseRad = kPi;
  }
  k.relativeSpeedMps = rel.tail<2>().norm();
  k.relativeCourseRad = wrapTwoPi(bearingOf(rel[2], rel[3]) + convergenceRad);
  k.cpa = cpaOf(rel, Prel);
  return k;
}

}  // namespace reckoner::track
