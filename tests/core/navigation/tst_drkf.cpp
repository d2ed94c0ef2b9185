#include <QTest>

#include "common/angles.h"
#include "navigation/drkf.h"
#include "support/compare_near.h"
#include "support/drkf_fixtures.h"

using namespace reckoner;
using namespace reckoner::nav;
using namespace reckoner::est::drkf;
using sensors::GpsSample;
using sensors::GyroSample;
using sensors::OwnShipSample;
using sensors::SpeedlogSample;

namespace {
DrkfConfig config() {
  DrkfConfig c;
  c.process = test::tableOneProcess();
  return c;
}

/// A filter at the origin steaming with water velocity (vx, vy), in a frame whose origin lies on the
/// central meridian (no convergence) unless lonDeg says otherwise.
Drkf makeFilter(double vx, double vy, double lonDeg = -123.0) {
  Belief b;
  b.x.setZero();
  b.x[kVelX] = vx;
  b.x[kVelY] = vy;
  b.P = initialCovariance(config().process, 30.0, 0.5);
  return Drkf(config(), geo::LocalFrame(49.0, lonDeg), b, 0);
}

const est::BlockReport* blockOf(const DrkfUpdateReport& r, DrkfBlock b) {
  return r.block(b);
}
// A pointer into a temporary report dangles at the end of its statement (ASan's stack-use-after-scope).
const est::BlockReport* blockOf(DrkfUpdateReport&& r, DrkfBlock b) = delete;
}  // namespace

