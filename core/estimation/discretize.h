#pragma once
// Exact discretisation of a linear time-invariant system dx/dt = F x + G w, E[w w^T] = I delta,
// by Van Loan's method (C. F. Van Loan, IEEE TAC 23(3), 1978): with
//   M = [ -F  G G^T ; 0  F^T ] dt,  exp(M) = [ . , Phi^-1 Q ; 0 , Phi^T ]
// Phi = exp(F dt) and Q = integral_0^dt exp(F s) G G^T exp(F^T s) ds (seed 000 eq. 6).
#include <Eigen/Core>
#include <unsupported/Eigen/MatrixFunctions>

#include "estimation/gaussian.h"

namespace reckoner::est {

template <int N>
struct Discretised {
  Mat<N> Phi;
  Mat<N> Q;
};

template <int N, int W>
Discretised<N> discretiseVanLoan(const Mat<N>& F, const MatRC<N, W>& G, double dtS) {
  Eigen::Matrix<double, 2 * N, 2 * N> M = Eigen::Matrix<double, 2 * N, 2 * N>::Zero();
  M.template topLeftCorner<N, N>() = -F * dtS;
  M.template topRightCorner<N, N>() = G * G.transpose() * dtS;
  M.template bottomRightCorner<N, N>() = F.transpose() * dtS;
  const Eigen::Matrix<double, 2 * N, 2 * N> E = M.exp();
  Discretised<N> d;
  d.Phi = E.template bottomRightCorner<N, N>().transpose();
  d.Q = d.Phi * E.template topRightCorner<N, N>();
  symmetrise(d.Q);
  return d;
}

}  // namespace reckoner::est
