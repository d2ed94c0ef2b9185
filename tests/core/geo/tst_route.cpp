// Route geometry on the ellipsoid: leg lengths and courses against GeographicLib's own inverse
// problems, a position's place on a leg (along- and cross-track, to go) for points set off the leg
// by known distances, the wheel-over distance, the turns that do not fit between their legs, and the
// route's own checks.
#include <QTest>

#include <GeographicLib/Geodesic.hpp>
#include <cmath>

#include "common/angles.h"
#include "common/units.h"
#include "geo/geodesic.h"
#include "geo/route.h"
#include "geo/route_turns.h"
#include "support/compare_near.h"

using namespace reckoner;
using namespace reckoner::geo;

namespace {

Route twoLegs(LegGeometry g) {
  Route r;
  r.name = "test";
  Waypoint a{1, "A", {47.60, -122.45}, {}, {}};
  Waypoint b{2, "B", {48.40, -124.70}, 0.8, {}};
  Waypoint c{3, "C", {48.40, -123.90}, {}, {}};
  b.leg.geometry = g;
  c.leg.geometry = g;
  r.waypoints = {a, b, c};
  return r;
}

GeoPoint offset(const GeoPoint& p, double azimuthRad, double distM) {
  GeoPoint q;
  GeographicLib::Geodesic::WGS84().Direct(p.latDeg, p.lonDeg, radToDeg(azimuthRad), distM, q.latDeg,
                                          q.lonDeg);
  return q;
}

}  // namespace

