#include "tracking/coupled_drttkf.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <stdexcept>

#include "common/angles.h"
#include "estimation/chi_square.h"
#include "estimation/ekf.h"
#include "estimation/singer.h"

namespace reckoner::track {
namespace {
/// The DRKF the coupled filter runs its own-ship updates through: an update engine on the joint
/// state's marginal, so without a divergence guard (a restart there would not be an update of the
/// marginal, and the joint state's conditional transfer would be wrong).
nav::DrkfConfig withoutGuard(nav::DrkfConfig c) {
  c.guard.enabled = false;
  return c;
}
}  // namespace

namespace dk = est::drkf;
using Eigen::MatrixXd;
using Eigen::VectorXd;

CoupledDrttkf::CoupledDrttkf(const CoupledConfig& c, const geo::LocalFrame& frame, const dk::Belief& initial,
                             TimeUs t0)
    : config_(c),
      frame_(frame),
      own_(withoutGuard(c.own), frame, initial, t0),
      ownProcess_(c.own.process),
      radarGate_(c.gateProbability > 0.0 ? est::chiSquareQuantile(c.gateProbability, 2.0) : 0.0),
      x_(initial.x),
      P_(initial.P),
      timeUs_(t0) {
  if (!c.targetAcceleration.valid() || !(c.initialSpeedSdMps > 0.0) || !(c.gateProbability >= 0.0) ||
      !(c.gateProbability < 1.0))
    throw std::invalid_argument("coupled filter: invalid target model, initial speed sd or gate");
}

int CoupledDrttkf::indexOf(int tag) const {
  for (std::size_t i = 0; i < tags_.size(); ++i)
    if (tags_[i] == tag) return static_cast<int>(i);
  return -1;
}

dk::Belief CoupledDrttkf::ownShip() const {
  dk::Belief b;
  b.x = x_.head<kOwnDim>();
  b.P = P_.topLeftCorner<kOwnDim, kOwnDim>();
  return b;
}

bool CoupledDrttkf::predictTo(TimeUs t) {
  if (t < timeUs_) return false;
  if (t == timeUs_) return true;
  const double dt = toSeconds(t - timeUs_);
  const int n = dim();
  MatrixXd Phi = MatrixXd::Zero(n, n), Q = MatrixXd::Zero(n, n);
  if (t - timeUs_ != cachedDtUs_) {
    cachedOwn_ = ownProcess_.discretise(dt);
    cachedTarget_ = est::singerDiscretisation(config_.targetAcceleration, dt);
    cachedDtUs_ = t - timeUs_;
  }
  const auto& own = cachedOwn_;
  Phi.topLeftCorner<kOwnDim, kOwnDim>() = own.Phi;
  Q.topLeftCorner<kOwnDim, kOwnDim>() = own.Q;
  const est::SingerAxis& s = cachedTarget_;
  for (int k = 0; k < targetCount(); ++k) {
    const int o = kOwnDim + kTargetDim * k;
    for (int axis = 0; axis < 2; ++axis) {
      const int idx[3] = {o + axis, o + 2 + axis, o + 4 + axis};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          Phi(idx[i], idx[j]) = s.Phi(i, j);
          Q(idx[i], idx[j]) = s.Q(i, j);
        }
    }
  }
  // Dense on purpose: this is the k N^3 propagation that eq. 10 compares against.
  VectorXd x = Phi * x_;
  MatrixXd P = Phi * P_ * Phi.transpose() + Q;
  P = 0.5 * (P + P.transpose());
  if (!x.allFinite() || !P.allFinite()) return false;
  x_ = std::move(x);
  P_ = std::move(P);
  timeUs_ = t;
  return true;
}

nav::DrkfUpdateReport CoupledDrttkf::updateOwnShip(TimeUs t,
                                                   std::span<const sensors::OwnShipSample> samples) {
  nav::DrkfUpdateReport rep;
  if (!predictTo(t)) {
    rep.joint.status = est::UpdateStatus::RejectedStale;
    return rep;
  }
  const dk::Belief prior = ownShip();
  own_.setBelief(prior, t);
  rep = own_.update(t, samples);
  const dk::Belief& post = own_.belief();
  const int r = dim() - kOwnDim;
  if (r == 0) {
    x_.head<kOwnDim>() = post.x;
    P_.topLeftCorner<kOwnDim, kOwnDim>() = post.P;
    return rep;
  }
  // Keep p(targets | own ship), replace p(own ship): K = P_rv P_vv^-1 on the prior.
  const Eigen::LDLT<dk::Covariance> ldlt(prior.P);
  const MatrixXd Prv = P_.bottomLeftCorner(r, kOwnDim);
  const MatrixXd K = ldlt.solve(Prv.transpose()).transpose();  // r x 11
  const MatrixXd KC = K * post.P;
  MatrixXd Prr = P_.bottomRightCorner(r, r) - K * Prv.transpose() + KC * K.transpose();
  Prr = 0.5 * (Prr + Prr.transpose());
  x_.tail(r) += K * (post.x - prior.x);
  x_.head<kOwnDim>() = post.x;
  P_.topLeftCorner<kOwnDim, kOwnDim>() = post.P;
  P_.bottomLeftCorner(r, kOwnDim) = KC;
  P_.topRightCorner(kOwnDim, r) = KC.transpose();
  P_.bottomRightCorner(r, r) = Prr;
  return rep;
}

