// Seed 002: the geodetic Kalman filter and least-squares fusion, beside the DRKF.
#include <QTest>

#include <GeographicLib/Constants.hpp>
#include <cmath>

#include "common/angles.h"
#include "estimation/chi_square.h"
#include "navigation/geodetic_kf.h"
#include "navigation/lsq_fusion.h"
#include "studies/own_ship_filters.h"
#include "support/compare_near.h"
#include "support/drkf_fixtures.h"

using namespace reckoner;
namespace gd = nav::geod;

class TestSeed002 : public QObject {
  Q_OBJECT
 private slots:
  void radiiOfCurvatureAreWgs84s() {
    // M(0) = a (1 - e^2), N(0) = a, and at the pole both are a / sqrt(1 - e^2).
    const double a = GeographicLib::Constants::WGS84_a(), f = GeographicLib::Constants::WGS84_f();
    const double e2 = f * (2 - f);
    RK_COMPARE_NEAR(gd::meridianRadius(0.0), a * (1 - e2), 1e-6);
    RK_COMPARE_NEAR(gd::primeVerticalRadius(0.0), a, 1e-6);
    RK_COMPARE_NEAR(gd::meridianRadius(kPi / 2), a / std::sqrt(1 - e2), 1e-6);
    RK_COMPARE_NEAR(gd::primeVerticalRadius(kPi / 2), a / std::sqrt(1 - e2), 1e-6);
  }

  void transitionJacobianMatchesNumeric_data() {
    QTest::addColumn<double>("latDeg");
    QTest::addColumn<double>("vE");
    QTest::addColumn<double>("vN");
    QTest::newRow("47 N, NE") << 47.27 << 6.0 << 6.0;
    QTest::newRow("65 N, due west") << 65.0 << -8.0 << 0.0;
    QTest::newRow("35 S, just west of north") << -35.0 << -0.3 << 7.0;
    QTest::newRow("slow: course held") << 10.0 << 0.1 << 0.2;
  }
  void transitionJacobianMatchesNumeric() {
    QFETCH(double, latDeg);
    QFETCH(double, vE);
    QFETCH(double, vN);
    gd::State x;
    x << degToRad(latDeg), degToRad(-122.4), vE, vN, wrapTwoPi(std::atan2(vE, vN)) + 0.01,
        std::hypot(vE, vN) + 0.02;
    const double T = 30.0, minSpeed = 0.5;
    const gd::Covariance F = gd::transitionJacobian(x, T, minSpeed);
    gd::Covariance Fn;
    const double h[] = {1e-8, 1e-8, 1e-6, 1e-6, 1e-6, 1e-6};
    for (int j = 0; j < gd::kStateDim; ++j) {
      gd::State xp = x, xm = x;
      xp[j] += h[j];
      xm[j] -= h[j];
      gd::State d = gd::transition(xp, T, minSpeed) - gd::transition(xm, T, minSpeed);
      d[gd::kCog] =
          angleDiff(gd::transition(xp, T, minSpeed)[gd::kCog], gd::transition(xm, T, minSpeed)[gd::kCog]);
      Fn.col(j) = d / (2 * h[j]);
    }
    for (int i = 0; i < gd::kStateDim; ++i)
      for (int j = 0; j < gd::kStateDim; ++j) {
        const test::NearContext at(QString("F(%1,%2)").arg(i).arg(j));
        RK_COMPARE_NEAR(F(i, j), Fn(i, j), 1e-6 * std::max(1.0, std::abs(Fn(i, j))));
      }
  }

  void oneDegreeOfLatitudeIsTheMeridianArc() {
    // Northward at 10 m/s for an hour from 45 N moves latitude by 36 km / M(lat) (to first order).
    gd::State x;
    x << degToRad(45.0), 0.0, 0.0, 10.0, 0.0, 10.0;
    const gd::State y = gd::transition(x, 3600.0, 0.5);
    RK_COMPARE_NEAR((y[gd::kLat] - x[gd::kLat]) * gd::meridianRadius(degToRad(45.0)), 36000.0, 1e-6);
    QCOMPARE(y[gd::kLon], 0.0);
  }

