#include <QTest>

#include "support/drkf_fixtures.h"

#include "common/angles.h"
#include "sensors/own_ship_simulators.h"
#include "support/compare_near.h"

using namespace reckoner;
using namespace reckoner::sensors;

class TestOwnShipSensors : public QObject {
  Q_OBJECT
 private slots:
  void gpsNoiseAndTrueNorthVelocity() {
    GpsSpec spec;
    spec.positionVarM2 = 100.0;
    spec.velocityVarM2PerS2 = 0.04;
    GpsSimulator gps(spec, Rng(1, kStreamGps));
    // Grid north velocity 5 m/s where grid north is 2 deg clockwise of true north and scale 0.9996.
    const geo::GridInfo grid{degToRad(2.0), 0.9996};
    constexpr int n = 20000;
    double sx = 0, sxx = 0, se = 0, sn = 0, see = 0;
    for (int i = 0; i < n; ++i) {
      const auto s = gps.measure(i, {100.0, 200.0}, 0.0, 5.0, grid);
      sx += s.position.xM - 100.0;
      sxx += (s.position.xM - 100.0) * (s.position.xM - 100.0);
      se += s.velEastMps;
      sn += s.velNorthMps;
      see += s.velEastMps * s.velEastMps;
      QCOMPARE(s.positionVarM2, 100.0);
      QVERIFY(s.hasVelocity);
    }
    RK_COMPARE_NEAR(sx / n, 0.0, 0.3);
    RK_COMPARE_NEAR(sxx / n, 100.0, 4.0);
    // True bearing = grid bearing + convergence: 2 deg east of north; true length = grid / scale.
    const double speed = 5.0 / 0.9996;
    RK_COMPARE_NEAR(se / n, speed * std::sin(degToRad(2.0)), 0.005);
    RK_COMPARE_NEAR(sn / n, speed * std::cos(degToRad(2.0)), 0.005);
    RK_COMPARE_NEAR(see / n - (se / n) * (se / n), 0.04, 0.002);
  }
  void gyroReportsTrueHeading() {
    GyroSpec spec;
    spec.sdRad = degToRad(0.001);
    GyroSimulator gyro(spec, Rng(2, kStreamGyro), 0, Rng(2, kStreamGyroBias));
    const auto s = gyro.measure(0, degToRad(359.5), {degToRad(1.0), 1.0});
    RK_COMPARE_NEAR(angleDiff(s.headingRad, degToRad(0.5)), 0.0, degToRad(0.01));
    QVERIFY(s.headingRad >= 0.0 && s.headingRad < kTwoPi);
  }
  void loranErrorIsGaussMarkov() {
    // GIVEN a Loran-C with a Gauss-Markov error WHEN sampled for a long time THEN its variance is the
    // stationary sigma^2 and its lag-tau autocorrelation exp(-beta tau).
    LoranSpec spec;
    spec.error = {20.0, 0.25};
    spec.whiteVarM2 = 1e-6;
    LoranSimulator loran(spec, Rng(3, kStreamLoran), 0);
    constexpr int n = 200000;
    std::vector<double> e(n);
    for (int i = 0; i < n; ++i)
      e[static_cast<std::size_t>(i)] = loran.measure(i * kMicrosPerSecond, {0.0, 0.0}).position.xM;
    double var = 0, lag1 = 0, lag4 = 0;
    for (int i = 0; i + 4 < n; ++i) {
      const auto k = static_cast<std::size_t>(i);
      var += e[k] * e[k];
      lag1 += e[k] * e[k + 1];
      lag4 += e[k] * e[k + 4];
    }
    RK_COMPARE_NEAR(var / n, 400.0, 20.0);
    RK_COMPARE_NEAR(lag1 / var, std::exp(-0.25), 0.02);
    RK_COMPARE_NEAR(lag4 / var, std::exp(-1.0), 0.03);
  }
  void speedlogModes() {
    SpeedlogSpec spec;
    spec.error = {0.0, 0.5};
    spec.whiteVarM2PerS2 = 1e-12;
    SpeedlogSimulator log(spec, Rng(4, kStreamSpeedlog), 0, Rng(4, kStreamLogScale));
    const auto g = log.measure(5, 7.0, 6.0, SpeedlogMode::GroundLock, {0.0, 0.9996});
    QCOMPARE(g.mode, SpeedlogMode::GroundLock);
    RK_COMPARE_NEAR(g.speedMps, 7.0 / 0.9996, 1e-5);
    const auto b = log.measure(10, 7.0, 6.0, SpeedlogMode::BottomLock, {0.0, 0.9996});
    QCOMPARE(b.mode, SpeedlogMode::BottomLock);
    RK_COMPARE_NEAR(b.speedMps, 6.0 / 0.9996, 1e-5);
  }
  void gaussMarkovSignalAdvancesOnlyForward() {
    Rng rng(5, 5);
    GaussMarkovSignal s({1.0, 0.1}, rng, 100);
    const double v = s.value();
    s.advanceTo(50, rng);
    QCOMPARE(s.value(), v);
    s.advanceTo(100, rng);
    QCOMPARE(s.value(), v);
  }
};

QTEST_APPLESS_MAIN(TestOwnShipSensors)
#include "tst_own_ship_sensors.moc"
