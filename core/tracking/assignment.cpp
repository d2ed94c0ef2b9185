#include "tracking/assignment.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace reckoner::track {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

/// Square minimum-cost perfect matching (every entry finite), shortest augmenting paths with
/// potentials. Returns the column of each row.
std::vector<std::size_t> hungarian(const std::vector<double>& a, std::size_t n) {
  // 1-based potentials u (rows), v (columns); p[j] = row matched to column j (0: none).
  std::vector<double> u(n + 1, 0.0), v(n + 1, 0.0), minv(n + 1);
  std::vector<std::size_t> p(n + 1, 0), way(n + 1, 0);
  std::vector<char> used(n + 1);
  for (std::size_t i = 1; i <= n; ++i) {
    p[0] = i;
    std::size_t j0 = 0;
    std::fill(minv.begin(), minv.end(), kInf);
    std::fill(used.begin(), used.end(), 0);
    do {
      used[j0] = 1;
      const std::size_t i0 = p[j0];
      double delta = kInf;
      std::size_t j1 = 0;
      for (std::size_t j = 1; j <= n; ++j) {
        if (used[j]) continue;
        const double cur = a[(i0 - 1) * n + (j - 1)] - u[i0] - v[j];
        if (cur < minv[j]) {
          minv[j] = cur;
          way[j] = j0;
        }
        if (minv[j] < delta) {
          delta = minv[j];
          j1 = j;
        }
      }
      for (std::size_t j = 0; j <= n; ++j) {
        if (used[j]) {
          u[p[j]] += delta;
          v[j] -= delta;
        } else {
          minv[j] -= delta;
        }
      }
      j0 = j1;
    } while (p[j0] != 0);
    do {
      const std::size_t j1 = way[j0];
      p[j0] = p[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  std::vector<std::size_t> colOf(n);
  for (std::size_t j = 1; j <= n; ++j) colOf[p[j] - 1] = j - 1;
  return colOf;
}
}  // namespace

std::vector<int> solveAssignment(const std::vector<double>& cost, std::size_t rows, std::size_t cols,
                                 const std::vector<double>& missCost) {
  if (cost.size() != rows * cols || missCost.size() != rows)
    throw std::invalid_argument("assignment: cost matrix and miss costs do not match the sizes");
  for (double m : missCost)
    if (!std::isfinite(m)) throw std::invalid_argument("assignment: miss costs must be finite");
  std::vector<int> out(rows, -1);
  if (rows == 0) return out;
  // Square problem of size rows + cols:
  //   [ cost      | miss on the diagonal ]   rows: tracks, then one "unused" dummy per plot
  //   [ 0 on diag | 0                    ]   columns: plots, then one "miss" dummy per track
  // A forbidden entry gets a cost larger than any feasible total, so it is never chosen while the
  // all-miss assignment exists.
  double big = 1.0;
  for (double m : missCost) big += std::abs(m);
  for (double c : cost)
    if (std::isfinite(c)) big += std::abs(c);
  big *= 4.0;
  const std::size_t n = rows + cols;
  std::vector<double> a(n * n, big);
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t j = 0; j < cols; ++j) {
      const double c = cost[i * cols + j];
      if (std::isfinite(c)) a[i * n + j] = c;
    }
    a[i * n + cols + i] = missCost[i];
  }
  for (std::size_t k = 0; k < cols; ++k) {
    a[(rows + k) * n + k] = 0.0;
    for (std::size_t i = 0; i < rows; ++i) a[(rows + k) * n + cols + i] = 0.0;
  }
  const auto colOf = hungarian(a, n);
  for (std::size_t i = 0; i < rows; ++i) {
    const std::size_t j = colOf[i];
    if (j < cols && std::isfinite(cost[i * cols + j])) out[i] = static_cast<int>(j);
  }
  return out;
}

GnnProblem::GnnProblem(std::size_t tracks, std::size_t plots, std::vector<double> missCost)
    : tracks_(tracks), plots_(plots), miss_(std::move(missCost)) {
  if (miss_.size() != tracks_) throw std::invalid_argument("GNN: one miss cost per track");
}

void GnnProblem::addPair(std::size_t track, std::size_t plot, double cost) {
  if (track >= tracks_ || plot >= plots_) throw std::out_of_range("GNN: pair index out of range");
  if (std::isfinite(cost)) pairs_.push_back({track, plot, cost});
}

std::vector<int> GnnProblem::solve() const {
  std::vector<int> out(tracks_, -1);
  // Union-find over tracks [0, T) and plots [T, T + P).
  std::vector<std::size_t> parent(tracks_ + plots_);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const auto find = [&parent](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& p : pairs_) {
    const std::size_t a = find(p.track), b = find(tracks_ + p.plot);
    if (a != b) parent[a] = b;
  }
  // Group pairs by cluster root.
  std::vector<std::size_t> order(pairs_.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::vector<std::size_t> root(pairs_.size());
  for (std::size_t k = 0; k < pairs_.size(); ++k) root[k] = find(pairs_[k].track);
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return root[x] < root[y]; });
  largest_ = 0;
  std::vector<std::size_t> rowIndex(tracks_, SIZE_MAX), colIndex(plots_, SIZE_MAX);
  for (std::size_t s = 0; s < order.size();) {
    std::size_t e = s;
    while (e < order.size() && root[order[e]] == root[order[s]]) ++e;
    if (e - s == 1) {  // one track, one plot
      const Pair& p = pairs_[order[s]];
      if (p.cost < miss_[p.track]) out[p.track] = static_cast<int>(p.plot);
      largest_ = std::max<std::size_t>(largest_, 1);
      s = e;
      continue;
    }
    std::vector<std::size_t> rows, cols;
    for (std::size_t k = s; k < e; ++k) {
      const Pair& p = pairs_[order[k]];
      if (rowIndex[p.track] == SIZE_MAX) {
        rowIndex[p.track] = rows.size();
        rows.push_back(p.track);
      }
      if (colIndex[p.plot] == SIZE_MAX) {
        colIndex[p.plot] = cols.size();
        cols.push_back(p.plot);
      }
    }
    largest_ = std::max(largest_, rows.size() + cols.size());
    std::vector<double> cost(rows.size() * cols.size(), kInf);
    std::vector<double> miss(rows.size());
    for (std::size_t k = s; k < e; ++k) {
      const Pair& p = pairs_[order[k]];
      double& c = cost[rowIndex[p.track] * cols.size() + colIndex[p.plot]];
      c = std::min(c, p.cost);
    }
    for (std::size_t i = 0; i < rows.size(); ++i) miss[i] = miss_[rows[i]];
    const auto sol = solveAssignment(cost, rows.size(), cols.size(), miss);
    for (std::size_t i = 0; i < rows.size(); ++i)
      if (sol[i] >= 0) out[rows[i]] = static_cast<int>(cols[static_cast<std::size_t>(sol[i])]);
    for (std::size_t r : rows) rowIndex[r] = SIZE_MAX;
    for (std::size_t c : cols) colIndex[c] = SIZE_MAX;
    s = e;
  }
  return out;
}

}  // namespace reckoner::track
