// The trial manoeuvre (docs/trial.md): no change of course or speed gives the present CPA; the
// probability of CPA below the limit agrees with a Monte Carlo of the same Gaussian; the danger sectors
// hold the course of a head-on encounter and not its reverse; a bad order gives no result; and over 50
// runs of the four-encounter scenario, the CPA each vessel really reaches once the manoeuvre is carried
// out in the simulation lies within the predicted sd (2 sd for 95%, never beyond 3.5 sd), the sd not
// far larger than the errors, and in line with the tracker's own sd of the present CPA.
#include <QTest>

#include <cmath>
#include <stdexcept>
#include <string>

#include "common/angles.h"
#include "common/rng.h"
#include "common/units.h"
#include "sim/trial_manoeuvre.h"
#include "studies/trial_study.h"
#include "support/compare_near.h"
#include "support/drkf_fixtures.h"

using namespace reckoner;

namespace {
/// Own ship at 10 kn north, turning at 1 deg/s, accelerating at 0.05 m/s^2.
sim::TrialOwnShip ownShip() {
  sim::TrialOwnShip o;
  o.waterVyMps = knotsToMps(10.0);
  o.maxTurnRateRadPerS = degToRad(1.0);
  o.maxAccelerationMps2 = 0.05;
  return o;
}

/// A target at (x, y) relative to own ship with ground velocity (vx, vy), position sd 30 m, velocity
/// sd 0.2 m/s, own velocity known.
sim::TrialTargetInput target(double x, double y, double vx, double vy) {
  sim::TrialTargetInput t;
  t.trackId = 1;
  t.state << x, y, vx, vy, 0.0, knotsToMps(10.0);
  t.covariance.setZero();
  t.covariance(0, 0) = t.covariance(1, 1) = 900.0;
  t.covariance(2, 2) = t.covariance(3, 3) = 0.04;
  t.covariance(4, 4) = t.covariance(5, 5) = 1e-6;
  return t;
}
}  // namespace

class TstTrialManoeuvre : public QObject {
  Q_OBJECT
 private slots:
  void noChangeGivesThePresentCpa() {
    const auto t = target(3000.0, 6000.0, -3.0, 0.0);
    const auto r = sim::trialManoeuvre(0, ownShip(), {t}, {0.0, knotsToMps(10.0), 0.0}, {});
    QCOMPARE(r.targets.size(), std::size_t{1});
    RK_COMPARE_NEAR(r.targets[0].cpaM, r.targets[0].presentCpaM, 1.0);
    RK_COMPARE_NEAR(r.targets[0].tcpaS, r.targets[0].presentTcpaS, 1.0);
  }

  void turnAwayOpensTheCpa() {
    // A vessel dead ahead on the reciprocal course: CPA about 0; a turn to starboard after 60 s opens it.
    const auto t = target(0.0, 9000.0, 0.0, -knotsToMps(10.0));
    const auto r = sim::trialManoeuvre(0, ownShip(), {t}, {degToRad(60.0), knotsToMps(10.0), 60.0}, {});
    QVERIFY(r.targets[0].presentCpaM < 1.0);
    QVERIFY(r.targets[0].cpaM > 1000.0);
    QVERIFY(r.manoeuvreEndS > 60.0 + 55.0);  // 60 degrees at 1 deg/s after the delay
    QVERIFY(r.targets[0].probabilityBelowLimit < r.targets[0].dangerous + 0.5);
  }

  void probabilityAgreesWithMonteCarlo() {
    // P(CPA < limit) from the covariance against the fraction of 2000 draws of the target's state
    // whose trial CPA is below the limit.
    const auto t = target(2500.0, 7000.0, -2.5, -0.5);
    sim::TrialSettings s;
    const sim::TrialOrder order{degToRad(20.0), knotsToMps(12.0), 30.0};
    // The limit half an sd above the predicted CPA: a case where the probability means something.
    const auto first = sim::trialManoeuvre(0, ownShip(), {t}, order, s).targets[0];
    s.cpaLimitM = first.cpaM + 0.5 * first.sdCpaM;
    const auto r = sim::trialManoeuvre(0, ownShip(), {t}, order, s);
    const double p = r.targets[0].probabilityBelowLimit;
    QVERIFY2(p > 0.5 && p < 0.9, qPrintable(QString::number(p)));
    Rng rng(7, 1);
    const Eigen::LLT<est::Mat<6>> llt(t.covariance);
    int below = 0;
    const int n = 2000;
    for (int i = 0; i < n; ++i) {
      est::Vec<6> w;
      for (int k = 0; k < 6; ++k) w[k] = rng.normal();
      sim::TrialTargetInput d = t;
      d.state += llt.matrixL() * w;
      d.covariance = est::Mat<6>::Identity() * 1e-9;
      below += sim::trialManoeuvre(0, ownShip(), {d}, order, s).targets[0].cpaM < s.cpaLimitM;
    }
    RK_COMPARE_NEAR(p, static_cast<double>(below) / n, 0.04);
  }

