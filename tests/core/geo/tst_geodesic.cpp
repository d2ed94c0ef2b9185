// Geodesic range and bearing against published values: a degree of the equator and of the meridian
// (from the WGS-84 constants), and Karney's JFK-to-Heathrow example; directions; bad input.
#include <QTest>

#include <cmath>

#include "common/angles.h"
#include "geo/geodesic.h"
#include "support/compare_near.h"

using namespace reckoner;
using namespace reckoner::geo;

class TestGeodesic : public QObject {
  Q_OBJECT
 private slots:
  void knownDistances() {
    // a degree of longitude on the equator is a * pi / 180
    const RangeBearing eq = rangeBearing({0.0, 10.0}, {0.0, 11.0});
    RK_COMPARE_NEAR(eq.rangeM, 6378137.0 * kPi / 180.0, 1e-3);
    RK_COMPARE_NEAR(radToDeg(eq.trueBearingRad), 90.0, 1e-9);
    // the first degree of latitude from the equator: 110 574.389 m on WGS-84
    const RangeBearing mer = rangeBearing({0.0, 0.0}, {1.0, 0.0});
    RK_COMPARE_NEAR(mer.rangeM, 110574.389, 1e-2);
    RK_COMPARE_NEAR(mer.trueBearingRad, 0.0, 1e-12);
    // JFK (40.6 N, 73.8 W) to LHR (51.6 N, 0.5 W): 5 551 759.400 m, initial azimuth 51.198883 deg
    const RangeBearing jfk = rangeBearing({40.6, -73.8}, {51.6, -0.5});
    RK_COMPARE_NEAR(jfk.rangeM, 5551759.400, 1e-2);
    RK_COMPARE_NEAR(radToDeg(jfk.trueBearingRad), 51.198883, 1e-6);
  }
  void directionsAndWrap() {
    RK_COMPARE_NEAR(radToDeg(rangeBearing({50.0, 0.0}, {49.0, 0.0}).trueBearingRad), 180.0, 1e-9);
    RK_COMPARE_NEAR(radToDeg(rangeBearing({0.0, 1.0}, {0.0, 0.0}).trueBearingRad), 270.0, 1e-9);
    // across the antimeridian: short way, westwards
    const RangeBearing w = rangeBearing({0.0, -179.5}, {0.0, 179.5});
    RK_COMPARE_NEAR(w.rangeM, 6378137.0 * kPi / 180.0, 1e-3);
    RK_COMPARE_NEAR(radToDeg(w.trueBearingRad), 270.0, 1e-9);
    QCOMPARE(rangeBearing({10.0, 10.0}, {10.0, 10.0}).rangeM, 0.0);
  }
  void badInputIsNaN() {
    QVERIFY(std::isnan(rangeBearing({91.0, 0.0}, {0.0, 0.0}).rangeM));
    QVERIFY(std::isnan(rangeBearing({0.0, 0.0}, {0.0, std::nan("")}).trueBearingRad));
  }
};

QTEST_GUILESS_MAIN(TestGeodesic)
#include "tst_geodesic.moc"
