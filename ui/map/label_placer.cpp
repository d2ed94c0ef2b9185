#include "ui/map/label_placer.h"

#include <array>
#include <limits>

namespace reckoner::ui {
namespace {
constexpr double kGapPx = 2.0;

/// Candidate k (0..23) for a request: 8 directions, 3 distances.
QRectF candidate(const LabelRequest& r, int k) {
  // Right-up first (where the label always was), then right, right-down, left-up, left, left-down, up
  // and down.
  static constexpr std::array<std::array<int, 2>, 8> kDirections{
      {{1, -1}, {1, 0}, {1, 1}, {-1, -1}, {-1, 0}, {-1, 1}, {0, -1}, {0, 1}}};
  const auto [dx, dy] = kDirections[static_cast<std::size_t>(k % 8)];
  const int ring = k / 8;
  const double w = r.size.width(), h = r.size.height();
  const double d = r.clearancePx + kGapPx + ring * (h + kGapPx);
  // Diagonal positions sit at the symbol's corner; straight ones centred on its side.
  const double off = (dx != 0 && dy != 0) ? 0.7 * d : d;
  double left = 0.0, top = 0.0;
  if (dx > 0) left = r.anchor.x() + off;
  if (dx < 0) left = r.anchor.x() - off - w;
  if (dx == 0) left = r.anchor.x() - w / 2.0;
  if (dy < 0) top = r.anchor.y() - off - h;
  if (dy > 0) top = r.anchor.y() + off;
  if (dy == 0) top = r.anchor.y() - h / 2.0;
  return {left, top, w, h};
}

double overlapArea(const QRectF& a, const std::vector<QRectF>& others) {
  double sum = 0.0;
  for (const QRectF& o : others) {
    const QRectF i = a.intersected(o);
    if (!i.isEmpty()) sum += i.width() * i.height();
  }
  return sum;
}
}  // namespace

std::vector<QRectF> placeLabels(const std::vector<LabelRequest>& requests, std::vector<QRectF> obstacles,
                                const QRectF& bounds) {
  constexpr int kCandidates = 24;
  std::vector<QRectF> placed;
  placed.reserve(requests.size());
  for (const LabelRequest& r : requests) {
    QRectF best = candidate(r, 0);
    double bestCost = std::numeric_limits<double>::infinity();
    for (int k = 0; k < kCandidates; ++k) {
      const QRectF c = candidate(r, k);
      // A gap of kGapPx around every label, so that two numbers never touch ("116" "130").
      const QRectF padded = c.adjusted(-kGapPx, -kGapPx, kGapPx, kGapPx);
      const double cost = overlapArea(padded, obstacles) + (bounds.contains(c) ? 0.0 : 1e6) + k * 1e-3;
      if (cost < bestCost) {
        best = c;
        bestCost = cost;
      }
      if (cost < 1.0) break;  // free (the rank term is below 1): the first free one wins
    }
    placed.push_back(best);
    obstacles.push_back(best);
  }
  return placed;
}

}  // namespace reckoner::ui
