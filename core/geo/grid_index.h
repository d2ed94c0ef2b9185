#pragma once
// The one uniform grid index of the project: items with a bounding box in the grid frame (metres), each
// placed in every cell its box touches, for "what is near this point / along this ray / in this row"
// queries. Used by the radar contours (radar/coastline.h), the land mask (radar/land_mask.h) and the
// track manager's plot index (tracking/track_manager.cpp).
//
// Cell (ix, iy) covers [ix c, (ix + 1) c) x [iy c, (iy + 1) c) for cell size c. The cells are stored
// compressed (items of all cells in one array, in cell order): directly addressed when the bounding
// rectangle of the items has few cells for the items it holds, else as a sorted list of the non-empty
// cells (a plot index spread over 100 km with 50 m cells would otherwise need 4e6 empty cells).
// Cost: build O(k log k) for k item-cell incidences, memory O(k) (+ the cells of the rectangle when
// directly addressed); a cell lookup O(1) directly addressed, O(log cells) otherwise.
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

namespace reckoner::geo {

/// An axis-aligned box in the grid frame, metres (x0 <= x1, y0 <= y1; a point has x0 == x1).
struct GridBox {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
};

class GridIndex {
 public:
  GridIndex() = default;
  /// Item i is boxes[i]. Boxes that are not finite are left out. cellM must be positive and finite
  /// (std::invalid_argument otherwise).
  GridIndex(double cellM, const std::vector<GridBox>& boxes);

  [[nodiscard]] double cellM() const { return cellM_; }
  /// The cell index of a coordinate (x for ix, y for iy).
  [[nodiscard]] std::int64_t cellOf(double v) const {
    return static_cast<std::int64_t>(std::floor(v / cellM_));
  }
  /// The items of cell (ix, iy) in ascending order; empty outside the indexed rectangle.
  [[nodiscard]] std::span<const std::uint32_t> cell(std::int64_t ix, std::int64_t iy) const;

  [[nodiscard]] bool empty() const { return items_.empty(); }
  /// The indexed rectangle of cells (inclusive bounds); meaningless when empty().
  [[nodiscard]] std::int64_t minX() const { return minX_; }
  [[nodiscard]] std::int64_t minY() const { return minY_; }
  [[nodiscard]] std::int64_t maxX() const { return minX_ + nx_ - 1; }
  [[nodiscard]] std::int64_t maxY() const { return minY_ + ny_ - 1; }
  /// Whether (ix, iy) lies inside the indexed rectangle.
  [[nodiscard]] bool inside(std::int64_t ix, std::int64_t iy) const {
    return !empty() && ix >= minX_ && iy >= minY_ && ix <= maxX() && iy <= maxY();
  }

 private:
  double cellM_ = 1.0;
  std::int64_t minX_ = 0, minY_ = 0, nx_ = 0, ny_ = 0;
  bool direct_ = true;
  std::vector<std::int64_t> keys_;    ///< sparse: the non-empty cells' linear keys, ascending
  std::vector<std::uint32_t> start_;  ///< per cell (direct) or per key (sparse), and one past the end
  std::vector<std::uint32_t> items_;
};

}  // namespace reckoner::geo