class TestRoute : public QObject {
  Q_OBJECT
 private slots:
  void lengthsAndCourses() {
    const Route gc = twoLegs(LegGeometry::GreatCircle);
    const Route rl = twoLegs(LegGeometry::RhumbLine);
    const RangeBearing ab = rangeBearing(gc.waypoints[0].position, gc.waypoints[1].position);
    RK_COMPARE_NEAR(legLengthM(gc, 1), ab.rangeM, 1e-6);
    RK_COMPARE_NEAR(legStartCourseRad(gc, 1), ab.trueBearingRad, 1e-12);
    // the rhumb line is longer than the geodesic, its course constant
    QVERIFY(legLengthM(rl, 1) > legLengthM(gc, 1));
    RK_COMPARE_NEAR(legStartCourseRad(rl, 1), legEndCourseRad(rl, 1), 1e-12);
    // due east along a parallel: 090 all the way on a rhumb line; the great circle starts north of east
    RK_COMPARE_NEAR(radToDeg(legStartCourseRad(rl, 2)), 90.0, 1e-9);
    QVERIFY(radToDeg(legStartCourseRad(gc, 2)) < 90.0);
    QVERIFY(radToDeg(legEndCourseRad(gc, 2)) > 90.0);
    // points along a leg end on its waypoints and are no further apart than asked
    const std::vector<GeoPoint> pts = legPoints(rl, 1, 5000.0);
    QVERIFY(pts.size() >= 2);
    QCOMPARE(pts.front().latDeg, rl.waypoints[0].position.latDeg);
    QCOMPARE(pts.back().lonDeg, rl.waypoints[1].position.lonDeg);
    for (std::size_t i = 1; i < pts.size(); ++i)
      QVERIFY(rangeBearing(pts[i - 1], pts[i]).rangeM <= 5000.0 + 1e-6);
  }
  void positionOnLeg_data() {
    QTest::addColumn<int>("geometry");
    QTest::addColumn<double>("alongFraction");
    QTest::addColumn<double>("crossM");
    for (int g = 0; g < 2; ++g) {
      const char* name = g == 0 ? "rhumb" : "great circle";
      QTest::addRow("%s, 30%%, 400 m starboard", name) << g << 0.3 << 400.0;
      QTest::addRow("%s, 80%%, 1 NM port", name) << g << 0.8 << -nmToMetres(1.0);
      QTest::addRow("%s, before start, 5 NM starboard", name) << g << -0.05 << nmToMetres(5.0);
      QTest::addRow("%s, past the end, on track", name) << g << 1.1 << 0.0;
    }
  }
  void positionOnLeg() {
    QFETCH(int, geometry);
    QFETCH(double, alongFraction);
    QFETCH(double, crossM);
    const Route r = twoLegs(geometry == 0 ? LegGeometry::RhumbLine : LegGeometry::GreatCircle);
    const double length = legLengthM(r, 1);
    const double along = alongFraction * length;
    const GeoPoint foot = legPoint(r, 1, along);
    const double course = legFix(r, 1, foot).trackCourseRad;
    const GeoPoint p = offset(foot, course + kPi / 2.0, crossM);
    const LegFix fix = legFix(r, 1, p);
    RK_COMPARE_NEAR(fix.alongTrackM, along, 0.01);
    RK_COMPARE_NEAR(fix.crossTrackM, crossM, 0.01);
    RK_COMPARE_NEAR(fix.legLengthM, length, 1e-6);
    RK_COMPARE_NEAR(fix.foot.latDeg, foot.latDeg, 1e-9);
    const RangeBearing toGo = rangeBearing(p, r.waypoints[1].position);
    RK_COMPARE_NEAR(fix.distanceToGoM, toGo.rangeM, 1e-6);
    RK_COMPARE_NEAR(fix.bearingToGoRad, toGo.trueBearingRad, 1e-12);
  }
  void badPositionIsNaN() {
    const LegFix fix = legFix(twoLegs(LegGeometry::RhumbLine), 1, {std::nan(""), 0.0});
    QVERIFY(std::isnan(fix.crossTrackM));
    QVERIFY(std::isnan(fix.alongTrackM));
  }
  void wheelOver() {
    Route r;
    r.defaultTurnRadiusNm = 0.5;
    r.waypoints = {{1, "", {0.0, 0.0}, {}, {}}, {2, "", {0.0, 0.1}, {}, {}}, {3, "", {0.1, 0.1}, {}, {}}};
    // east then north: 90 degrees to port; the turn starts R tan 45 = R before the waypoint
    RK_COMPARE_NEAR(radToDeg(courseChangeRad(r, 1)), -90.0, 0.01);
    RK_COMPARE_NEAR(wheelOverDistanceM(r, 1), nmToMetres(0.5), 1.0);
    r.waypoints[1].turnRadiusNm = 1.0;
    RK_COMPARE_NEAR(wheelOverDistanceM(r, 1), nmToMetres(1.0), 2.0);
    QCOMPARE(wheelOverDistanceM(r, 0), 0.0);
    QCOMPARE(wheelOverDistanceM(r, 2), 0.0);
  }
  void turnsThatDoNotFit() {
    // East 0.1 degree along the equator, north 0.1 degree along a meridian, east again 0.03 degree: two
    // right-angle turns. Along the equator and a meridian a rhumb line is the geodesic, and the short
    // parallel differs from it by millimetres, so the legs are taken from GeographicLib's inverse problem
    // here; half of the shorter leg at a turn is the most its wheel-over may take.
    Route r;
    r.defaultTurnRadiusNm = 0.5;
    r.waypoints = {{1, "A", {0.0, 0.0}, {}, {}},
                   {2, "B", {0.0, 0.1}, {}, {}},
                   {3, "C", {0.1, 0.1}, {}, {}},
                   {4, "D", {0.1, 0.13}, {}, {}}};
    const auto inverse = [](const GeoPoint& a, const GeoPoint& b) {
      double s = 0.0;
      GeographicLib::Geodesic::WGS84().Inverse(a.latDeg, a.lonDeg, b.latDeg, b.lonDeg, s);
      return s;
    };
    const double ab = inverse(r.waypoints[0].position, r.waypoints[1].position);
    const double bc = inverse(r.waypoints[1].position, r.waypoints[2].position);
    const double cd = inverse(r.waypoints[2].position, r.waypoints[3].position);
    // 0.5 NM fits at B (legs of about 6 NM) but not at C: the last leg is 1.8 NM, half of it 0.9 NM.
    r.waypoints[2].turnRadiusNm = 1.2;
    TurnFit b = turnFit(r, 1);
    QVERIFY(b.fits);
    RK_COMPARE_NEAR(radToDeg(b.changeRad), -90.0, 0.01);
    RK_COMPARE_NEAR(b.legBeforeM, ab, 1e-6);
    RK_COMPARE_NEAR(b.legAfterM, bc, 1e-6);
    RK_COMPARE_NEAR(b.plannedRadiusM, 926.0, 1e-9);
    RK_COMPARE_NEAR(b.radiusM, 926.0, 1e-6);  // sailed as planned
    QCOMPARE(b.wheelOverM, b.plannedWheelOverM);
    const std::vector<TurnFit> bad = geo::turnsThatDoNotFit(r);
    QCOMPARE(bad.size(), std::size_t{1});
    const TurnFit& c = bad[0];
    QCOMPARE(c.waypoint, std::size_t{2});
    QVERIFY(!c.fits);
    RK_COMPARE_NEAR(radToDeg(c.changeRad), 90.0, 0.01);  // north, then east: to starboard
    RK_COMPARE_NEAR(c.plannedRadiusM, 2222.4, 1e-9);
    RK_COMPARE_NEAR(c.plannedWheelOverM, 2222.4, 1.0);  // R tan 45
    RK_COMPARE_NEAR(c.wheelOverM, cd / 2.0, 1e-6);      // the short leg limits it
    RK_COMPARE_NEAR(c.radiusM, cd / 2.0, 1.0);          // w / tan 45
    // The same turn on the route's default radius, once the waypoint's own is removed: it fits.
    r.waypoints[2].turnRadiusNm.reset();
    QVERIFY(geo::turnsThatDoNotFit(r).empty());
    // A radius of 0 is a corner, and a corner always fits.
    r.defaultTurnRadiusNm = 0.0;
    QVERIFY(turnFit(r, 2).fits);
    QCOMPARE(turnFit(r, 2).radiusM, 0.0);
    // Back the way she came (a course change of 180 degrees): no arc is tangent to both legs; the turn
    // is sailed in half the shorter leg on a radius of about nothing.
    r.defaultTurnRadiusNm = 0.1;
    r.waypoints[3].position = {0.0, 0.1};
    const TurnFit u = turnFit(r, 2);
    RK_COMPARE_NEAR(std::abs(radToDeg(u.changeRad)), 180.0, 0.01);
    QVERIFY(!u.fits);
    RK_COMPARE_NEAR(u.wheelOverM, bc / 2.0, 1e-6);
    QVERIFY(u.radiusM < 1.0);
    // The same reversal on a radius so small that its capped wheel-over (R tan 89.5°, 115 R = 2.1 km)
    // has room in legs of 11 km: still not sailed as planned (a radius of about nothing), so reported.
    r.defaultTurnRadiusNm = 0.01;
    const TurnFit v = turnFit(r, 2);
    QVERIFY(v.plannedWheelOverM < bc / 2.0);
    QCOMPARE(v.wheelOverM, v.plannedWheelOverM);
    QVERIFY(v.radiusM < 1e-6 * v.plannedRadiusM);
    QVERIFY(!v.fits);
    QCOMPARE(geo::turnsThatDoNotFit(r).size(), std::size_t{1});
    // 179.5 degrees: the wheel-over of 179 degrees turns on half the planned radius
    r.waypoints[3].position = {0.0, 0.1 + 0.1 * std::tan(degToRad(0.5))};
    const TurnFit h = turnFit(r, 2);
    RK_COMPARE_NEAR(std::abs(radToDeg(h.changeRad)), 179.5, 0.01);
    RK_COMPARE_NEAR(h.radiusM / h.plannedRadiusM, std::tan(degToRad(89.5)) / std::tan(degToRad(89.75)), 0.01);
    QVERIFY(!h.fits);
    // The ends have no turn.
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, turnFit(r, 0));
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, turnFit(r, 3));
  }
  void problems() {
    Route r = twoLegs(LegGeometry::RhumbLine);
    QVERIFY(r.problems().empty());
    r.waypoints[2].id = 1;
    r.waypoints[1].position.latDeg = 95.0;
    r.waypoints[2].leg.portXtlNm = -0.1;
    const std::vector<std::string> p = r.problems();
    QCOMPARE(p.size(), std::size_t{3});
    QVERIFY(p[0].find("position") != std::string::npos);
    QVERIFY(p[1].find("used twice") != std::string::npos);
    QVERIFY(p[2].find("port cross-track limit") != std::string::npos);
    Route one;
    one.waypoints = {{1, "", {0.0, 0.0}, {}, {}}};
    QVERIFY(one.problems().front().find("at least two") != std::string::npos);
  }
};

QTEST_GUILESS_MAIN(TestRoute)
#include "tst_route.moc"