  void leastSquaresOfGpsAndDeadReckoning() {
    // Eqs. 6 and 7: with H = [I; I] and R = diag(R_GPS, R_DR), P = (R_GPS^-1 + R_DR^-1)^-1 and
    // x = P (R_GPS^-1 z_GPS + R_DR^-1 z_DR): the closed form and the general solver agree, and the
    // more precise fix weighs more.
    est::Mat<2> Rg, Rd;
    Rg << 25.0, 5.0, 5.0, 16.0;
    Rd << 400.0, -30.0, -30.0, 100.0;
    const est::Vec<2> zg(10.0, -4.0), zd(40.0, 12.0);
    const std::array<nav::PositionFix, 2> fixes{nav::PositionFix{zg, Rg}, nav::PositionFix{zd, Rd}};
    const auto g = nav::leastSquares(fixes);
    QVERIFY(g);
    const est::Mat<2> P = (Rg.inverse() + Rd.inverse()).inverse();
    const est::Vec<2> x = P * (Rg.inverse() * zg + Rd.inverse() * zd);
    QVERIFY((g->x - x).norm() < 1e-9);
    QVERIFY((g->P - P).norm() < 1e-9);
    QVERIFY((g->x - zg).norm() < (g->x - zd).norm());
    // A fix with a covariance that is not positive definite, or not finite, gives nothing.
    const std::array<nav::PositionFix, 2> bad{nav::PositionFix{zg, Rg}, nav::PositionFix{zd, -Rd}};
    QVERIFY(!nav::leastSquares(bad));
    const std::array<nav::PositionFix, 1> nan{nav::PositionFix{est::Vec<2>(std::nan(""), 0.0), Rg}};
    QVERIFY(!nav::leastSquares(nan));
  }

  void consistentBesideTheDrkfOnTheirMatchedModel() {
    // GIVEN seed 002's matched scenario (no current, white-noise log and gyro, GPS off from 300 to
    // 1200 s), 50 runs WHEN the DRKF, the geodetic KF and the least-squares navigator run on the same
    // samples THEN each one's run-averaged 4-dof NEES (position and velocity over ground) has its mean
    // inside the 95% band in both phases with at least 80% of the times inside, and their position
    // errors are within 10% of the DRKF's.
    const sim::Scenario s = test::builtinScenario("seed002-matched");
    const auto runs = studies::runOwnShipFiltersMonteCarlo(s, 50, 2, 1);
    const auto band = est::averageNeesBounds(4, 50);
    const auto st = studies::summariseOwnShipFilters(runs, fromSeconds(60.0), band);
    for (int k = 0; k < studies::kOwnShipFilterCount; ++k) {
      for (int ph = 0; ph < 2; ++ph) {
        const auto& p = st[static_cast<std::size_t>(k)][static_cast<std::size_t>(ph)];
        qInfo(
            "%-8s %s: position RMSE %.2f m, velocity %.3f m/s, mean NEES %.2f (%.0f%% in [%.2f, %.2f]), p95 "
            "%.1f m",
            studies::ownShipFilterName(static_cast<studies::OwnShipFilter>(k)),
            ph == 0 ? "GPS on " : "GPS off", p.positionRmseM, p.velocityRmseMps, p.meanNees,
            100 * p.shareInBand, band.lower, band.upper, p.p95PositionErrorM);
        QVERIFY(p.rows > 0);
        QVERIFY(band.contains(p.meanNees));
        QVERIFY(p.shareInBand >= 0.8);
        QVERIFY(p.positionRmseM < 1.1 * st[0][static_cast<std::size_t>(ph)].positionRmseM);
      }
    }
  }

  void badInputIsRefusedOrIgnored() {
    nav::GeodeticKfConfig c;
    c.accelerationQ = -1.0;
    QVERIFY(!c.check().empty());
    const geo::LocalFrame frame(47.27, -122.45);
    QVERIFY_THROWS_EXCEPTION(
        std::invalid_argument,
        nav::GeodeticKf(c, nav::GeodeticKf::initialBelief(frame, {0, 0}, 10, 5, 5, 0.5), 0));
    nav::GeodeticKf f({}, nav::GeodeticKf::initialBelief(frame, {0, 0}, 10, 5, 5, 0.5), 0);
    // A GPS fix with a NaN position is rejected, the state unchanged.
    sensors::GpsSample g;
    g.timeUs = kMicrosPerSecond;
    g.position = {std::nan(""), 0.0};
    g.positionVarM2 = 25.0;
    const std::array<sensors::OwnShipSample, 1> samples{g};
    const auto u = f.update(kMicrosPerSecond, samples, frame);
    QVERIFY(!u.position.applied());
    QVERIFY(f.belief().x.allFinite());
    QVERIFY(!f.predictTo(0));  // the past
    nav::LsqNavigatorConfig lc;
    lc.driftM2PerS = -1.0;
    QVERIFY(!lc.check().empty());
  }
};

QTEST_APPLESS_MAIN(TestSeed002)
#include "tst_seed002.moc"
