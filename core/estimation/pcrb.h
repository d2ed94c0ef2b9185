#pragma once
// The posterior Cramer-Rao bound (Tichavsky, Muravchik and Nehorai 1998) for a linear-Gaussian motion
// model observed by a nonlinear measurement with additive Gaussian noise, computed along the TRUE
// trajectory (the measurement Jacobian taken at the true state):
//   J(k+1) = (Q + F J(k)^-1 F')^-1 + H' R^-1 H,    bound(k) = J(k)^-1.
// No unbiased estimator using the same model and measurements can have a smaller error covariance, so
// an RMSE divided by the bound's square root says how far a tracker is from the best possible.
#include <Eigen/Cholesky>

#include "estimation/gaussian.h"

namespace reckoner::metrics {

template <int N, int M>
class Pcrb {
 public:
  /// Starts from the prior covariance P0 (positive definite).
  explicit Pcrb(const est::Mat<N>& P0) : J_(inverse(P0)) {}

  /// One step: the model over the interval (F, Q) and the measurement at the true state (H, R).
  void step(const est::Mat<N>& F, const est::Mat<N>& Q, const est::MatRC<M, N>& H, const est::Mat<M>& R) {
    const est::Mat<N> predicted = Q + F * inverse(J_) * F.transpose();
    const Eigen::LDLT<est::Mat<M>> r(R);
    J_ = inverse(predicted) + H.transpose() * r.solve(H);
  }
  /// Adds a measurement's information without motion (several measurements at one time).
  void measure(const est::MatRC<M, N>& H, const est::Mat<M>& R) {
    const Eigen::LDLT<est::Mat<M>> r(R);
    J_ += H.transpose() * r.solve(H);
  }
  [[nodiscard]] est::Mat<N> bound() const { return inverse(J_); }

 private:
  static est::Mat<N> inverse(const est::Mat<N>& A) {
    const Eigen::LDLT<est::Mat<N>> ldlt(A);
    est::Mat<N> out = ldlt.solve(est::Mat<N>::Identity());
    return 0.5 * (out + out.transpose());
  }
  est::Mat<N> J_;
};

}  // namespace reckoner::metrics
