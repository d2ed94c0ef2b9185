#pragma once
// The data associator: global nearest neighbour. From the hypothesiser's table (each track's miss
// cost, the pairs inside the gate with their costs) it takes the assignment of minimum total cost,
// each track at most one plot and each plot at most one track, solved exactly by GnnProblem
// (assignment.h) cluster by cluster.
#include <cstddef>
#include <vector>

#include "tracking/hypothesiser.h"

namespace reckoner::track {

struct PlotAssignment {
  std::vector<int> trackOfPlot;    ///< per plot, the index of the track (in the table) taking it, or -1
  std::size_t largestCluster = 0;  ///< tracks + plots of the largest cluster solved
};

/// Throws std::out_of_range for a pair outside the table, std::invalid_argument for a non-finite miss
/// cost in a cluster of several pairs.
[[nodiscard]] PlotAssignment associateNearest(const HypothesisTable& table);

}  // namespace reckoner::track
