// nav::RouteMonitor (route monitoring, MSC.232(82) 11.4): a ship sailed along a three-leg route, its
// positions set by GeographicLib's own direct problems at known along-track distances and cross-track
// offsets (not by the route's geometry code). Cross-track distance, the leg change at the wheel-over line
// and in the arrival circle, the turn arc, arrival, off track with hysteresis, the approach warning, the
// ETAs, the cross-track sd, the autopilot sentences' values, manual leg change, restart, bad input.
#include <QTest>

#include <GeographicLib/Geodesic.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "common/angles.h"
#include "common/units.h"
#include "navigation/route_monitor.h"
#include "support/compare_near.h"

using namespace reckoner;
using namespace reckoner::nav;

namespace {

const GeographicLib::Geodesic& wgs84() {
  return GeographicLib::Geodesic::WGS84();
}

geo::GeoPoint direct(const geo::GeoPoint& p, double azimuthDeg, double distM, double* aziAtEndDeg = nullptr) {
  geo::GeoPoint q;
  double azi2 = 0.0;
  wgs84().Direct(p.latDeg, p.lonDeg, azimuthDeg, distM, q.latDeg, q.lonDeg, azi2);
  if (aziAtEndDeg) *aziAtEndDeg = azi2;
  return q;
}

struct Inverse {
  double distM = 0, azi1Deg = 0, azi2Deg = 0;
};
Inverse inverse(const geo::GeoPoint& a, const geo::GeoPoint& b) {
  Inverse r;
  wgs84().Inverse(a.latDeg, a.lonDeg, b.latDeg, b.lonDeg, r.distM, r.azi1Deg, r.azi2Deg);
  return r;
}

/// A -> B 6 NM on 045, -> C 6 NM on 100 (55 deg to starboard), -> D 5 NM on 030 (70 deg to port); great
/// circles, turn radius 0.5 NM. Leg 1: limits 0.2 NM port, 0.1 NM starboard, 8 kn; leg 2: 12 kn; leg 3
/// no planned speed. D has no name (its id names it in RMB / APB).
geo::Route threeLegs() {
  geo::Route r;
  r.name = "three legs";
  const geo::GeoPoint a{50.0, -5.0};
  const geo::GeoPoint b = direct(a, 45.0, nmToMetres(6.0));
  const geo::GeoPoint c = direct(b, 100.0, nmToMetres(6.0));
  const geo::GeoPoint d = direct(c, 30.0, nmToMetres(5.0));
  r.waypoints = {{1, "A", a, {}, {}}, {2, "B", b, {}, {}}, {3, "C", c, {}, {}}, {40, "", d, {}, {}}};
  for (geo::Waypoint& w : r.waypoints) w.leg.geometry = geo::LegGeometry::GreatCircle;
  r.waypoints[1].leg.portXtlNm = 0.2;
  r.waypoints[1].leg.plannedSpeedKn = 8.0;
  r.waypoints[2].leg.plannedSpeedKn = 12.0;
  return r;
}

/// The point alongM along the leg arriving at `to` and offsetM square to it (+ starboard), and the
/// leg's azimuth at the foot (radians).
struct OnLeg {
  geo::GeoPoint p;
  double courseRad = 0;
};
OnLeg onLeg(const geo::Route& r, std::size_t to, double alongM, double offsetM) {
  const geo::GeoPoint& from = r.waypoints[to - 1].position;
  const Inverse leg = inverse(from, r.waypoints[to].position);
  double aziDeg = 0.0;
  const geo::GeoPoint foot = direct(from, leg.azi1Deg, alongM, &aziDeg);
  return {direct(foot, aziDeg + 90.0, offsetM), wrapTwoPi(degToRad(aziDeg))};
}

double legLength(const geo::Route& r, std::size_t to) {
  return inverse(r.waypoints[to - 1].position, r.waypoints[to].position).distM;
}

/// The course change at waypoint k and its wheel-over distance R tan(|change| / 2), from GeographicLib.
double courseChange(const geo::Route& r, std::size_t k) {
  const double in = inverse(r.waypoints[k - 1].position, r.waypoints[k].position).azi2Deg;
  const double out = inverse(r.waypoints[k].position, r.waypoints[k + 1].position).azi1Deg;
  return angleDiff(degToRad(out), degToRad(in));
}
double wheelOver(const geo::Route& r, std::size_t k) {
  return nmToMetres(r.waypoints[k].turnRadiusNm.value_or(r.defaultTurnRadiusNm)) *
         std::tan(std::abs(courseChange(r, k)) / 2.0);
}

OwnShipFix fixAt(const geo::GeoPoint& p, double courseRad, double sogKn = 10.0) {
  OwnShipFix f;
  f.position = p;
  f.sogMps = knotsToMps(sogKn);
  f.cogRad = courseRad;
  return f;
}

TimeUs seconds(double s) {
  return fromSeconds(s);
}

int countEvents(const std::vector<RouteEvent>& events, RouteEventKind kind) {
  return static_cast<int>(
      std::count_if(events.begin(), events.end(), [&](const RouteEvent& e) { return e.kind == kind; }));
}

}  // namespace

