#pragma once
// The divergence guard every filter with a covariance carries (the DRKF, every track filter of the
// bank): after each epoch or update the filter asks it two things (docs/consistency.md, "Divergence
// guards"):
//   covariance  P finite, symmetric to a relative tolerance and positive definite: the LDLT pivots of
//               its correlation matrix D^-1/2 P D^-1/2 all above minPivot (scale-free, so states in
//               metres and in radians are judged alike). States the caller masks out (modelled as
//               exactly known: a Gauss-Markov state of sigma 0) and states whose row is exactly zero
//               are left out.
//   NIS         a sliding window of the last `window` updates' NIS (each clipped at its chi-square
//               quantile at clipProbability, so that one wild value cannot carry a window): the window
//               is "far above its band" when its sum lies above both the upper end of the two-sided
//               bandProbability band of chi-square(window dof) and minMeanNisPerDof times its dof;
//               the guard trips when that holds at `sustain` updates in a row.
// A tripped guard marks the filter diverged; the filter restarts from its next good measurement and
// calls reset(), which counts the reset by its reason. Plain value, no allocation, never throws.
#include <Eigen/Cholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "estimation/chi_square.h"
#include "estimation/gaussian.h"

namespace reckoner::est {

enum class DivergenceReason : std::uint8_t {
  None,
  Covariance,  ///< P not finite, not symmetric or not positive definite
  Nis,         ///< the windowed NIS far above its band, sustained
};
constexpr const char* divergenceReasonName(DivergenceReason r) {
  switch (r) {
    case DivergenceReason::None:
      return "none";
    case DivergenceReason::Covariance:
      return "covariance";
    case DivergenceReason::Nis:
      return "nis";
  }
  return "?";
}
/// For an alert's text: "covariance not positive definite", "innovations far larger than expected".
constexpr const char* divergenceReasonText(DivergenceReason r) {
  switch (r) {
    case DivergenceReason::None:
      return "none";
    case DivergenceReason::Covariance:
      return "covariance not positive definite";
    case DivergenceReason::Nis:
      return "innovations far larger than its covariance allows";
  }
  return "?";
}

struct DivergenceGuardConfig {
  bool enabled = true;
  int window = 30;                  ///< updates in the sliding NIS window, [2, kMaxWindow]
  double clipProbability = 0.9999;  ///< each NIS counts at most its chi-square quantile at this
  double bandProbability = 0.999;   ///< two-sided band of the window's sum
  double minMeanNisPerDof = 4.0;    ///< "far": the window's mean NIS per degree of freedom at least this
  int sustain = 10;                 ///< consecutive updates far above before tripping, >= 1
  double symmetryTolerance = 1e-6;  ///< |P_ij - P_ji| <= this * sqrt(P_ii P_jj)
  double minPivot = 1e-12;          ///< smallest LDLT pivot of the correlation matrix
};

/// Resets made, by the reason that tripped the guard.
struct DivergenceCounts {
  long covariance = 0;
  long nis = 0;
  [[nodiscard]] long total() const { return covariance + nis; }
  DivergenceCounts& operator+=(const DivergenceCounts& o) {
    covariance += o.covariance;
    nis += o.nis;
    return *this;
  }
};

/// The covariance test's verdict and its margin.
struct CovarianceHealth {
  bool finite = false;
  bool symmetric = false;
  bool positiveDefinite = false;
  double minPivot = std::numeric_limits<double>::quiet_NaN();  ///< of the correlation matrix's LDLT
  [[nodiscard]] bool ok() const { return finite && symmetric && positiveDefinite; }
};

/// Checks P over the states whose keep[i] is true (keep null: all); see the file comment.
template <int N>
CovarianceHealth checkCovariance(const Mat<N>& P, const std::array<bool, N>* keep, double symmetryTolerance,
                                 double minPivot) {
  CovarianceHealth h;
  h.finite = P.allFinite();
  if (!h.finite) return h;
  std::array<int, N> idx{};
  int n = 0;
  bool negative = false;
  for (int i = 0; i < N; ++i) {
    if (keep && !(*keep)[static_cast<std::size_t>(i)]) continue;
    if (P(i, i) < 0.0) negative = true;
    if (P(i, i) == 0.0 && P.row(i).cwiseAbs().maxCoeff() == 0.0 && P.col(i).cwiseAbs().maxCoeff() == 0.0)
      continue;  // exactly known and uncorrelated
    idx[static_cast<std::size_t>(n++)] = i;
  }
  h.symmetric = true;
  for (int a = 0; a < n && h.symmetric; ++a)
    for (int b = 0; b < a; ++b) {
      const int i = idx[static_cast<std::size_t>(a)], j = idx[static_cast<std::size_t>(b)];
      const double scale = std::sqrt(std::abs(P(i, i) * P(j, j)));
      if (std::abs(P(i, j) - P(j, i)) > symmetryTolerance * scale + std::numeric_limits<double>::min()) {
        h.symmetric = false;
        break;
      }
    }
  if (negative || n == 0) {
    h.positiveDefinite = n == 0 && !negative;
    h.minPivot = negative ? -1.0 : 1.0;
    return h;
  }
  Mat<N> C = Mat<N>::Identity();
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      const int i = idx[static_cast<std::size_t>(a)], j = idx[static_cast<std::size_t>(b)];
      C(a, b) = 0.5 * (P(i, j) + P(j, i)) / std::sqrt(P(i, i) * P(j, j));
    }
  const Eigen::LDLT<Mat<N>> ldlt(C);  // the unused trailing rows are the identity: pivots of 1
  h.minPivot = ldlt.info() == Eigen::Success ? ldlt.vectorD().minCoeff() : -1.0;
  h.positiveDefinite = h.minPivot > minPivot;
  return h;
}

