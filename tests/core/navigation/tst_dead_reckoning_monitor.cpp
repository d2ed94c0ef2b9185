// nav::DeadReckoningMonitor (when own ship is dead reckoning) and nav::DeadReckoningHorizon (how long it
// stays within a limit), on hand-made update reports and a real DRKF.
#include <QTest>

#include "navigation/dead_reckoning_monitor.h"
#include "support/drkf_fixtures.h"

using namespace reckoner;
using namespace reckoner::nav;

namespace {
TimeUs seconds(double s) {
  return fromSeconds(s);
}

/// An epoch at t carrying the given blocks, each with the given outcome.
DrkfUpdateReport epoch(double tS, std::initializer_list<std::pair<DrkfBlock, est::UpdateStatus>> blocks) {
  DrkfUpdateReport r;
  r.timeUs = seconds(tS);
  for (const auto& [block, status] : blocks) {
    est::BlockReport& b = r.blocks[static_cast<std::size_t>(r.blockCount++)];
    b.tag = block;
    b.dim = 2;
    b.status = status;
  }
  return r;
}

constexpr auto kAccepted = est::UpdateStatus::Accepted;

Drkf filterAtRest() {
  DrkfConfig c;
  c.process = test::tableOneProcess();
  drkf::Belief b;
  b.x.setZero();
  b.x[drkf::kVelY] = 5.0;
  b.P = initialCovariance(c.process, 10.0, 0.2);
  return Drkf(c, geo::LocalFrame(49.0, -123.0), b, 0);
}

DeadReckoningAids speedlogAndGyro() {
  DeadReckoningAids aids;
  aids.speedlog = true;
  aids.gyro = true;
  return aids;
}
}  // namespace

class TestDeadReckoningMonitor : public QObject {
  Q_OBJECT
 private slots:
  void gpsLostMeansDeadReckoningThreeSecondsLater() {
    // GIVEN GPS positions applied every second up to 100 s WHEN the monitor is evaluated every second
    // THEN it is not dead reckoning up to 103 s (the fix 3 s old still counts) and is from 104 s on,
    // one open interval starting there; WHEN GPS comes back at 110 s THEN the interval closes there.
    DeadReckoningMonitor m;
    for (int t = 0; t <= 100; ++t) {
      m.addEpoch(epoch(t, {{kGpsPosition, kAccepted}, {kGyro, kAccepted}}));
      QVERIFY(!m.evaluate(seconds(t)).active);
    }
    for (int t = 101; t <= 103; ++t) {
      m.addEpoch(epoch(t, {{kGyro, kAccepted}}));  // epochs without a position change nothing
      QVERIFY2(!m.evaluate(seconds(t)).active, qPrintable(QString("t = %1 s").arg(t)));
    }
    for (int t = 104; t < 110; ++t) {
      const DeadReckoningStatus& s = m.evaluate(seconds(t));
      QVERIFY(s.active);
      QCOMPARE(s.sinceUs, seconds(104));
    }
    QCOMPARE(m.intervals().size(), std::size_t{1});
    QVERIFY(!m.intervals()[0].endUs);
    m.addEpoch(epoch(110, {{kGpsPosition, kAccepted}}));
    QVERIFY(!m.evaluate(seconds(110)).active);
    QCOMPARE(m.intervals()[0].startUs, seconds(104));
    QCOMPARE(m.intervals()[0].endUs.value_or(-1), seconds(110));
  }

  void theLatestUpdateOfABlockDecides() {
    // GIVEN a GPS position applied at 10 s WHEN the next one at 11 s is refused by its gate THEN the
    // ship is dead reckoning at 11 s (a refused fix is no fix, whatever came before); WHEN one is
    // applied without gating (accepted forced) THEN that counts.
    DeadReckoningMonitor m;
    m.addEpoch(epoch(10, {{kGpsPosition, kAccepted}}));
    QVERIFY(!m.evaluate(seconds(10)).active);
    m.addEpoch(epoch(11, {{kGpsPosition, est::UpdateStatus::RejectedGate}}));
    QVERIFY(m.evaluate(seconds(11)).active);
    m.addEpoch(epoch(12, {{kGpsPosition, est::UpdateStatus::AcceptedForced}}));
    QVERIFY(!m.evaluate(seconds(12)).active);
  }

  void loranCPositionsCountLikeGps() {
    // GIVEN GPS refused and Loran-C applied in the same epoch THEN not dead reckoning; WHEN Loran-C
    // goes 3.5 s without an update THEN dead reckoning.
    DeadReckoningMonitor m;
    m.addEpoch(epoch(5, {{kGpsPosition, est::UpdateStatus::RejectedGate}, {kLoranPosition, kAccepted}}));
    QVERIFY(!m.evaluate(seconds(5)).active);
    QVERIFY(!m.evaluate(seconds(8)).active);
    QVERIFY(m.evaluate(seconds(8.5)).active);
  }