class TestRouteMonitor : public QObject {
  Q_OBJECT
 private slots:
  void sailsTheRouteOnOffsetTracks();
  void legChangesAtTheWheelOverLineNotBefore();
  void legChangesInTheArrivalCircle();
  void cornersAndTurnsThatDoNotFit();
  void arrivesAtTheFinalWaypoint();
  void offTrackWithHysteresis();
  void etaIsTheRemainingDistanceOverTheSpeed();
  void crossTrackSdIsTheCovarianceOnTheNormal();
  void autopilotSentences();
  void headingToSteerAcrossNorth();
  void manualLegChangeAndRestart();
  void manualRuleKeepsTheLeg();
  void badInput();
};

void TestRouteMonitor::sailsTheRouteOnOffsetTracks() {
  // GIVEN the route, WHEN own ship sails the straight part of each leg at 10 kn, 1 s steps, set off the
  // track by +60 m, -40 m and +25 m THEN the XTD is the offset, the leg is the one sailed, the leg
  // changes twice at the wheel-over line, each waypoint is approached once (60 s before its wheel-over
  // point), own ship arrives once and is never off track.
  const geo::Route route = threeLegs();
  RouteMonitor m(route);
  const double offsets[] = {0.0, 60.0, -40.0, 25.0};
  const double stepM = knotsToMps(10.0);
  std::vector<RouteEvent> events;
  double tS = 0.0;
  for (std::size_t to = 1; to <= 3; ++to) {
    const double startM = to == 1 ? 0.0 : wheelOver(route, to - 1) + 1.0;
    const double endM = to == 3 ? legLength(route, 3) : legLength(route, to) - wheelOver(route, to) - 1.0;
    for (double along = startM; along <= endM; along += stepM, tS += 1.0) {
      const OnLeg s = onLeg(route, to, along, offsets[to]);
      const RouteStatus st = m.update(seconds(tS), fixAt(s.p, s.courseRad));
      const test::NearContext ctx(QString("leg %1 along %2 m").arg(to).arg(along));
      QVERIFY(st.valid);
      QCOMPARE(st.to, to);
      QCOMPARE(st.trackPart, TrackPart::Leg);
      QVERIFY(!st.offTrack);
      RK_COMPARE_NEAR(st.crossTrackM, offsets[to], 1e-3);
      QCOMPARE(st.side, offsets[to] < 0.0 ? TrackSide::Port : TrackSide::Starboard);
      RK_COMPARE_NEAR(angleDiff(st.trackCourseRad, s.courseRad), 0.0, 1e-9);
      RK_COMPARE_NEAR(st.distanceToWaypointM, inverse(s.p, route.waypoints[to].position).distM, 1e-3);
      for (const RouteEvent& e : st.events) {
        QCOMPARE(e.timeUs, seconds(tS));
        if (e.kind == RouteEventKind::ApproachingWaypoint) {
          QVERIFY(st.timeToWheelOverS <= 60.0);
          QVERIFY(st.timeToWheelOverS > 59.0);  // the first update within the warning time
        }
        events.push_back(e);
      }
    }
  }
  QCOMPARE(countEvents(events, RouteEventKind::LegChanged), 3);  // the first choice and two changes
  QCOMPARE(events.front().cause, LegChangeCause::Restart);
  QCOMPARE(events.front().previousTo, std::size_t{0});
  QCOMPARE(countEvents(events, RouteEventKind::ApproachingWaypoint), 3);
  QCOMPARE(countEvents(events, RouteEventKind::ArrivedFinal), 1);
  QCOMPARE(countEvents(events, RouteEventKind::OffTrackEntered), 0);
  std::size_t changes = 0;
  for (const RouteEvent& e : events) {
    if (e.kind == RouteEventKind::ApproachingWaypoint) QCOMPARE(e.waypoint, e.to);
    if (e.kind != RouteEventKind::LegChanged || e.cause == LegChangeCause::Restart) continue;
    ++changes;
    QCOMPARE(e.cause, LegChangeCause::WheelOverLine);
    QCOMPARE(e.previousTo, changes);
    QCOMPARE(e.to, changes + 1);
  }
}

