#pragma once
// Route monitoring (IMO MSC.232(82) 11.4; docs/routes.md, "Route monitoring"): own ship against the
// route it follows. Which leg is active and when the next one takes over (at the wheel-over line or in
// the arrival circle, or by hand), the cross-track distance from the planned track (the legs and the
// turn arcs between them) with its standard deviation, the leg's cross-track limit and an off-track
// state with hysteresis, course, bearing, distance and time to the waypoint and to the wheel-over
// point, the ETA at every waypoint still ahead, and the events of each update (leg changed, approaching
// a waypoint, off track, arrived). Plus the values of the autopilot sentences XTE, RMB and APB.
//
// Pure and per-step: plain values in, plain values out. Construction checks the route and the settings
// (std::invalid_argument); update() never throws: a fix it cannot use gives a status marked not valid.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "common/angles.h"
#include "common/time.h"
#include "common/units.h"
#include "geo/route.h"
#include "io/nmea_out.h"

namespace reckoner::nav {

enum class LegChangeRule : std::uint8_t {
  Automatic,  ///< the next leg takes over at the wheel-over line or on entering the arrival circle
  Manual      ///< only manualLegChange() and restartFromNearestLeg() change the leg
};

struct RouteMonitorSettings {
  double arrivalCircleNm = 0.1;    ///< radius of the arrival circle around each waypoint, NM, > 0
  double approachWarningS = 60.0;  ///< 'approaching waypoint' this long before the wheel-over point, s, >= 0
  LegChangeRule legChange = LegChangeRule::Automatic;
  double offTrackClearFraction = 0.9;  ///< off track clears below this fraction of the limit, (0, 1]
  double minSpeedKn = 0.1;             ///< below this SOG, times to go and ETAs are NaN / absent, kn, > 0
};

/// Own ship as the route monitor reads it (the DRKF's estimate, true directions and metres).
struct PositionCovariance {
  double varNorthM2 = 0, varEastM2 = 0, covNorthEastM2 = 0;
};
struct OwnShipFix {
  geo::GeoPoint position;
  double sogMps = 0.0;                                   ///< speed over ground, m/s, >= 0
  double cogRad = 0.0;                                   ///< course over ground, true, radians
  std::optional<PositionCovariance> positionCovariance;  ///< north/east, m^2: gives the XTD's sd
  std::optional<double> velocitySdMps;                   ///< sd of the SOG, m/s: gives the ETAs' sd
};

enum class TrackSide : std::uint8_t { Port, Starboard };

/// The part of the planned track around the waypoint before the active leg that own ship is measured
/// from: the active leg, the turn arc joining the two legs, or the previous leg up to the arc's start
/// (own ship has not reached the turn yet, the leg having changed in the arrival circle or by hand).
enum class TrackPart : std::uint8_t { Leg, Turn, PreviousLeg };

enum class RouteEventKind : std::uint8_t {
  LegChanged,           ///< previousTo -> to (cause)
  ApproachingWaypoint,  ///< own ship is within the warning time of waypoint `waypoint`'s wheel-over point
  OffTrackEntered,      ///< |XTD| passed the limit on `side` (of the leg measured from)
  OffTrackLeft,         ///< |XTD| fell below the clearing fraction of the limit
  ArrivedFinal          ///< arrival circle of the last waypoint entered, or its perpendicular passed
};
enum class LegChangeCause : std::uint8_t { WheelOverLine, ArrivalCircle, Manual, Restart };

struct RouteEvent {
  RouteEventKind kind = RouteEventKind::LegChanged;
  TimeUs timeUs = 0;           ///< the update that reports it
  std::size_t to = 0;          ///< the active leg (its waypoint `to`) after the event
  std::size_t previousTo = 0;  ///< LegChanged: the leg before (0: none, the first choice of a leg)
  std::size_t waypoint = 0;    ///< ApproachingWaypoint and ArrivedFinal: the waypoint's index
  LegChangeCause cause = LegChangeCause::WheelOverLine;  ///< LegChanged only
  TrackSide side = TrackSide::Starboard;                 ///< OffTrackEntered / OffTrackLeft
};

/// Time and ETA at one waypoint still ahead. Distances along the legs (waypoint to waypoint, not along
/// the turn arcs). NaN / absent where the speed is below the settings' minimum or unknown.
struct WaypointEta {
  std::size_t waypoint = 0;
  double distanceM = 0.0;       ///< rest of the active leg (length - along-track, >= 0) + the legs after it
  double timeS = 0.0;           ///< distanceM / SOG: 'ETA from the DRKF's speed', SOG on every leg
  double timeSdS = 0.0;         ///< distanceM * sd(SOG) / SOG^2 (first order); NaN without velocitySdMps
  std::optional<TimeUs> etaUs;  ///< t + timeS, stream time
  std::optional<UtcUs> etaUtc;  ///< utc + timeS, when update() was given UTC
  double plannedTimeS = 0.0;    ///< at the legs' planned speeds; NaN from the first leg without one
  std::optional<TimeUs> plannedEtaUs;
  std::optional<UtcUs> plannedEtaUtc;
};

struct RouteStatus {
  bool valid = false;  ///< the fix's position was usable; else only to, the leg's data and events
  TimeUs timeUs = 0;
  std::size_t to = 1;                    ///< the active leg: from waypoints[to - 1] to waypoints[to]
  TrackPart trackPart = TrackPart::Leg;  ///< the part of the planned track measured from
  double crossTrackM = 0.0;    ///< from the planned track, signed: + own ship starboard of it, metres
  double crossTrackSdM = 0.0;  ///< sd of crossTrackM (covariance on the track's normal); NaN without one
  TrackSide side = TrackSide::Starboard;  ///< the side own ship is on (starboard when exactly on track)
  double crossTrackLimitM = 0.0;  ///< the limit on that side of the leg measured from (the previous leg's
                                  ///< while trackPart is PreviousLeg), metres
  bool offTrack = false;
  /// The planned track's course at the foot point (the arc's in a turn): the course to steer along it.
  double trackCourseRad = 0.0;
  double legCourseRad = 0.0;  ///< the leg's course at its start (origin -> destination), [0, 2 pi)
  double alongTrackM = 0.0;   ///< from the leg's start to the foot on the (straight) leg
  double legLengthM = 0.0;
  double bearingToWaypointRad = 0.0;  ///< true, from own ship to waypoints[to], [0, 2 pi)
  double distanceToWaypointM = 0.0;   ///< geodesic, own ship to waypoints[to]
  double wheelOverDistanceM = 0.0;    ///< before waypoints[to] (0 at the last waypoint)
  double distanceToWheelOverM = 0.0;  ///< along the leg to the wheel-over line; < 0 once passed
  double timeToWheelOverS = 0.0;      ///< distanceToWheelOverM / SOG; NaN below the minimum speed
  double timeToWaypointS = 0.0;       ///< etas.front().timeS
  bool arrivalCircleEntered = false;  ///< distanceToWaypointM <= the arrival circle's radius
  bool perpendicularPassed = false;   ///< alongTrackM > legLengthM
  bool arrived = false;               ///< the last waypoint reached (ArrivedFinal reported)
  double sogMps = 0.0, cogRad = 0.0;  ///< as given
  std::vector<WaypointEta> etas;      ///< waypoints to .. last, in order
  std::vector<RouteEvent> events;     ///< since the previous update, in the order they happened
};

/// The leg whose corridor (0 <= along-track <= length, |XTD| within the side's limit) holds p, the one
/// with the smallest |XTD| if several do (the earlier on a tie); else the nearest leg (distance to the
/// segment). 0 for a position that is not finite.
std::size_t nearestLeg(const geo::Route& route, const geo::GeoPoint& p);

class RouteMonitor {
 public:
  /// Throws std::invalid_argument listing route.problems(), or naming a setting out of range.
  explicit RouteMonitor(geo::Route route, RouteMonitorSettings settings = {});