  void velocityHeadingAndLogAreNoPositionFix() {
    // GIVEN only GPS velocity, speedlog and gyro applied THEN dead reckoning from the first evaluation.
    DeadReckoningMonitor m;
    m.addEpoch(epoch(0, {{kGpsVelocity, kAccepted}, {kSpeedlog, kAccepted}, {kGyro, kAccepted}}));
    const DeadReckoningStatus& s = m.evaluate(0);
    QVERIFY(s.active);
    QCOMPARE(s.sinceUs, TimeUs{0});
  }

  void radarFixesCountForFourMatchingIntervals() {
    // GIVEN a 2 s sweep matched every 3 sweeps THEN a radar fix counts for 4 x 6 s = 24 s; a rule for
    // everySweeps 0 counts it as 1.
    QCOMPARE(deadReckoningRule(2.0, 3).radarFixRecentS, 24.0);
    QCOMPARE(deadReckoningRule(2.0, 0).radarFixRecentS, 8.0);
    QCOMPARE(deadReckoningRule(2.0, 3).fixRecentS, 3.0);
    DeadReckoningMonitor m(deadReckoningRule(2.0, 3));
    QVERIFY(m.evaluate(seconds(100)).active);
    m.addRadarFix(seconds(101));
    QVERIFY(!m.evaluate(seconds(101)).active);
    QVERIFY(!m.evaluate(seconds(125)).active);
    QVERIFY(m.evaluate(seconds(125.5)).active);
    QCOMPARE(m.intervals().size(), std::size_t{2});
    QCOMPARE(m.intervals()[0].endUs.value_or(-1), seconds(101));
    QCOMPARE(m.intervals()[1].startUs, seconds(125.5));
  }

  void horizonIsCountedDownAndRecomputedWhenTheAidsChange() {
    // GIVEN a DRKF with 10 m of position sd and speedlog and gyro WHEN asked with a 185 m limit THEN a
    // positive horizon below 4 h, the same as timeToPositionLimitS; asked 2 s later THEN 2 s less;
    // WHEN the gyro goes off THEN it is computed again (no longer the countdown); WHEN the ship is no
    // longer dead reckoning THEN none.
    const Drkf f = filterAtRest();
    DeadReckoningHorizon h;
    const DeadReckoningAids aids = speedlogAndGyro();
    const std::optional<double> first = h.update(true, 0, f, aids, 185.0);
    QVERIFY(first.has_value());
    QVERIFY2(*first > 0.0 && *first < DeadReckoningHorizon::kMaxS, qPrintable(QString::number(*first)));
    QCOMPARE(*first, timeToPositionLimitS(f, aids, 185.0, DeadReckoningHorizon::kMaxS).value_or(-1.0));
    QCOMPARE(h.update(true, seconds(2), f, aids, 185.0).value_or(-1.0), *first - 2.0);
    DeadReckoningAids noGyro = aids;
    noGyro.gyro = false;
    const double computed =
        timeToPositionLimitS(f, noGyro, 185.0, DeadReckoningHorizon::kMaxS).value_or(-1.0);
    QCOMPARE(h.update(true, seconds(3), f, noGyro, 185.0).value_or(-1.0), computed);
    QVERIFY(!h.update(false, seconds(4), f, noGyro, 185.0).has_value());
  }

  void horizonIsRecomputedForANewLimitOrAfterFiveSeconds() {
    // GIVEN an answer at t = 0 WHEN the limit changes THEN the answer is the new limit's; WHEN asked
    // 6 s after the previous question THEN it is computed again (the filter's answer, not a countdown);
    // WHEN the limit is never reached in 4 h THEN kMaxS.
    const Drkf f = filterAtRest();
    DeadReckoningHorizon h;
    const DeadReckoningAids aids = speedlogAndGyro();
    QVERIFY(h.update(true, 0, f, aids, 185.0).has_value());
    const double wider = timeToPositionLimitS(f, aids, 400.0, DeadReckoningHorizon::kMaxS).value_or(-1.0);
    QCOMPARE(h.update(true, seconds(1), f, aids, 400.0).value_or(-1.0), wider);
    QCOMPARE(h.update(true, seconds(7), f, aids, 400.0).value_or(-1.0), wider);
    QCOMPARE(h.update(true, seconds(8), f, aids, 1e9).value_or(-1.0), DeadReckoningHorizon::kMaxS);
  }
};

QTEST_APPLESS_MAIN(TestDeadReckoningMonitor)
#include "tst_dead_reckoning_monitor.moc"
