#pragma once
// The one percentile of the project (docs/outputs.md, "Statistics"): the nearest-rank percentile. For
// n finite samples and 0 < p <= 1 it is the smallest sample x such that at least a share p of the
// samples are <= x, i.e. the ceil(p n)-th smallest. "p95" in every table (the IMO accuracy cells, the
// radar-fix and own-ship filter studies, the manoeuvre report, the campaigns) is this statistic.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace reckoner {

/// Nearest-rank percentile of the samples (taken by value: they are partially reordered). Non-finite
/// samples count as samples (an infinite error is larger than every finite one). An empty set gives
/// `empty` (NaN unless the caller chooses, e.g. infinity for "no sample, so no bound").
inline double percentileNearestRank(std::vector<double> samples, double p,
                                    double empty = std::numeric_limits<double>::quiet_NaN()) {
  if (samples.empty() || !(p > 0.0)) return empty;
  const auto n = samples.size();
  auto rank = static_cast<std::size_t>(std::ceil(std::min(p, 1.0) * static_cast<double>(n)));
  rank = std::clamp<std::size_t>(rank, 1, n);
  const auto kth = samples.begin() + static_cast<std::ptrdiff_t>(rank - 1);
  std::nth_element(samples.begin(), kth, samples.end());
  return *kth;
}

/// The 95th nearest-rank percentile (see percentileNearestRank).
inline double percentile95(std::vector<double> samples,
                           double empty = std::numeric_limits<double>::quiet_NaN()) {
  return percentileNearestRank(std::move(samples), 0.95, empty);
}

}  // namespace reckoner
