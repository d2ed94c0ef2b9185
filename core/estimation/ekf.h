#pragma once
// Generic extended Kalman filter algebra over fixed-size Eigen types. Models are stateless; this file
// only does algebra. Updates use the Joseph form with an LDLT solve of the innovation covariance
// (never an explicit inverse), symmetrise P, and leave the state untouched when anything is not finite.
// Products use lazyProduct (coefficient-based): for filter-sized matrices (<= ~20) Eigen's blocked GEMM
// path costs more than the arithmetic itself (docs/performance.md).
#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "estimation/gaussian.h"
#include "estimation/model_concepts.h"
#include "estimation/update_report.h"

namespace reckoner::est {

/// Linear(ised) prediction x <- Phi x, P <- Phi P Phi^T + Q. Returns false and leaves g unchanged if the
/// result is not finite.
template <int N>
bool predictLinear(Gaussian<N>& g, const Mat<N>& Phi, const Mat<N>& Q) {
  const Vec<N> x = Phi * g.x;
  const Mat<N> PhiP = Phi.lazyProduct(g.P);
  Mat<N> P = PhiP.lazyProduct(Phi.transpose()) + Q;
  symmetrise(P);
  if (!x.allFinite() || !P.allFinite()) return false;
  g.x = x;
  g.P = P;
  return true;
}

/// Nonlinear prediction with a process model providing f(x, dt), transition(x, dt) = df/dx and
/// noise(dt) = Q (model_concepts.h). Returns false and leaves g unchanged if the result is not finite.
template <int N, ProcessModel<N> Model>
bool predict(Gaussian<N>& g, const Model& model, double dtS) {
  const Mat<N> Phi = model.transition(g.x, dtS);
  const Vec<N> x = model.f(g.x, dtS);
  const Mat<N> PhiP = Phi.lazyProduct(g.P);
  Mat<N> P = PhiP.lazyProduct(Phi.transpose()) + model.noise(dtS);
  symmetrise(P);
  if (!x.allFinite() || !P.allFinite()) return false;
  g.x = x;
  g.P = P;
  return true;
}

/// Positive-definiteness test on an LDLT factorisation: every pivot strictly positive relative to the
/// largest one.
template <class Ldlt>
bool ldltPositiveDefinite(const Ldlt& ldlt) {
  if (ldlt.info() != Eigen::Success || ldlt.rows() == 0) return false;
  const auto d = ldlt.vectorD();
  const double maxD = d.maxCoeff();
  return maxD > 0.0 && d.minCoeff() > maxD * 1e-14;
}

/// Every LDLT pivot strictly positive: the test for a covariance given at a boundary (an initial
/// belief), whose diagonal may span many orders of magnitude (a Gauss-Markov state with sigma 0).
template <class Derived>
bool isPositiveDefinite(const Eigen::MatrixBase<Derived>& P) {
  if (!P.allFinite() || P.rows() == 0) return false;
  const Eigen::LDLT<typename Derived::PlainObject> ldlt(P);
  return ldlt.info() == Eigen::Success && ldlt.vectorD().minCoeff() > 0.0;
}

/// A B^T for a product known to be symmetric (e.g. A P A^T with AP = A P): computes the lower triangle
/// (N(N+1)/2 dot products) and mirrors it.
template <int N, class DA, class DB>
Mat<N> symmetricProduct(const Eigen::MatrixBase<DA>& A, const Eigen::MatrixBase<DB>& B) {
  Mat<N> out;
  for (int j = 0; j < N; ++j) {
    for (int i = j; i < N; ++i) {
      const double v = A.row(i).dot(B.row(j));
      out(i, j) = v;
      out(j, i) = v;
    }
  }
  return out;
}

/// Everything the Joseph update needs besides the state: innovation y = z - h(x) (angles wrapped),
/// Jacobian H, measurement covariance R, and the products P H^T and S = H P H^T + R (symmetrised).
template <int N, int MaxM>
struct LinearisedMeasurement {
  BVec<MaxM> y;
  BMatRows<MaxM, N> H;
  BMat<MaxM> R;
  BMatCols<N, MaxM> PHt;
  BMat<MaxM> S;

