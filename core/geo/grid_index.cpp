#include "geo/grid_index.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <utility>

namespace reckoner::geo {
namespace {
/// Coordinates beyond this are not of a chart or a radar picture (the Earth's circumference is 4e7 m);
/// such boxes are left out rather than overflow the cell arithmetic.
constexpr double kMaxCoordinateM = 1e9;

bool usable(const GridBox& b) {
  for (const double v : {b.x0, b.y0, b.x1, b.y1})
    if (!std::isfinite(v) || std::abs(v) > kMaxCoordinateM) return false;
  return b.x0 <= b.x1 && b.y0 <= b.y1;
}
}  // namespace

GridIndex::GridIndex(double cellM, const std::vector<GridBox>& boxes) : cellM_(cellM) {
  if (!(cellM > 0.0) || !std::isfinite(cellM))
    throw std::invalid_argument("grid index: cell size must be positive");
  if (boxes.size() > std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument("grid index: too many items");
  std::int64_t x0 = std::numeric_limits<std::int64_t>::max(), y0 = x0,
               x1 = std::numeric_limits<std::int64_t>::min(), y1 = x1;
  for (const auto& b : boxes) {
    if (!usable(b)) continue;
    x0 = std::min(x0, cellOf(b.x0));
    y0 = std::min(y0, cellOf(b.y0));
    x1 = std::max(x1, cellOf(b.x1));
    y1 = std::max(y1, cellOf(b.y1));
  }
  if (x0 > x1) return;  // nothing usable
  minX_ = x0;
  minY_ = y0;
  nx_ = x1 - x0 + 1;
  ny_ = y1 - y0 + 1;
  if (nx_ > (std::int64_t{1} << 31) || ny_ > (std::int64_t{1} << 31))
    throw std::invalid_argument("grid index: cell size too small for the extent of the items");
  // (linear cell key, item), sorted: the items of each cell in ascending order.
  std::vector<std::pair<std::int64_t, std::uint32_t>> entries;
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    const auto& b = boxes[i];
    if (!usable(b)) continue;
    for (std::int64_t iy = cellOf(b.y0); iy <= cellOf(b.y1); ++iy)
      for (std::int64_t ix = cellOf(b.x0); ix <= cellOf(b.x1); ++ix)
        entries.emplace_back((iy - minY_) * nx_ + (ix - minX_), i);
  }
  std::sort(entries.begin(), entries.end());
  items_.reserve(entries.size());
  for (const auto& e : entries) items_.push_back(e.second);
  const auto cells = static_cast<double>(nx_) * static_cast<double>(ny_);
  direct_ = cells <= 4.0 * static_cast<double>(entries.size()) + 4096.0;
  if (direct_) {
    start_.assign(static_cast<std::size_t>(nx_ * ny_) + 1, 0);
    for (const auto& e : entries) ++start_[static_cast<std::size_t>(e.first) + 1];
    for (std::size_t k = 1; k < start_.size(); ++k) start_[k] += start_[k - 1];
    return;
  }
  for (std::size_t k = 0; k < entries.size(); ++k) {
    if (keys_.empty() || keys_.back() != entries[k].first) {
      keys_.push_back(entries[k].first);
      start_.push_back(static_cast<std::uint32_t>(k));
    }
  }
  start_.push_back(static_cast<std::uint32_t>(entries.size()));
}

std::span<const std::uint32_t> GridIndex::cell(std::int64_t ix, std::int64_t iy) const {
  if (!inside(ix, iy)) return {};
  const std::int64_t key = (iy - minY_) * nx_ + (ix - minX_);
  std::size_t slot = 0;
  if (direct_) {
    slot = static_cast<std::size_t>(key);
  } else {
    const auto it = std::lower_bound(keys_.begin(), keys_.end(), key);
    if (it == keys_.end() || *it != key) return {};
    slot = static_cast<std::size_t>(it - keys_.begin());
  }
  return {items_.data() + start_[slot], items_.data() + start_[slot + 1]};
}

}  // namespace reckoner::geo
