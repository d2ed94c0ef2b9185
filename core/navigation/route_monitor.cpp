#include "navigation/route_monitor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "common/angles.h"
#include "geo/geodesic.h"
#include "geo/route_turns.h"

namespace reckoner::nav {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// A course change smaller than this is no turn (no arc, no wheel-over distance).
constexpr double kMinTurnRad = 1e-9;

bool usable(const geo::GeoPoint& p) {
  return std::isfinite(p.latDeg) && std::isfinite(p.lonDeg) && std::abs(p.latDeg) <= 90.0 &&
         std::abs(p.lonDeg) <= 180.0;
}

void checkSettings(const RouteMonitorSettings& s, std::vector<std::string>& out) {
  if (!(std::isfinite(s.arrivalCircleNm) && s.arrivalCircleNm > 0.0))
    out.push_back("arrival circle radius must be a finite number > 0 NM, not " +
                  std::to_string(s.arrivalCircleNm));
  if (!(std::isfinite(s.approachWarningS) && s.approachWarningS >= 0.0))
    out.push_back("approach warning time must be a finite number >= 0 s, not " +
                  std::to_string(s.approachWarningS));
  if (!(s.offTrackClearFraction > 0.0 && s.offTrackClearFraction <= 1.0))
    out.push_back("off-track clearing fraction must be in (0, 1], not " +
                  std::to_string(s.offTrackClearFraction));
  if (!(std::isfinite(s.minSpeedKn) && s.minSpeedKn > 0.0))
    out.push_back("minimum speed must be a finite number > 0 kn, not " + std::to_string(s.minSpeedKn));
}

/// sd of the position along the starboard normal of a track on course courseRad (true).
double normalSd(const std::optional<PositionCovariance>& c, double courseRad) {
  if (!c) return kNaN;
  const double n = -std::sin(courseRad);  // the normal's north and east components
  const double e = std::cos(courseRad);
  const double var = n * n * c->varNorthM2 + e * e * c->varEastM2 + 2.0 * n * e * c->covNorthEastM2;
  return var >= 0.0 ? std::sqrt(var) : kNaN;  // NaN too for a non-finite covariance
}

std::string waypointId(const geo::Waypoint& w) {
  return w.name.empty() ? std::to_string(w.id) : w.name;
}

double limitM(const geo::LegPlan& leg, TrackSide side) {
  return nmToMetres(side == TrackSide::Port ? leg.portXtlNm : leg.starboardXtlNm);
}

}  // namespace

std::size_t nearestLeg(const geo::Route& route, const geo::GeoPoint& p) {
  if (!usable(p)) return 0;
  std::size_t bestCorridor = 0, bestNear = 0;
  double corridorXtdM = std::numeric_limits<double>::infinity();
  double nearM = std::numeric_limits<double>::infinity();
  for (std::size_t to = 1; to <= route.legCount(); ++to) {
    const geo::LegFix f = geo::legFix(route, to, p);
    const double xtdM = std::abs(f.crossTrackM);
    const bool alongLeg = f.alongTrackM >= 0.0 && f.alongTrackM <= f.legLengthM;
    const TrackSide side = f.crossTrackM < 0.0 ? TrackSide::Port : TrackSide::Starboard;
    if (alongLeg && xtdM <= limitM(route.waypoints[to].leg, side) && xtdM < corridorXtdM) {
      corridorXtdM = xtdM;
      bestCorridor = to;
    }
    double distanceM = xtdM;  // to the segment
    if (f.alongTrackM < 0.0) distanceM = geo::rangeBearing(p, route.waypoints[to - 1].position).rangeM;
    if (f.alongTrackM > f.legLengthM) distanceM = f.distanceToGoM;
    if (distanceM < nearM) {
      nearM = distanceM;
      bestNear = to;
    }
  }
  return bestCorridor != 0 ? bestCorridor : bestNear;
}