  /// Fills PHt and S from H, R and the prior covariance P. Measurement Jacobians are sparse (1 to 4
  /// non-zeros in a row of 11 for the DRKF), so both products visit only H's non-zeros.
  void computeInnovationCovariance(const Mat<N>& P) {
    const auto m = H.rows();
    PHt.resize(N, m);
    S.resize(m, m);
    for (Eigen::Index r = 0; r < m; ++r) {
      PHt.col(r).setZero();
      for (int j = 0; j < N; ++j)
        if (H(r, j) != 0.0) PHt.col(r) += H(r, j) * P.col(j);
    }
    for (Eigen::Index r = 0; r < m; ++r) {
      for (Eigen::Index c = 0; c <= r; ++c) {
        double v = R(r, c);
        for (int j = 0; j < N; ++j)
          if (H(r, j) != 0.0) v += H(r, j) * PHt(j, c);
        S(r, c) = v;
        S(c, r) = v;
      }
    }
    symmetrise(S);  // R may be slightly asymmetric; S is used symmetric
  }
};

/// Joseph-form update from a linearised measurement whose PHt and S are already computed.
///   K = P H^T S^-1 (LDLT);  x += K y;  P = (I - K H) P (I - K H)^T + K R K^T.
/// gate > 0 rejects when NIS = y^T S^-1 y exceeds it. The state is unchanged unless the report says
/// Accepted.
template <int N, int MaxM>
UpdateReport<MaxM> updateJoseph(Gaussian<N>& g, const LinearisedMeasurement<N, MaxM>& m, double gate) {
  UpdateReport<MaxM> rep;
  rep.dim = static_cast<int>(m.y.rows());
  rep.gate = gate;
  rep.innovation = m.y;
  if (rep.dim == 0) return rep;  // Empty
  if (!m.y.allFinite() || !m.H.allFinite() || !m.R.allFinite()) {
    rep.status = UpdateStatus::RejectedNonFinite;
    return rep;
  }
  rep.S = m.S;
  const Eigen::LDLT<BMat<MaxM>> ldlt(m.S);
  if (!ldltPositiveDefinite(ldlt)) {
    rep.status = UpdateStatus::RejectedNumerical;
    return rep;
  }
  rep.nis = m.y.dot(ldlt.solve(m.y));
  if (!std::isfinite(rep.nis) || rep.nis < 0.0) {
    rep.status = UpdateStatus::RejectedNumerical;
    return rep;
  }
  if (gate > 0.0 && rep.nis > gate) {
    rep.status = UpdateStatus::RejectedGate;
    return rep;
  }
  const BMatCols<N, MaxM> K = ldlt.solve(m.PHt.transpose()).transpose();
  const Vec<N> x = g.x + K * m.y;
  Mat<N> A = Mat<N>::Identity();  // I - K H, visiting H's non-zeros
  for (Eigen::Index r = 0; r < m.H.rows(); ++r)
    for (int j = 0; j < N; ++j)
      if (m.H(r, j) != 0.0) A.col(j) -= m.H(r, j) * K.col(r);
  const Mat<N> AP = g.P - K.lazyProduct(m.PHt.transpose());  // (I - K H) P, reusing P H^T
  const BMatCols<N, MaxM> KR = K.lazyProduct(m.R);
  Mat<N> P = symmetricProduct<N>(AP, A) + symmetricProduct<N>(KR, K);
  if (!x.allFinite() || !P.allFinite()) {
    rep.status = UpdateStatus::RejectedNumerical;
    return rep;
  }
  g.x = x;
  g.P = P;
  rep.status = UpdateStatus::Accepted;
  return rep;
}

/// Measurement update from an innovation y = z - h(x) (angles already wrapped), Jacobian H and
/// measurement covariance R. gate > 0 rejects when the NIS exceeds it.
template <int N, int MaxM>
UpdateReport<MaxM> updateJoseph(Gaussian<N>& g, const BVec<MaxM>& y, const BMatRows<MaxM, N>& H,
                                const BMat<MaxM>& R, double gate) {
  LinearisedMeasurement<N, MaxM> m{y, H, R, {}, {}};
  if (y.rows() > 0 && y.allFinite() && H.allFinite() && R.allFinite()) m.computeInnovationCovariance(g.P);
  return updateJoseph<N, MaxM>(g, m, gate);
}

/// Update with a single measurement model (h, jacobian, residual; model_concepts.h, models/). Returns
/// the report.
template <int N, MeasurementModel<N> Model>
UpdateReport<Model::kDim> update(Gaussian<N>& g, const Model& model, const Vec<Model::kDim>& z,
                                 const Mat<Model::kDim>& R, double gate) {
  constexpr int M = Model::kDim;
  const BVec<M> y = model.residual(z, model.h(g.x));
  const BMatRows<M, N> H = model.jacobian(g.x);
  const BMat<M> Rb = R;
  return updateJoseph<N, M>(g, y, H, Rb, gate);
}

/// Normalised estimation error squared (x_true - x)^T P^-1 (x_true - x), by LDLT. NaN if P is not
/// positive definite. err is the caller's error vector (angles already wrapped).
template <int N>
double nees(const Vec<N>& err, const Mat<N>& P) {
  const Eigen::LDLT<Mat<N>> ldlt(P);
  if (!ldltPositiveDefinite(ldlt)) return std::numeric_limits<double>::quiet_NaN();
  return err.dot(ldlt.solve(err));
}

}  // namespace reckoner::est
