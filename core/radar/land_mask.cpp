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
  if (edges_.empty()) return;
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const auto& e : edges_) {
    x0 = std::min({x0, e.a[0], e.b[0]});
    y0 = std::min({y0, e.a[1], e.b[1]});
    x1 = std::max({x1, e.a[0], e.b[0]});
    y1 = std::max({y1, e.a[1], e.b[1]});
  }
  minX_ = static_cast<std::int64_t>(std::floor(x0 / cellM_));
  minY_ = static_cast<std::int64_t>(std::floor(y0 / cellM_));
  nx_ = static_cast<std::int64_t>(std::floor(x1 / cellM_)) - minX_ + 1;
  ny_ = static_cast<std::int64_t>(std::floor(y1 / cellM_)) - minY_ + 1;
  cells_.assign(static_cast<std::size_t>(nx_ * ny_), {});
  for (std::uint32_t i = 0; i < edges_.size(); ++i) {
    const auto& e = edges_[i];
    const auto cx0 = static_cast<std::int64_t>(std::floor(std::min(e.a[0], e.b[0]) / cellM_)) - minX_;
    const auto cx1 = static_cast<std::int64_t>(std::floor(std::max(e.a[0], e.b[0]) / cellM_)) - minX_;
    const auto cy0 = static_cast<std::int64_t>(std::floor(std::min(e.a[1], e.b[1]) / cellM_)) - minY_;
    const auto cy1 = static_cast<std::int64_t>(std::floor(std::max(e.a[1], e.b[1]) / cellM_)) - minY_;
    for (std::int64_t iy = cy0; iy <= cy1; ++iy)
      for (std::int64_t ix = cx0; ix <= cx1; ++ix)
        cells_[static_cast<std::size_t>(iy * nx_ + ix)].push_back(i);
  }
}

bool LandMask::contains(const est::Vec<2>& p) const {
  if (edges_.empty() || !p.allFinite()) return false;
  const auto iy = static_cast<std::int64_t>(std::floor(p[1] / cellM_)) - minY_;
  const auto ix0 = static_cast<std::int64_t>(std::floor(p[0] / cellM_)) - minX_;
  if (iy < 0 || iy >= ny_ || ix0 >= nx_) return false;
  // Crossings of the ray from p towards +x; each edge is counted in the one cell holding its crossing.
  bool inside = false;
  for (std::int64_t ix = std::max<std::int64_t>(ix0, 0); ix < nx_; ++ix) {
    for (const std::uint32_t i : cells_[static_cast<std::size_t>(iy * nx_ + ix)]) {
      const Edge& e = edges_[i];
      if ((e.a[1] > p[1]) == (e.b[1] > p[1])) continue;
      const double x = e.a[0] + (p[1] - e.a[1]) * (e.b[0] - e.a[0]) / (e.b[1] - e.a[1]);
      if (x <= p[0]) continue;
      if (static_cast<std::int64_t>(std::floor(x / cellM_)) - minX_ != ix) continue;
      inside = !inside;
    }
  }
  return inside;
}

}  // namespace reckoner::radar
