#pragma once
// A route as an ECDIS plans it (MSC.232(82) 11.3, IEC 61174's RTZ model): named waypoints, each with
// the leg that arrives at it (rhumb line or great circle, cross-track limits to port and starboard,
// planned speed, the leg's own safety contour and depth where given), turn radii, and the schedules
// an RTZ file may carry. Navigator units, as RTZ has them: nautical miles, knots, metres of depth; so a
// route read from a file and written again is the same numbers.
//
// The geometry is exact on the WGS-84 ellipsoid (GeographicLib's geodesics and rhumb lines): leg
// lengths and courses, points along a leg, and a position's place on a leg (along-track distance,
// signed cross-track distance, course and distance to go), the wheel-over distance before a waypoint.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/time.h"
#include "geo/local_frame.h"

namespace reckoner::geo {

/// How a leg runs between its waypoints (RTZ geometryType Loxodrome / Orthodrome).
enum class LegGeometry : std::uint8_t { RhumbLine, GreatCircle };

/// The leg that arrives at a waypoint, from the waypoint before it. The first waypoint's leg is unused.
struct LegPlan {
  LegGeometry geometry = LegGeometry::RhumbLine;
  double portXtlNm = 0.1;                ///< cross-track limit to port, NM (RTZ portsideXTD)
  double starboardXtlNm = 0.1;           ///< cross-track limit to starboard, NM (RTZ starboardXTD)
  std::optional<double> plannedSpeedKn;  ///< RTZ speedMax (or the schedule's speed), knots
  std::optional<double> minSpeedKn;      ///< RTZ speedMin
  std::optional<double> safetyContourM;  ///< the leg's own safety contour, metres (RTZ safetyContour)
  std::optional<double> safetyDepthM;    ///< the leg's own safety depth, metres (RTZ safetyDepth)
  std::string note;                      ///< RTZ legInfo
  bool operator==(const LegPlan&) const = default;
};

struct Waypoint {
  int id = 0;  ///< unique in the route (RTZ waypoint id)
  std::string name;
  GeoPoint position;
  std::optional<double> turnRadiusNm;  ///< RTZ radius; none: the route's default
  LegPlan leg;                         ///< the leg from the waypoint before this one
  bool operator==(const Waypoint& o) const {
    return id == o.id && name == o.name && position.latDeg == o.position.latDeg &&
           position.lonDeg == o.position.lonDeg && turnRadiusNm == o.turnRadiusNm && leg == o.leg;
  }
};

/// One row of an RTZ schedule: times at a waypoint (UTC) and the speed to it.
struct ScheduleEntry {
  int waypointId = 0;
  std::optional<UtcUs> etd, eta;
  std::optional<double> speedKn;
  bool operator==(const ScheduleEntry&) const = default;
};

struct Schedule {
  int id = 0;
  std::string name;
  std::vector<ScheduleEntry> manual, calculated;
  bool operator==(const Schedule&) const = default;
};

struct Route {
  std::string name;    ///< RTZ routeName
  std::string author;  ///< RTZ routeAuthor
  std::string status;  ///< RTZ routeStatus
  double defaultTurnRadiusNm = 0.5;
  std::vector<Waypoint> waypoints;
  std::vector<Schedule> schedules;
  bool operator==(const Route&) const = default;

  [[nodiscard]] std::size_t legCount() const { return waypoints.size() < 2 ? 0 : waypoints.size() - 1; }
  /// The turn radius at waypoint k, NM: its own or the route's default.
  [[nodiscard]] double turnRadiusNm(std::size_t k) const;
  /// What makes the route unusable, one line each naming the waypoint and field (empty: none): fewer
  /// than two waypoints, a position not finite or out of range, duplicate ids, two consecutive
  /// waypoints at the same place, negative or non-finite limits, radii or speeds.
  [[nodiscard]] std::vector<std::string> problems() const;
};

/// Where a position lies against one leg (the leg arriving at waypoint `to`).
struct LegFix {
  double alongTrackM = 0.0;   ///< from the leg's start along the leg to the foot point (< 0 before it)
  double crossTrackM = 0.0;   ///< from the leg, signed: positive to starboard of the leg's direction
  double legLengthM = 0.0;    ///< the whole leg
  double trackCourseRad = 0;  ///< the leg's true direction at the foot point, [0, 2 pi)
  double distanceToGoM = 0;   ///< geodesic distance from the position to waypoint `to`
  double bearingToGoRad = 0;  ///< true bearing from the position to waypoint `to`, [0, 2 pi)
  GeoPoint foot;              ///< the point of the leg (extended) nearest the position
};

/// Length of the leg arriving at waypoint `to` (1 <= to < waypoints.size()), metres.
double legLengthM(const Route& route, std::size_t to);
/// The leg's true course at its start (constant along a rhumb line), radians [0, 2 pi).
double legStartCourseRad(const Route& route, std::size_t to);
/// The leg's true course as it arrives at `to`, radians [0, 2 pi).
double legEndCourseRad(const Route& route, std::size_t to);
/// The point `alongM` metres along the leg from its start (any value: the line extended).
GeoPoint legPoint(const Route& route, std::size_t to, double alongM);
/// The leg's start, its end and points between no more than maxSpacingM apart along it.
std::vector<GeoPoint> legPoints(const Route& route, std::size_t to, double maxSpacingM);
/// The position against the leg arriving at `to`. NaN fields for a non-finite position.
LegFix legFix(const Route& route, std::size_t to, const GeoPoint& p);
/// The course change at waypoint k (0 < k < last), radians in (-pi, pi], positive to starboard.
double courseChangeRad(const Route& route, std::size_t k);
/// The distance before waypoint k at which a turn on its radius begins so that the arc is tangent to
/// both legs: R tan(|change| / 2), metres (0 at the first and last waypoints).
double wheelOverDistanceM(const Route& route, std::size_t k);

}  // namespace reckoner::geo