RouteMonitor::RouteMonitor(geo::Route route, RouteMonitorSettings settings)
    : route_(std::move(route)), settings_(settings) {
  std::vector<std::string> problems = route_.problems();
  checkSettings(settings_, problems);
  if (!problems.empty()) {
    std::string text = "route monitor: ";
    for (std::size_t i = 0; i < problems.size(); ++i) text += (i ? "; " : "") + problems[i];
    throw std::invalid_argument(text);
  }
  const std::size_t n = route_.waypoints.size();
  legLengthM_.assign(n, 0.0);
  legCourseRad_.assign(n, 0.0);
  for (std::size_t to = 1; to < n; ++to) {
    legLengthM_[to] = geo::legLengthM(route_, to);
    legCourseRad_[to] = geo::legStartCourseRad(route_, to);
  }
  turns_.assign(n, Turn{});
  for (std::size_t k = 1; k + 1 < n; ++k) {
    // A turn that would take more than half of either leg is sailed on the largest radius that fits,
    // so that consecutive turns never overlap and every leg keeps a straight part to monitor.
    const geo::TurnFit fit = geo::turnFit(route_, k);
    if (std::abs(fit.changeRad) < kMinTurnRad) continue;
    turns_[k] = {fit.changeRad, fit.wheelOverM, fit.radiusM};
  }
  approachWarned_.assign(n, false);
}

bool RouteMonitor::manualLegChange(std::size_t to) {
  if (to < 1 || to > route_.legCount()) return false;
  restartPending_ = false;
  changeLeg(to, LegChangeCause::Manual);
  armed_ = false;
  return true;
}

void RouteMonitor::changeLeg(std::size_t to, LegChangeCause cause) {
  const std::size_t from = chosen_ ? to_ : 0;
  chosen_ = true;
  if (from == to) return;
  to_ = to;
  // Waypoints ahead of the new leg may be approached and reached (again, after going back).
  std::fill(approachWarned_.begin() + static_cast<std::ptrdiff_t>(to), approachWarned_.end(), false);
  arrived_ = false;
  RouteEvent e;
  e.kind = RouteEventKind::LegChanged;
  e.to = to;
  e.previousTo = from;
  e.cause = cause;
  report(e);
}

// The automatic rule: the next leg takes over once own ship is on or past the wheel-over line (along-track
// >= length - wheel-over distance; the perpendicular at the last waypoint) or inside the arrival circle.
// After a change by hand it is armed only once own ship has been seen before both.
geo::LegFix RouteMonitor::advanceLegs(const geo::GeoPoint& p) {
  geo::LegFix fix = geo::legFix(route_, to_, p);
  const double circleM = nmToMetres(settings_.arrivalCircleNm);
  for (std::size_t guard = 0; guard < route_.legCount(); ++guard) {
    const bool pastLine = fix.alongTrackM >= legLengthM_[to_] - turns_[to_].wheelOverM;
    const bool inCircle = fix.distanceToGoM <= circleM;
    if (!pastLine && !inCircle) {
      armed_ = true;
      break;
    }
    if (!armed_ || settings_.legChange == LegChangeRule::Manual || to_ + 1 >= route_.waypoints.size()) break;
    changeLeg(to_ + 1, pastLine ? LegChangeCause::WheelOverLine : LegChangeCause::ArrivalCircle);
    fix = geo::legFix(route_, to_, p);
  }
  return fix;
}

// The planned track around the waypoint before this leg: the previous leg up to its wheel-over point, the
// arc of radius R tangent to both legs (a corner where R is 0), this leg from the arc's end. In this leg's
// frame (u along from its start, v to starboard), with the course change D (s its sign) and the wheel-over
// distance w: centre (w, s R), the arc from (-w cos D, w sin D) on the previous leg to (w, 0). Own ship
// before the arc's end and past its start (the wedge between its two radii) is measured from the arc,
// before its start from the previous leg (exactly, by legFix), else from this leg. Plane geometry in the
// turn: w is at most a few km.
RouteMonitor::Place RouteMonitor::placeOnTrack(const geo::LegFix& fix, const geo::GeoPoint& p) const {
  Place place{fix.crossTrackM, fix.trackCourseRad, TrackPart::Leg, to_};
  if (to_ < 2) return place;
  const Turn& turn = turns_[to_ - 1];
  if (turn.changeRad == 0.0) return place;
  const double a = fix.alongTrackM, x = fix.crossTrackM, w = turn.wheelOverM, r = turn.radiusM;
  if (a > w) return place;
  // how far past the arc's start along the previous leg's direction (cos D, -sin D)
  const double pastStart = a * std::cos(turn.changeRad) - x * std::sin(turn.changeRad) + w;
  if (pastStart < 0.0) {
    const geo::LegFix previous = geo::legFix(route_, to_ - 1, p);
    return {previous.crossTrackM, previous.trackCourseRad, TrackPart::PreviousLeg, to_ - 1};
  }
  const double s = turn.changeRad > 0.0 ? 1.0 : -1.0;
  const double du = a - w, dv = x - s * r;
  const double fromCentreM = std::hypot(du, dv);
  if (!(fromCentreM > 0.0)) return place;
  // the arc's direction at the foot: the radius turned a quarter toward the way the turn goes, relative
  // to this leg's direction at the foot on it
  const double tu = -s * dv / fromCentreM, tv = s * du / fromCentreM;
  return {s * (r - fromCentreM), wrapTwoPi(fix.trackCourseRad + std::atan2(tv, tu)), TrackPart::Turn, to_};
}

