#include "tracking/cpa.h"

#include <cmath>

#include "common/angles.h"

namespace reckoner::track {
namespace tk = est::ttkf;

namespace {
/// TCPA and the Jacobian of the CPA point d = r + v TCPA with respect to (r, v):
///   d TCPA/dr = -v/|v|^2, d TCPA/dv = -r/|v|^2 + 2 (r.v) v/|v|^4, dd/dr = I + v dTCPA/dr^T,
///   dd/dv = TCPA I + v dTCPA/dv^T.
struct CpaPoint {
  double tcpaS;
  est::Vec<2> d;
  est::Vec<4> dTcpa;  ///< gradient of TCPA
  est::MatRC<2, 4> Jd;
};

CpaPoint cpaPoint(const est::Vec<4>& rel) {
  const est::Vec<2> r = rel.head<2>(), v = rel.tail<2>();
  const double vv = v.squaredNorm(), rv = r.dot(v);
  CpaPoint c;
  c.tcpaS = -rv / vv;
  c.d = r + v * c.tcpaS;
  const est::Vec<2> dTauDr = -v / vv;
  const est::Vec<2> dTauDv = -r / vv + 2.0 * rv * v / (vv * vv);
  c.dTcpa << dTauDr, dTauDv;
  c.Jd.leftCols<2>() = est::Mat<2>::Identity() + v * dTauDr.transpose();
  c.Jd.rightCols<2>() = c.tcpaS * est::Mat<2>::Identity() + v * dTauDv.transpose();
  return c;
}
}  // namespace

Eigen::Matrix<double, 4, tk::kStateDim> relativeSelector() {
  Eigen::Matrix<double, 4, tk::kStateDim> A = Eigen::Matrix<double, 4, tk::kStateDim>::Zero();
  A(0, tk::kTgtX) = A(1, tk::kTgtY) = A(2, tk::kTgtVx) = A(3, tk::kTgtVy) = 1.0;
  A(0, tk::kOwnX) = A(1, tk::kOwnY) = A(2, tk::kOwnVx) = A(3, tk::kOwnVy) = -1.0;
  return A;
}

est::MatRC<2, 4> cpaJacobian(const est::Vec<4>& rel) {
  const CpaPoint c = cpaPoint(rel);
  const double cpa = c.d.norm();
  est::MatRC<2, 4> J;
  J.row(1) = c.dTcpa.transpose();
  if (cpa > 1e-9)
    J.row(0) = (c.d / cpa).transpose() * c.Jd;  // d cpa = u^T dd with u = d / |d|
  else
    J.row(0).setZero();  // |d| is not differentiable at a collision course; first order gives 0
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
  const CpaPoint pt = cpaPoint(rel);
  c.defined = true;
  c.tcpaS = pt.tcpaS;
  c.cpaM = pt.d.norm();
  c.sdTcpaS = std::sqrt(std::max(0.0, pt.dTcpa.dot(P * pt.dTcpa)));
  // Far from a collision course CPA = |d| is near-linear and its sd is that of d along d; near one it
  // is not (|d| has a kink at 0), and the honest figure is the RMS distance of the estimated CPA
  // point from the true one, sqrt(trace C_d).
  const est::Mat<2> Cd = pt.Jd * P * pt.Jd.transpose();
  const double spread = std::sqrt(std::max(0.0, Cd.trace()));
  if (c.cpaM > 3.0 * spread) {
    const est::Vec<2> u = pt.d / c.cpaM;
    c.sdCpaM = std::sqrt(std::max(0.0, u.dot(Cd * u)));
  } else {
    c.sdCpaM = spread;
  }
  return c;
}

TrackKinematics kinematicsOf(const tk::Belief& b, double convergenceRad) {
  TrackKinematics k;
  const auto& x = b.x;
  static const Eigen::Matrix<double, 4, tk::kStateDim> A = relativeSelector();
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
