#pragma once
// What the soak (docs/robustness.md, "Soak") checks at every frame of the engine: every number finite,
// every covariance (own ship's and each track's) symmetric and positive definite, and the NEES of own
// ship and of the tracks against the truth, gathered per hour.
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "estimation/chi_square.h"
#include "sim/simulation_engine.h"

namespace reckoner::soak {

/// NEES values gathered over one hour of the run.
struct NeesHour {
  double sum = 0.0;
  std::int64_t count = 0;
  std::int64_t aboveQ99 = 0;  ///< values above the chi-square 99% quantile of one value
  [[nodiscard]] double mean() const { return count > 0 ? sum / static_cast<double>(count) : 0.0; }
};

struct NeesSeries {
  int dof = 0;
  std::vector<NeesHour> hours;
  void add(double nees, double hourIndex, double q99);
  [[nodiscard]] NeesHour total() const;
};

struct FrameChecks {
  std::int64_t frames = 0;
  std::int64_t covariancesChecked = 0;  ///< own ship's and every track's, each frame
  std::int64_t nonFinite = 0;           ///< frames with a NaN or infinity in an estimate or covariance
  std::int64_t asymmetric = 0;          ///< covariances not symmetric to 1e-9 of their largest entry
  std::int64_t notPositiveDefinite = 0;
  std::vector<std::string> problems;  ///< the first few, with their time and what
  NeesSeries own, tracks;             ///< own ship: the DRKF's NEES; tracks: target x, y, vx, vy (4 dof)
  std::int64_t maxTracks = 0, maxAisTargets = 0, maxTargetsPresent = 0;
  [[nodiscard]] bool clean() const { return nonFinite == 0 && asymmetric == 0 && notPositiveDefinite == 0; }
};

class FrameChecker {
 public:
  FrameChecker(const sim::Scenario& scenario, const est::drkf::ProcessParams& process);
  void check(const sim::SimFrame& f);
  [[nodiscard]] const FrameChecks& result() const { return r_; }

 private:
  template <int N>
  /// trackId -1: own ship's.
  void covariance(const est::Mat<N>& P, const est::Vec<N>& x, const sim::SimFrame& f, int trackId);
  void problem(const sim::SimFrame& f, const std::string& what);
  void sweeps(const sim::SimFrame& f);

  const sim::Scenario& scenario_;
  std::unordered_map<int, std::size_t> index_;  ///< target id -> scenario order
  est::drkf::ProcessParams process_;
  double ownQ99_ = 0.0, trackQ99_ = 0.0;
  FrameChecks r_;
};

}  // namespace reckoner::soak
