#include "geo/geodesic.h"

#include <GeographicLib/Geodesic.hpp>
#include <cmath>
#include <limits>

#include "common/angles.h"

namespace reckoner::geo {

RangeBearing rangeBearing(const GeoPoint& from, const GeoPoint& to) {
  const auto valid = [](const GeoPoint& p) {
    return std::isfinite(p.latDeg) && std::isfinite(p.lonDeg) && std::abs(p.latDeg) <= 90.0;
  };
  if (!valid(from) || !valid(to)) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan};
  }
  double s12 = 0.0, azi1 = 0.0, azi2 = 0.0;
  GeographicLib::Geodesic::WGS84().Inverse(from.latDeg, from.lonDeg, to.latDeg, to.lonDeg, s12, azi1, azi2);
  return {s12, wrapTwoPi(degToRad(azi1))};
}

}  // namespace reckoner::geo