void CoupledDrttkf::addTarget(int tag, const GridPlot& plot) {
  const int n = dim();
  const double s = std::sin(plot.bearingRad), c = std::cos(plot.bearingRad), r = plot.rangeM;
  est::Mat<2> J;
  J << s, r * c, c, -r * s;
  const est::Mat<2> Rxy = J * est::Vec<2>(plot.rangeVarM2, plot.bearingVarRad2).asDiagonal() * J.transpose();
  VectorXd x(n + kTargetDim);
  x.head(n) = x_;
  x.tail<kTargetDim>().setZero();
  x[n] = x_[dk::kPosX] + r * s;
  x[n + 1] = x_[dk::kPosY] + r * c;
  MatrixXd P = MatrixXd::Zero(n + kTargetDim, n + kTargetDim);
  P.topLeftCorner(n, n) = P_;
  // Target position = own position + offset: it inherits own position's covariances.
  const int own[2] = {dk::kPosX, dk::kPosY};
  for (int a = 0; a < 2; ++a) {
    P.block(n + a, 0, 1, n) = P_.row(own[a]);
    P.block(0, n + a, n, 1) = P_.col(own[a]);
  }
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) P(n + a, n + b) = P_(own[a], own[b]) + Rxy(a, b);
  const double v2 = config_.initialSpeedSdMps * config_.initialSpeedSdMps;
  const double a2 = std::max(config_.targetAcceleration.sigma * config_.targetAcceleration.sigma, 1e-12);
  P(n + 2, n + 2) = P(n + 3, n + 3) = v2;
  P(n + 4, n + 4) = P(n + 5, n + 5) = a2;
  x_ = std::move(x);
  P_ = std::move(P);
  tags_.push_back(tag);
}

est::UpdateReport<2> CoupledDrttkf::updateRadar(int tag, const GridPlot& plot) {
  est::UpdateReport<2> rep;
  if (!predictTo(plot.timeUs)) {
    rep.status = est::UpdateStatus::RejectedStale;
    return rep;
  }
  const int k = indexOf(tag);
  if (k < 0) {
    addTarget(tag, plot);
    rep.status = est::UpdateStatus::Accepted;
    return rep;
  }
  const int n = dim(), o = kOwnDim + kTargetDim * k;
  const double dx = x_[o] - x_[dk::kPosX], dy = x_[o + 1] - x_[dk::kPosY];
  const double r2 = dx * dx + dy * dy, r = std::sqrt(r2);
  if (r < config_.minRangeM) {
    rep.status = est::UpdateStatus::RejectedDegenerate;
    return rep;
  }
  MatrixXd H = MatrixXd::Zero(2, n);
  H(0, o) = dx / r;
  H(0, o + 1) = dy / r;
  H(0, dk::kPosX) = -dx / r;
  H(0, dk::kPosY) = -dy / r;
  H(1, o) = dy / r2;
  H(1, o + 1) = -dx / r2;
  H(1, dk::kPosX) = -dy / r2;
  H(1, dk::kPosY) = dx / r2;
  const est::Vec<2> y(plot.rangeM - r, angleDiff(plot.bearingRad, bearingOf(dx, dy)));
  const est::Mat<2> R = est::Vec<2>(plot.rangeVarM2, plot.bearingVarRad2).asDiagonal();
  const MatrixXd PHt = P_ * H.transpose();
  const est::Mat<2> S = H * PHt + R;
  const Eigen::LDLT<est::Mat<2>> ldlt(S);
  rep.dim = 2;
  rep.innovation = y;
  rep.S = S;
  if (!est::ldltPositiveDefinite(ldlt)) {
    rep.status = est::UpdateStatus::RejectedNumerical;
    return rep;
  }
  rep.nis = y.dot(ldlt.solve(y));
  if (radarGate_ > 0.0 && rep.nis > radarGate_) {
    rep.status = est::UpdateStatus::RejectedGate;
    return rep;
  }
  const MatrixXd K = ldlt.solve(PHt.transpose()).transpose();  // n x 2
  // Joseph form, dense: (I - K H) P (I - K H)^T + K R K^T.
  MatrixXd A = -K * H;
  A.diagonal().array() += 1.0;
  MatrixXd P = A * P_ * A.transpose() + K * R * K.transpose();
  P = 0.5 * (P + P.transpose());
  VectorXd x = x_ + K * y;
  if (!x.allFinite() || !P.allFinite()) {
    rep.status = est::UpdateStatus::RejectedNumerical;
    return rep;
  }
  x_ = std::move(x);
  P_ = std::move(P);
  rep.status = est::UpdateStatus::Accepted;
  return rep;
}

}  // namespace reckoner::track
