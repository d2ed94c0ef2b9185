#include "geo/route.h"

#include <GeographicLib/Geodesic.hpp>
#include <GeographicLib/GeodesicLine.hpp>
#include <GeographicLib/Rhumb.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include "common/angles.h"
#include "common/units.h"

namespace reckoner::geo {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

const GeographicLib::Geodesic& geodesic() {
  return GeographicLib::Geodesic::WGS84();
}
const GeographicLib::Rhumb& rhumb() {
  static const GeographicLib::Rhumb r(GeographicLib::Constants::WGS84_a(),
                                      GeographicLib::Constants::WGS84_f());
  return r;
}

void checkLeg(const Route& route, std::size_t to) {
  if (to == 0 || to >= route.waypoints.size()) {
    throw std::out_of_range("route leg " + std::to_string(to) + " of " + std::to_string(route.legCount()));
  }
}

/// The leg as a line: a start, an azimuth and a length, with points and azimuths along it.
struct LegLine {
  LegGeometry geometry;
  GeoPoint from;
  double azimuthDeg = 0.0;  // at the start
  double lengthM = 0.0;

  /// The point s metres along and the line's azimuth there, degrees.
  void at(double s, GeoPoint& p, double& aziDeg) const {
    if (geometry == LegGeometry::GreatCircle) {
      geodesic().Direct(from.latDeg, from.lonDeg, azimuthDeg, s, p.latDeg, p.lonDeg, aziDeg);
    } else {
      rhumb().Direct(from.latDeg, from.lonDeg, azimuthDeg, s, p.latDeg, p.lonDeg);
      aziDeg = azimuthDeg;
    }
    p.lonDeg = std::remainder(p.lonDeg, 360.0);
  }
};

LegLine legLine(const Route& route, std::size_t to) {
  checkLeg(route, to);
  const GeoPoint& a = route.waypoints[to - 1].position;
  const GeoPoint& b = route.waypoints[to].position;
  LegLine line{route.waypoints[to].leg.geometry, a};
  if (line.geometry == LegGeometry::GreatCircle) {
    double azi2 = 0.0;
    geodesic().Inverse(a.latDeg, a.lonDeg, b.latDeg, b.lonDeg, line.lengthM, line.azimuthDeg, azi2);
  } else {
    rhumb().Inverse(a.latDeg, a.lonDeg, b.latDeg, b.lonDeg, line.lengthM, line.azimuthDeg);
  }
  return line;
}

bool finitePosition(const GeoPoint& p) {
  return std::isfinite(p.latDeg) && std::isfinite(p.lonDeg) && std::abs(p.latDeg) <= 90.0 &&
         std::abs(p.lonDeg) <= 180.0;
}

void checkNonNegative(std::vector<std::string>& out, const std::string& where, const char* field,
                      const std::optional<double>& v) {
  if (v && !(std::isfinite(*v) && *v >= 0.0)) {
    out.push_back(where + ": " + field + " must be a finite number >= 0, not " + std::to_string(*v));
  }
}

}  // namespace

double Route::turnRadiusNm(std::size_t k) const {
  return k < waypoints.size() && waypoints[k].turnRadiusNm ? *waypoints[k].turnRadiusNm : defaultTurnRadiusNm;
}

std::vector<std::string> Route::problems() const {
  std::vector<std::string> out;
  if (waypoints.size() < 2) {
    out.push_back("route \"" + name + "\": " + std::to_string(waypoints.size()) +
                  " waypoint(s); a route needs at least two");
  }
  checkNonNegative(out, "route \"" + name + "\"", "default turn radius", defaultTurnRadiusNm);
  std::set<int> ids;
  for (std::size_t k = 0; k < waypoints.size(); ++k) {
    const Waypoint& w = waypoints[k];
    const std::string where = "waypoint " + std::to_string(k + 1) + " (id " + std::to_string(w.id) +
                              (w.name.empty() ? "" : ", \"" + w.name + "\"") + ")";
    if (!ids.insert(w.id).second) out.push_back(where + ": id " + std::to_string(w.id) + " is used twice");
    if (!finitePosition(w.position)) {
      out.push_back(where + ": position must be latitude in [-90, 90] and longitude in [-180, 180]");
      continue;
    }
    checkNonNegative(out, where, "turn radius", w.turnRadiusNm);
    if (k == 0) continue;
    checkNonNegative(out, where, "port cross-track limit", w.leg.portXtlNm);
    checkNonNegative(out, where, "starboard cross-track limit", w.leg.starboardXtlNm);
    checkNonNegative(out, where, "planned speed", w.leg.plannedSpeedKn);
    checkNonNegative(out, where, "minimum speed", w.leg.minSpeedKn);
    checkNonNegative(out, where, "safety depth", w.leg.safetyDepthM);
    if (w.leg.safetyContourM && !std::isfinite(*w.leg.safetyContourM)) {
      out.push_back(where + ": safety contour must be finite");
    }
    const GeoPoint& prev = waypoints[k - 1].position;
    if (finitePosition(prev) && prev.latDeg == w.position.latDeg && prev.lonDeg == w.position.lonDeg) {
      out.push_back(where + ": at the same place as the waypoint before it (a leg of length 0)");
    }
  }
  return out;
}

