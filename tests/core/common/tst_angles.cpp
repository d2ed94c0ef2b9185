#include <QTest>

#include "common/angles.h"
#include "common/step_schedule.h"
#include "common/units.h"
#include "support/compare_near.h"

using namespace reckoner;

class TestAngles : public QObject {
  Q_OBJECT
 private slots:
  void wrapPiRange() {
    QCOMPARE(wrapPi(kPi), kPi);
    QCOMPARE(wrapPi(-kPi), kPi);  // (-pi, pi]
    QCOMPARE(wrapPi(3.0 * kPi), kPi);
    RK_COMPARE_NEAR(wrapPi(degToRad(370.0)), degToRad(10.0), 1e-12);
    RK_COMPARE_NEAR(wrapPi(degToRad(-190.0)), degToRad(170.0), 1e-12);
    RK_COMPARE_NEAR(wrapPi(1e6 * kTwoPi + 0.25), 0.25, 1e-6);
    QVERIFY(std::isnan(wrapPi(std::nan(""))));
  }
  void wrapTwoPiRange() {
    QCOMPARE(wrapTwoPi(0.0), 0.0);
    RK_COMPARE_NEAR(wrapTwoPi(-degToRad(1.0)), degToRad(359.0), 1e-12);
    QVERIFY(wrapTwoPi(kTwoPi) < 1e-15);
    for (double a = -20.0; a < 20.0; a += 0.37) {
      const double w = wrapTwoPi(a);
      QVERIFY(w >= 0.0 && w < kTwoPi);
    }
  }
  void differenceAcrossNorth() {
    // GIVEN headings either side of north WHEN differenced THEN the short way round.
    RK_COMPARE_NEAR(angleDiff(degToRad(1.0), degToRad(359.0)), degToRad(2.0), 1e-12);
    RK_COMPARE_NEAR(angleDiff(degToRad(359.0), degToRad(1.0)), -degToRad(2.0), 1e-12);
    RK_COMPARE_NEAR(angleDiff(degToRad(180.0), 0.0), kPi, 1e-12);
  }
  void bearings() {
    RK_COMPARE_NEAR(bearingOf(0.0, 1.0), 0.0, 1e-15);
    RK_COMPARE_NEAR(bearingOf(1.0, 0.0), degToRad(90.0), 1e-15);
    RK_COMPARE_NEAR(bearingOf(0.0, -1.0), degToRad(180.0), 1e-15);
    RK_COMPARE_NEAR(bearingOf(-1.0, 0.0), degToRad(270.0), 1e-15);
    RK_COMPARE_NEAR(bearingOf(-1e-9, 1.0), kTwoPi - 1e-9, 1e-15);
  }
  void units() {
    QCOMPARE(knotsToMps(1.0), 1852.0 / 3600.0);
    QCOMPARE(nmToMetres(1.0), 1852.0);
    RK_COMPARE_NEAR(mpsToKnots(knotsToMps(12.5)), 12.5, 1e-12);
  }
  void stepSchedule() {
    StepSchedule<bool> s(true);
    QVERIFY(s.addChange(10, false));
    QVERIFY(s.addChange(20, true));
    QVERIFY(!s.addChange(20, false));  // not strictly increasing
    QCOMPARE(s.at(0), true);
    QCOMPARE(s.at(9), true);
    QCOMPARE(s.at(10), false);
    QCOMPARE(s.at(19), false);
    QCOMPARE(s.at(20), true);
    QCOMPARE(s.at(1000), true);
  }
};

QTEST_APPLESS_MAIN(TestAngles)
#include "tst_angles.moc"