  /// Own ship at stream time t (UTC utc when known). The first usable fix, and the first after
  /// restartFromNearestLeg(), chooses the leg (nearestLeg); the rule then moves it on.
  RouteStatus update(TimeUs t, const OwnShipFix& fix, std::optional<UtcUs> utc = std::nullopt);

  /// Makes leg `to` (1 <= to <= legCount) active; reported at the next update. Automatic changes from it
  /// wait until own ship has been seen before its wheel-over line and outside its arrival circle (so a
  /// leg chosen by hand is kept). False (nothing changes) for a leg the route does not have.
  bool manualLegChange(std::size_t to);
  /// The next usable fix chooses the leg again (nearestLeg).
  void restartFromNearestLeg() { restartPending_ = true; }

  [[nodiscard]] const geo::Route& route() const { return route_; }
  [[nodiscard]] const RouteMonitorSettings& settings() const { return settings_; }
  [[nodiscard]] std::size_t activeLeg() const { return to_; }
  /// The wheel-over distance at waypoint k used here: R tan(|change| / 2), but no more than half of
  /// either leg at k (a turn that does not fit is sailed on the largest radius that does), metres.
  [[nodiscard]] double wheelOverDistanceM(std::size_t k) const { return turns_.at(k).wheelOverM; }

 private:
  struct Turn {
    double changeRad = 0.0, wheelOverM = 0.0, radiusM = 0.0;
  };
  /// Own ship against the planned track: the active leg, the turn arc before it or the previous leg.
  struct Place {
    double crossTrackM = 0.0, courseRad = 0.0;
    TrackPart part = TrackPart::Leg;
    std::size_t limitsOf = 1;  ///< the leg whose cross-track limits apply
  };
  void report(const RouteEvent& e) { pending_.push_back(e); }  // stamped with the time of the next update
  void changeLeg(std::size_t to, LegChangeCause cause);
  geo::LegFix advanceLegs(const geo::GeoPoint& p);
  [[nodiscard]] Place placeOnTrack(const geo::LegFix& fix, const geo::GeoPoint& p) const;
  void updateOffTrack(RouteStatus& s, std::size_t limitsOf);
  void fillTimes(RouteStatus& s, const OwnShipFix& fix, std::optional<UtcUs> utc) const;
  void fillLegData(RouteStatus& s) const;

