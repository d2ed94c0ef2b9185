// Route geometry on the ellipsoid: leg lengths and courses against GeographicLib's own inverse
// problems, a position's place on a leg (along- and cross-track, to go) for points set off the leg
// by known distances, the wheel-over distance, and the route's own checks.
#include <QTest>

#include <GeographicLib/Geodesic.hpp>
#include <cmath>

#include "common/angles.h"
#include "common/units.h"
#include "geo/geodesic.h"
#include "geo/route.h"
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