void TestRouteMonitor::legChangesAtTheWheelOverLineNotBefore() {
  // GIVEN own ship on leg 1's track WHEN it sails in 1 m steps up to 1 m before the wheel-over line THEN
  // leg 1 stays; WHEN 1 m past it THEN leg 2, measured from the turn arc: XTD 0 at the arc's start with
  // leg 1's course, the corner outside the arc by R / cos(change / 2) - R, XTD 0 and leg 2's course at
  // the arc's end, and the straight leg after it.
  const geo::Route route = threeLegs();
  RouteMonitor m(route);
  const double wop = legLength(route, 1) - wheelOver(route, 1);
  RK_COMPARE_NEAR(m.wheelOverDistanceM(1), wheelOver(route, 1), 1e-6);
  RK_COMPARE_NEAR(m.wheelOverDistanceM(2), wheelOver(route, 2), 1e-6);
  RK_COMPARE_NEAR(m.wheelOverDistanceM(3), 0.0, 0.0);
  double tS = 0.0;
  for (double along = wop - 30.0; along <= wop - 1.0; along += 1.0, tS += 1.0) {
    const OnLeg s = onLeg(route, 1, along, 0.0);
    const RouteStatus st = m.update(seconds(tS), fixAt(s.p, s.courseRad));
    QCOMPARE(st.to, std::size_t{1});
    RK_COMPARE_NEAR(st.distanceToWheelOverM, wop - along, 1e-3);
  }
  const OnLeg past = onLeg(route, 1, wop + 1.0, 0.0);
  RouteStatus st = m.update(seconds(tS), fixAt(past.p, past.courseRad));
  QCOMPARE(st.to, std::size_t{2});
  QCOMPARE(st.events.size(), std::size_t{1});
  QCOMPARE(st.events[0].kind, RouteEventKind::LegChanged);
  QCOMPARE(st.events[0].cause, LegChangeCause::WheelOverLine);
  QCOMPARE(st.events[0].previousTo, std::size_t{1});
  RK_COMPARE_NEAR(st.legLengthM, legLength(route, 2), 1e-3);
  // 1 m along the arc (radius R) its course has turned 1 / R to starboard. The turn is plane geometry in
  // leg 2's frame: courses within 1e-4 rad (0.006 deg) of the ellipsoid's, XTD within centimetres.
  const double r = nmToMetres(route.defaultTurnRadiusNm);
  QCOMPARE(st.trackPart, TrackPart::Turn);
  RK_COMPARE_NEAR(st.crossTrackM, 0.0, 0.05);
  RK_COMPARE_NEAR(angleDiff(st.trackCourseRad, past.courseRad), 1.0 / r, 1e-4);
  QVERIFY(!st.offTrack);

  const double change = courseChange(route, 1);  // to starboard: the corner is outside, to port
  QVERIFY(change > 0.0);
  st = m.update(seconds(++tS), fixAt(route.waypoints[1].position, past.courseRad));
  QCOMPARE(st.trackPart, TrackPart::Turn);
  RK_COMPARE_NEAR(st.crossTrackM, -(r / std::cos(change / 2.0) - r), 0.5);
  QCOMPARE(st.to, std::size_t{2});

  const OnLeg arcEnd = onLeg(route, 2, wheelOver(route, 1) - 1.0, 0.0);
  st = m.update(seconds(++tS), fixAt(arcEnd.p, arcEnd.courseRad));
  QCOMPARE(st.trackPart, TrackPart::Turn);
  RK_COMPARE_NEAR(st.crossTrackM, 0.0, 0.05);
  RK_COMPARE_NEAR(angleDiff(st.trackCourseRad, arcEnd.courseRad), -1.0 / r, 1e-4);
  const OnLeg straight = onLeg(route, 2, wheelOver(route, 1) + 1.0, -30.0);
  st = m.update(seconds(++tS), fixAt(straight.p, straight.courseRad));
  QCOMPARE(st.trackPart, TrackPart::Leg);
  RK_COMPARE_NEAR(st.crossTrackM, -30.0, 1e-3);
}

