#pragma once
// Routes for tests: waypoints WP1, WP2, ... at the points given, every leg a rhumb line with the same
// cross-track limit to port and starboard.
#include <string>
#include <vector>

#include "geo/route.h"

namespace reckoner::test {

inline geo::Route routeOf(const std::vector<geo::GeoPoint>& points, double xtlNm,
                          const std::string& name = "test") {
  geo::Route r;
  r.name = name;
  for (std::size_t i = 0; i < points.size(); ++i) {
    geo::Waypoint w;
    w.id = static_cast<int>(i + 1);
    w.name = "WP" + std::to_string(i + 1);
    w.position = points[i];
    w.leg.portXtlNm = w.leg.starboardXtlNm = xtlNm;
    r.waypoints.push_back(w);
  }
  return r;
}

}  // namespace reckoner::test
