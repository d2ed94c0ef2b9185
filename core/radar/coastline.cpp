#include "radar/coastline.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace reckoner::radar {
namespace {
/// Closest point of segment ab to p.
est::Vec<2> closestOn(const est::Vec<2>& a, const est::Vec<2>& b, const est::Vec<2>& p) {
  const est::Vec<2> ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return a + t * ab;
}
/// Parameter s >= 0 along the ray o + s u where it crosses segment ab, if it does.
std::optional<double> rayHit(const est::Vec<2>& o, const est::Vec<2>& u, const est::Vec<2>& a,
                             const est::Vec<2>& b) {
  const est::Vec<2> e = b - a;
  const double den = u[0] * e[1] - u[1] * e[0];
  if (std::abs(den) < 1e-12) return std::nullopt;
  const est::Vec<2> w = a - o;
  const double s = (w[0] * e[1] - w[1] * e[0]) / den;  // along the ray
  const double t = (w[0] * u[1] - w[1] * u[0]) / den;  // along the segment
  if (s < 0.0 || t < 0.0 || t > 1.0) return std::nullopt;
  return s;
}
}  // namespace

Coastline::Coastline(std::vector<CoastSegment> segments, double cellM) : cellM_(cellM) {
  if (!(cellM > 0.0)) throw std::invalid_argument("coastline: cell size must be positive");
  for (auto& s : segments)
    if (s.a.allFinite() && s.b.allFinite() && (s.b - s.a).norm() > 1e-3 && s.sdM > 0.0)
      segments_.push_back(s);
  if (segments_.empty()) return;
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const auto& s : segments_) {
    x0 = std::min({x0, s.a[0], s.b[0]});
    y0 = std::min({y0, s.a[1], s.b[1]});
    x1 = std::max({x1, s.a[0], s.b[0]});
    y1 = std::max({y1, s.a[1], s.b[1]});
  }
  minX_ = static_cast<std::int64_t>(std::floor(x0 / cellM_));
  minY_ = static_cast<std::int64_t>(std::floor(y0 / cellM_));
  nx_ = static_cast<std::int64_t>(std::floor(x1 / cellM_)) - minX_ + 1;
  ny_ = static_cast<std::int64_t>(std::floor(y1 / cellM_)) - minY_ + 1;
  cells_.assign(static_cast<std::size_t>(nx_ * ny_), {});
  // Each segment goes into every cell its bounding box touches (segments are short against cells).
  for (std::uint32_t i = 0; i < segments_.size(); ++i) {
    const auto& s = segments_[i];
    const auto cx0 = static_cast<std::int64_t>(std::floor(std::min(s.a[0], s.b[0]) / cellM_));
    const auto cx1 = static_cast<std::int64_t>(std::floor(std::max(s.a[0], s.b[0]) / cellM_));
    const auto cy0 = static_cast<std::int64_t>(std::floor(std::min(s.a[1], s.b[1]) / cellM_));
    const auto cy1 = static_cast<std::int64_t>(std::floor(std::max(s.a[1], s.b[1]) / cellM_));
    for (std::int64_t ix = cx0; ix <= cx1; ++ix)
      for (std::int64_t iy = cy0; iy <= cy1; ++iy) cells_[static_cast<std::size_t>(key(ix, iy))].push_back(i);
  }
}

std::int64_t Coastline::key(std::int64_t ix, std::int64_t iy) const {
  return (iy - minY_) * nx_ + (ix - minX_);
}

const std::vector<std::uint32_t>* Coastline::cell(std::int64_t ix, std::int64_t iy) const {
  if (ix < minX_ || iy < minY_ || ix >= minX_ + nx_ || iy >= minY_ + ny_) return nullptr;
  return &cells_[static_cast<std::size_t>(key(ix, iy))];
}

std::optional<Coastline::Nearest> Coastline::nearest(const est::Vec<2>& p, double maxDistanceM) const {
  if (segments_.empty() || !p.allFinite()) return std::nullopt;
  const auto cx = static_cast<std::int64_t>(std::floor(p[0] / cellM_));
  const auto cy = static_cast<std::int64_t>(std::floor(p[1] / cellM_));
  const auto reach = static_cast<std::int64_t>(std::ceil(maxDistanceM / cellM_));
  std::optional<Nearest> best;
  double bestD = maxDistanceM;
  for (std::int64_t ix = cx - reach; ix <= cx + reach; ++ix) {
    for (std::int64_t iy = cy - reach; iy <= cy + reach; ++iy) {
      const auto* c = cell(ix, iy);
      if (!c) continue;
      for (const std::uint32_t i : *c) {
        const auto& s = segments_[i];
        const est::Vec<2> q = closestOn(s.a, s.b, p);
        const double d = (p - q).norm();
        if (d <= bestD) {
          bestD = d;
          const est::Vec<2> e = (s.b - s.a).normalized();
          best = Nearest{q, est::Vec<2>(-e[1], e[0]), d, i};
        }
      }
    }
  }
  return best;
}

std::optional<double> Coastline::firstHit(const est::Vec<2>& origin, double azimuthRad,
                                          double maxRangeM) const {
  if (segments_.empty() || !origin.allFinite()) return std::nullopt;
  const est::Vec<2> u(std::sin(azimuthRad), std::cos(azimuthRad));
  // Walk the grid cells along the ray (Amanatides and Woo); the first cell with a crossing that lies
  // inside it gives the nearest hit.
  auto ix = static_cast<std::int64_t>(std::floor(origin[0] / cellM_));
  auto iy = static_cast<std::int64_t>(std::floor(origin[1] / cellM_));
  const int stepX = u[0] > 0 ? 1 : -1, stepY = u[1] > 0 ? 1 : -1;
  const double inf = std::numeric_limits<double>::infinity();
  const auto boundary = [&](std::int64_t i, int step, double o) {
    return (static_cast<double>(step > 0 ? i + 1 : i) * cellM_ - o);
  };
  double tMaxX = u[0] != 0.0 ? boundary(ix, stepX, origin[0]) / u[0] : inf;
  double tMaxY = u[1] != 0.0 ? boundary(iy, stepY, origin[1]) / u[1] : inf;
  const double tDeltaX = u[0] != 0.0 ? cellM_ / std::abs(u[0]) : inf;
  const double tDeltaY = u[1] != 0.0 ? cellM_ / std::abs(u[1]) : inf;
  double tEnter = 0.0;
  while (tEnter <= maxRangeM) {
    const double tExit = std::min(tMaxX, tMaxY);
    if (const auto* c = cell(ix, iy)) {
      double best = inf;
      for (const std::uint32_t i : *c)
        if (const auto s = rayHit(origin, u, segments_[i].a, segments_[i].b)) best = std::min(best, *s);
      if (best <= std::min(tExit, maxRangeM) + 1e-9) return best;
    } else if ((ix < minX_ && stepX < 0) || (iy < minY_ && stepY < 0) || (ix >= minX_ + nx_ && stepX > 0) ||
               (iy >= minY_ + ny_ && stepY > 0)) {
      return std::nullopt;  // left the indexed area for good
    }
    tEnter = tExit;
    if (tMaxX < tMaxY) {
      tMaxX += tDeltaX;
      ix += stepX;
    } else {
      tMaxY += tDeltaY;
      iy += stepY;
    }
  }
  return std::nullopt;
}

}  // namespace reckoner::radar
