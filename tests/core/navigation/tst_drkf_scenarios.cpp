// GIVEN / WHEN / THEN behaviour of the DRKF on the deterministic simulator, 50 Monte Carlo runs each.
// The figures these tests print are the ones in docs/consistency.md.
#include <QTest>

#include "sim/sensor_profile.h"
#include "support/compare_near.h"
#include "support/drkf_fixtures.h"

using namespace reckoner;
using metrics::PhaseKind;

Q_DECLARE_METATYPE(std::string)

namespace {
constexpr int kRuns = 50;

/// Pre-outage steady state: mean claimed position sd over the last 60 s of the first phase.
double steadySd(const test::MonteCarloStudy& mc) {
  const auto& first = mc.summary.phases.front().stats.phase;
  const auto& s = mc.summary.series;
  double sum = 0.0;
  int n = 0;
  for (std::size_t k = 0; k < s.timeS.size(); ++k) {
    if (s.timeS[k] > toSeconds(first.endUs) - 60.0 && s.timeS[k] <= toSeconds(first.endUs)) {
      sum += s.rmsSdPositionM[k];
      ++n;
    }
  }
  return sum / n;
}

double sdAt(const test::MonteCarloStudy& mc, double tS) {
  const auto& s = mc.summary.series;
  for (std::size_t k = 0; k < s.timeS.size(); ++k)
    if (s.timeS[k] >= tS - 1e-9) return s.rmsSdPositionM[k];
  return std::nan("");
}

void tableRows() {
  QTest::addColumn<std::string>("scenario");
  for (const char* s :
       {"matched-model", "table1-test1", "table1-test2", "table1-test3", "table1-test4", "table1-test5"})
    QTest::newRow(s) << std::string(s);
}
}  // namespace

class TestDrkfScenarios : public QObject {
  Q_OBJECT
 private slots:
  void matchedModelIsConsistentInEveryPhase() {
    // GIVEN truth drawn from the filter's own model WHEN 50 runs are averaged THEN the mean NEES of
    // every phase - GPS, Loran-C, dead reckoning in both speedlog modes, GPS back - lies inside the
    // two-sided 95% bounds for 11 states (9.74 to 12.34).
    const auto& mc = test::monteCarlo("matched-model", kRuns);
    RK_COMPARE_NEAR(mc.summary.bounds.lower, 9.74, 0.01);
    RK_COMPARE_NEAR(mc.summary.bounds.upper, 12.34, 0.01);
    QCOMPARE(mc.summary.phases.size(), std::size_t(5));
    for (const auto& p : mc.summary.phases) {
      qInfo("matched-model phase %d %-30s mean NEES %.2f (max %.2f, %.0f%% of steps inside)",
            p.stats.phase.index + 1, p.stats.phase.label.c_str(), p.stats.meanNees, p.maxMeanNees,
            100 * p.fractionStepsInside);
      QVERIFY2(p.inside, qPrintable(QString::fromStdString(p.stats.phase.label)));
      // Per-time averages fall outside a 95% interval about 5% of the time; far more would mean a
      // phase average hiding a transient.
      QVERIFY(p.fractionStepsInside > 0.85);
    }
    QVERIFY(mc.summary.allPhasesInside);
  }

  void calibrationStatesAreConsistent_data() {
    QTest::addColumn<int>("profile");
    QTest::addColumn<bool>("log");
    QTest::newRow("imo") << static_cast<int>(sim::SensorProfile::Imo) << true;
    QTest::newRow("realistic") << static_cast<int>(sim::SensorProfile::Realistic) << true;
    // No log: dead reckoning on the heading alone (the speed-neutral heading update, docs/drkf.md).
    QTest::newRow("realistic, no log") << static_cast<int>(sim::SensorProfile::Realistic) << false;
  }
  void calibrationStatesAreConsistent() {
    // GIVEN the matched-model scenario with a profile's sensors (a gyro with a calibration error, a
    // log with a scale-factor error, the slow current and Loran-C bias) simulated and modelled alike
    // WHEN 50 runs are averaged THEN the mean NEES of all 13 states is never above its 95% bounds
    // (never optimistic), inside them with GNSS and Loran-C, and within 15% of 13 in dead reckoning
    // (slightly conservative there: docs/consistency.md).
    QFETCH(int, profile);
    QFETCH(bool, log);
    sim::Scenario sc = test::builtinScenario("matched-model");
    sim::applySensorProfile(sc, static_cast<sim::SensorProfile>(profile));
    sc.speedlog.fitted = log;
    // The world drawn from the filter's own models: matched.
    sc.current = *sc.filter.current;
    if (sc.filter.shipMotion.enabled) {  // the profile's ship motion model
      sc.ownShip.randomAcceleration.reset();
      sc.ownShip.randomShipMotion = sc.filter.shipMotion;
    } else {
      sc.ownShip.randomAcceleration = sc.filter.acceleration;
    }
    const auto runs = sim::runMonteCarlo(sc, kRuns, 2, sc.seed);
    const auto summary = metrics::summariseMonteCarlo(sc, runs);
    QCOMPARE(summary.neesDof, 13);
    for (const auto& p : summary.phases) {
      qInfo("%s phase %d %-30s mean NEES %.2f (bounds %.2f-%.2f, max %.2f)",
            sim::nameOf(static_cast<sim::SensorProfile>(profile)), p.stats.phase.index + 1,
            p.stats.phase.label.c_str(), p.stats.meanNees, summary.bounds.lower, summary.bounds.upper,
            p.maxMeanNees);
      const QString label = QString::fromStdString(p.stats.phase.label);
      // Dead reckoning on a heading alone is a little optimistic (the EKF's linearisation of a turning
      // ship whose speed is uncertain by a metre per second: docs/consistency.md), by up to 10% there.
      const bool headingOnly = !log && p.stats.phase.kind == metrics::PhaseKind::DeadReckoning;
      QVERIFY2(p.stats.meanNees < summary.bounds.upper * (headingOnly ? 1.1 : 1.0), qPrintable(label));
      const bool fixes = p.stats.phase.kind != metrics::PhaseKind::DeadReckoning;
      QVERIFY2(p.stats.meanNees > (fixes ? summary.bounds.lower : 0.85 * 13.0), qPrintable(label));
    }
  }
  void paperKinematicsStayBelowTwiceTheUpperBound_data() { tableRows(); }
  void paperKinematicsStayBelowTwiceTheUpperBound() {
    // GIVEN the deterministic turns of Table II (a model mismatch) WHEN 50 runs are averaged THEN the
    // mean NEES stays below 2 x 12.34 in every phase.
    QFETCH(std::string, scenario);
    const auto& mc = test::monteCarlo(scenario, kRuns);
    for (const auto& p : mc.summary.phases) {
      qInfo("%s phase %d %-30s mean NEES %.2f max %.2f", scenario.c_str(), p.stats.phase.index + 1,
            p.stats.phase.label.c_str(), p.stats.meanNees, p.maxMeanNees);
      QVERIFY2(p.stats.meanNees < 2 * 12.34, qPrintable(QString::fromStdString(p.stats.phase.label)));
    }
  }