class DivergenceGuard {
 public:
  static constexpr int kMaxWindow = 64;
  static constexpr int kMaxDof = 8;

  explicit DivergenceGuard(const DivergenceGuardConfig& config = {}) : config_(config) {
    config_.window = std::clamp(config_.window, 2, kMaxWindow);
    config_.sustain = std::max(config_.sustain, 1);
    for (int d = 1; d <= kMaxDof; ++d)
      clip_[static_cast<std::size_t>(d)] = chiSquareQuantile(config_.clipProbability, d);
  }

  /// One update's NIS of `dof` degrees of freedom (1 to kMaxDof; others and non-finite values are
  /// ignored). Returns true when this update trips the guard.
  bool addNis(double nis, int dof) {
    if (!config_.enabled || !std::isfinite(nis) || dof < 1 || dof > kMaxDof) return false;
    const double v = std::min(std::max(nis, 0.0), clip_[static_cast<std::size_t>(dof)]);
    const auto slot = static_cast<std::size_t>(next_);
    if (count_ == config_.window) {
      sum_ -= nis_[slot];
      dofSum_ -= dof_[slot];
    } else {
      ++count_;
    }
    nis_[slot] = v;
    dof_[slot] = dof;
    sum_ += v;
    dofSum_ += dof;
    next_ = (next_ + 1) % config_.window;
    if (next_ == 0) {  // once per turn of the ring, the running sum afresh (no drift)
      sum_ = 0.0;
      for (int i = 0; i < count_; ++i) sum_ += nis_[static_cast<std::size_t>(i)];
    }
    if (count_ < config_.window) return false;
    const double k = static_cast<double>(dofSum_);
    peakMeanPerDof_ = std::max(peakMeanPerDof_, sum_ / k);
    // The band's quantile is computed only for a window already far above in magnitude (rare).
    const bool far = sum_ > config_.minMeanNisPerDof * k &&
                     sum_ > chiSquareQuantile(0.5 + 0.5 * config_.bandProbability, k);
    above_ = far ? above_ + 1 : 0;
    if (above_ < config_.sustain || diverged()) return false;
    reason_ = DivergenceReason::Nis;
    return true;
  }

  /// Checks P (keep: the states to judge, null for all). Returns true when this check trips the guard.
  template <int N>
  bool checkCovariance(const Mat<N>& P, const std::array<bool, N>* keep = nullptr) {
    if (!config_.enabled) return false;
    const CovarianceHealth h = est::checkCovariance<N>(P, keep, config_.symmetryTolerance, config_.minPivot);
    if (std::isfinite(h.minPivot)) minPivotSeen_ = std::min(minPivotSeen_, h.minPivot);
    if (h.ok() || diverged()) return false;
    reason_ = DivergenceReason::Covariance;
    return true;
  }

  [[nodiscard]] bool diverged() const { return reason_ != DivergenceReason::None; }
  [[nodiscard]] DivergenceReason reason() const { return reason_; }
  /// The filter has restarted: counts the reset under the reason that tripped, empties the window.
  void reset() {
    if (reason_ == DivergenceReason::Covariance) ++counts_.covariance;
    if (reason_ == DivergenceReason::Nis) ++counts_.nis;
    reason_ = DivergenceReason::None;
    count_ = next_ = dofSum_ = above_ = 0;
    sum_ = 0.0;
  }
  [[nodiscard]] const DivergenceCounts& resets() const { return counts_; }
  [[nodiscard]] const DivergenceGuardConfig& config() const { return config_; }
  /// The window's mean NIS per degree of freedom now (NaN until the window is full).
  [[nodiscard]] double windowMeanPerDof() const {
    return count_ == config_.window ? sum_ / static_cast<double>(dofSum_)
                                    : std::numeric_limits<double>::quiet_NaN();
  }
  /// Margins seen so far, for the consistency figures: the largest full-window mean NIS per dof and the
  /// smallest correlation pivot (1 and 0 before any).
  [[nodiscard]] double peakWindowMeanPerDof() const { return peakMeanPerDof_; }
  [[nodiscard]] double minPivotSeen() const { return minPivotSeen_; }

 private:
  DivergenceGuardConfig config_;
  std::array<double, kMaxDof + 1> clip_{};
  std::array<double, kMaxWindow> nis_{};
  std::array<int, kMaxWindow> dof_{};
  int count_ = 0, next_ = 0, dofSum_ = 0, above_ = 0;
  double sum_ = 0.0;
  DivergenceReason reason_ = DivergenceReason::None;
  DivergenceCounts counts_;
  double peakMeanPerDof_ = 0.0;
  double minPivotSeen_ = 1.0;
};

}  // namespace reckoner::est