void TestRouteMonitor::legChangesInTheArrivalCircle() {
  // GIVEN an arrival circle of 0.5 NM, larger than the wheel-over distance at B WHEN own ship, 100 m to
  // port of leg 1, comes within it THEN leg 2 takes over, the cause the arrival circle, but own ship is
  // still measured from leg 1 (and its limits) up to the turn's start, not off track; past it, from the arc.
  const geo::Route route = threeLegs();
  RouteMonitorSettings settings;
  settings.arrivalCircleNm = 0.5;
  RouteMonitor m(route, settings);
  QVERIFY(wheelOver(route, 1) < nmToMetres(0.5));
  const double len = legLength(route, 1);
  OnLeg s = onLeg(route, 1, len - nmToMetres(0.5) - 2.0, -100.0);
  RouteStatus st = m.update(0, fixAt(s.p, s.courseRad));
  QCOMPARE(st.to, std::size_t{1});
  QVERIFY(!st.arrivalCircleEntered);
  s = onLeg(route, 1, len - nmToMetres(0.5) + 10.0, -100.0);
  st = m.update(seconds(1.0), fixAt(s.p, s.courseRad));
  QCOMPARE(st.to, std::size_t{2});
  QCOMPARE(st.events.size(), std::size_t{1});
  QCOMPARE(st.events[0].cause, LegChangeCause::ArrivalCircle);
  QCOMPARE(st.trackPart, TrackPart::PreviousLeg);
  RK_COMPARE_NEAR(st.crossTrackM, -100.0, 1e-3);
  RK_COMPARE_NEAR(angleDiff(st.trackCourseRad, s.courseRad), 0.0, 1e-9);
  RK_COMPARE_NEAR(st.crossTrackLimitM, nmToMetres(0.2), 1e-9);  // leg 1's port limit, not leg 2's 0.1 NM
  QVERIFY(!st.offTrack);
  s = onLeg(route, 1, len - wheelOver(route, 1) + 1.0, 0.0);
  st = m.update(seconds(2.0), fixAt(s.p, s.courseRad));
  QCOMPARE(st.trackPart, TrackPart::Turn);
  RK_COMPARE_NEAR(st.crossTrackM, 0.0, 0.05);
}

void TestRouteMonitor::cornersAndTurnsThatDoNotFit() {
  // GIVEN a turn radius of 0 at B (a corner) WHEN own ship is 10 m to port of leg 1 and 3 m before B THEN it
  // is on leg 2 (arrival circle), measured from leg 1; 3 m past B's perpendicular, from the corner:
  // -hypot(3, 10). GIVEN a radius of 20 NM at B THEN the wheel-over distance is half the shorter leg.
  geo::Route route = threeLegs();
  route.waypoints[1].turnRadiusNm = 0.0;
  RouteMonitor m(route);
  RK_COMPARE_NEAR(m.wheelOverDistanceM(1), 0.0, 0.0);
  const double len = legLength(route, 1);
  OnLeg s = onLeg(route, 1, len - 3.0, -10.0);
  RouteStatus st = m.update(0, fixAt(s.p, s.courseRad));
  QCOMPARE(st.to, std::size_t{2});
  QCOMPARE(st.trackPart, TrackPart::PreviousLeg);
  RK_COMPARE_NEAR(st.crossTrackM, -10.0, 1e-3);
  s = onLeg(route, 1, len + 3.0, -10.0);
  st = m.update(seconds(1.0), fixAt(s.p, s.courseRad));
  QCOMPARE(st.trackPart, TrackPart::Turn);
  RK_COMPARE_NEAR(st.crossTrackM, -std::hypot(3.0, 10.0), 0.01);

  route.waypoints[1].turnRadiusNm = 20.0;
  QVERIFY(wheelOver(route, 1) > 0.5 * legLength(route, 1));
  RK_COMPARE_NEAR(RouteMonitor(route).wheelOverDistanceM(1),
                  0.5 * std::min(legLength(route, 1), legLength(route, 2)), 1e-6);
}

void TestRouteMonitor::arrivesAtTheFinalWaypoint() {
  // GIVEN own ship on the last leg WHEN it comes within 0.1 NM of D THEN arrival, reported once; its
  // perpendicular passed later; WHEN another ship passes D 300 m abeam THEN it arrives at the perpendicular.
  const geo::Route route = threeLegs();
  const double len = legLength(route, 3);
  const double circle = nmToMetres(0.1);
  RouteMonitor m(route);
  QVERIFY(m.manualLegChange(3));
  int arrivals = 0;
  double tS = 0.0;
  for (double along = len - circle - 20.5; along <= len + 20.0; along += 1.0, tS += 1.0) {
    const OnLeg s = onLeg(route, 3, along, 0.0);
    const RouteStatus st = m.update(seconds(tS), fixAt(s.p, s.courseRad));
    QCOMPARE(st.to, std::size_t{3});
    QCOMPARE(st.arrivalCircleEntered, len - along <= circle);
    QCOMPARE(st.perpendicularPassed, along > len);
    QCOMPARE(st.arrived, len - along <= circle);
    arrivals += countEvents(st.events, RouteEventKind::ArrivedFinal);
    if (countEvents(st.events, RouteEventKind::ArrivedFinal)) RK_COMPARE_NEAR(len - along, circle, 1.0);
  }
  QCOMPARE(arrivals, 1);

  RouteMonitor abeam(route);
  QVERIFY(abeam.manualLegChange(3));
  OnLeg s = onLeg(route, 3, len - 1.0, 300.0);
  RouteStatus st = abeam.update(0, fixAt(s.p, s.courseRad));
  QVERIFY(!st.arrived);
  s = onLeg(route, 3, len + 1.0, 300.0);
  st = abeam.update(seconds(1.0), fixAt(s.p, s.courseRad));
  QVERIFY(st.arrived && st.perpendicularPassed && !st.arrivalCircleEntered);
  QCOMPARE(countEvents(st.events, RouteEventKind::ArrivedFinal), 1);
}

