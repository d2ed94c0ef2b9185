#include <QTest>

#include "support/drkf_fixtures.h"

#include "common/angles.h"
#include "files/scenario_json.h"
#include "resources/embedded.h"
#include "support/compare_near.h"
#include "support/drkf_fixtures.h"

using namespace reckoner;

namespace {
const char* kValid = R"({
  "format": "reckoner-scenario/1",
  "name": "t",
  "origin": {"lat_deg": 49.29, "lon_deg": -123.11},
  "duration_s": 100,
  "current": {"variance_m2_s2": 0.3, "beta_per_s": 0.17},
  "own_ship": {"velocity_mps": [5, 5], "schedule": [{"t_s": 10, "turn_rate_dps": 1.5}]},
  "sensors": {
    "gps": {"position_variance_m2": 1600, "velocity_variance_m2_s2": 0.25,
            "schedule": [{"t_s": 30, "on": false}, {"t_s": 60, "on": true}]},
    "speedlog": {"markov_variance_m2_s2": 0.5, "markov_beta_per_s": 0.5, "white_variance_m2_s2": 0.01,
                 "schedule": [{"t_s": 40, "mode": "bottom_lock"}]},
    "gyro": {"sd_deg": 1}
  }
})";

/// kValid with `from` replaced by `to` (which must occur).
std::string variant(const std::string& from, const std::string& to) {
  std::string s = kValid;
  const auto at = s.find(from);
  if (at == std::string::npos) qFatal("test text not found: %s", from.c_str());
  return s.replace(at, from.size(), to);
}
}  // namespace