void RouteMonitor::updateOffTrack(RouteStatus& s, std::size_t limitsOf) {
  s.side = s.crossTrackM < 0.0 ? TrackSide::Port : TrackSide::Starboard;
  s.crossTrackLimitM = limitM(route_.waypoints[limitsOf].leg, s.side);
  const double off = std::abs(s.crossTrackM);
  const bool now =
      offTrack_ ? off > settings_.offTrackClearFraction * s.crossTrackLimitM : off > s.crossTrackLimitM;
  if (now != offTrack_) {
    RouteEvent e;
    e.kind = now ? RouteEventKind::OffTrackEntered : RouteEventKind::OffTrackLeft;
    e.to = to_;
    e.side = s.side;
    report(e);
  }
  offTrack_ = now;
  s.offTrack = now;
}

void RouteMonitor::fillTimes(RouteStatus& s, const OwnShipFix& fix, std::optional<UtcUs> utc) const {
  const bool moving = std::isfinite(fix.sogMps) && fix.sogMps >= knotsToMps(settings_.minSpeedKn);
  const double v = moving ? fix.sogMps : kNaN;
  const double sdV = fix.velocitySdMps && *fix.velocitySdMps >= 0.0 ? *fix.velocitySdMps : kNaN;
  s.timeToWheelOverS = s.distanceToWheelOverM / v;
  double distanceM = 0.0, plannedS = 0.0;
  for (std::size_t k = to_; k < route_.waypoints.size(); ++k) {
    const double legM = k == to_ ? std::max(0.0, s.legLengthM - s.alongTrackM) : legLengthM_[k];
    distanceM += legM;
    const std::optional<double>& plannedKn = route_.waypoints[k].leg.plannedSpeedKn;
    plannedS += plannedKn && *plannedKn >= settings_.minSpeedKn ? legM / knotsToMps(*plannedKn) : kNaN;
    WaypointEta e;
    e.waypoint = k;
    e.distanceM = distanceM;
    e.timeS = distanceM / v;
    e.timeSdS = distanceM * sdV / (v * v);
    e.plannedTimeS = plannedS;
    if (std::isfinite(e.timeS)) {
      e.etaUs = s.timeUs + fromSeconds(e.timeS);
      if (utc) e.etaUtc = *utc + fromSeconds(e.timeS);
    }
    if (std::isfinite(plannedS)) {
      e.plannedEtaUs = s.timeUs + fromSeconds(plannedS);
      if (utc) e.plannedEtaUtc = *utc + fromSeconds(plannedS);
    }
    s.etas.push_back(e);
  }
  s.timeToWaypointS = s.etas.front().timeS;
}

void RouteMonitor::fillLegData(RouteStatus& s) const {
  s.to = to_;
  s.legLengthM = legLengthM_[to_];
  s.legCourseRad = legCourseRad_[to_];
  s.wheelOverDistanceM = turns_[to_].wheelOverM;
  s.arrived = arrived_;
  s.offTrack = offTrack_;
}

