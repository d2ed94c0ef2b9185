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

/// A zigzag in Commencement Bay (Tacoma, US5WA22M) of legs of 0.5 to 0.8 NM turning about 92 degrees to
/// port at WP2 and WP4, on a default radius of 2 NM that no turn has room for; WP3 a corner (radius 0).
inline geo::Route zigzagInCommencementBay(const std::string& name = "zigzag") {
  geo::Route r =
      routeOf({{47.30, -122.47}, {47.29, -122.46}, {47.295, -122.45}, {47.285, -122.44}, {47.29, -122.43}},
              0.05, name);
  r.defaultTurnRadiusNm = 2.0;
  r.waypoints[2].turnRadiusNm = 0.0;
  return r;
}

}  // namespace reckoner::test
