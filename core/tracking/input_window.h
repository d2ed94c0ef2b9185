#pragma once
// Input estimation over a sliding window (Bar-Shalom and Li; seed 001 eqs. 17 to 29), for any filter
// of N states observed by a 2-row measurement: each update of the non-manoeuvring filter contributes
// its transition into the update (Phi), the gain of a constant acceleration input over that interval
// (G), its measurement Jacobian (H), Kalman gain (W), innovation covariance (S) and innovation. From a
// full window: the least-squares input u, its covariance L, the statistic d = u' L^-1 u and the state
// correction M with x += M u, P += M L M' (docs/manoeuvres.md).
#include <Eigen/Cholesky>
#include <deque>

#include "estimation/ekf.h"
#include "estimation/gaussian.h"

namespace reckoner::track {

template <int N>
class InputWindow {
 public:
  struct Entry {
    est::Mat<N> Phi;
    est::MatRC<N, 2> G;
    est::MatRC<2, N> H;
    est::MatRC<N, 2> W;
    est::Mat<2> S;
    est::Vec<2> innovation;
  };
  struct Estimate {
    bool tested = false;
    double d = 0.0;
    est::Vec<2> u = est::Vec<2>::Zero();
    est::Mat<2> L = est::Mat<2>::Zero();
    est::MatRC<N, 2> M = est::MatRC<N, 2>::Zero();
  };

  explicit InputWindow(int length = 2) : length_(length) {}
  [[nodiscard]] int length() const { return length_; }
  void clear() { entries_.clear(); }
  void push(const Entry& e) {
    entries_.push_back(e);
    while (static_cast<int>(entries_.size()) > length_) entries_.pop_front();
  }

  /// The estimate from the current window (tested = false until the window is full or when the
  /// normal equations are singular).
  [[nodiscard]] Estimate estimate() const {
    Estimate out;
    if (static_cast<int>(entries_.size()) < length_) return out;
    // C(first) = G(first); C(i+1) = Phi(i+1) (I - W(i) H(i)) C(i) + G(i+1): the response of the
    // predicted state to the input, including the filter's own partial response through its gains.
    const est::Mat<N> I = est::Mat<N>::Identity();
    est::MatRC<N, 2> C = entries_.front().G;
    est::Mat<2> A = est::Mat<2>::Zero();  // Psi' S^-1 Psi
    est::Vec<2> b = est::Vec<2>::Zero();  // Psi' S^-1 y
    for (std::size_t i = 0; i < entries_.size(); ++i) {
      const Entry& e = entries_[i];
      if (i > 0) C = (e.Phi * (I - entries_[i - 1].W * entries_[i - 1].H) * C + e.G).eval();
      const est::Mat<2> Psi = e.H * C;
      const Eigen::LDLT<est::Mat<2>> Sldlt(e.S);
      A += Psi.transpose() * Sldlt.solve(Psi);
      b += Psi.transpose() * Sldlt.solve(e.innovation);
    }
    const Eigen::LDLT<est::Mat<2>> Aldlt(A);
    if (!est::ldltPositiveDefinite(Aldlt)) return out;
    out.u = Aldlt.solve(b);
    out.L = Aldlt.solve(est::Mat<2>::Identity());
    out.d = out.u.dot(A * out.u);
    if (!std::isfinite(out.d)) return out;
    const Entry& last = entries_.back();
    out.M = (I - last.W * last.H) * C;
    out.tested = true;
    return out;
  }

 private:
  int length_;
  std::deque<Entry> entries_;
};

}  // namespace reckoner::track
