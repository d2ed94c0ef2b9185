#include "charts/route/route_check.h"

#include <GeographicLib/Geodesic.hpp>
#include <algorithm>
#include <cmath>

#include "common/angles.h"
#include "common/units.h"
#include "geo/geodesic.h"

namespace reckoner::charts {
namespace {

constexpr double kMaxPieceM = 500.0;
// A corridor narrower than this is this wide: a zero limit is the track itself, checked as a strip of
// a centimetre so that the polygon stays a polygon.
constexpr double kMinHalfWidthM = 0.01;

MercatorPoint offsetMercator(const geo::GeoPoint& p, double azimuthRad, double distM) {
  LatLon q;
  GeographicLib::Geodesic::WGS84().Direct(p.latDeg, p.lonDeg, radToDeg(azimuthRad), distM, q.latDeg,
                                          q.lonDeg);
  return toMercator(q);
}

LatLon latLonOf(const geo::GeoPoint& p) {
  return {p.latDeg, p.lonDeg};
}

}  // namespace

std::vector<std::vector<MercatorPoint>> legCorridor(const geo::Route& route, std::size_t to) {
  const geo::LegPlan& leg = route.waypoints.at(to).leg;
  const double port = std::max(nmToMetres(leg.portXtlNm), kMinHalfWidthM);
  const double stbd = std::max(nmToMetres(leg.starboardXtlNm), kMinHalfWidthM);
  const std::vector<geo::GeoPoint> pts = geo::legPoints(route, to, kMaxPieceM);
  std::vector<std::vector<MercatorPoint>> pieces;
  pieces.reserve(pts.size() - 1);
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const geo::GeoPoint& a = pts[i - 1];
    const geo::GeoPoint& b = pts[i];
    const double courseA = geo::rangeBearing(a, b).trueBearingRad;
    // the course at the piece's end, from the end looking back
    const double courseB = wrapTwoPi(geo::rangeBearing(b, a).trueBearingRad + kPi);
    pieces.push_back({toMercator(latLonOf(a)), offsetMercator(a, courseA + kPi / 2.0, stbd),
                      offsetMercator(b, courseB + kPi / 2.0, stbd),
                      offsetMercator(b, courseB - kPi / 2.0, port),
                      offsetMercator(a, courseA - kPi / 2.0, port)});
  }
  return pieces;
}

void checkLeg(const geo::Route& route, std::size_t to, const ChartHazards& hazards,
              std::vector<RouteFinding>& out) {
  std::vector<std::uint8_t> found(hazards.hazards().size(), 0);
  const auto add = [&](std::uint32_t h, const LatLon& at) {
    const Hazard& hz = hazards.hazards()[h];
    out.push_back({to, hz.kind, at, hazards.cells()[hz.cell]->info().name, hz.feature->objectClass,
                   hz.feature->lnam, hz.depthM, h});
    found[h] = 1;
  };
  // areas the leg starts in (they may hold the whole corridor, with no edge in it)
  const LatLon start = latLonOf(route.waypoints.at(to - 1).position);
  std::vector<std::uint32_t> holding;
  hazards.containing(toMercator(start), holding);
  for (const std::uint32_t h : holding) add(h, start);
  std::vector<HazardContact> contacts;
  for (const std::vector<MercatorPoint>& piece : legCorridor(route, to)) {
    contacts.clear();
    hazards.touching(piece, contacts, found);
    // in order of distance from the piece's start on the track
    const auto dist2 = [&](const HazardContact& c) {
      return (c.at.x - piece[0].x) * (c.at.x - piece[0].x) + (c.at.y - piece[0].y) * (c.at.y - piece[0].y);
    };
    std::sort(contacts.begin(), contacts.end(),
              [&](const HazardContact& a, const HazardContact& b) { return dist2(a) < dist2(b); });
    for (const HazardContact& c : contacts) add(c.hazard, fromMercator(c.at));
  }
}

std::vector<RouteFinding> checkRoute(const geo::Route& route, const ChartHazards& hazards) {
  std::vector<RouteFinding> out;
  for (std::size_t to = 1; to < route.waypoints.size(); ++to) checkLeg(route, to, hazards, out);
  return out;
}

PickedFeature findingReport(const ChartHazards& hazards, const RouteFinding& finding,
                            const S57Catalogue& catalogue) {
  const Hazard& hz = hazards.hazards().at(finding.hazard);
  return describeFeature(*hazards.cells()[hz.cell], *hz.feature, catalogue);
}

}  // namespace reckoner::charts