  void dangerSectorsHoldTheCollisionCourse() {
    // Head-on, closing at about 19 kn from 5 km: TCPA about 8 minutes, inside the 12-minute limit.
    const auto t = target(0.0, 5000.0, 0.0, -knotsToMps(10.0));
    const auto r = sim::trialManoeuvre(0, ownShip(), {t}, {0.0, knotsToMps(10.0), 0.0}, {});
    const auto& d = r.sectors;
    QCOMPARE(d.courses, 180);
    QCOMPARE(d.speedsMps.size(), std::size_t{8});
    // The ring nearest 10 kn: north is dangerous, south is not.
    std::size_t ring = 0;
    for (std::size_t i = 0; i < d.speedsMps.size(); ++i)
      if (std::abs(d.speedsMps[i] - knotsToMps(10.0)) < std::abs(d.speedsMps[ring] - knotsToMps(10.0)))
        ring = i;
    QCOMPARE(d.danger[ring * 180 + 0], std::uint8_t{1});
    QCOMPARE(d.danger[ring * 180 + 90], std::uint8_t{0});
    // The runs cover exactly the dangerous cells.
    int inRuns = 0, cells = 0;
    for (const auto& [j, k] : d.dangerousRuns(ring)) {
      QVERIFY(j <= k);
      inRuns += k - j + 1;
    }
    for (int j = 0; j < 180; ++j) cells += d.danger[ring * 180 + static_cast<std::size_t>(j)];
    QCOMPARE(inRuns, cells);
    QVERIFY(d.dangerousRuns(d.speedsMps.size()).empty());
  }

  void badOrderGivesNothing() {
    const auto t = target(0.0, 9000.0, 0.0, -3.0);
    QVERIFY(sim::trialManoeuvre(0, ownShip(), {t}, {0.0, std::nan(""), 0.0}, {}).targets.empty());
    QVERIFY(sim::trialManoeuvre(0, ownShip(), {t}, {0.0, 5.0, -1.0}, {}).targets.empty());
  }

  void realisedCpaWithinPredictedSdOver50Runs() {
    // GIVEN the four encounters, a trial at 300 s: 40 degrees true, 10 kn, after 30 s
    // WHEN it is carried out in the simulation (50 seeds)
    // THEN each vessel's realised CPA is within the predicted sd as a Gaussian says, and the sd is
    // honest both ways.
    const sim::Scenario s = test::builtinScenario("trial-encounters");
    sim::TrialSettings settings;
    settings.cpaLimitM = s.tracker.dangerCpaM;
    const sim::TrialOrder order{degToRad(40.0), knotsToMps(10.0), 30.0};
    int n = 0, within2 = 0;
    double z2 = 0.0, worst = 0.0;
    for (std::uint64_t seed = 1; seed <= 50; ++seed) {
      const auto c = studies::checkTrial(s, seed, fromSeconds(300.0), order, settings, true);
      QCOMPARE(c.targets.size(), std::size_t{4});
      for (const auto& t : c.targets) {
        QVERIFY(t.realisedCpaM.has_value());
        const double z = (*t.realisedCpaM - t.predicted.cpaM) / t.predicted.sdCpaM;
        ++n;
        within2 += std::abs(z) <= 2.0;
        z2 += z * z;
        worst = std::max(worst, std::abs(z));
      }
    }
    qInfo("trial: %d CPAs, within 2 sd %.1f%%, mean z^2 %.3f, worst |z| %.2f", n, 100.0 * within2 / n, z2 / n,
          worst);
    QCOMPARE(n, 200);
    QVERIFY(within2 >= 0.95 * n);
    QVERIFY(worst < 3.5);
    QVERIFY(z2 / n < 1.28);  // not overconfident (chi-square 99% upper bound for 200 samples)
    QVERIFY(z2 / n > 0.2);   // the sd at most about 2.2 times the errors
  }
};

QTEST_APPLESS_MAIN(TstTrialManoeuvre)
#include "tst_trial_manoeuvre.moc"
