#include <QTest>

#include <cstdint>

#include "common/angles.h"
#include "sim/vessel_motion.h"
#include "support/compare_near.h"

using namespace reckoner;
using namespace reckoner::sim;

namespace {
const est::GaussMarkov kNoCurrent{0.0, 1.0};
}

class TestVesselTruth : public QObject {
  Q_OBJECT
 private slots:
  void tableTwoTurnKeepsSpeedAndTurnsClockwise() {
    // GIVEN Table II test 4 (7, 7) m/s turning 4.01 deg/s from 80 s WHEN time passes THEN the speed is
    // kept and the heading increases by the rate.
    VesselMotionSpec spec;
    spec.initialVelocityMps = {7.0, 7.0};
    spec.schedule.push_back({80 * kMicrosPerSecond, std::nullopt, degToRad(4.01), std::nullopt});
    VesselMotionModel m(spec, kNoCurrent, Rng(1, kStreamTruth));
    m.advanceTo(80 * kMicrosPerSecond);
    RK_COMPARE_NEAR(m.state().position.xM, 560.0, 1e-6);  // straight at 7 m/s for 80 s
    RK_COMPARE_NEAR(m.state().headingRad, degToRad(45.0), 1e-12);
    m.advanceTo(90 * kMicrosPerSecond);
    const auto& s = m.state();
    RK_COMPARE_NEAR(std::hypot(s.waterVxMps, s.waterVyMps), std::hypot(7.0, 7.0), 1e-9);
    RK_COMPARE_NEAR(angleDiff(s.headingRad, degToRad(45.0 + 40.1)), 0.0, 1e-9);
    // Centripetal acceleration |v| w, perpendicular to the velocity.
    RK_COMPARE_NEAR(std::hypot(s.accelXMps2, s.accelYMps2), std::hypot(7.0, 7.0) * degToRad(4.01), 1e-9);
    RK_COMPARE_NEAR(s.accelXMps2 * s.waterVxMps + s.accelYMps2 * s.waterVyMps, 0.0, 1e-9);
    // A full circle returns to the start of the turn (trapezoidal integration: centimetres).
    const double period = 360.0 / 4.01;
    m.advanceTo(fromSeconds(80.0 + period));
    QVERIFY2(std::hypot(m.state().position.xM - 560.0, m.state().position.yM - 560.0) < 0.05,
             qPrintable(QString("%1 %2").arg(m.state().position.xM).arg(m.state().position.yM)));
  }
  void footnoteRotationExactly() {
    // Table II footnote: Vx' = cos(w d) Vx + sin(w d) Vy, Vy' = cos(w d) Vy - sin(w d) Vx.
    VesselMotionSpec spec;
    spec.initialVelocityMps = {3.0, -2.0};
    spec.schedule.push_back({0, std::nullopt, 0.05, std::nullopt});
    VesselMotionModel m(spec, kNoCurrent, Rng(1, kStreamTruth));
    m.advanceTo(kMicrosPerSecond);
    const double c = std::cos(0.05), s = std::sin(0.05);
    RK_COMPARE_NEAR(m.state().waterVxMps, c * 3.0 + s * -2.0, 1e-12);
    RK_COMPARE_NEAR(m.state().waterVyMps, c * -2.0 - s * 3.0, 1e-12);
  }
  void velocityRampAtMaximumAcceleration() {
    VesselMotionSpec spec;
    spec.initialHeadingRad = degToRad(45.0);
    spec.maxAccelerationMps2 = 0.5;
    spec.schedule.push_back(
        {104 * kMicrosPerSecond, std::array<double, 2>{5.0, 5.0}, std::nullopt, std::nullopt});
    VesselMotionModel m(spec, kNoCurrent, Rng(1, kStreamTruth));
    m.advanceTo(104 * kMicrosPerSecond);
    QCOMPARE(m.state().waterVxMps, 0.0);
    RK_COMPARE_NEAR(m.state().headingRad, degToRad(45.0), 1e-12);  // held while stopped
    m.advanceTo(110 * kMicrosPerSecond);
    RK_COMPARE_NEAR(std::hypot(m.state().waterVxMps, m.state().waterVyMps), 3.0, 1e-9);
    RK_COMPARE_NEAR(std::hypot(m.state().accelXMps2, m.state().accelYMps2), 0.5, 1e-9);
    m.advanceTo(120 * kMicrosPerSecond);
    RK_COMPARE_NEAR(m.state().waterVxMps, 5.0, 1e-12);
    QCOMPARE(m.state().accelXMps2, 0.0);
  }
  void helmOrderTurnsAtTheRateLimitAndRampsTheSpeed() {
    // GIVEN a ship at 5 m/s heading 000 with a 0.5 deg/s turn and 0.05 m/s^2 speed limit WHEN ordered to
    // 090 at 8 m/s at 10 s THEN the heading changes by 0.5 deg/s, the speed by 0.05 m/s^2, both settle
    // on the order, and the acceleration output is the derivative of the velocity.
    VesselMotionSpec spec;
    spec.initialVelocityMps = {0.0, 5.0};
    spec.maxAccelerationMps2 = 0.05;
    spec.maxTurnRateRadPerS = degToRad(0.5);
    KinematicEvent e;
    e.timeUs = 10 * kMicrosPerSecond;
    e.order = HelmOrder{degToRad(90.0), 8.0};
    spec.schedule.push_back(e);
    VesselMotionModel m(spec, kNoCurrent, Rng(1, kStreamTruth));
    m.advanceTo(10 * kMicrosPerSecond);
    QVERIFY(m.order().has_value());
    m.advanceTo(50 * kMicrosPerSecond);
    const auto& s = m.state();
    RK_COMPARE_NEAR(radToDeg(s.headingRad), 20.0, 1e-6);
    RK_COMPARE_NEAR(std::hypot(s.waterVxMps, s.waterVyMps), 7.0, 1e-9);
    const double vx = s.waterVxMps, vy = s.waterVyMps;
    m.advanceTo(fromSeconds(50.1));
    RK_COMPARE_NEAR((m.state().waterVxMps - vx) / 0.1, m.state().accelXMps2, 1e-9);
    RK_COMPARE_NEAR((m.state().waterVyMps - vy) / 0.1, m.state().accelYMps2, 1e-9);
    m.advanceTo(200 * kMicrosPerSecond);  // 180 s of turning needs 180 s; speed settled after 60 s
    RK_COMPARE_NEAR(angleDiff(m.state().headingRad, degToRad(90.0)), 0.0, 1e-9);
    RK_COMPARE_NEAR(m.state().waterVxMps, 8.0, 1e-9);
    QCOMPARE(m.state().accelXMps2, 0.0);
  }
  void thousandsOfOrdersMoveTheShipAsTheSameScheduleGivenAhead() {
    // GIVEN a ship with a random acceleration WHEN an autopilot orders a new heading every 2 s for
    // 6000 s (3000 orders: the model drops spent ones as it goes) THEN it is where the same ship with the
    // same 3000 orders in its schedule from the start is, bit for bit.
    VesselMotionSpec spec;
    spec.initialVelocityMps = {0.0, 5.0};
    spec.maxAccelerationMps2 = 0.05;
    spec.maxTurnRateRadPerS = degToRad(0.5);
    spec.randomAcceleration = est::GaussMarkov{0.01, 0.05};
    std::vector<KinematicEvent> orders;
    for (int k = 1; k <= 3000; ++k) {
      KinematicEvent e;
      e.timeUs = std::int64_t{k} * 2 * kMicrosPerSecond + 1;
      e.order = HelmOrder{degToRad(std::fmod(7.0 * k, 360.0)), 4.0 + (k % 5)};
      orders.push_back(e);
    }
    VesselMotionSpec ahead = spec;
    ahead.schedule = orders;
    VesselMotionModel a(ahead, kNoCurrent, Rng(3, kStreamTruth));
    VesselMotionModel b(spec, kNoCurrent, Rng(3, kStreamTruth));
    for (const KinematicEvent& e : orders) {
      b.advanceTo(e.timeUs - 1);
      QVERIFY(b.overrideFrom(e));
    }
    a.advanceTo(6010 * kMicrosPerSecond);
    b.advanceTo(6010 * kMicrosPerSecond);
    QCOMPARE(b.state().position.xM, a.state().position.xM);
    QCOMPARE(b.state().position.yM, a.state().position.yM);
    QCOMPARE(b.state().headingRad, a.state().headingRad);
  }
  void helmOrderTakesTheShorterWayRound() {
    // 350 -> 010 turns starboard through north (the 359 -> 1 degree crossing).
    VesselMotionSpec spec;
    spec.initialVelocityMps = {5.0 * std::sin(degToRad(350.0)), 5.0 * std::cos(degToRad(350.0))};
    spec.maxTurnRateRadPerS = degToRad(1.0);
    KinematicEvent e;
    e.order = HelmOrder{degToRad(10.0), 5.0};
    spec.schedule.push_back(e);
    VesselMotionModel m(spec, kNoCurrent, Rng(1, kStreamTruth));
    m.advanceTo(5 * kMicrosPerSecond);
    RK_COMPARE_NEAR(angleDiff(m.state().headingRad, degToRad(355.0)), 0.0, 1e-9);
    m.advanceTo(15 * kMicrosPerSecond);
    RK_COMPARE_NEAR(angleDiff(m.state().headingRad, degToRad(5.0)), 0.0, 1e-9);
  }
  void operatorOverrideReplacesTheRestOfTheScript() {
    VesselMotionSpec spec;
    spec.initialVelocityMps = {0.0, 5.0};
    spec.schedule.push_back({100 * kMicrosPerSecond, std::nullopt, degToRad(1.0), std::nullopt});
    VesselMotionModel m(spec, kNoCurrent, Rng(1, kStreamTruth));
    m.advanceTo(50 * kMicrosPerSecond);
    KinematicEvent e;
    e.timeUs = 20 * kMicrosPerSecond;
    QVERIFY(!m.overrideFrom(e));  // in the past
    e.timeUs = 50 * kMicrosPerSecond + 1;
    e.order = HelmOrder{0.0, 3.0};
    QVERIFY(m.overrideFrom(e));
    m.advanceTo(150 * kMicrosPerSecond);
    RK_COMPARE_NEAR(m.state().headingRad, 0.0, 1e-9);  // the scripted turn at 100 s is gone
    RK_COMPARE_NEAR(m.state().waterVyMps, 3.0, 1e-9);
  }
  void instantaneousWhenNoLimit() {
    VesselMotionSpec spec;
    spec.schedule.push_back(
        {10 * kMicrosPerSecond, std::array<double, 2>{1.0, 2.0}, std::nullopt, std::nullopt});
    VesselMotionModel m(spec, kNoCurrent, Rng(1, kStreamTruth));
    m.advanceTo(10 * kMicrosPerSecond);
    QCOMPARE(m.state().waterVxMps, 1.0);
    QCOMPARE(m.state().waterVyMps, 2.0);
  }
  void currentIsStationaryGaussMarkov() {
    // GIVEN a current with sigma 0.5 m/s WHEN sampled over many seeds at two times THEN its variance
    // is sigma^2 both times and its correlation exp(-beta dt).
    const est::GaussMarkov current{0.5, 0.1};
    constexpr int n = 4000;
    double v0 = 0, v1 = 0, c01 = 0;
    for (int seed = 0; seed < n; ++seed) {
      VesselMotionModel m(VesselMotionSpec{}, current, Rng(static_cast<std::uint64_t>(seed), kStreamTruth));
      const double a = m.state().currentXMps;
      m.advanceTo(5 * kMicrosPerSecond);
      const double b = m.state().currentXMps;
      v0 += a * a;
      v1 += b * b;
      c01 += a * b;
      // Position integrates the current: the ship has no water velocity.
      QCOMPARE(m.state().waterVxMps, 0.0);
    }
    RK_COMPARE_NEAR(v0 / n, 0.25, 0.02);
    RK_COMPARE_NEAR(v1 / n, 0.25, 0.02);
    RK_COMPARE_NEAR(c01 / v0, std::exp(-0.5), 0.04);
  }
  void sameSeedSameTruth() {
    VesselMotionSpec spec;
    spec.initialVelocityMps = {4.0, 1.0};
    spec.randomAcceleration = est::GaussMarkov{0.1, 0.2};
    VesselMotionModel a(spec, {0.3, 0.2}, Rng(7, kStreamTruth)), b(spec, {0.3, 0.2}, Rng(7, kStreamTruth));
    a.advanceTo(fromSeconds(123.4));
    for (int k = 1; k <= 1234; ++k) b.advanceTo(std::int64_t{k} * 100'000);
    QCOMPARE(a.state().position.xM, b.state().position.xM);
    QCOMPARE(a.state().accelYMps2, b.state().accelYMps2);
  }
};

QTEST_APPLESS_MAIN(TestVesselTruth)
#include "tst_vessel_motion.moc"