void TestRouteMonitor::offTrackWithHysteresis() {
  // GIVEN leg 1 (limits 0.1 NM starboard, 0.2 NM port; clear at 90%) WHEN own ship's offset goes through
  // values on both sides THEN off track is entered past the limit and left only below 90% of it.
  const geo::Route route = threeLegs();
  RouteMonitor m(route);
  const double stbd = nmToMetres(0.1), port = nmToMetres(0.2);
  struct Step {
    double offsetM;
    bool off;
    int entered, left;
  };
  const Step steps[] = {{100.0, false, 0, 0},        {stbd + 5.0, true, 1, 0},
                        {0.95 * stbd, true, 0, 0},   {0.89 * stbd, false, 0, 1},
                        {0.95 * stbd, false, 0, 0},  {-(stbd + 5.0), false, 0, 0},  // port's limit is wider
                        {-(port + 5.0), true, 1, 0}, {-0.95 * port, true, 0, 0},
                        {-0.89 * port, false, 0, 1}};
  double tS = 0.0;
  for (const Step& step : steps) {
    const OnLeg s = onLeg(route, 1, 3000.0, step.offsetM);
    const RouteStatus st = m.update(seconds(tS++), fixAt(s.p, s.courseRad));
    const test::NearContext ctx(QString("offset %1 m").arg(step.offsetM));
    QCOMPARE(st.offTrack, step.off);
    QCOMPARE(countEvents(st.events, RouteEventKind::OffTrackEntered), step.entered);
    QCOMPARE(countEvents(st.events, RouteEventKind::OffTrackLeft), step.left);
    RK_COMPARE_NEAR(st.crossTrackLimitM, step.offsetM < 0.0 ? port : stbd, 1e-9);
    for (const RouteEvent& e : st.events)
      if (e.kind == RouteEventKind::OffTrackEntered) QCOMPARE(e.side, st.side);
  }
}

void TestRouteMonitor::etaIsTheRemainingDistanceOverTheSpeed() {
  // GIVEN own ship 2000 m along leg 1 at 10 kn (sd 0.1 m/s) and UTC WHEN updated THEN each waypoint's
  // time is the distance along the legs over the SOG, its sd d sd(v) / v^2, the UTC ETA that time
  // later; at planned speeds 8 and 12 kn for B and C and none for D (leg 3 has none).
  const geo::Route route = threeLegs();
  RouteMonitor m(route);
  const OnLeg s = onLeg(route, 1, 2000.0, 0.0);
  OwnShipFix f = fixAt(s.p, s.courseRad);
  f.velocitySdMps = 0.1;
  const UtcUs utc = 1'714'550'400'000'000;  // 2024-05-01T08:00:00Z
  const TimeUs t = seconds(100.0);
  RouteStatus st = m.update(t, f, utc);
  QCOMPARE(st.etas.size(), std::size_t{3});
  const double v = knotsToMps(10.0);
  const double d[] = {legLength(route, 1) - 2000.0, legLength(route, 1) - 2000.0 + legLength(route, 2),
                      legLength(route, 1) - 2000.0 + legLength(route, 2) + legLength(route, 3)};
  const double planned[] = {d[0] / knotsToMps(8.0),
                            d[0] / knotsToMps(8.0) + legLength(route, 2) / knotsToMps(12.0)};
  for (std::size_t i = 0; i < 3; ++i) {
    const WaypointEta& e = st.etas[i];
    QCOMPARE(e.waypoint, i + 1);
    RK_COMPARE_NEAR(e.distanceM, d[i], 1e-3);
    RK_COMPARE_NEAR(e.timeS, d[i] / v, 1e-3);
    RK_COMPARE_NEAR(e.timeSdS, d[i] * 0.1 / (v * v), 1e-3);
    QVERIFY(e.etaUs && e.etaUtc);
    RK_COMPARE_NEAR(toSeconds(*e.etaUs - t), d[i] / v, 1e-3);
    RK_COMPARE_NEAR(toSeconds(*e.etaUtc - utc), d[i] / v, 1e-3);
    QCOMPARE(e.plannedEtaUtc.has_value(), i < 2);
    if (i < 2) RK_COMPARE_NEAR(e.plannedTimeS, planned[i], 1e-3);
    if (i < 2) RK_COMPARE_NEAR(toSeconds(*e.plannedEtaUtc - utc), planned[i], 1e-3);
  }
  QVERIFY(std::isnan(st.etas[2].plannedTimeS));
  RK_COMPARE_NEAR(st.timeToWaypointS, d[0] / v, 1e-3);
  RK_COMPARE_NEAR(st.timeToWheelOverS, (d[0] - wheelOver(route, 1)) / v, 1e-3);

  // stopped: no times from the SOG; the planned ones stay
  f.sogMps = 0.0;
  st = m.update(seconds(101.0), f, utc);
  QVERIFY(std::isnan(st.timeToWaypointS) && std::isnan(st.timeToWheelOverS));
  QVERIFY(std::isnan(st.etas[0].timeS) && !st.etas[0].etaUs && !st.etas[0].etaUtc);
  RK_COMPARE_NEAR(st.etas[0].plannedTimeS, planned[0], 1e-3);
}

