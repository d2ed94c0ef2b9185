#pragma once
// Range and bearing between two geodetic points on the WGS-84 ellipsoid along the geodesic
// (GeographicLib's Karney algorithm): exact at any distance, unlike the local grid, whose transverse
// Mercator projection is only valid within some 35 degrees of its central meridian.
#include "geo/local_frame.h"

namespace reckoner::geo {

struct RangeBearing {
  double rangeM = 0.0;          ///< geodesic distance, metres
  double trueBearingRad = 0.0;  ///< initial azimuth at `from`, clockwise from true north, [0, 2 pi)
};

/// NaN fields for non-finite input or a latitude outside [-90, 90].
RangeBearing rangeBearing(const GeoPoint& from, const GeoPoint& to);

}  // namespace reckoner::geo