class TestDrkf : public QObject {
  Q_OBJECT
 private slots:
  void headingAloneLeavesTheSpeedAlone() {
    // GIVEN the ship motion model, a ship at 5 m/s whose speed is uncertain by 1 m/s and whose turn
    // rate and along-track acceleration are correlated with its velocity (after a minute of prediction)
    // WHEN headings alone arrive, 0.5 deg to starboard of its course THEN the velocity turns towards them,
    // its length stays what the prediction made it, the along-track acceleration is untouched, and P
    // stays symmetric positive definite; a heading of a ship stopped is refused as degenerate.
    DrkfConfig c = config();
    c.process.ship.enabled = true;
    Belief b;
    b.x.setZero();
    b.x[kVelY] = 5.0;
    b.x[kAlongAccel] = 0.002;
    b.x[kTurnRate] = 0.001;
    b.P = initialCovariance(c.process, 30.0, 1.0);
    Drkf f(c, geo::LocalFrame(49.0, -123.0), b, 0);
    QVERIFY(f.predictTo(60 * kMicrosPerSecond));
    for (int k = 1; k <= 10; ++k) {
      if (k == 1) {  // a minute without a heading: the first one re-anchors the direction
        const TimeUs t = 61 * kMicrosPerSecond;
        QVERIFY(f.predictTo(t));
        const double speed = std::hypot(f.belief().x[kVelX], f.belief().x[kVelY]);
        const std::vector<OwnShipSample> s{GyroSample{t, degToRad(10.0), 1e-6}};
        const DrkfUpdateReport r = f.update(t, s);
        const auto* g = blockOf(r, kGyro);
        QVERIFY(g && g->status == est::UpdateStatus::AcceptedForced);
        const State& x = f.belief().x;
        RK_COMPARE_NEAR(std::hypot(x[kVelX], x[kVelY]), speed, 1e-9);
        // the velocity turned to the gyro's heading less the heading bias
        RK_COMPARE_NEAR(angleDiff(bearingOf(x[kVelX], x[kVelY]), degToRad(10.0) - x[kHeadingBias]), 0.0,
                        1e-5);
        QVERIFY(est::isPositiveDefinite(f.belief().P));
        continue;
      }
      const TimeUs t = (60 + k) * kMicrosPerSecond;
      QVERIFY(f.predictTo(t));
      const State before = f.belief().x;
      const double course = bearingOf(before[kVelX], before[kVelY]);
      const std::vector<OwnShipSample> s{
          GyroSample{t, wrapTwoPi(course + degToRad(0.5)), degToRad(0.3) * degToRad(0.3)}};
      const auto r = f.update(t, s);
      const auto* g = blockOf(r, kGyro);
      QVERIFY(g);
      QVERIFY2(g->status == est::UpdateStatus::Accepted, std::string(est::statusName(g->status)).c_str());
      const State& x = f.belief().x;
      RK_COMPARE_NEAR(std::hypot(x[kVelX], x[kVelY]), std::hypot(before[kVelX], before[kVelY]), 1e-3);
      QCOMPARE(x[kAlongAccel], before[kAlongAccel]);
      QVERIFY(angleDiff(bearingOf(x[kVelX], x[kVelY]), course) > 0.0);  // turned to starboard
      QVERIFY(est::isPositiveDefinite(f.belief().P));
      QVERIFY((f.belief().P - f.belief().P.transpose()).cwiseAbs().maxCoeff() == 0.0);
    }
    Belief stopped = b;
    stopped.x[kVelY] = 0.1;
    Drkf g(c, geo::LocalFrame(49.0, -123.0), stopped, 0);
    const std::vector<OwnShipSample> s{GyroSample{kMicrosPerSecond, 0.0, 1e-4}};
    const auto r = g.update(kMicrosPerSecond, s);
    QVERIFY(blockOf(r, kGyro) && blockOf(r, kGyro)->status == est::UpdateStatus::RejectedDegenerate);
  }
  void gyroAcrossNorthPullsTheShortWay() {
    // GIVEN a ship heading 359 deg WHEN the gyro says 1 deg THEN the innovation is +2 deg and the
    // estimated heading moves towards north, not the long way round through south.
    Drkf f = makeFilter(-6.0 * std::sin(degToRad(1.0)), 6.0 * std::cos(degToRad(1.0)));
    const std::vector<OwnShipSample> s{
        GyroSample{kMicrosPerSecond, degToRad(1.0), degToRad(1.0) * degToRad(1.0)}};
    const auto r = f.update(kMicrosPerSecond, s);
    const auto* g = blockOf(r, kGyro);
    QVERIFY(g && g->status == est::UpdateStatus::Accepted);
    // (1e-6 rad: after the 1 s prediction the ship is 0.1 m off the central meridian, convergence 2e-8)
    RK_COMPARE_NEAR(r.joint.innovation[g->row], degToRad(2.0), 1e-6);
    QVERIFY(r.joint.nis < 1.0);  // +2 deg against a prior heading sd of ~5 deg; -358 deg would be gated out
    const double heading = bearingOf(f.belief().x[kVelX], f.belief().x[kVelY]);
    QVERIFY2(heading > degToRad(359.0) || heading < degToRad(1.0),
             qPrintable(QString::number(radToDeg(heading))));
  }
  void convergenceIsRemovedFromTrueNorthMeasurements() {
    // GIVEN an origin 0.55 deg east of the central meridian (grid convergence ~0.4 deg) and a ship
    // going grid north WHEN the gyro reports the TRUE heading (grid + convergence) THEN the
    // innovation is zero.
    Drkf f = makeFilter(0.0, 6.0, -122.45);
    const double gamma = f.frame().gridInfo({0.0, 0.0}).convergenceRad;
    QVERIFY(gamma > degToRad(0.3));
    const std::vector<OwnShipSample> s{GyroSample{kMicrosPerSecond, gamma, 1e-6}};
    const auto r = f.update(kMicrosPerSecond, s);
    RK_COMPARE_NEAR(r.joint.nis, 0.0, 1e-3);
  }
  void stationaryShipSkipsHeadingAndSpeed() {
    Drkf f = makeFilter(0.0, 0.0);
    const std::vector<OwnShipSample> s{
        GyroSample{kMicrosPerSecond, 1.0, 1e-4},
        SpeedlogSample{kMicrosPerSecond, 0.1, sensors::SpeedlogMode::BottomLock, 0.01}};
    const auto r = f.update(kMicrosPerSecond, s);
    QCOMPARE(blockOf(r, kGyro)->status, est::UpdateStatus::RejectedDegenerate);
    QCOMPARE(blockOf(r, kSpeedlog)->status, est::UpdateStatus::RejectedDegenerate);
    QCOMPARE(r.dim, 0);
  }
  void outlierGatedThenReopened() {
    // GIVEN a filter that has lost its position (every GPS fix 2 km off) WHEN the fixes keep coming
    // THEN they are gated out for gate_reopen_s (10 s), then one is applied ungated after inflating the
    // position uncertainty until it is consistent: the filter jumps to GPS and accepts the next fix.
    Drkf f = makeFilter(0.0, 5.0);
    int rejected = 0;
    for (int k = 1; k <= 13; ++k) {
      const TimeUs t = k * kMicrosPerSecond;
      const std::vector<OwnShipSample> s{GpsSample{t, {2000.0, 5.0 * k}, 100.0, false, 0, 0, 0}};
      const auto r = f.update(t, s);
      const auto status = blockOf(r, kGpsPosition)->status;
      if (k <= 10) QCOMPARE(status, est::UpdateStatus::RejectedGate);
      if (k == 11) {
        QCOMPARE(status, est::UpdateStatus::AcceptedForced);
        RK_COMPARE_NEAR(f.belief().x[kPosX], 2000.0, 60.0);
        QVERIFY(std::sqrt(f.belief().P(kPosX, kPosX)) > 9.0);  // no tighter than the fix itself
      }
      if (k >= 12) QCOMPARE(status, est::UpdateStatus::Accepted);
      rejected += status == est::UpdateStatus::RejectedGate;
    }
    QCOMPARE(rejected, 10);
    QCOMPARE(f.counters().byStatus[kGpsPosition][static_cast<int>(est::UpdateStatus::AcceptedForced)], 1L);
  }
  void gyroIsNeverForced() {
    Drkf f = makeFilter(0.0, 6.0);
    for (int k = 1; k <= 30; ++k) {
      const TimeUs t = k * kMicrosPerSecond;
      const std::vector<OwnShipSample> s{GyroSample{t, degToRad(120.0), 1e-4}};
      const auto r = f.update(t, s);
      QVERIFY(blockOf(r, kGyro)->status != est::UpdateStatus::AcceptedForced);
    }
  }
  void staleAndNonFiniteSamples() {
    Drkf f = makeFilter(0.0, 5.0);
    QVERIFY(f.predictTo(10 * kMicrosPerSecond));
    QVERIFY(!f.predictTo(5 * kMicrosPerSecond));
    const std::vector<OwnShipSample> old{GpsSample{5 * kMicrosPerSecond, {0, 0}, 100.0, false, 0, 0, 0}};
    const auto r = f.update(5 * kMicrosPerSecond, old);
    QCOMPARE(r.joint.status, est::UpdateStatus::RejectedStale);
    QCOMPARE(f.timeUs(), 10 * kMicrosPerSecond);
    // A sample stamped differently from the epoch is skipped and counted.
    const std::vector<OwnShipSample> mixed{GpsSample{12 * kMicrosPerSecond, {0, 50}, 100.0, false, 0, 0, 0},
                                           GpsSample{11 * kMicrosPerSecond, {0, 55}, 100.0, false, 0, 0, 0}};
    f.update(11 * kMicrosPerSecond, mixed);
    QCOMPARE(f.counters().staleSamples, 2L);
    const std::vector<OwnShipSample> nan{
        GpsSample{13 * kMicrosPerSecond, {std::nan(""), 0}, 100.0, false, 0, 0, 0}};
    const auto before = f.belief();
    const auto rn = f.update(13 * kMicrosPerSecond, nan);
    QCOMPARE(blockOf(rn, kGpsPosition)->status, est::UpdateStatus::RejectedNonFinite);
    QVERIFY(std::isfinite(f.belief().P.sum()));
    QVERIFY((f.belief().x - before.x).norm() > 0.0);  // predicted on, but nothing applied
    QCOMPARE(rn.dim, 0);
  }
  void badConfigurationThrows() {
    Belief b;
    b.P = Covariance::Identity();
    b.P(3, 3) = -1.0;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, Drkf(config(), geo::LocalFrame(49.0, -123.0), b, 0));
    DrkfConfig c = config();
    c.gateProbability = 1.0;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, Drkf(c, geo::LocalFrame(49.0, -123.0), Belief{}, 0));
  }
  void longGapsArePredictedExactly_data() {
    QTest::addColumn<double>("gapS");
    QTest::newRow("200 s") << 200.0;
    QTest::newRow("one hour") << 3600.0;
  }
  void longGapsArePredictedExactly() {
    // GIVEN a filter WHEN predicted across a gap in one call THEN the belief is the one of predicting
    // second by second (Van Loan over the whole gap lost Q to cancellation: at 200 s the covariance was
    // not positive definite and no update was ever applied again).
    QFETCH(double, gapS);
    Drkf once = makeFilter(3.0, 4.0), stepped = makeFilter(3.0, 4.0);
    QVERIFY(once.predictTo(fromSeconds(gapS)));
    for (int k = 1; k <= static_cast<int>(gapS); ++k) QVERIFY(stepped.predictTo(k * kMicrosPerSecond));
    const Covariance& P = once.belief().P;
    QVERIFY(est::isPositiveDefinite(P));
    const double rel =
        (P - stepped.belief().P).cwiseAbs().maxCoeff() / stepped.belief().P.cwiseAbs().maxCoeff();
    QVERIFY2(rel < 1e-9, qPrintable(QString("relative difference %1").arg(rel)));
    QVERIFY((once.belief().x - stepped.belief().x).cwiseAbs().maxCoeff() < 1e-6);
    // And the filter takes a fix after it.
    const std::vector<OwnShipSample> fix{
        GpsSample{once.timeUs(), {3.0 * gapS + 100.0, 4.0 * gapS}, 1600.0, false, 0.0, 0.0, 0.0}};
    const auto r = once.update(once.timeUs(), fix);
    QCOMPARE(blockOf(r, kGpsPosition)->status, est::UpdateStatus::Accepted);
  }
  void gapOfAMonthStaysFinite() {
    Drkf f = makeFilter(3.0, 4.0);
    QVERIFY(f.predictTo(fromSeconds(30.0 * 86400.0)));
    QVERIFY(f.belief().x.allFinite());
    QVERIFY(est::isPositiveDefinite(f.belief().P));
  }
  void groundOutputs() {
    Belief b;
    b.x.setZero();
    b.x[kCurX] = 0.5;
    b.x[kVelX] = 3.0;
    b.P = Covariance::Identity();
    b.P(kCurX, kVelX) = b.P(kVelX, kCurX) = 0.25;
    const auto g = groundStateOf(b);
    QCOMPARE(g[2], 3.5);
    QCOMPARE(groundCovarianceOf(b)(2, 2), 2.5);  // 1 + 1 + 2 * 0.25
  }
};

QTEST_APPLESS_MAIN(TestDrkf)
#include "tst_drkf.moc"
