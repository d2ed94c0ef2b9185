#include <QTest>

#include <algorithm>
#include <map>

#include "sim/scenario_run.h"
#include "sim/simulation_engine.h"
#include "support/drkf_fixtures.h"

using namespace reckoner;
using namespace reckoner::sim;
using sensors::SensorId;

class TestSimulationEngine : public QObject {
  Q_OBJECT
 private slots:
  void oneSeedGivesTheSameRunBitForBit() {
    const Scenario s = test::builtinScenario("table1-test1");
    const RunResult a = runScenario(s, 17), b = runScenario(s, 17), c = runScenario(s, 18);
    QCOMPARE(a.rows.size(), b.rows.size());
    bool identical = true, differs = false;
    for (std::size_t k = 0; k < a.rows.size(); ++k) {
      identical = identical && a.rows[k].estXM == b.rows[k].estXM && a.rows[k].trueYM == b.rows[k].trueYM &&
                  a.rows[k].nees == b.rows[k].nees && a.rows[k].sdVxMps == b.rows[k].sdVxMps;
      differs = differs || a.rows[k].estXM != c.rows[k].estXM;
    }
    QVERIFY(identical);
    QVERIFY(differs);
  }
  void monteCarloIndependentOfThreadCount() {
    Scenario s = test::builtinScenario("matched-model");
    s.durationUs = 200 * kMicrosPerSecond;
    const auto one = runMonteCarlo(s, 5, 1, 100), three = runMonteCarlo(s, 5, 3, 100);
    for (std::size_t r = 0; r < 5; ++r) {
      QCOMPARE(one[r].seed, 100 + r);
      QCOMPARE(one[r].rows.back().estXM, three[r].rows.back().estXM);
      QCOMPARE(one[r].rows.back().nees, three[r].rows.back().nees);
    }
  }
  void measurementDimensionFollowsTheOutageSchedule() {
    // GIVEN the table schedule WHEN everything is on THEN 8 rows per epoch (the paper's 8x11 H);
    // WHEN GPS and Loran-C are off THEN 2 rows (2x11): speedlog and gyro.
    SimulationEngine e(test::builtinScenario("table1-test3"), 1);
    // (A sensor occasionally fails its gate on this mismatched-model run, so compare the usual
    // dimension of each configuration.)
    std::map<std::string, std::map<int, int>> dims;
    while (!e.finished()) {
      const SimFrame f = e.step();
      QCOMPARE(f.updates.size(), std::size_t(1));
      ++dims[sensorLabel(f.sensors)][f.updates.front().dim];
    }
    auto usual = [&](const std::string& label) {
      const auto& h = dims[label];
      return std::max_element(h.begin(), h.end(), [](auto x, auto y) { return x.second < y.second; })->first;
    };
    QCOMPARE(usual("gps+loran_c+speedlog_gl+gyro"), 8);
    QCOMPARE(usual("loran_c+speedlog_gl+gyro"), 4);
    QCOMPARE(usual("speedlog_gl+gyro"), 2);
    QCOMPARE(usual("speedlog_bl+gyro"), 2);
    QVERIFY(dims["gps+loran_c+speedlog_gl+gyro"][8] > 590);
  }
  void sensorsAtTheirOwnRates() {
    Scenario s = test::builtinScenario("matched-model");
    s.durationUs = 20 * kMicrosPerSecond;
    s.gyro.rateHz = 10.0;
    s.gps.rateHz = 0.5;
    SimulationEngine e(s, 3);
    int gyro = 0, gps = 0, epochs = 0;
    while (!e.finished()) {
      const SimFrame f = e.step();
      epochs += static_cast<int>(f.updates.size());
      for (const auto& m : f.measurements) {
        gyro += sensors::sensorOf(m) == SensorId::Gyro;
        gps += sensors::sensorOf(m) == SensorId::Gps;
      }
      QCOMPARE(e.drkf().timeUs(), f.timeUs);
    }
    QCOMPARE(gyro, 200);
    QCOMPARE(gps, 10);
    QCOMPARE(epochs, 200);  // the filter predicts to every measurement's own time
  }
  void outageRemovesSamples() {
    SimulationEngine e(test::builtinScenario("table1-test5"), 2);
    while (!e.finished()) {
      const SimFrame f = e.step();
      const bool gpsExpected = f.timeUs <= 299 * kMicrosPerSecond || f.timeUs >= 1200 * kMicrosPerSecond;
      const bool gpsSeen = std::any_of(f.measurements.begin(), f.measurements.end(),
                                       [](const auto& m) { return sensors::sensorOf(m) == SensorId::Gps; });
      QCOMPARE(gpsSeen, gpsExpected);
    }
  }
  void invalidScenarioIsRefused() {
    Scenario s = test::builtinScenario("matched-model");
    s.gps.positionVarM2 = -1.0;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, SimulationEngine(s, 1));
    QVERIFY(checkScenario(s).find("sensors.gps") == 0);
  }
};

QTEST_APPLESS_MAIN(TestSimulationEngine)
#include "tst_simulation_engine.moc"
