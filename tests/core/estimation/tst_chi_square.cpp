#include <QTest>

#include "common/rng.h"
#include "estimation/chi_square.h"
#include "estimation/nis_window.h"
#include "support/compare_near.h"

using namespace reckoner::est;

class TestChiSquare : public QObject {
  Q_OBJECT
 private slots:
  void quantilesMatchTables_data() {
    QTest::addColumn<double>("p");
    QTest::addColumn<double>("dof");
    QTest::addColumn<double>("expected");
    // Reference values from standard chi-square tables (Abramowitz & Stegun 26.4).
    QTest::newRow("0.95,1") << 0.95 << 1.0 << 3.841459;
    QTest::newRow("0.99,2") << 0.99 << 2.0 << 9.210340;
    QTest::newRow("0.9999,1") << 0.9999 << 1.0 << 15.136705;
    QTest::newRow("0.9999,2") << 0.9999 << 2.0 << 18.420681;
    QTest::newRow("0.025,10") << 0.025 << 10.0 << 3.246973;
    QTest::newRow("0.975,10") << 0.975 << 10.0 << 20.483177;
    QTest::newRow("0.5,100") << 0.5 << 100.0 << 99.334129;
    QTest::newRow("0.001,3") << 0.001 << 3.0 << 0.024297;
  }
  void quantilesMatchTables() {
    QFETCH(double, p);
    QFETCH(double, dof);
    QFETCH(double, expected);
    const double q = chiSquareQuantile(p, dof);
    RK_COMPARE_NEAR(q, expected, 1e-5 * std::max(1.0, expected));
    RK_COMPARE_NEAR(chiSquareCdf(q, dof), p, 1e-10);
  }
  void roundTripAcrossDegreesOfFreedom() {
    for (double dof : {0.5, 1.0, 2.0, 7.0, 60.0, 550.0, 600.0, 5000.0})
      for (double p : {1e-6, 0.025, 0.3, 0.5, 0.975, 0.999999})
        RK_COMPARE_NEAR(chiSquareCdf(chiSquareQuantile(p, dof), dof), p, 1e-9);
  }
  void averageNeesBoundsOfTheIssues() {
    // 50 runs of an 11-state filter: the bounds quoted for the DRKF; of a 12-state one, the TTKF's.
    const auto b11 = averageNeesBounds(11, 50);
    RK_COMPARE_NEAR(b11.lower, 9.74, 0.005);
    RK_COMPARE_NEAR(b11.upper, 12.34, 0.005);
    const auto b12 = averageNeesBounds(12, 50);
    RK_COMPARE_NEAR(b12.lower, 10.68, 0.005);
    RK_COMPARE_NEAR(b12.upper, 13.40, 0.005);
    QVERIFY(b11.contains(11.0) && !b11.contains(12.5) && !b11.contains(9.7));
  }
  void invalidArguments() {
    QVERIFY(std::isnan(chiSquareQuantile(0.0, 2.0)));
    QVERIFY(std::isnan(chiSquareQuantile(1.0, 2.0)));
    QVERIFY(std::isnan(chiSquareQuantile(0.5, -1.0)));
    QVERIFY(std::isnan(regularisedGammaP(-1.0, 1.0)));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, averageNeesBounds(0, 50));
  }
  void nisWindowFlagsNoiseLargerThanConfigured() {
    // GIVEN 2-dof innovations drawn with the covariance the filter claims WHEN windows of 60 are tested
    // at 99% THEN about 1% of windows fall outside the band; with the true sd twice the claimed one every
    // window is above it, and with half of it every window is below.
    auto run = [](double sdRatio) {
      reckoner::Rng rng(5, 1);
      reckoner::est::NisWindow w(60, 0.99);
      for (int k = 0; k < 60 * 400; ++k) {
        const double a = sdRatio * rng.normal(), b = sdRatio * rng.normal();
        w.add(a * a + b * b, 2);
      }
      return w.counts();
    };
    const auto ok = run(1.0), noisy = run(2.0), quiet = run(0.5);
    QCOMPARE(ok.windows, 400L);
    QVERIFY2(ok.above + ok.below <= 12,
             qPrintable(QString("%1 above, %2 below").arg(ok.above).arg(ok.below)));
    RK_COMPARE_NEAR(ok.meanPerDof(), 1.0, 0.03);
    QCOMPARE(noisy.above, 400L);
    QCOMPARE(quiet.below, 400L);
    reckoner::est::NisWindow w;
    w.add(std::nan(""), 2);
    w.add(1.0, 0);
    QCOMPARE(w.counts().dof, 0L);
  }
};

QTEST_APPLESS_MAIN(TestChiSquare)
#include "tst_chi_square.moc"
