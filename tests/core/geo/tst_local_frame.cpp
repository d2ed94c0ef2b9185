#include <QTest>

#include <GeographicLib/Geodesic.hpp>

#include "common/angles.h"
#include "geo/local_frame.h"
#include "support/compare_near.h"

using namespace reckoner;

class TestLocalFrame : public QObject {
  Q_OBJECT
 private slots:
  void originIsZero() {
    const geo::LocalFrame f(47.27, -122.45);
    QCOMPARE(f.utmZone(), 10);
    QCOMPARE(f.centralMeridianDeg(), -123.0);
    const auto p = f.toLocal({47.27, -122.45});
    RK_COMPARE_NEAR(p.xM, 0.0, 1e-6);
    RK_COMPARE_NEAR(p.yM, 0.0, 1e-6);
  }
  void roundTrip() {
    const geo::LocalFrame f(47.27, -122.45);
    for (double dlat = -0.5; dlat <= 0.5; dlat += 0.25) {
      for (double dlon = -0.7; dlon <= 0.7; dlon += 0.35) {
        const geo::GeoPoint g{47.27 + dlat, -122.45 + dlon};
        const auto back = f.toGeodetic(f.toLocal(g));
        RK_COMPARE_NEAR(back.latDeg, g.latDeg, 1e-9);
        RK_COMPARE_NEAR(back.lonDeg, g.lonDeg, 1e-9);
      }
    }
  }
  void gridAxesPointEastAndNorth() {
    const geo::LocalFrame f(49.29, -123.0);  // on the central meridian: no convergence at the origin
    const auto n = f.toLocal({49.30, -123.0});
    const auto e = f.toLocal({49.29, -122.99});
    QVERIFY(n.yM > 1000.0);
    RK_COMPARE_NEAR(n.xM, 0.0, 1e-6);
    QVERIFY(e.xM > 700.0);
    RK_COMPARE_NEAR(e.yM, 0.0, 10.0);
  }
  void convergenceAndScaleAgreeWithGeodesics() {
    // East of the central meridian in the north: grid north lies clockwise of true north (gamma > 0).
    const geo::LocalFrame f(47.27, -122.45);
    const geo::GeoPoint p{47.30, -122.30};
    const auto gp = f.toLocal(p);
    const auto info = f.gridInfo(gp);
    QVERIFY(info.convergenceRad > 0.0);
    // A short step due true north has grid bearing -gamma.
    const auto q = f.toLocal({p.latDeg + 0.001, p.lonDeg});
    const double gridBearing = std::atan2(q.xM - gp.xM, q.yM - gp.yM);
    RK_COMPARE_NEAR(angleDiff(gridBearing, -info.convergenceRad), 0.0, 1e-6);
    // Grid length / geodesic length is the point scale.
    double s12 = 0.0;
    GeographicLib::Geodesic::WGS84().Inverse(p.latDeg, p.lonDeg, p.latDeg + 0.001, p.lonDeg, s12);
    const double grid = std::hypot(q.xM - gp.xM, q.yM - gp.yM);
    RK_COMPARE_NEAR(grid / s12, info.scale, 1e-6);
    QVERIFY(info.scale > 0.9996 && info.scale < 1.001);
  }
  void badInput() {
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, geo::LocalFrame(85.0, 0.0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, geo::LocalFrame(std::nan(""), 0.0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, geo::LocalFrame(10.0, 200.0));
    const geo::LocalFrame f(47.27, -122.45);
    QVERIFY(std::isnan(f.toLocal({std::nan(""), 0.0}).xM));
    QVERIFY(std::isnan(f.toLocal({47.0, 60.0}).xM));  // half the world away from the zone
    QVERIFY(std::isnan(f.toGeodetic({std::nan(""), 0.0}).latDeg));
    QVERIFY(std::isnan(f.gridInfo({0.0, std::nan("")}).convergenceRad));
  }
};

QTEST_APPLESS_MAIN(TestLocalFrame)
#include "tst_local_frame.moc"