void TestRouteMonitor::crossTrackSdIsTheCovarianceOnTheNormal() {
  // GIVEN a covariance with sd 100 m along leg 2 and 7 m across, rotated into north/east by the leg's
  // course WHEN own ship is on leg 2 THEN the XTD's sd is 7 m; and 100 m with the two swapped.
  const geo::Route route = threeLegs();
  RouteMonitor m(route);
  const OnLeg s = onLeg(route, 2, 4000.0, 20.0);
  for (const auto& [sdAlong, sdAcross] : {std::pair{100.0, 7.0}, std::pair{7.0, 100.0}}) {
    const double an = std::cos(s.courseRad), ae = std::sin(s.courseRad);   // along, north / east
    const double nn = -std::sin(s.courseRad), ne = std::cos(s.courseRad);  // starboard normal
    OwnShipFix f = fixAt(s.p, s.courseRad);
    f.positionCovariance = PositionCovariance{sdAlong * sdAlong * an * an + sdAcross * sdAcross * nn * nn,
                                              sdAlong * sdAlong * ae * ae + sdAcross * sdAcross * ne * ne,
                                              sdAlong * sdAlong * an * ae + sdAcross * sdAcross * nn * ne};
    const RouteStatus st = m.update(0, f);
    QCOMPARE(st.to, std::size_t{2});
    RK_COMPARE_NEAR(st.crossTrackM, 20.0, 1e-3);
    RK_COMPARE_NEAR(st.crossTrackSdM, sdAcross, 1e-6);
  }
  const RouteStatus none = m.update(1, fixAt(s.p, s.courseRad));
  QVERIFY(std::isnan(none.crossTrackSdM));
}

void TestRouteMonitor::autopilotSentences() {
  // GIVEN own ship 50 m starboard of leg 1, COG 10 deg off the track, 10 kn THEN XTE / RMB / APB: steer
  // left, 50 m in NM, closing velocity SOG cos(COG - bearing), heading to steer the course corrected by
  // atan(-50 / 0.25 NM); 50 m to port: steer right; 2 NM to starboard: the correction clamped at 45 deg.
  const geo::Route route = threeLegs();
  RouteMonitor m(route);
  const double lookahead = nmToMetres(0.25);
  double tS = 0.0;
  for (const double offset : {50.0, -50.0, nmToMetres(2.0)}) {
    const OnLeg s = onLeg(route, 1, 3000.0, offset);
    const double cog = s.courseRad + degToRad(10.0);
    const RouteStatus st = m.update(seconds(tS++), fixAt(s.p, cog));
    const test::NearContext ctx(QString("offset %1 m").arg(offset));
    const io::nmea::XteOut xte = xteOf(st, 'D');
    QVERIFY(xte.valid);
    QCOMPARE(xte.mode, 'D');
    QCOMPARE(xte.steerRight, offset < 0.0);
    RK_COMPARE_NEAR(xte.crossTrackNm, metresToNm(std::abs(offset)), 1e-8);
    const auto fields = io::nmea::checkedFields(io::nmea::xte("EC", xte));
    QVERIFY(fields && fields->size() > 4);
    QCOMPARE(QString::fromStdString((*fields)[4]), offset < 0.0 ? QString("R") : QString("L"));

    const io::nmea::RmbOut rmb = rmbOf(st, route);
    const Inverse toB = inverse(s.p, route.waypoints[1].position);
    QVERIFY(rmb.valid && !rmb.arrived);
    QCOMPARE(rmb.steerRight, offset < 0.0);
    QCOMPARE(rmb.originId, std::string("A"));
    QCOMPARE(rmb.destinationId, std::string("B"));
    QCOMPARE(rmb.destLatDeg, route.waypoints[1].position.latDeg);
    RK_COMPARE_NEAR(rmb.rangeToDestNm, metresToNm(toB.distM), 1e-8);
    RK_COMPARE_NEAR(angleDiff(degToRad(rmb.bearingToDestTrueDeg), degToRad(toB.azi1Deg)), 0.0, 1e-9);
    RK_COMPARE_NEAR(rmb.closingVelocityKn, 10.0 * std::cos(cog - degToRad(toB.azi1Deg)), 1e-9);

    const io::nmea::ApbOut apb = apbOf(st, route);
    QVERIFY(apb.valid && !apb.arrivalCircleEntered && !apb.perpendicularPassed);
    QCOMPARE(apb.steerRight, offset < 0.0);
    QCOMPARE(apb.destinationId, std::string("B"));
    const double originToDest = inverse(route.waypoints[0].position, route.waypoints[1].position).azi1Deg;
    RK_COMPARE_NEAR(apb.bearingOriginToDestDeg, originToDest, 1e-9);
    const double correction = std::max(-0.25 * kPi, std::min(0.25 * kPi, std::atan(-offset / lookahead)));
    RK_COMPARE_NEAR(angleDiff(degToRad(apb.headingToSteerDeg), s.courseRad + correction), 0.0, 1e-9);
    if (offset > 1000.0) RK_COMPARE_NEAR(correction, -0.25 * kPi, 0.0);
  }
  // two ship lengths of 120 m
  const OnLeg s = onLeg(route, 1, 3000.0, 50.0);
  const RouteStatus st = m.update(seconds(tS++), fixAt(s.p, s.courseRad));
  const io::nmea::ApbOut apb = apbOf(st, route, 'A', CrossTrackSteering::forShipLength(120.0));
  RK_COMPARE_NEAR(angleDiff(degToRad(apb.headingToSteerDeg), s.courseRad - std::atan(50.0 / 240.0)), 0.0,
                  1e-9);
  // the last leg: D has no name, its id names it
  QVERIFY(m.manualLegChange(3));
  const RouteStatus last = m.update(seconds(tS++), fixAt(onLeg(route, 3, 100.0, 0.0).p, 0.0));
  QCOMPARE(rmbOf(last, route).destinationId, std::string("40"));
  QCOMPARE(rmbOf(last, route).originId, std::string("C"));
}

