#pragma once
// Decoupled (one DRKF feeding a TTKF per target, seed 000 figure 3) against the optimal coupled
// filter (11 + 6n states) on identical measurement streams: accuracy and measured cost beside eq. 10.
#include <cstdint>
#include <vector>

#include "sim/scenario.h"

namespace reckoner::studies {

struct ComparisonRow {
  int targets = 0;
  int runs = 0;
  int coupledDim = 0;
  // Target errors after each target's first 60 s, pooled over targets, epochs and runs.
  double decoupledRmsePositionM = 0, coupledRmsePositionM = 0;
  double decoupledRmseVelocityMps = 0, coupledRmseVelocityMps = 0;
  double decoupledMeanNees = 0, coupledMeanNees = 0;  ///< target position and velocity (4 states)
  // Measured cost on the first run: filtering time per simulated second (one DRKF cycle with its plots),
  // and one covariance propagation alone (the operation eq. 10 counts).
  double decoupledUsPerCycle = 0, coupledUsPerCycle = 0;
  double decoupledPropagationUs = 0, coupledPropagationUs = 0;
  double eq10Ratio = 0;      ///< (11 + 6n)^3 / (11^3 + n 12^3)
  double eq10SavingPct = 0;  ///< eq. 10
  [[nodiscard]] double cycleRatio() const { return coupledUsPerCycle / decoupledUsPerCycle; }
  [[nodiscard]] double propagationRatio() const { return coupledPropagationUs / decoupledPropagationUs; }
};

/// The scenario with exactly n targets: its own first, then copies of them turned about own ship's
/// start by multiples of 360/k degrees (course and position), with fresh ids.
sim::Scenario withTargetCount(const sim::Scenario& s, int n);

/// For each n: `runs` seeds of withTargetCount(s, n), known association (the paper's assumption).
/// Throws std::invalid_argument if the scenario has no radar or no targets.
std::vector<ComparisonRow> compareCoupled(const sim::Scenario& s, const std::vector<int>& targetCounts,
                                          int runs, int threads, std::uint64_t seed);

}  // namespace reckoner::studies