  void deadReckoningGrowsAndGpsCollapsesIt_data() { tableRows(); }
  void deadReckoningGrowsAndGpsCollapsesIt() {
    // GIVEN GPS on WHEN GPS and Loran-C are lost THEN the position sd grows through dead reckoning,
    // the true error stays inside 3 sd in at least 95% of the steps, AND WHEN GPS returns THEN within
    // 30 s the sd is back within twice its pre-outage steady state.
    QFETCH(std::string, scenario);
    const auto& mc = test::monteCarlo(scenario, kRuns);
    const double steady = steadySd(mc);
    double previousEnd = 0.0;
    bool sawDeadReckoning = false, sawReturn = false;
    for (std::size_t i = 0; i < mc.summary.phases.size(); ++i) {
      const auto& p = mc.summary.phases[i];
      if (p.stats.phase.kind == PhaseKind::DeadReckoning) {
        sawDeadReckoning = true;
        QVERIFY2(p.stats.sdPositionEndM > p.stats.sdPositionStartM, "sd must grow in dead reckoning");
        QVERIFY2(p.stats.fractionWithin3Sd >= 0.95, qPrintable(QString::number(p.stats.fractionWithin3Sd)));
        qInfo("%s DR phase %d: sd %.1f -> %.1f m, error within 3 sd in %.1f%% of steps", scenario.c_str(),
              p.stats.phase.index + 1, p.stats.sdPositionStartM, p.stats.sdPositionEndM,
              100 * p.stats.fractionWithin3Sd);
      }
      if (i > 0 && p.stats.phase.kind == PhaseKind::Gps &&
          mc.summary.phases[i - 1].stats.phase.kind != PhaseKind::Gps) {
        sawReturn = true;
        const double t0 = toSeconds(p.stats.phase.startUs);
        const double after30 = sdAt(mc, t0 + 30.0);
        qInfo("%s GPS back at %.0f s: sd %.1f m before, %.1f m 30 s later (steady %.1f m)", scenario.c_str(),
              t0, previousEnd, after30, steady);
        QVERIFY(previousEnd > 1.5 * steady);
        QVERIFY2(after30 < 2.0 * steady, qPrintable(QString("%1 vs steady %2").arg(after30).arg(steady)));
      }
      previousEnd = p.stats.sdPositionEndM;
    }
    QVERIFY(sawDeadReckoning && sawReturn);
  }

  void bottomLockLosesTheCurrent() {
    // GIVEN dead reckoning with a strong current (tests 1 and 2) WHEN the speedlog switches from
    // ground-lock to bottom-lock THEN the position variance grows faster (the current is unobserved).
    for (const char* name : {"table1-test1", "table1-test2"}) {
      const auto& mc = test::monteCarlo(name, kRuns);
      double growth[2] = {0, 0};
      int n = 0;
      for (const auto& p : mc.summary.phases) {
        if (p.stats.phase.kind != PhaseKind::DeadReckoning) continue;
        const double dt = toSeconds(p.stats.phase.endUs - p.stats.phase.startUs);
        growth[n++] = (p.stats.sdPositionEndM * p.stats.sdPositionEndM -
                       p.stats.sdPositionStartM * p.stats.sdPositionStartM) /
                      dt;
      }
      QCOMPARE(n, 2);
      qInfo("%s variance growth: ground-lock %.2f m^2/s, bottom-lock %.2f m^2/s", name, growth[0], growth[1]);
      QVERIFY(growth[1] > 1.3 * growth[0]);
    }
  }
};

QTEST_APPLESS_MAIN(TestDrkfScenarios)
#include "tst_drkf_scenarios.moc"