void TestRouteMonitor::headingToSteerAcrossNorth() {
  // GIVEN a leg on 002 and own ship 100 m to starboard THEN the heading to steer is 002 - atan(100 / 463 m),
  // about 349.8, in [0, 360); 100 m to port: about 014.2.
  geo::Route route;
  const geo::GeoPoint a{50.0, -5.0};
  route.waypoints = {{1, "A", a, {}, {}}, {2, "B", direct(a, 2.0, nmToMetres(5.0)), {}, {}}};
  route.waypoints[1].leg.geometry = geo::LegGeometry::GreatCircle;
  RouteMonitor m(route);
  for (const double offset : {100.0, -100.0}) {
    const OnLeg s = onLeg(route, 1, 2000.0, offset);
    const RouteStatus st = m.update(0, fixAt(s.p, s.courseRad));
    const double hts = apbOf(st, route).headingToSteerDeg;
    QVERIFY(hts >= 0.0 && hts < 360.0);
    const double expected = radToDeg(wrapTwoPi(s.courseRad + std::atan(-offset / nmToMetres(0.25))));
    RK_COMPARE_NEAR(hts, expected, 1e-9);
    QVERIFY(offset > 0.0 ? hts > 340.0 : hts < 20.0);
  }
}

void TestRouteMonitor::manualLegChangeAndRestart() {
  // GIVEN own ship in the middle of leg 2 from the start THEN the first fix chooses leg 2; WHEN leg 1 is
  // chosen by hand (own ship past its wheel-over line) THEN leg 1 is kept; WHEN restarted THEN leg 2.
  const geo::Route route = threeLegs();
  RouteMonitor m(route);
  const OnLeg s = onLeg(route, 2, 5000.0, 30.0);
  RouteStatus st = m.update(0, fixAt(s.p, s.courseRad));
  QCOMPARE(st.to, std::size_t{2});
  QCOMPARE(st.events.size(), std::size_t{1});
  QCOMPARE(st.events[0].cause, LegChangeCause::Restart);
  QCOMPARE(st.events[0].previousTo, std::size_t{0});
  QVERIFY(m.manualLegChange(1));
  QVERIFY(!m.manualLegChange(0));
  QVERIFY(!m.manualLegChange(4));
  for (int i = 1; i <= 3; ++i) {
    st = m.update(seconds(i), fixAt(s.p, s.courseRad));
    QCOMPARE(st.to, std::size_t{1});
    QCOMPARE(countEvents(st.events, RouteEventKind::LegChanged), i == 1 ? 1 : 0);
    if (i == 1) QCOMPARE(st.events[0].cause, LegChangeCause::Manual);
    QVERIFY(st.offTrack);  // measured from leg 1, as chosen
  }
  m.restartFromNearestLeg();
  st = m.update(seconds(4), fixAt(s.p, s.courseRad));
  QCOMPARE(st.to, std::size_t{2});
  QVERIFY(!st.offTrack);
  QCOMPARE(countEvents(st.events, RouteEventKind::LegChanged), 1);
  QCOMPARE(st.events[0].cause, LegChangeCause::Restart);
  QCOMPARE(st.events[0].previousTo, std::size_t{1});

  // outside every corridor: the nearest leg; inside two: the smaller |XTD|
  QCOMPARE(nearestLeg(route, direct(route.waypoints[3].position, 30.0, nmToMetres(2.0))), std::size_t{3});
  QCOMPARE(nearestLeg(route, direct(route.waypoints[0].position, 225.0, nmToMetres(1.0))), std::size_t{1});
  QCOMPARE(nearestLeg(route, onLeg(route, 1, 3000.0, nmToMetres(1.0)).p), std::size_t{1});
  const double len2 = legLength(route, 2);  // inside the turn at C (to port): in both corridors
  QCOMPARE(nearestLeg(route, onLeg(route, 2, len2 - 50.0, -20.0).p), std::size_t{2});
  QCOMPARE(nearestLeg(route, onLeg(route, 2, len2 - 10.0, -60.0).p), std::size_t{3});
  QCOMPARE(nearestLeg(route, {std::nan(""), 0.0}), std::size_t{0});
}

