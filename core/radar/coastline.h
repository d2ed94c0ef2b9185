#pragma once
// Radar-conspicuous chart contours for seed 004's matching (docs/radar_matching.md): line segments in
// the grid frame (land area edges, coastline, shoreline constructions), each with the reliability of
// its object (a concrete quay echoes where the chart says; a flat sandy shore moves with the water
// level). A uniform grid indexes them for nearest-point queries and for casting radar beams.
#include <cstdint>
#include <optional>
#include <vector>

#include "estimation/gaussian.h"
#include "geo/grid_index.h"

namespace reckoner::radar {

struct CoastSegment {
  est::Vec<2> a, b;  ///< grid metres
  double sdM = 5.0;  ///< how far the echo may lie from this contour (chart and object), m
};

class Coastline {
 public:
  /// Segments shorter than 1 mm or not finite are dropped. cellM: the index's cell size.
  explicit Coastline(const std::vector<CoastSegment>& segments, double cellM = 100.0);

  struct Nearest {
    est::Vec<2> point;   ///< on the contour
    est::Vec<2> normal;  ///< unit, perpendicular to the segment
    double distanceM = 0.0;
    std::size_t segment = 0;
  };
  /// The nearest contour point within maxDistanceM of p, if any.
  [[nodiscard]] std::optional<Nearest> nearest(const est::Vec<2>& p, double maxDistanceM) const;
  /// Range of the first contour crossed by a ray from `origin` along grid azimuth `azimuthRad`
  /// (clockwise from grid north) within maxRangeM.
  [[nodiscard]] std::optional<double> firstHit(const est::Vec<2>& origin, double azimuthRad,
                                               double maxRangeM) const;

  [[nodiscard]] const std::vector<CoastSegment>& segments() const { return segments_; }
  [[nodiscard]] bool empty() const { return segments_.empty(); }

 private:
  std::vector<CoastSegment> segments_;
  double cellM_;
  geo::GridIndex index_;  ///< the segments by bounding box
};

}  // namespace reckoner::radar
