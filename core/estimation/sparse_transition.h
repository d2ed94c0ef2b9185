#pragma once
// A transition matrix stored by its non-zero entries. Navigation and tracking transitions are block
// sparse (the DRKF's 11x11 Phi has 25 non-zeros), so Phi P Phi^T costs 2 nnz N multiply-adds instead
// of 2 N^3 (docs/performance.md).
#include <array>
#include <cstdint>

#include "estimation/gaussian.h"

namespace reckoner::est {

template <int N>
class SparseTransition {
 public:
  SparseTransition() = default;
  explicit SparseTransition(const Mat<N>& Phi) : dense_(Phi) {
    for (int i = 0; i < N; ++i) {
      rowStart_[static_cast<std::size_t>(i)] = count_;
      for (int j = 0; j < N; ++j) {
        if (Phi(i, j) != 0.0) {
          cols_[static_cast<std::size_t>(count_)] = static_cast<std::uint8_t>(j);
          vals_[static_cast<std::size_t>(count_)] = Phi(i, j);
          ++count_;
        }
      }
    }
    rowStart_[N] = count_;
  }

  [[nodiscard]] const Mat<N>& dense() const { return dense_; }
  [[nodiscard]] int nonZeros() const { return count_; }

  /// Phi x.
  [[nodiscard]] Vec<N> apply(const Vec<N>& x) const {
    Vec<N> y;
    for (int i = 0; i < N; ++i) {
      double s = 0.0;
      for (int k = rowStart_[i]; k < rowStart_[i + 1]; ++k) s += vals_[k] * x[cols_[k]];
      y[i] = s;
    }
    return y;
  }

  /// Phi P Phi^T for symmetric P (only the lower triangle is computed, then mirrored).
  [[nodiscard]] Mat<N> congruence(const Mat<N>& P) const {
    Mat<N> PhiP;  // row i = sum_k Phi(i, k) P(k, :)
    for (int i = 0; i < N; ++i) {
      PhiP.row(i).setZero();
      for (int k = rowStart_[i]; k < rowStart_[i + 1]; ++k) PhiP.row(i) += vals_[k] * P.row(cols_[k]);
    }
    Mat<N> out;
    for (int j = 0; j < N; ++j) {  // out(i, j) = sum_k PhiP(i, k) Phi(j, k), i >= j
      for (int i = j; i < N; ++i) {
        double s = 0.0;
        for (int k = rowStart_[j]; k < rowStart_[j + 1]; ++k) s += vals_[k] * PhiP(i, cols_[k]);
        out(i, j) = s;
        out(j, i) = s;
      }
    }
    return out;
  }

 private:
  Mat<N> dense_ = Mat<N>::Identity();
  std::array<int, N + 1> rowStart_{};
  std::array<std::uint8_t, static_cast<std::size_t>(N) * N> cols_{};
  std::array<double, static_cast<std::size_t>(N) * N> vals_{};
  int count_ = 0;
};

/// Prediction with a sparse transition: x <- Phi x, P <- Phi P Phi^T + Q (Q symmetric).
/// Returns false and leaves g unchanged if the result is not finite.
template <int N>
bool predictLinear(Gaussian<N>& g, const SparseTransition<N>& Phi, const Mat<N>& Q) {
  const Vec<N> x = Phi.apply(g.x);
  const Mat<N> P = Phi.congruence(g.P) + Q;  // congruence() is exactly symmetric; Q is symmetric
  if (!x.allFinite() || !P.allFinite()) return false;
  g.x = x;
  g.P = P;
  return true;
}

}  // namespace reckoner::est