class TestScenarioJson : public QObject {
  Q_OBJECT
 private slots:
  void readsEveryField() {
    const sim::Scenario s = files::parseScenario(kValid, "t.json");
    QCOMPARE(s.name, std::string("t"));
    QCOMPARE(s.durationUs, 100 * kMicrosPerSecond);
    RK_COMPARE_NEAR(s.current.sigma, std::sqrt(0.3), 1e-15);
    QCOMPARE(s.ownShip.schedule.size(), std::size_t(1));
    RK_COMPARE_NEAR(*s.ownShip.schedule[0].turnRateRadPerS, degToRad(1.5), 1e-15);
    QVERIFY(s.gps.fitted && s.speedlog.fitted && s.gyro.fitted && !s.loran.fitted);
    QCOMPARE(s.gps.power.at(35 * kMicrosPerSecond), false);
    QCOMPARE(s.gps.power.at(60 * kMicrosPerSecond), true);
    QCOMPARE(s.speedlog.mode.at(45 * kMicrosPerSecond), sensors::SpeedlogMode::BottomLock);
    QCOMPARE(s.speedlog.power.at(45 * kMicrosPerSecond), true);
    RK_COMPARE_NEAR(s.gyro.sdRad, degToRad(1.0), 1e-15);
    QCOMPARE(s.filter.gateProbability, 0.9999);  // default
  }
  void everyBuiltinScenarioLoads() {
    QVERIFY(resources::scenarios().size() >= 7);
    QVERIFY(resources::findScenario(resources::kDefaultScenario) != nullptr);
    for (const auto& f : resources::scenarios()) {
      const sim::Scenario s = files::parseScenario(f.text, std::string(f.name));
      QVERIFY2(sim::checkScenario(s).empty(), f.name.data());
    }
  }
  void badInputNamesFileLineAndField_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("expected");  // substring of the single error line
    QTest::newRow("malformed JSON") << QString::fromStdString(
                                           variant("\"duration_s\": 100,", "\"duration_s\": 100,,"))
                                    << "t.json:5: malformed JSON: line 5";
    QTest::newRow("unknown field") << QString::fromStdString(
                                          variant("\"sd_deg\": 1", "\"sd_deg\": 1, \"bias_deg\": 2"))
                                   << "t.json:13: sensors.gyro.bias_deg: unknown field";
    QTest::newRow("negative variance")
        << QString::fromStdString(variant("\"position_variance_m2\": 1600", "\"position_variance_m2\": -5"))
        << "t.json:9: sensors.gps.position_variance_m2: must be positive, got -5";
    QTest::newRow("unknown sensor") << QString::fromStdString(
                                           variant("\"gyro\": {", "\"radar2\": {\"x\": 1},\n    \"gyro\": {"))
                                    << "t.json:13: sensors.radar2: unknown sensor 'radar2'";
    QTest::newRow("missing field") << QString::fromStdString(variant("\"duration_s\": 100,", ""))
                                   << "t.json:1: duration_s: required field is missing";
    QTest::newRow("wrong type") << QString::fromStdString(
                                       variant("\"duration_s\": 100", "\"duration_s\": \"100\""))
                                << "t.json:5: duration_s: must be a number, got a string";
    QTest::newRow("schedule out of order")
        << QString::fromStdString(variant("{\"t_s\": 60, \"on\": true}", "{\"t_s\": 20, \"on\": true}"))
        << "t.json:10: sensors.gps.schedule[1].t_s: schedule times must increase";
    QTest::newRow("time beyond duration")
        << QString::fromStdString(variant("{\"t_s\": 40, \"mode\"", "{\"t_s\": 400, \"mode\""))
        << "sensors.speedlog.schedule[0].t_s: time 400 s lies beyond duration_s";
    QTest::newRow("bad mode") << QString::fromStdString(variant("\"bottom_lock\"", "\"bottom\""))
                              << "sensors.speedlog.schedule[0].mode: must be \"ground_lock\"";
    QTest::newRow("bad origin") << QString::fromStdString(variant("\"lat_deg\": 49.29", "\"lat_deg\": 89.0"))
                                << "t.json:4: origin.lat_deg: must lie in [-80, 84]";
    QTest::newRow("wrong format") << QString::fromStdString(
                                         variant("reckoner-scenario/1", "reckoner-scenario/2"))
                                  << "t.json:2: format: must be \"reckoner-scenario/1\"";
    QTest::newRow("negative beta") << QString::fromStdString(
                                          variant("\"beta_per_s\": 0.17", "\"beta_per_s\": -0.17"))
                                   << "t.json:6: current.beta_per_s: must be positive";
    QTest::newRow("not an object") << "[1, 2]"
                                   << "t.json:1: must be an object, got an array";
    QTest::newRow("radar matching correlation")
        << QString::fromStdString(
               variant("\"duration_s\": 100,",
                       "\"duration_s\": 100, \"radar_matching\": {\"error_correlation\": 1.2},"))
        << "radar_matching.error_correlation: must be in [0, 0.95]";
    QTest::newRow("radar matching schedule")
        << QString::fromStdString(variant(
               "\"duration_s\": 100,",
               "\"duration_s\": 100, \"radar_matching\": {\"schedule\": [{\"t_s\": 50, \"on\": 1}]},"))
        << "radar_matching.schedule[0].on: must be";
    QTest::newRow("empty event") << QString::fromStdString(
                                        variant("{\"t_s\": 10, \"turn_rate_dps\": 1.5}", "{\"t_s\": 10}"))
                                 << "own_ship.schedule[0].velocity_mps: event needs";
  }
  void badInputNamesFileLineAndField() {
    QFETCH(QString, text);
    QFETCH(QString, expected);
    try {
      files::parseScenario(text.toStdString(), "t.json");
      QFAIL("accepted a bad scenario");
    } catch (const io::InputError& e) {
      const QString msg = QString::fromStdString(e.what());
      QVERIFY2(msg.contains(expected), qPrintable(msg));
      QVERIFY(!msg.contains('\n'));
    }
  }
  void readsTargetsRadarAndTracker() {
    const std::string text = variant("\"gyro\": {\"sd_deg\": 1}", R"("gyro": {"sd_deg": 1},
    "radar": {"range_sd_m": 20, "bearing_sd_deg": 0.5, "max_range_nm": 12, "detection_probability": 0.9}
  },
  "targets": [{"id": 7, "name": "ferry", "position_m": [100, 200], "velocity_mps": [1, 2],
               "random_acceleration": {"variance_m2_s4": 0.01, "beta_per_s": 0.1},
               "schedule": [{"t_s": 40, "velocity_mps": [5, 5]}], "appear_s": 10, "leave_s": 50}],
  "tracker": {"own_acceleration": {"sigma_mps2": 0.1, "beta_per_s": 0.2},
              "target_acceleration": {"variance_m2_s4": 0.005, "beta_per_s": 0.1},
              "own_ship_feed": "measurement", "capacity": 50)");
    const sim::Scenario s = files::parseScenario(text, "t.json");
    QVERIFY(s.radar.fitted);
    QCOMPARE(s.radar.rangeSdM, 20.0);
    RK_COMPARE_NEAR(s.radar.maxRangeM, 12 * 1852.0, 1e-9);
    QCOMPARE(s.radar.detectionProbability, 0.9);
    QCOMPARE(s.targets.size(), std::size_t(1));
    QCOMPARE(s.targets[0].id, 7);
    QCOMPARE(s.targets[0].name, std::string("ferry"));
    QCOMPARE(s.targets[0].appearUs, 10 * kMicrosPerSecond);
    QCOMPARE(s.targets[0].leaveUs, std::optional<TimeUs>(50 * kMicrosPerSecond));
    RK_COMPARE_NEAR(s.targets[0].motion.randomAcceleration->sigma, 0.1, 1e-12);
    QCOMPARE(s.targets[0].motion.schedule.size(), std::size_t(1));
    RK_COMPARE_NEAR(s.tracker.targetAcceleration.sigma, std::sqrt(0.005), 1e-12);
    QCOMPARE(s.tracker.feed, track::OwnShipFeed::Measurement);
    QCOMPARE(s.tracker.capacity, std::size_t(50));
    QCOMPARE(s.tracker.association, track::Association::Nearest);  // default
  }
  void readsTheA823BudgetClutterAndTrackManagement() {
    const std::string text = variant("\"gyro\": {\"sd_deg\": 1}", R"("gyro": {"sd_deg": 1},
    "radar": {"error_budget": "a823", "gyro_calibration_deg": -0.5, "clutter_per_km2": 0.1,
              "clutter_max_range_nm": 3, "min_range_m": 40}
  },
  "tracker": {"association": "known", "confirm": {"hits": 2, "of_sweeps": 3}, "keep": {"hits": 4, "of_sweeps": 8},
              "auto_acquire": false, "lost_hold_s": 30, "danger_cpa_nm": 0.5, "danger_tcpa_min": 6,
              "acquisition_zones": [{"min_range_nm": 0.5, "max_range_nm": 6, "from_bearing_deg": 270, "to_bearing_deg": 90}])");
    const sim::Scenario s = files::parseScenario(text, "t.json");
    QCOMPARE(s.radar.rangeSdM, 20.0);
    RK_COMPARE_NEAR(radToDeg(s.radar.bearingSdRad), std::hypot(0.05, 0.03), 1e-12);
    RK_COMPARE_NEAR(radToDeg(s.radar.bearingBacklashRad), 0.05, 1e-12);
    RK_COMPARE_NEAR(s.radar.rangeQuantumM, 0.02 * 1852.0, 1e-9);
    RK_COMPARE_NEAR(radToDeg(s.radar.bearingQuantumRad), 0.2, 1e-12);
    RK_COMPARE_NEAR(radToDeg(s.radar.gyroCalibrationRad), -0.5, 1e-12);  // overridden
    RK_COMPARE_NEAR(radToDeg(s.radar.gyroScatterSdRad), 0.12, 1e-12);
    QCOMPARE(s.radar.clutterPerKm2, 0.1);
    RK_COMPARE_NEAR(s.radar.clutterMaxRangeM, 3 * 1852.0, 1e-9);
    QCOMPARE(s.radar.minRangeM, 40.0);
    QCOMPARE(s.tracker.association, track::Association::Known);
    QCOMPARE(s.tracker.confirmHits, 2);
    QCOMPARE(s.tracker.confirmSweeps, 3);
    QCOMPARE(s.tracker.keepHits, 4);
    QCOMPARE(s.tracker.keepSweeps, 8);
    QVERIFY(!s.tracker.autoAcquire);
    QCOMPARE(s.tracker.lostHoldS, 30.0);
    RK_COMPARE_NEAR(s.tracker.dangerCpaM, 926.0, 1e-9);
    QCOMPARE(s.tracker.dangerTcpaS, 360.0);
    QCOMPARE(s.tracker.zones.size(), std::size_t(1));
    QVERIFY(s.tracker.zones[0].contains(3000.0, degToRad(10.0)));
    QVERIFY(!s.tracker.zones[0].contains(3000.0, degToRad(180.0)));
    // Without the budget the two sds are required; a wrong budget name is refused.
    for (const auto& [radar, msg] :
         {std::pair{R"("radar": {"range_sd_m": 20})",
                    "sensors.radar.bearing_sd_deg: required field is missing"},
          std::pair{R"("radar": {"error_budget": "b999"})", "sensors.radar.error_budget: must be"},
          std::pair{R"("radar": {"error_budget": "a823", "clutter_per_km2": -1})",
                    "sensors.radar.clutter_per_km2: must not be negative"},
          std::pair{R"("radar": {"error_budget": "a823", "min_range_m": 50000, "max_range_nm": 12})",
                    "sensors.radar.min_range_m: must be below max_range_nm"}}) {
      try {
        files::parseScenario(
            variant("\"gyro\": {\"sd_deg\": 1}", std::string("\"gyro\": {\"sd_deg\": 1}, ") + radar),
            "t.json");
        QFAIL(radar);
      } catch (const io::InputError& e) {
        QVERIFY2(QString(e.what()).contains(msg), e.what());
      }
    }
  }
  void badTargetsAndTracker_data() {
    QTest::addColumn<QString>("insert");
    QTest::addColumn<QString>("expected");
    QTest::newRow("duplicate id") << R"("targets": [{"id": 1}, {"id": 1}],)"
                                  << "targets[1].id: id 1 is used by another target";
    QTest::newRow("leaves before it appears") << R"("targets": [{"id": 1, "appear_s": 60, "leave_s": 60}],)"
                                              << "targets[0].leave_s: must be after appear_s";
    QTest::newRow("negative id") << R"("targets": [{"id": -3}],)"
                                 << "targets[0].id: must be a non-negative integer";
    QTest::newRow("unknown target field") << R"("targets": [{"id": 1, "colour": "red"}],)"
                                          << "targets[0].colour: unknown field";
    QTest::newRow("bad feed") << R"("tracker": {"own_ship_feed": "both"},)"
                              << "tracker.own_ship_feed: must be";
    QTest::newRow("zero capacity") << R"("tracker": {"capacity": 0},)"
                                   << "tracker.capacity: must be an integer";
    QTest::newRow("bad association") << R"("tracker": {"association": "oracle"},)"
                                     << "tracker.association: must be";
    QTest::newRow("M above N") << R"("tracker": {"confirm": {"hits": 4, "of_sweeps": 3}},)"
                               << "tracker.confirm: needs integers";
    QTest::newRow("fractional keep") << R"("tracker": {"keep": {"hits": 4.5, "of_sweeps": 10}},)"
                                     << "tracker.keep: needs integers";
    QTest::newRow("inverted zone")
        << R"("tracker": {"acquisition_zones": [{"min_range_nm": 5, "max_range_nm": 2}]},)"
        << "tracker.acquisition_zones[0].max_range_nm: must exceed min_range_nm";
    QTest::newRow("zone without range")
        << R"("tracker": {"acquisition_zones": [{"from_bearing_deg": 10}]},)"
        << "tracker.acquisition_zones[0].max_range_nm: required field is missing";
    QTest::newRow("negative danger cpa") << R"("tracker": {"danger_cpa_nm": -1},)"
                                         << "tracker.danger_cpa_nm: must not be negative";
    QTest::newRow("both variance and sigma")
        << R"("tracker": {"target_acceleration": {"variance_m2_s4": 1, "sigma_mps2": 1, "beta_per_s": 1}},)"
        << "tracker.target_acceleration.sigma_mps2: give either";
    QTest::newRow("unknown filter") << R"("tracker": {"filter": "kalman"},)"
                                    << "tracker.filter: must be \"ekf\"";
    QTest::newRow("alpha above the paper's bound")
        << R"("tracker": {"filter": "abg", "alpha_beta_gamma": {"alpha": 0.7}},)"
        << "tracker.alpha_beta_gamma.alpha: must lie in (0, 0.6]";
    QTest::newRow("unknown abg field") << R"("tracker": {"alpha_beta_gamma": {"beta": 0.1}},)"
                                       << "tracker.alpha_beta_gamma.beta: unknown field";
    QTest::newRow("negative IMM sojourn") << R"("tracker": {"imm": {"ct_sojourn_s": -5}},)"
                                          << "tracker.imm.ct_sojourn_s: must be positive";
    QTest::newRow("IMM probability of one") << R"("tracker": {"imm": {"manoeuvre_probability": 1}},)"
                                            << "tracker.imm.manoeuvre_probability: must lie in (0, 1)";
  }
  void readsTheTrackerKind() {
    // "filter" chooses; "input_estimation" alone means ekf-ie (files written before the choice).
    const auto withTracker = [](const std::string& tracker) {
      return files::parseScenario(
          variant("\"duration_s\": 100,", "\"duration_s\": 100,\n  \"tracker\": " + tracker + ","), "t.json");
    };
    QCOMPARE(withTracker("{}").tracker.kind, track::TrackerKind::Ekf);
    QCOMPARE(withTracker(R"({"input_estimation": {"window": 10}})").tracker.kind,
             track::TrackerKind::EkfInputEstimation);
    const auto s = withTracker(
        R"({"filter": "imm", "imm": {"ct_sojourn_s": 30, "initial_turn_sd_dps": 2}, "alpha_beta_gamma": {"alpha": 0.2, "expanding_start": false}})");
    QCOMPARE(s.tracker.kind, track::TrackerKind::Imm);
    QCOMPARE(s.tracker.imm.ctSojournS, 30.0);
    RK_COMPARE_NEAR(radToDeg(s.tracker.imm.initialTurnSdRadPerS), 2.0, 1e-12);
    QCOMPARE(s.tracker.abg.alpha, 0.2);
    QVERIFY(!s.tracker.abg.expandingStart);
    // Written and read back unchanged.
    const auto back = files::parseScenario(files::writeScenario(s), "back.json");
    QCOMPARE(back.tracker.kind, s.tracker.kind);
    QCOMPARE(back.tracker.imm.ctSojournS, 30.0);
    QCOMPARE(back.tracker.imm.ctTurnQ, s.tracker.imm.ctTurnQ);
    QCOMPARE(back.tracker.abg.alpha, 0.2);
    QCOMPARE(back.tracker.abg.expandingStart, false);
  }
  void badTargetsAndTracker() {
    QFETCH(QString, insert);
    QFETCH(QString, expected);
    const std::string text =
        variant("\"duration_s\": 100,", "\"duration_s\": 100,\n  " + insert.toStdString());
    try {
      files::parseScenario(text, "t.json");
      QFAIL("accepted a bad scenario");
    } catch (const io::InputError& e) {
      QVERIFY2(QString(e.what()).contains(expected), e.what());
    }
  }
  void missingFileIsNamed() {
    try {
      files::loadScenarioFile("/nonexistent/dir/s.json");
      QFAIL("opened a missing file");
    } catch (const io::InputError& e) {
      QCOMPARE(QString(e.what()), QString("/nonexistent/dir/s.json: cannot open: No such file or directory"));
    }
  }
};

QTEST_APPLESS_MAIN(TestScenarioJson)
#include "tst_scenario_json.moc"
