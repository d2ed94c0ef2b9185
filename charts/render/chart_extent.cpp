#include "charts/render/chart_extent.h"

#include <algorithm>
#include <cmath>

#include "common/angles.h"

namespace reckoner::charts {
namespace {
constexpr double kEarthRadiusM = 6378137.0;  // the view's Mercator sphere (viewport.cpp)
}

std::vector<CellPtr> cellsAt(const std::vector<CellPtr>& cells, const LatLon& p) {
  std::vector<CellPtr> at;
  for (const CellPtr& c : cells)
    if (c && c->coverageBounds().contains(p) && c->covers(p)) at.push_back(c);
  std::stable_sort(at.begin(), at.end(), [](const CellPtr& a, const CellPtr& b) {
    const int sa = a->info().compilationScale > 0 ? a->info().compilationScale : 1 << 30;
    const int sb = b->info().compilationScale > 0 ? b->info().compilationScale : 1 << 30;
    return sa < sb;
  });
  return at;
}

Bounds coverageOf(const std::vector<CellPtr>& cells) {
  Bounds b;
  for (const CellPtr& c : cells)
    if (c) b.add(c->coverageBounds());
  return b;
}

double largestScaleAt(const std::vector<CellPtr>& cells, const LatLon& p) {
  for (const CellPtr& c : cellsAt(cells, p))
    if (c->info().compilationScale > 0)
      return std::max(kLargestScale, c->info().compilationScale / kMaxOverscale);
  return kLargestScaleWithoutChart;
}

double smallestScale(double latDeg, int widthPx, double pixelSizeMm) {
  // The view spans widthPx N p / (R cos lat) radians of longitude (viewport.cpp); 2 pi for the world.
  const double cosLat = std::max(std::cos(degToRad(std::clamp(latDeg, -85.0, 85.0))), 0.05);
  return 2.0 * kPi * kEarthRadiusM * cosLat / (std::max(widthPx, 16) * pixelSizeMm / 1000.0);
}

Viewport fitView(const Bounds& box, int widthPx, int heightPx, double rotationRad, double marginPx,
                 double pixelSizeMm) {
  // Centred on the box's middle in Mercator (the view's own projection), so the margins match.
  const MercatorPoint lo = toMercator({box.minLatDeg, box.minLonDeg});
  const MercatorPoint hi = toMercator({box.maxLatDeg, box.maxLonDeg});
  const double midY = 0.5 * (lo.y + hi.y);
  const LatLon centre{std::clamp(radToDeg(2.0 * std::atan(std::exp(midY)) - kPi / 2.0), -84.0, 84.0),
                      0.5 * (box.minLonDeg + box.maxLonDeg)};
  // At a fixed centre the screen extent is inversely proportional to 1:N: measure it at a trial scale.
  constexpr double kTrial = 100000.0;
  const Viewport trial(centre, kTrial, widthPx, heightPx, pixelSizeMm, rotationRad);
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const LatLon& corner : {LatLon{box.minLatDeg, box.minLonDeg}, LatLon{box.minLatDeg, box.maxLonDeg},
                               LatLon{box.maxLatDeg, box.minLonDeg}, LatLon{box.maxLatDeg, box.maxLonDeg}}) {
    const ScreenPoint s = trial.toScreen(corner);
    x0 = std::min(x0, s.x);
    x1 = std::max(x1, s.x);
    y0 = std::min(y0, s.y);
    y1 = std::max(y1, s.y);
  }
  const double roomX = std::max(widthPx - 2.0 * marginPx, 8.0),
               roomY = std::max(heightPx - 2.0 * marginPx, 8.0);
  const double need = std::max((x1 - x0) / roomX, (y1 - y0) / roomY);
  const double scale = need > 0.0 ? kTrial * need : kLargestScaleWithoutChart;
  return {centre, scale, widthPx, heightPx, pixelSizeMm, rotationRad};
}

}  // namespace reckoner::charts
