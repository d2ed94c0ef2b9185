#include "charts/radar/radar_contours.h"

#include <cmath>

namespace reckoner::charts {

radar::Coastline radarContours(const std::vector<CellPtr>& cells, const geo::LocalFrame& frame,
                               const geo::GridPoint& centre, double radiusM,
                               const RadarContourParams& params) {
  std::vector<radar::CoastSegment> segments;
  const est::Vec<2> c(centre.xM, centre.yM);
  const auto near = [&](const est::Vec<2>& p) { return (p - c).norm() <= radiusM; };
  for (const auto& cell : cells) {
    if (!cell) continue;
    for (const ChartFeature& f : cell->features()) {
      const bool construction = f.objectClass == "SLCONS";
      if (!construction && f.objectClass != "LNDARE" && f.objectClass != "COALNE") continue;
      if (f.geometry.primitive == Primitive::Point || f.geometry.primitive == Primitive::None) continue;
      const double sd = construction ? params.constructionSdM : params.naturalSdM;
      const bool closed = f.geometry.primitive == Primitive::Area;
      for (const auto& part : f.geometry.parts) {
        if (part.size() < 2) continue;
        std::vector<est::Vec<2>> pts;
        pts.reserve(part.size());
        for (const LatLon& ll : part) {
          const geo::GridPoint g = frame.toLocal({ll.latDeg, ll.lonDeg});
          pts.emplace_back(g.xM, g.yM);
        }
        const std::size_t n = closed ? pts.size() : pts.size() - 1;
        for (std::size_t i = 0; i < n; ++i) {
          const est::Vec<2>& a = pts[i];
          const est::Vec<2>& b = pts[(i + 1) % pts.size()];
          if (!a.allFinite() || !b.allFinite() || (!near(a) && !near(b))) continue;
          segments.push_back({a, b, sd});
        }
      }
    }
  }
  return radar::Coastline(segments);
}

radar::LandMask landMask(const std::vector<CellPtr>& cells, const geo::LocalFrame& frame,
                         const geo::GridPoint& centre, double radiusM) {
  std::vector<std::vector<est::Vec<2>>> rings;
  const est::Vec<2> c(centre.xM, centre.yM);
  for (const auto& cell : cells) {
    if (!cell) continue;
    for (const ChartFeature& f : cell->features()) {
      if (f.objectClass != "LNDARE" || f.geometry.primitive != Primitive::Area) continue;
      for (const auto& part : f.geometry.parts) {
        std::vector<est::Vec<2>> ring;
        est::Vec<2> lo = est::Vec<2>::Constant(1e300), hi = est::Vec<2>::Constant(-1e300);
        for (const LatLon& ll : part) {
          const geo::GridPoint g = frame.toLocal({ll.latDeg, ll.lonDeg});
          ring.emplace_back(g.xM, g.yM);
          lo = lo.cwiseMin(ring.back());
          hi = hi.cwiseMax(ring.back());
        }
        // Kept when its bounding box meets the circle's (a ring around the centre has no vertex near it).
        if ((lo.array() <= (c.array() + radiusM)).all() && (hi.array() >= (c.array() - radiusM)).all())
          rings.push_back(std::move(ring));
      }
    }
  }
  return radar::LandMask(rings);
}

}  // namespace reckoner::charts
