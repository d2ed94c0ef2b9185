#pragma once
// A variable-dimension measurement set: any subset of a filter's measurement models, stacked into one
// innovation, Jacobian and covariance (the paper's 8x11 H shrinks to 2x11 in dead reckoning). Each model
// is a block with its own chi-square gate; blocks failing their gate are dropped before the joint
// Joseph update, so one bad sensor does not reject the others.
#include <array>
#include <cmath>
#include <type_traits>

#include "estimation/ekf.h"

namespace reckoner::est {

/// Per-block outcome of a stacked update.
struct BlockReport {
  int tag = -1;  ///< caller's identifier (e.g. a sensor id)
  int dim = 0;
  double nis = std::numeric_limits<double>::quiet_NaN();  ///< the block's own NIS against its S block
  double gate = 0.0;                                      ///< <= 0: ungated
  bool forced = false;  ///< the caller bypassed the gate (reported as AcceptedForced when applied)
  int row = -1;         ///< first row of this block in the joint report's innovation, when applied
  UpdateStatus status = UpdateStatus::Empty;
};

template <int N, int MaxM, int MaxBlocks = MaxM>
class MeasurementStack {
 public:
  /// Adds one model's rows, linearised at the prior mean x. z and R are in the model's measurement
  /// space; gate <= 0 applies the block without gating; forced marks a deliberate bypass. A degenerate
  /// model (model.degenerate(x)) or non-finite input is recorded as rejected and adds no rows.
  /// Returns false, adding nothing, when the stack has no room left (MaxM rows, MaxBlocks blocks).
  /// The model's contract: StackableMeasurementModel (model_concepts.h).
  template <StackableMeasurementModel<N> Model>
  bool add(int tag, const Model& model, const Vec<N>& x, const Vec<Model::kDim>& z, const Mat<Model::kDim>& R,
           double gate, bool forced = false) {
    constexpr int M = Model::kDim;
    static_assert(M <= MaxM);
    if (blockCount_ >= MaxBlocks || dim_ + M > MaxM) return false;
    BlockReport& b = blocks_[blockCount_++];
    b = BlockReport{tag, M, std::numeric_limits<double>::quiet_NaN(), gate, forced, -1, UpdateStatus::Empty};
    if (!z.allFinite() || !R.allFinite()) {
      b.status = UpdateStatus::RejectedNonFinite;
      return true;
    }
    if (model.degenerate(x)) {
      b.status = UpdateStatus::RejectedDegenerate;
      return true;
    }
    const Vec<M> y = model.residual(z, model.h(x));
    const MatRC<M, N> H = model.jacobian(x);
    if (!y.allFinite() || !H.allFinite()) {
      b.status = UpdateStatus::RejectedNonFinite;
      return true;
    }
    offsets_[blockCount_ - 1] = dim_;
    y_.template segment<M>(dim_) = y;
    H_.template middleRows<M>(dim_) = H;
    R_.template block<M, M>(dim_, dim_) = R;
    dim_ += M;
    b.status = UpdateStatus::Accepted;  // provisional: rows present, gate not yet applied
    return true;
  }

  /// Gates each block on its own NIS, then applies the accepted blocks jointly (Joseph form).
  /// P H^T and S are computed once for all rows: a block's own innovation covariance is its diagonal
  /// block of S, and dropping a block only removes its rows and columns. Returns the joint report;
  /// per-block outcomes are in block(i).
  UpdateReport<MaxM> apply(Gaussian<N>& g) {
    LinearisedMeasurement<N, MaxM> all{y_.head(dim_), H_.topRows(dim_), R_.topLeftCorner(dim_, dim_), {}, {}};
    if (dim_ > 0) all.computeInnovationCovariance(g.P);

    std::array<int, MaxM> keepRows{};
    std::array<int, MaxBlocks> kept{};
    int m = 0, keptCount = 0;
    for (int i = 0; i < blockCount_; ++i) {
      BlockReport& b = blocks_[i];
      if (b.status != UpdateStatus::Accepted) continue;
      const int o = offsets_[i];
      b.nis = blockNis(all.y.segment(o, b.dim), all.S.block(o, o, b.dim, b.dim));
      if (!std::isfinite(b.nis)) {
        b.status = UpdateStatus::RejectedNumerical;
        continue;
      }
      if (b.gate > 0.0 && b.nis > b.gate) {
        b.status = UpdateStatus::RejectedGate;
        continue;
      }
      b.row = m;
      for (int r = 0; r < b.dim; ++r) keepRows[m++] = o + r;
      kept[keptCount++] = i;
    }

    UpdateReport<MaxM> rep;
    if (m == dim_) {
      rep = updateJoseph<N, MaxM>(g, all, 0.0);
    } else {
      LinearisedMeasurement<N, MaxM> sub;
      sub.y.resize(m);
      sub.H.resize(m, N);
      sub.R.resize(m, m);
      sub.PHt.resize(N, m);
      sub.S.resize(m, m);
      for (int a = 0; a < m; ++a) {
        const int ra = keepRows[a];
        sub.y[a] = all.y[ra];
        sub.H.row(a) = all.H.row(ra);
        sub.PHt.col(a) = all.PHt.col(ra);
        for (int c = 0; c < m; ++c) {
          sub.R(a, c) = all.R(ra, keepRows[c]);
          sub.S(a, c) = all.S(ra, keepRows[c]);
        }
      }
      rep = updateJoseph<N, MaxM>(g, sub, 0.0);
    }
    for (int k = 0; k < keptCount; ++k) {
      BlockReport& b = blocks_[kept[k]];
      b.status =
          rep.applied() ? (b.forced ? UpdateStatus::AcceptedForced : UpdateStatus::Accepted) : rep.status;
      if (!rep.applied()) b.row = -1;
    }
    return rep;
  }

  [[nodiscard]] int blockCount() const { return blockCount_; }
  [[nodiscard]] const BlockReport& block(int i) const { return blocks_[i]; }

 private:
  /// y^T S^-1 y by LDLT; fixed-size factorisations for the usual one- and two-row blocks.
  template <class Y, class S>
  static double blockNis(const Y& y, const S& Sb) {
    switch (y.rows()) {
      case 1:
        return fixedNis<1>(y, Sb);
      case 2:
        return fixedNis<2>(y, Sb);
      default:
        return fixedNis<Eigen::Dynamic>(y, Sb);
    }
  }
  template <int D, class Y, class S>
  static double fixedNis(const Y& y, const S& Sb) {
    using V = std::conditional_t<D == Eigen::Dynamic, BVec<MaxM>, Vec<D>>;
    using M = std::conditional_t<D == Eigen::Dynamic, BMat<MaxM>, Mat<D>>;
    const V yb = y;
    const M Sm = Sb;
    const Eigen::LDLT<M> ldlt(Sm);
    if (!ldltPositiveDefinite(ldlt)) return std::numeric_limits<double>::quiet_NaN();
    return yb.dot(ldlt.solve(yb));
  }

  int dim_ = 0;
  int blockCount_ = 0;
  std::array<BlockReport, MaxBlocks> blocks_{};
  std::array<int, MaxBlocks> offsets_{};
  Eigen::Matrix<double, MaxM, 1> y_ = Eigen::Matrix<double, MaxM, 1>::Zero();
  Eigen::Matrix<double, MaxM, N, Eigen::RowMajor> H_ =
      Eigen::Matrix<double, MaxM, N, Eigen::RowMajor>::Zero();
  Eigen::Matrix<double, MaxM, MaxM> R_ = Eigen::Matrix<double, MaxM, MaxM>::Zero();
};

}  // namespace reckoner::est
