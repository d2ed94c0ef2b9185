#pragma once
// The optimal coupled dead-reckoning / target-tracking filter that seed 000 decoupled (section 2.3,
// eq. 10): one joint state of 11 + 6n (the DRKF's 11 own-ship states once, then position, velocity and
// Gauss-Markov acceleration of each target), fed the same own-ship samples and radar plots as the
// DRKF and the TTKF bank. It exists to measure what decoupling costs in accuracy and saves in time
// (`reckoner-cli compare`, docs/performance.md).
//  - Prediction is dense, P <- Phi P Phi^T + Q over the whole joint state: the k N^3 that eq. 10
//    counts, at every own-ship epoch and at every plot's own time.
//  - An own-ship epoch updates the own-ship marginal with the DRKF's own code (same models, gates and
//    re-anchoring) and carries it to the joint state exactly: the measurement depends on the own-ship
//    states only, so p(targets | own ship) is unchanged (the conditional form of the Kalman update).
//  - A radar plot is a dense Joseph-form update of the joint state (range and true bearing).
#include <Eigen/Core>
#include <optional>
#include <span>
#include <vector>

#include "estimation/gauss_markov.h"
#include "estimation/singer.h"
#include "navigation/drkf.h"
#include "tracking/ttkf.h"

namespace reckoner::track {

struct CoupledConfig {
  nav::DrkfConfig own;
  est::GaussMarkov targetAcceleration{0.5, 1.0};
  double gateProbability = 0.9999;  ///< radar chi-square gate; 0 disables
  double initialSpeedSdMps = 10.0;
  double minRangeM = 1.0;
};

class CoupledDrttkf {
 public:
  static constexpr int kOwnDim = est::drkf::kStateDim;
  static constexpr int kTargetDim = 6;  ///< x, y, vx, vy, ax, ay

  /// Throws std::invalid_argument for a bad configuration or initial belief.
  CoupledDrttkf(const CoupledConfig& config, const geo::LocalFrame& frame, const est::drkf::Belief& initial,
                TimeUs t0);

  bool predictTo(TimeUs t);
  /// An own-ship epoch (as nav::Drkf::update).
  nav::DrkfUpdateReport updateOwnShip(TimeUs t, std::span<const sensors::OwnShipSample> samples);
  /// A plot of target `tag` (known association, as the paper assumes): updates its states, or adds
  /// six states for a new target. Returns the update report (Accepted for an initiation).
  est::UpdateReport<2> updateRadar(int tag, const GridPlot& plot);

  [[nodiscard]] int dim() const { return static_cast<int>(x_.size()); }
  [[nodiscard]] int targetCount() const { return static_cast<int>(tags_.size()); }
  [[nodiscard]] TimeUs timeUs() const { return timeUs_; }
  /// Index of the target with this tag, or -1.
  [[nodiscard]] int indexOf(int tag) const;
  /// The own-ship marginal (the DRKF's 11 states).
  [[nodiscard]] est::drkf::Belief ownShip() const;
  /// Target i's [x, y, vx, vy, ax, ay] and covariance.
  [[nodiscard]] est::Vec<6> target(int i) const { return x_.segment<6>(kOwnDim + kTargetDim * i); }
  [[nodiscard]] est::Mat<6> targetCovariance(int i) const {
    return P_.block<6, 6>(kOwnDim + kTargetDim * i, kOwnDim + kTargetDim * i);
  }
  /// The DRKF used for the own-ship updates (its counters).
  [[nodiscard]] const nav::Drkf& ownShipFilter() const { return own_; }

 private:
  void addTarget(int tag, const GridPlot& plot);
  CoupledConfig config_;
  geo::LocalFrame frame_;
  nav::Drkf own_;
  est::drkf::ProcessModel ownProcess_;
  double radarGate_;
  Eigen::VectorXd x_;
  Eigen::MatrixXd P_;
  std::vector<int> tags_;
  TimeUs timeUs_;
  // The last discretisation (own-ship epochs repeat the same step).
  TimeUs cachedDtUs_ = -1;
  est::Discretised<est::drkf::kStateDim> cachedOwn_;
  est::SingerAxis cachedTarget_;
};

}  // namespace reckoner::track
