#pragma once
// Optimal (minimum total cost) assignment of tracks to plots for global nearest neighbour association.
// Each row (track) takes at most one column (plot) and each column at most one row; a row may stay
// unassigned at its own miss cost. Forbidden pairs (outside the gate) have infinite cost.
// Solved exactly by the shortest-augmenting-path Hungarian method (O(n^3), n = rows + columns) on the
// square problem padded with "miss" and "unused" dummies; callers split large problems into
// independent clusters first (GnnProblem).
#include <cstddef>
#include <vector>

namespace reckoner::track {

/// cost is row-major rows x cols; returns, per row, the column it takes or -1. Throws
/// std::invalid_argument for a size mismatch or a non-finite miss cost.
std::vector<int> solveAssignment(const std::vector<double>& cost, std::size_t rows, std::size_t cols,
                                 const std::vector<double>& missCost);

/// A sparse association problem: gated (track, plot, cost) pairs. solve() splits it into connected
/// clusters and solves each one exactly, so well separated targets cost O(pairs).
class GnnProblem {
 public:
  GnnProblem(std::size_t tracks, std::size_t plots, std::vector<double> missCost);
  void addPair(std::size_t track, std::size_t plot, double cost);
  /// Per track, the plot it takes or -1.
  [[nodiscard]] std::vector<int> solve() const;
  [[nodiscard]] std::size_t largestCluster() const { return largest_; }

 private:
  struct Pair {
    std::size_t track, plot;
    double cost;
  };
  std::size_t tracks_, plots_;
  std::vector<double> miss_;
  std::vector<Pair> pairs_;
  mutable std::size_t largest_ = 0;
};

}  // namespace reckoner::track
