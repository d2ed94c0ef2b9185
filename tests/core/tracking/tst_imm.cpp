// The IMM baseline (constant velocity + coordinated turn) and the radar-rate manoeuvre trial that
// compares it with seed 001's input estimation.
#include <QTest>

#include <cmath>

#include "common/angles.h"
#include "common/rng.h"
#include "estimation/ekf.h"
#include "studies/manoeuvre_trial.h"
#include "support/compare_near.h"
#include "support/numeric_jacobian.h"
#include "tracking/imm.h"

using namespace reckoner;
namespace ct = est::ct;

class TestImm : public QObject {
  Q_OBJECT
 private slots:
  void coordinatedTurnJacobianMatchesNumeric() {
    for (const ct::State& x : {ct::State(100.0, -50.0, 5.0, 3.0, 0.02), ct::State(0.0, 0.0, -4.0, 6.0, -0.05),
                               ct::State(10.0, 10.0, 6.0, 0.0, 1e-8), ct::State(0.0, 0.0, 0.0, 7.0, 0.0)}) {
      for (const double T : {0.5, 2.0, 10.0}) {
        const auto numeric = est::numericJacobian<ct::kStateDim, ct::kStateDim>(
            [T](const ct::State& s) { return ct::ctPredict(s, T); }, x);
        const double err = (numeric - ct::ctTransition(x, T)).cwiseAbs().maxCoeff();
        QVERIFY2(err < 1e-5,
                 qPrintable(QString("w %1, T %2: Jacobian error %3").arg(x[ct::kW]).arg(T).arg(err)));
      }
    }
  }

  void aFullTurnReturnsToItsStart() {
    // Clockwise at 3 deg/s for 120 s: 360 degrees, back at the start with the same velocity; heading
    // 000 turns to 090 after 30 s (clockwise positive, like bearings).
    const ct::State s(0.0, 0.0, 0.0, 5.0, degToRad(3.0));
    const ct::State quarter = ct::ctPredict(s, 30.0);
    RK_COMPARE_NEAR(quarter[ct::kVx], 5.0, 1e-9);
    RK_COMPARE_NEAR(quarter[ct::kVy], 0.0, 1e-9);
    QVERIFY(quarter[ct::kX] > 0.0 && quarter[ct::kY] > 0.0);
    const ct::State full = ct::ctPredict(s, 120.0);
    QVERIFY((full - s).head<4>().norm() < 1e-9);
  }

  void straightTargetStaysInConstantVelocityAndIsConsistent() {
    // GIVEN a straight target at 2 s sweeps THEN the IMM's turn probability stays low and the combined
    // estimate is consistent or conservative: the turn mode's larger process noise mixes in, so the
    // position-velocity NEES averages about 1.9 against 4 (docs/manoeuvres.md), never over-confident.
    track::ImmConfig cfg;
    cfg.bearingSdRad = degToRad(0.3);
    double neesSum = 0.0, ctSum = 0.0;
    int n = 0;
    for (int r = 0; r < 50; ++r) {
      track::ImmTracker imm(cfg);
      Rng rng(9, static_cast<std::uint64_t>(r));
      for (int k = 0; k <= 300; ++k) {
        const double t = 2.0 * k;
        const double tx = 4000.0 - 6.0 * t, ty = 3000.0 + 1.0 * t;
        imm.update(fromSeconds(t), wrapTwoPi(bearingOf(tx, ty) + rng.normal(0.0, cfg.bearingSdRad)),
                   std::hypot(tx, ty) + rng.normal(0.0, cfg.rangeSdM), 0.0, 0.0);
        if (k < 60) continue;
        const auto g = imm.combined();
        const est::Vec<4> e(g.x[0] - tx, g.x[1] - ty, g.x[2] + 6.0, g.x[3] - 1.0);
        neesSum += est::nees<4>(e, g.P.topLeftCorner<4, 4>());
        ctSum += imm.modeProbabilities()[track::ImmTracker::kCt];
        ++n;
      }
    }
    const double meanNees = neesSum / n, meanCt = ctSum / n;
    qInfo("straight: mean NEES %.2f (4 dof), mean turn probability %.3f", meanNees, meanCt);
    QVERIFY2(meanNees > 1.5 && meanNees < 5.0, qPrintable(QString::number(meanNees)));
    QVERIFY2(meanCt < 0.2, qPrintable(QString::number(meanCt)));
  }

