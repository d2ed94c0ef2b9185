#pragma once
// Land areas for chart-aided ARPA (issue 7): polygons in the grid frame (the chart's LNDARE rings) and
// a point-in-land test, even-odd over all rings so that lakes and holes are water. A uniform grid of
// the ring edges keeps the test to the edges of one row of cells.
#include <cstdint>
#include <vector>

#include "estimation/gaussian.h"
#include "geo/grid_index.h"

namespace reckoner::radar {

class LandMask {
 public:
  /// Rings of at least three finite points (closed implicitly). cellM: the index's cell size.
  explicit LandMask(const std::vector<std::vector<est::Vec<2>>>& rings, double cellM = 200.0);
  [[nodiscard]] bool contains(const est::Vec<2>& p) const;
  [[nodiscard]] bool empty() const { return edges_.empty(); }
  /// The rings kept (at least three finite points each), for drawing.
  [[nodiscard]] const std::vector<std::vector<est::Vec<2>>>& rings() const { return rings_; }

 private:
  struct Edge {
    est::Vec<2> a, b;
  };
  std::vector<Edge> edges_;
  std::vector<std::vector<est::Vec<2>>> rings_;
  double cellM_;
  geo::GridIndex index_;  ///< the edges by bounding box
};

}  // namespace reckoner::radar
