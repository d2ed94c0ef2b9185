#include "radar/land_mask.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace reckoner::radar {

LandMask::LandMask(const std::vector<std::vector<est::Vec<2>>>& rings, double cellM) : cellM_(cellM) {
  if (!(cellM > 0.0)) throw std::invalid_argument("land mask: cell size must be positive");
  for (const auto& r : rings) {
    if (r.size() < 3) continue;
    bool finite = true;
    for (const auto& p : r) finite = finite && p.allFinite();
    if (!finite) continue;
    rings_.push_back(r);
    for (std::size_t i = 0; i < r.size(); ++i) {
      const est::Vec<2>& a = r[i];
      const est::Vec<2>& b = r[(i + 1) % r.size()];
      if (a[1] != b[1]) edges_.push_back({a, b});  // horizontal edges never cross a horizontal ray
    }
  }
  std::vector<geo::GridBox> boxes;
  boxes.reserve(edges_.size());
  for (const auto& e : edges_)
    boxes.push_back({std::min(e.a[0], e.b[0]), std::min(e.a[1], e.b[1]), std::max(e.a[0], e.b[0]),
                     std::max(e.a[1], e.b[1])});
  index_ = geo::GridIndex(cellM_, boxes);
}

bool LandMask::contains(const est::Vec<2>& p) const {
  if (edges_.empty() || !p.allFinite()) return false;
  const auto iy = index_.cellOf(p[1]);
  const auto ix0 = index_.cellOf(p[0]);
  if (!index_.inside(index_.minX(), iy) || ix0 > index_.maxX()) return false;
  // Crossings of the ray from p towards +x; each edge is counted in the one cell holding its crossing.
  bool inside = false;
  for (std::int64_t ix = std::max(ix0, index_.minX()); ix <= index_.maxX(); ++ix) {
    for (const std::uint32_t i : index_.cell(ix, iy)) {
      const Edge& e = edges_[i];
      if ((e.a[1] > p[1]) == (e.b[1] > p[1])) continue;
      const double x = e.a[0] + (p[1] - e.a[1]) * (e.b[0] - e.a[0]) / (e.b[1] - e.a[1]);
      if (x <= p[0]) continue;
      if (index_.cellOf(x) != ix) continue;
      inside = !inside;
    }
  }
  return inside;
}

}  // namespace reckoner::radar