  geo::Route route_;
  RouteMonitorSettings settings_;
  std::vector<double> legLengthM_, legCourseRad_;  ///< by `to` (index 0 unused)
  std::vector<Turn> turns_;                        ///< by waypoint
  std::size_t to_ = 1;
  bool chosen_ = false;  ///< a leg has been chosen (by the first fix, by hand or on restart)
  bool restartPending_ = true;
  bool armed_ = true;  ///< automatic leg changes allowed
  bool offTrack_ = false;
  bool arrived_ = false;
  std::vector<bool> approachWarned_;  ///< by waypoint
  std::vector<RouteEvent> pending_;
};

/// The cross-track steering law of APB's heading to steer: the track's course corrected toward the
/// track by atan(-XTD / lookahead), at most maxCorrectionRad either way.
struct CrossTrackSteering {
  double lookaheadM = nmToMetres(0.25);  ///< 0.25 NM, or 2 ship lengths (forShipLength)
  double maxCorrectionRad = 0.25 * kPi;  ///< 45 degrees
  static CrossTrackSteering forShipLength(double lengthM) {
    CrossTrackSteering s;
    s.lookaheadM = 2.0 * lengthM;
    return s;
  }
};
/// Heading to steer, true, [0, 2 pi): trackCourseRad + clamp(atan(-crossTrackM / lookaheadM)).
double headingToSteerRad(const RouteStatus& s, const CrossTrackSteering& law = {});

/// The sentences' values (io::nmea::xte, rmb, apb): cross-track magnitude in NM, steer right when own ship
/// is port of the track; valid = s.valid. mode: A autonomous, D differential, E dead reckoning. A waypoint's
/// id in RMB and APB is its name, or its number when it has no name.
io::nmea::XteOut xteOf(const RouteStatus& s, char mode = 'A');
io::nmea::RmbOut rmbOf(const RouteStatus& s, const geo::Route& route, char mode = 'A');
io::nmea::ApbOut apbOf(const RouteStatus& s, const geo::Route& route, char mode = 'A',
                       const CrossTrackSteering& law = {});

}  // namespace reckoner::nav
