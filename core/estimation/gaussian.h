#pragma once
// Fixed-size Gaussian state and the bounded-dynamic matrix types used for a variable measurement set.
#include <Eigen/Core>
#include <cmath>

namespace reckoner::est {

template <int N>
using Vec = Eigen::Matrix<double, N, 1>;
template <int N>
using Mat = Eigen::Matrix<double, N, N>;
template <int R, int C>
using MatRC = Eigen::Matrix<double, R, C>;

/// Dynamic size up to MaxM, stored inline (no heap allocation).
template <int MaxM>
using BVec = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, MaxM, 1>;
template <int MaxM>
using BMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, MaxM, MaxM>;
template <int MaxM, int N>
using BMatRows = Eigen::Matrix<double, Eigen::Dynamic, N, Eigen::RowMajor, MaxM, N>;
template <int N, int MaxM>
using BMatCols = Eigen::Matrix<double, N, Eigen::Dynamic, Eigen::ColMajor, N, MaxM>;

/// A Gaussian belief: mean x and covariance P (symmetric positive definite).
template <int N>
struct Gaussian {
  Vec<N> x = Vec<N>::Zero();
  Mat<N> P = Mat<N>::Identity();
};

/// Largest eigenvalue of the symmetric 2 x 2 matrix [a b; b c] (the variance along an ellipse's major
/// axis).
inline double largestEigenvalue2x2(double a, double b, double c) {
  return 0.5 * (a + c) + std::hypot(0.5 * (a - c), b);
}
inline double largestEigenvalue(const Mat<2>& P) {
  return largestEigenvalue2x2(P(0, 0), 0.5 * (P(0, 1) + P(1, 0)), P(1, 1));
}

/// P <- (P + P^T) / 2, in place.
template <class Derived>
void symmetrise(Eigen::MatrixBase<Derived>& P) {
  P = 0.5 * (P + P.transpose()).eval();
}

}  // namespace reckoner::est