double legLengthM(const Route& route, std::size_t to) {
  return legLine(route, to).lengthM;
}

double legStartCourseRad(const Route& route, std::size_t to) {
  return wrapTwoPi(degToRad(legLine(route, to).azimuthDeg));
}

double legEndCourseRad(const Route& route, std::size_t to) {
  const LegLine line = legLine(route, to);
  GeoPoint p;
  double azi = 0.0;
  line.at(line.lengthM, p, azi);
  return wrapTwoPi(degToRad(azi));
}

GeoPoint legPoint(const Route& route, std::size_t to, double alongM) {
  const LegLine line = legLine(route, to);
  GeoPoint p;
  double azi = 0.0;
  line.at(alongM, p, azi);
  return p;
}

std::vector<GeoPoint> legPoints(const Route& route, std::size_t to, double maxSpacingM) {
  const LegLine line = legLine(route, to);
  if (!(maxSpacingM > 0.0) || !std::isfinite(maxSpacingM)) {
    throw std::invalid_argument("legPoints: spacing must be positive and finite");
  }
  const auto pieces = static_cast<std::size_t>(std::max(1.0, std::ceil(line.lengthM / maxSpacingM)));
  std::vector<GeoPoint> out;
  out.reserve(pieces + 1);
  out.push_back(route.waypoints[to - 1].position);
  for (std::size_t i = 1; i < pieces; ++i) {
    GeoPoint p;
    double azi = 0.0;
    line.at(line.lengthM * static_cast<double>(i) / static_cast<double>(pieces), p, azi);
    out.push_back(p);
  }
  out.push_back(route.waypoints[to].position);
  return out;
}

LegFix legFix(const Route& route, std::size_t to, const GeoPoint& p) {
  const LegLine line = legLine(route, to);
  LegFix fix;
  fix.legLengthM = line.lengthM;
  if (!finitePosition(p)) {
    fix.alongTrackM = fix.crossTrackM = fix.trackCourseRad = fix.distanceToGoM = fix.bearingToGoRad = kNaN;
    fix.foot = {kNaN, kNaN};
    return fix;
  }
  // The foot point: where the bearing to p is square to the line. Each step moves the foot by the
  // along-line part of the distance to p (one step is exact in the plane; a few converge on the
  // ellipsoid for any cross-track distance a leg's corridor has).
  double s = 0.0;
  GeoPoint foot;
  double lineAzi = 0.0, dist = 0.0, azi1 = 0.0, azi2 = 0.0;
  for (int iter = 0; iter < 8; ++iter) {
    line.at(s, foot, lineAzi);
    geodesic().Inverse(foot.latDeg, foot.lonDeg, p.latDeg, p.lonDeg, dist, azi1, azi2);
    const double step = dist * std::cos(degToRad(azi1 - lineAzi));
    s += step;
    if (std::abs(step) < 1e-4) break;
  }
  line.at(s, foot, lineAzi);
  geodesic().Inverse(foot.latDeg, foot.lonDeg, p.latDeg, p.lonDeg, dist, azi1, azi2);
  fix.alongTrackM = s;
  fix.crossTrackM = std::sin(degToRad(azi1 - lineAzi)) >= 0.0 ? dist : -dist;
  fix.trackCourseRad = wrapTwoPi(degToRad(lineAzi));
  fix.foot = foot;
  const GeoPoint& end = route.waypoints[to].position;
  geodesic().Inverse(p.latDeg, p.lonDeg, end.latDeg, end.lonDeg, dist, azi1, azi2);
  fix.distanceToGoM = dist;
  fix.bearingToGoRad = wrapTwoPi(degToRad(azi1));
  return fix;
}

double courseChangeRad(const Route& route, std::size_t k) {
  if (k == 0 || k + 1 >= route.waypoints.size()) return 0.0;
  return wrapPi(legStartCourseRad(route, k + 1) - legEndCourseRad(route, k));
}

double wheelOverDistanceM(const Route& route, std::size_t k) {
  const double change = std::abs(courseChangeRad(route, k));
  if (change == 0.0) return 0.0;
  return nmToMetres(route.turnRadiusNm(k)) * std::tan(std::min(change, degToRad(179.0)) / 2.0);
}

}  // namespace reckoner::geo