void TestRouteMonitor::manualRuleKeepsTheLeg() {
  // GIVEN the manual rule WHEN own ship sails past leg 1's wheel-over line and waypoint THEN leg 1 stays.
  const geo::Route route = threeLegs();
  RouteMonitorSettings settings;
  settings.legChange = LegChangeRule::Manual;
  RouteMonitor m(route, settings);
  for (const double along : {3000.0, legLength(route, 1) - 10.0, legLength(route, 1) + 50.0}) {
    const OnLeg s = onLeg(route, 1, along, 0.0);
    QCOMPARE(m.update(0, fixAt(s.p, s.courseRad)).to, std::size_t{1});
  }
  QVERIFY(m.manualLegChange(2));
  QCOMPARE(m.activeLeg(), std::size_t{2});
}

void TestRouteMonitor::badInput() {
  // A route with one waypoint and settings out of range are refused with what is wrong; a NaN or
  // out-of-range position gives a status marked not valid and changes nothing; a NaN SOG no times.
  geo::Route one = threeLegs();
  one.waypoints.resize(1);
  try {
    RouteMonitor m(one);
    QFAIL("a route with one waypoint was accepted");
  } catch (const std::invalid_argument& e) {
    QVERIFY2(std::string(e.what()).find("at least two") != std::string::npos, e.what());
  }
  for (const auto& change : {+[](RouteMonitorSettings& s) { s.arrivalCircleNm = 0.0; },
                             +[](RouteMonitorSettings& s) { s.approachWarningS = std::nan(""); },
                             +[](RouteMonitorSettings& s) { s.offTrackClearFraction = 1.5; },
                             +[](RouteMonitorSettings& s) { s.minSpeedKn = -1.0; }}) {
    RouteMonitorSettings settings;
    change(settings);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, RouteMonitor(threeLegs(), settings));
  }

  const geo::Route route = threeLegs();
  RouteMonitor m(route);
  const OnLeg s = onLeg(route, 2, 5000.0, 30.0);
  for (const geo::GeoPoint bad : {geo::GeoPoint{std::nan(""), 0.0}, geo::GeoPoint{95.0, 0.0},
                                  geo::GeoPoint{50.0, std::numeric_limits<double>::infinity()}}) {
    const RouteStatus st = m.update(0, fixAt(bad, 0.0));
    QVERIFY(!st.valid);
    QVERIFY(std::isnan(st.crossTrackM) && std::isnan(st.timeToWaypointS));
    QVERIFY(st.etas.empty() && st.events.empty());
    QVERIFY(!xteOf(st).valid && !rmbOf(st, route).valid && !apbOf(st, route).valid);
  }
  RouteStatus st = m.update(seconds(1), fixAt(s.p, s.courseRad));  // the first usable fix chooses
  QVERIFY(st.valid);
  QCOMPARE(st.to, std::size_t{2});
  st = m.update(seconds(2), fixAt({std::nan(""), std::nan("")}, 0.0));
  QVERIFY(!st.valid);
  QCOMPARE(st.to, std::size_t{2});
  OwnShipFix f = fixAt(s.p, s.courseRad);
  f.sogMps = std::nan("");
  f.positionCovariance = PositionCovariance{std::nan(""), 1.0, 0.0};
  st = m.update(seconds(3), f);
  QVERIFY(st.valid);
  RK_COMPARE_NEAR(st.crossTrackM, 30.0, 1e-3);
  QVERIFY(std::isnan(st.timeToWaypointS) && std::isnan(st.crossTrackSdM));
  QVERIFY(std::isnan(rmbOf(st, route).closingVelocityKn));
}

QTEST_GUILESS_MAIN(TestRouteMonitor)
#include "tst_route_monitor.moc"
