#include "geo/local_frame.h"

#include <GeographicLib/TransverseMercator.hpp>
#include <GeographicLib/UTMUPS.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace reckoner::geo {
namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Beyond this longitude difference from the central meridian the Krueger series loses accuracy
// (GeographicLib documents 5 nm within 3900 km of the central meridian).
constexpr double kMaxLonOffsetDeg = 35.0;
const GeographicLib::TransverseMercator& utm() {
  return GeographicLib::TransverseMercator::UTM();
}
}  // namespace

LocalFrame::LocalFrame(double originLatDeg, double originLonDeg) : origin_{originLatDeg, originLonDeg} {
  if (!std::isfinite(originLatDeg) || originLatDeg < -80.0 || originLatDeg > 84.0) {
    throw std::invalid_argument("origin latitude " + std::to_string(originLatDeg) +
                                " deg is outside the UTM band [-80, 84]");
  }
  if (!std::isfinite(originLonDeg) || originLonDeg < -180.0 || originLonDeg > 180.0) {
    throw std::invalid_argument("origin longitude " + std::to_string(originLonDeg) +
                                " deg is outside [-180, 180]");
  }
  zone_ = GeographicLib::UTMUPS::StandardZone(originLatDeg, originLonDeg);
  lon0Deg_ = 6.0 * zone_ - 183.0;  // central meridian of UTM zone 1..60
  double gamma = 0.0;
  double k = 0.0;
  utm().Forward(lon0Deg_, originLatDeg, originLonDeg, x0M_, y0M_, gamma, k);
}

GridPoint LocalFrame::toLocal(const GeoPoint& p) const {
  if (!std::isfinite(p.latDeg) || !std::isfinite(p.lonDeg) || std::abs(p.latDeg) > 90.0) return {kNaN, kNaN};
  const double dLon = std::remainder(p.lonDeg - lon0Deg_, 360.0);
  if (std::abs(dLon) > kMaxLonOffsetDeg) return {kNaN, kNaN};
  double x = 0.0, y = 0.0, gamma = 0.0, k = 0.0;
  utm().Forward(lon0Deg_, p.latDeg, p.lonDeg, x, y, gamma, k);
  return {x - x0M_, y - y0M_};
}

GeoPoint LocalFrame::toGeodetic(const GridPoint& p) const {
  if (!std::isfinite(p.xM) || !std::isfinite(p.yM)) return {kNaN, kNaN};
  double lat = 0.0, lon = 0.0, gamma = 0.0, k = 0.0;
  utm().Reverse(lon0Deg_, p.xM + x0M_, p.yM + y0M_, lat, lon, gamma, k);
  return {lat, lon};
}

GridInfo LocalFrame::gridInfo(const GridPoint& p) const {
  if (!std::isfinite(p.xM) || !std::isfinite(p.yM)) return {kNaN, kNaN};
  double lat = 0.0, lon = 0.0, gammaDeg = 0.0, k = 0.0;
  utm().Reverse(lon0Deg_, p.xM + x0M_, p.yM + y0M_, lat, lon, gammaDeg, k);
  // GeographicLib's gamma is the bearing of grid north clockwise from true north, in degrees.
  return {gammaDeg * (std::numbers::pi / 180.0), k};
}

}  // namespace reckoner::geo