  void thirtyDegreeTurnFlaggedWithinAMinuteWithFewFalseAlarms() {
    // Issue 6: input estimation detects a 30 deg turn at 2 s sweeps within 60 s in at least 90% of
    // runs with fewer than one false alarm per hour on straight tracks. Here for the seed 001 EKF at
    // radar rates (window 15 sweeps, Pfa 1e-4) and the IMM on the same plots.
    studies::ManoeuvreTrial turn;
    turn.turnRad = degToRad(30.0);
    const studies::TrackerConfigs cfg = studies::radarRateTrackers(turn);
    int ieWithin = 0, immWithin = 0;
    for (int r = 0; r < 50; ++r) {
      const auto o = studies::runManoeuvreTrial(turn, cfg, 500 + static_cast<std::uint64_t>(r));
      const auto& ie = o.trackers[studies::kEkfIe];
      const auto& imm = o.trackers[studies::kImm];
      ieWithin += ie.delayS && *ie.delayS <= 60.0 ? 1 : 0;
      immWithin += imm.delayS && *imm.delayS <= 60.0 ? 1 : 0;
    }
    studies::ManoeuvreTrial straight;
    straight.durationS = 3600.0;
    int ieFalse = 0, immFalse = 0;
    for (int r = 0; r < 10; ++r) {
      const auto o = studies::runManoeuvreTrial(straight, cfg, 900 + static_cast<std::uint64_t>(r));
      ieFalse += o.trackers[studies::kEkfIe].falseAlarms;
      immFalse += o.trackers[studies::kImm].falseAlarms;
      QCOMPARE(o.trackers[studies::kEkf].falseAlarms, 0);  // the plain EKF never flags
    }
    qInfo("30 deg turn flagged within 60 s: IE %d/50, IMM %d/50; false alarms in 10 h: IE %d, IMM %d",
          ieWithin, immWithin, ieFalse, immFalse);
    QVERIFY(ieWithin >= 45);
    QVERIFY(ieFalse < 10);
    QVERIFY(immWithin >= 45);
  }

  void trackersStayAboveTheirBound() {
    // The PCRB of a truly straight target (no process noise in the bound) along its trajectory is a
    // floor for every tracker's position RMSE (up to Monte Carlo scatter): none may beat it by more
    // than a few percent.
    studies::ManoeuvreTrial straight;
    straight.boundProcessNoiseQ = 0.0;
    const studies::TrackerConfigs cfg = studies::radarRateTrackers(straight);
    std::array<double, studies::kTrackerKinds> sum{};
    double boundSum = 0.0;
    double n = 0.0;
    for (int r = 0; r < 40; ++r) {
      const auto o = studies::runManoeuvreTrial(straight, cfg, 70 + static_cast<std::uint64_t>(r));
      for (std::size_t i = 0; i < o.tS.size(); ++i) {
        if (o.tS[i] < 120.0) continue;
        for (int k = 0; k < studies::kTrackerKinds; ++k) sum[k] += std::pow(o.trackers[k].posErrM[i], 2);
        boundSum += o.pcrbPosM[i] * o.pcrbPosM[i];
        n += 1.0;
      }
    }
    for (int k = 0; k < studies::kTrackerKinds; ++k) {
      const double ratio = std::sqrt(sum[k] / n) / std::sqrt(boundSum / n);
      qInfo("%s: RMSE / PCRB %.2f", studies::trackerName(static_cast<studies::TrackerKind>(k)), ratio);
      QVERIFY2(
          ratio > 0.95,
          qPrintable(
              QString("%1: %2").arg(studies::trackerName(static_cast<studies::TrackerKind>(k))).arg(ratio)));
    }
  }

  void badInputIsRefused() {
    track::ImmConfig cfg;
    cfg.ctSojournS = 0.0;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, track::ImmTracker{cfg});
    track::ImmTracker imm(track::ImmConfig{});
    QVERIFY(std::isnan(imm.update(0, std::nan(""), 1000.0, 0.0, 0.0)));
    QVERIFY(!imm.initialised());
    imm.update(0, 0.5, 1000.0, 0.0, 0.0);
    QVERIFY(imm.initialised());
    QVERIFY(std::isnan(imm.update(0, 0.5, 1000.0, 0.0, 0.0)));  // not after the last plot
  }
};

QTEST_APPLESS_MAIN(TestImm)
#include "tst_imm.moc"
