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

Coastline::Coastline(const std::vector<CoastSegment>& segments, double cellM) : cellM_(cellM) {
  if (!(cellM > 0.0)) throw std::invalid_argument("coastline: cell size must be positive");
  for (const auto& s : segments)
    if (s.a.allFinite() && s.b.allFinite() && (s.b - s.a).norm() > 1e-3 && s.sdM > 0.0)
      segments_.push_back(s);
  // Each segment goes into every cell its bounding box touches (segments are short against cells).
  std::vector<geo::GridBox> boxes;
  boxes.reserve(segments_.size());
  for (const auto& s : segments_)
    boxes.push_back({std::min(s.a[0], s.b[0]), std::min(s.a[1], s.b[1]), std::max(s.a[0], s.b[0]),
                     std::max(s.a[1], s.b[1])});
  index_ = geo::GridIndex(cellM_, boxes);
}

std::optional<Coastline::Nearest> Coastline::nearest(const est::Vec<2>& p, double maxDistanceM) const {
  if (segments_.empty() || !p.allFinite()) return std::nullopt;
  const auto cx = index_.cellOf(p[0]);
  const auto cy = index_.cellOf(p[1]);
  const auto reach = static_cast<std::int64_t>(std::ceil(maxDistanceM / cellM_));
  std::optional<Nearest> best;
  double bestD = maxDistanceM;
  for (std::int64_t ix = cx - reach; ix <= cx + reach; ++ix) {
    for (std::int64_t iy = cy - reach; iy <= cy + reach; ++iy) {
      for (const std::uint32_t i : index_.cell(ix, iy)) {
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
  auto ix = index_.cellOf(origin[0]);
  auto iy = index_.cellOf(origin[1]);
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
    if (index_.inside(ix, iy)) {
      double best = inf;
      for (const std::uint32_t i : index_.cell(ix, iy))
        if (const auto s = rayHit(origin, u, segments_[i].a, segments_[i].b)) best = std::min(best, *s);
      if (best <= std::min(tExit, maxRangeM) + 1e-9) return best;
    } else if ((ix < index_.minX() && stepX < 0) || (iy < index_.minY() && stepY < 0) ||
               (ix > index_.maxX() && stepX > 0) || (iy > index_.maxY() && stepY > 0)) {
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