RouteStatus RouteMonitor::update(TimeUs t, const OwnShipFix& fix, std::optional<UtcUs> utc) {
  RouteStatus s;
  s.timeUs = t;
  s.sogMps = fix.sogMps;
  s.cogRad = fix.cogRad;
  if (usable(fix.position)) {
    if (restartPending_) {
      restartPending_ = false;
      changeLeg(nearestLeg(route_, fix.position), LegChangeCause::Restart);
      armed_ = true;
    }
    const geo::LegFix legFix = advanceLegs(fix.position);
    fillLegData(s);
    s.valid = true;
    const Place place = placeOnTrack(legFix, fix.position);
    s.trackPart = place.part;
    s.crossTrackM = place.crossTrackM;
    s.trackCourseRad = place.courseRad;
    s.crossTrackSdM = normalSd(fix.positionCovariance, place.courseRad);
    s.alongTrackM = legFix.alongTrackM;
    s.bearingToWaypointRad = legFix.bearingToGoRad;
    s.distanceToWaypointM = legFix.distanceToGoM;
    s.distanceToWheelOverM = s.legLengthM - s.wheelOverDistanceM - s.alongTrackM;
    s.arrivalCircleEntered = legFix.distanceToGoM <= nmToMetres(settings_.arrivalCircleNm);
    s.perpendicularPassed = legFix.alongTrackM > s.legLengthM;
    const bool lastLeg = to_ + 1 == route_.waypoints.size();
    if (lastLeg && !arrived_ && (s.arrivalCircleEntered || s.perpendicularPassed)) {
      arrived_ = s.arrived = true;
      RouteEvent e;
      e.kind = RouteEventKind::ArrivedFinal;
      e.to = e.waypoint = to_;
      report(e);
    }
    updateOffTrack(s, place.limitsOf);
    fillTimes(s, fix, utc);
    if (!approachWarned_[to_] && s.timeToWheelOverS <= settings_.approachWarningS) {
      approachWarned_[to_] = true;
      RouteEvent e;
      e.kind = RouteEventKind::ApproachingWaypoint;
      e.to = e.waypoint = to_;
      report(e);
    }
  } else {
    fillLegData(s);
    s.crossTrackM = s.crossTrackSdM = s.crossTrackLimitM = s.trackCourseRad = s.alongTrackM = kNaN;
    s.bearingToWaypointRad = s.distanceToWaypointM = s.distanceToWheelOverM = kNaN;
    s.timeToWheelOverS = s.timeToWaypointS = kNaN;
  }
  for (RouteEvent& e : pending_) e.timeUs = t;
  s.events = std::move(pending_);
  pending_.clear();
  return s;
}

double headingToSteerRad(const RouteStatus& s, const CrossTrackSteering& law) {
  const double correction = std::atan(-s.crossTrackM / law.lookaheadM);
  return wrapTwoPi(s.trackCourseRad + std::clamp(correction, -law.maxCorrectionRad, law.maxCorrectionRad));
}

io::nmea::XteOut xteOf(const RouteStatus& s, char mode) {
  io::nmea::XteOut o;
  o.valid = s.valid && std::isfinite(s.crossTrackM);
  o.crossTrackNm = metresToNm(std::abs(s.crossTrackM));
  o.steerRight = s.crossTrackM < 0.0;  // own ship port of the track: steer right, toward it
  o.mode = mode;
  return o;
}

io::nmea::RmbOut rmbOf(const RouteStatus& s, const geo::Route& route, char mode) {
  const io::nmea::XteOut x = xteOf(s, mode);
  io::nmea::RmbOut o;
  o.valid = x.valid;
  o.crossTrackNm = x.crossTrackNm;
  o.steerRight = x.steerRight;
  o.originId = waypointId(route.waypoints.at(s.to - 1));
  const geo::Waypoint& dest = route.waypoints.at(s.to);
  o.destinationId = waypointId(dest);
  o.destLatDeg = dest.position.latDeg;
  o.destLonDeg = dest.position.lonDeg;
  o.rangeToDestNm = metresToNm(s.distanceToWaypointM);
  o.bearingToDestTrueDeg = radToDeg(s.bearingToWaypointRad);
  o.closingVelocityKn = mpsToKnots(s.sogMps * std::cos(s.cogRad - s.bearingToWaypointRad));
  o.arrived = s.arrivalCircleEntered || s.perpendicularPassed;
  o.mode = mode;
  return o;
}

io::nmea::ApbOut apbOf(const RouteStatus& s, const geo::Route& route, char mode,
                       const CrossTrackSteering& law) {
  const io::nmea::XteOut x = xteOf(s, mode);
  io::nmea::ApbOut o;
  o.valid = x.valid;
  o.crossTrackNm = x.crossTrackNm;
  o.steerRight = x.steerRight;
  o.arrivalCircleEntered = s.arrivalCircleEntered;
  o.perpendicularPassed = s.perpendicularPassed;
  o.bearingOriginToDestDeg = radToDeg(s.legCourseRad);
  o.destinationId = waypointId(route.waypoints.at(s.to));
  o.bearingPresentToDestDeg = radToDeg(s.bearingToWaypointRad);
  o.headingToSteerDeg = radToDeg(headingToSteerRad(s, law));
  o.mode = mode;
  return o;
}

}  // namespace reckoner::nav
