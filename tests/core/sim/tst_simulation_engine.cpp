#include <QTest>

#include <algorithm>
#include <map>

#include "common/angles.h"
#include "files/scenario_json.h"
#include "navigation/dr_horizon.h"
#include "resources/embedded.h"
#include "sim/scenario_run.h"
#include "sim/simulation_engine.h"
#include "support/drkf_fixtures.h"

using namespace reckoner;
using namespace reckoner::sim;
using sensors::SensorId;

namespace {
/// Largest difference between two runs' frames (truth, estimate, covariance, tracks); infinity when
/// they differ in shape.
double runDifference(const std::vector<SimFrame>& a, const std::vector<SimFrame>& b) {
  if (a.size() != b.size()) {
    qWarning("runs differ in length: %zu and %zu frames", a.size(), b.size());
    return std::numeric_limits<double>::infinity();
  }
  double worst = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const SimFrame &fa = a[k], &fb = b[k];
    // (A target added during a run is in the frames from then on; in the saved scenario's run it is
    // listed from the start, not yet present.)
    const auto present = [](const SimFrame& f) {
      return std::count(f.targetPresent.begin(), f.targetPresent.end(), 1);
    };
    if (fa.timeUs != fb.timeUs || fa.tracks.size() != fb.tracks.size() || present(fa) != present(fb) ||
        fa.measurements.size() != fb.measurements.size() || fa.plots.size() != fb.plots.size()) {
      qWarning(
          "frames differ at t = %g s: tracks %zu/%zu, targets %td/%td, measurements %zu/%zu, plots %zu/%zu",
          toSeconds(fa.timeUs), fa.tracks.size(), fb.tracks.size(), present(fa), present(fb),
          fa.measurements.size(), fb.measurements.size(), fa.plots.size(), fb.plots.size());
      return std::numeric_limits<double>::infinity();
    }
    worst = std::max(worst, std::hypot(fa.truth.position.xM - fb.truth.position.xM,
                                       fa.truth.position.yM - fb.truth.position.yM));
    worst = std::max(worst, (fa.estimate.x - fb.estimate.x).cwiseAbs().maxCoeff());
    worst = std::max(worst, (fa.estimate.P - fb.estimate.P).cwiseAbs().maxCoeff());
    for (std::size_t i = 0; i < fa.tracks.size(); ++i)
      worst = std::max(worst, (fa.tracks[i].estimate.x - fb.tracks[i].estimate.x).cwiseAbs().maxCoeff());
    for (std::size_t i = 0; i < fa.targets.size(); ++i) {
      if (!fa.targetPresent[i]) continue;
      worst = std::max(worst, std::hypot(fa.targets[i].position.xM - fb.targets[i].position.xM,
                                         fa.targets[i].position.yM - fb.targets[i].position.yM));
    }
    if (worst > 1e-6) {
      qWarning("runs part at t = %g s (truth %g, estimate %g, targets)", toSeconds(fa.timeUs),
               std::hypot(fa.truth.position.xM - fb.truth.position.xM,
                          fa.truth.position.yM - fb.truth.position.yM),
               (fa.estimate.x - fb.estimate.x).cwiseAbs().maxCoeff());
      return worst;
    }
  }
  return worst;
}

std::vector<SimFrame> runAll(SimulationEngine& e) {
  std::vector<SimFrame> frames;
  while (!e.finished()) frames.push_back(e.step());
  return frames;
}
}  // namespace

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
  void aTargetThatLeavesIsNoLongerSeen() {
    // ais-harbour: the radar sees every target; the first with a transponder leaves at 600 s: no echo or
    // AIS message of it after that, its track and AIS target are dropped, and its transponder released.
    Scenario s = test::builtinScenario("ais-harbour");
    const TimeUs leave = 600 * kMicrosPerSecond;
    const auto k =
        static_cast<std::size_t>(std::find_if(s.targets.begin(), s.targets.end(),
                                              [](const TargetSpec& t) { return t.ais.has_value(); }) -
                                 s.targets.begin());
    QVERIFY(k < s.targets.size());
    s.targets[k].leaveUs = leave;
    QVERIFY(checkScenario(s).empty());
    const int id = s.targets[k].id;
    const std::uint32_t mmsi = s.targets[k].ais->mmsi;
    SimulationEngine e(s, 3);
    const std::size_t transponders = e.ais().transponders();
    QCOMPARE(transponders,
             static_cast<std::size_t>(std::count_if(s.targets.begin(), s.targets.end(),
                                                    [](const TargetSpec& t) { return t.ais.has_value(); })));
    int plotsBefore = 0, plotsAfter = 0, aisBefore = 0, aisAfter = 0;
    bool trackedBefore = false, trackedAtEnd = false, inTableAtEnd = false;
    while (!e.finished()) {
      const SimFrame f = e.step();
      for (std::size_t i = 0; i < f.plots.size(); ++i)
        if (f.plotSources[i] == id) ++(f.plots[i].timeUs < leave ? plotsBefore : plotsAfter);
      for (const auto& r : f.aisReceived)
        if (r.message.mmsi == mmsi) ++(r.rxUs < leave ? aisBefore : aisAfter);
      QCOMPARE(f.targetPresent[k], std::uint8_t(f.timeUs < leave ? 1 : 0));
      // AND its transponder (and the hull history it keeps) is released when it leaves, not before
      QCOMPARE(e.ais().transponders(), f.timeUs < leave ? transponders : transponders - 1);
      const bool tracked = std::any_of(f.tracks.begin(), f.tracks.end(), [&](const TrackSnapshot& t) {
        return t.targetId == id && t.status != track::TrackStatus::Lost;
      });
      if (f.timeUs == leave) trackedBefore = tracked;
      trackedAtEnd = tracked;
      inTableAtEnd = f.aisTargets && std::any_of(f.aisTargets->begin(), f.aisTargets->end(),
                                                 [&](const track::AisTarget& a) { return a.mmsi == mmsi; });
    }
    QVERIFY2(plotsBefore > 100, qPrintable(QString::number(plotsBefore)));
    QCOMPARE(plotsAfter, 0);
    QVERIFY(aisBefore > 20);
    QCOMPARE(aisAfter, 0);
    QVERIFY(trackedBefore);
    QVERIFY(!trackedAtEnd);
    QVERIFY(!inTableAtEnd);
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
  void operatorCommandsAreRecordedSoTheSavedScenarioRepeatsTheRun() {
    // GIVEN the default scenario WHEN an operator orders a new course, switches GPS off, the log to
    // bottom lock, the radar off and on, adds a target, steers a target and extends the run THEN the
    // scenario written afterwards, read back and run with the same seed, gives the same run.
    const Scenario original = test::builtinScenario("default");
    SimulationEngine live(original, original.seed);
    std::vector<SimFrame> liveFrames;
    const auto stepTo = [&](double tS) {
      while (!live.finished() && toSeconds(live.timeUs()) < tS) liveFrames.push_back(live.step());
    };
    stepTo(30);
    // Guard zones drawn on the chart: a ring sector ahead, later none (the whole picture again).
    const track::AcquisitionZone ahead{200.0, 5000.0, degToRad(60.0), degToRad(180.0)};
    QVERIFY(live.setAcquisitionZones({ahead}));
    QVERIFY(!live.setAcquisitionZones({track::AcquisitionZone{500.0, 100.0, 0.0, 0.0}}));  // min > max
    stepTo(60);
    QCOMPARE(liveFrames.back().zones.size(), std::size_t(1));
    QVERIFY(liveFrames.back().zones.front() == ahead);
    live.orderOwnShip(HelmOrder{degToRad(200.0), 4.0});
    stepTo(90);
    live.setSensorPower(SensorId::Gps, false);
    live.setSpeedlogMode(sensors::SpeedlogMode::BottomLock);
    TargetSpec added;
    added.id = -1;
    added.motion.initialPosition = {liveFrames.back().truth.position.xM + 1500.0,
                                    liveFrames.back().truth.position.yM - 800.0};
    added.motion.initialVelocityMps = {-3.0, 1.0};
    const std::optional<int> id = live.addTarget(added);
    QVERIFY(id.has_value());
    stepTo(120);
    live.setRadarPower(false);
    stepTo(130);
    live.setRadarPower(true);
    live.orderOwnShip(HelmOrder{degToRad(90.0), 6.0});
    QVERIFY(live.setAcquisitionZones({}));
    QVERIFY(live.orderTarget(1, HelmOrder{degToRad(300.0), 3.0, degToRad(1.0), 0.05}));
    QVERIFY(!live.orderTarget(99, HelmOrder{0.0, 1.0}));
    stepTo(1800);
    QVERIFY(live.finished());
    QVERIFY(live.extendTo(1850 * kMicrosPerSecond));
    stepTo(1850);
    QCOMPARE(liveFrames.size(), std::size_t(1850));
    // The added target was tracked.
    QVERIFY(std::any_of(liveFrames.back().tracks.begin(), liveFrames.back().tracks.end(),
                        [&](const TrackSnapshot& t) { return t.targetId == *id; }));
    QVERIFY(liveFrames[200].order.has_value());

    const std::string text = files::writeScenario(live.scenario());
    const Scenario reopened = files::parseScenario(text, "saved.json");
    QCOMPARE(reopened.durationUs, 1850 * kMicrosPerSecond);
    QCOMPARE(reopened.targets.size(), original.targets.size() + 1);
    QCOMPARE(reopened.gps.power.at(fromSeconds(90.0)), true);  // the epoch at 90 s had GPS
    QCOMPARE(reopened.gps.power.at(fromSeconds(91.0)), false);
    QCOMPARE(reopened.tracker.zoneChanges.size(), std::size_t(2));
    QVERIFY(reopened.tracker.zoneChanges[0].second == std::vector<track::AcquisitionZone>{ahead});
    QVERIFY(reopened.tracker.zoneChanges[1].second.empty());
    QVERIFY(liveFrames[1000].zones.empty());
    SimulationEngine again(reopened, reopened.seed);
    const std::vector<SimFrame> againFrames = runAll(again);
    const double diff = runDifference(liveFrames, againFrames);
    QVERIFY2(diff < 1e-6, qPrintable(QString("largest difference %1").arg(diff)));
  }
  void operatorValuesStayWithinWhatAFileMayHold() {
    // GIVEN a running scenario WHEN the operator orders 200 m/s, adds a target 5,000 km away and runs
    // past a month THEN the order is held to 100 kn, the target refused, the run not extended, and the
    // scenario written afterwards reads back (a saved file used to hold what the reader refuses).
    SimulationEngine live(test::builtinScenario("default"), 1);
    live.step();
    live.orderOwnShip(HelmOrder{degToRad(90.0), 200.0});
    QVERIFY(live.orderTarget(1, HelmOrder{0.0, 1e6}));
    TargetSpec far;
    far.motion.initialPosition = {5e6, 0.0};
    QVERIFY(!live.addTarget(far).has_value());
    QVERIFY(!live.extendTo(fromSeconds(31.0 * 86400.0)));
    const auto& order = live.scenario().ownShip.schedule.back().order;
    QVERIFY(order && order->speedMps <= 51.44 + 1e-9);
    const Scenario back = files::parseScenario(files::writeScenario(live.scenario()), "saved.json");
    QCOMPARE(back.ownShip.schedule.size(), live.scenario().ownShip.schedule.size());
  }
  void everyBuiltinScenarioSurvivesWriteAndRead() {
    for (const auto& f : resources::scenarios()) {
      const Scenario s = files::parseScenario(f.text, std::string(f.name));
      const Scenario back = files::parseScenario(files::writeScenario(s), std::string(f.name) + " (written)");
      QCOMPARE(back.durationUs, s.durationUs);
      QCOMPARE(back.targets.size(), s.targets.size());
      QCOMPARE(back.ownShip.schedule.size(), s.ownShip.schedule.size());
      SimulationEngine a(s, 5), b(back, 5);
      std::vector<SimFrame> fa, fb;
      for (int k = 0; k < 120 && !a.finished(); ++k) {
        fa.push_back(a.step());
        fb.push_back(b.step());
      }
      const double diff = runDifference(fa, fb);
      QVERIFY2(
          diff < 1e-6,
          qPrintable(QString("%1: %2").arg(QString::fromUtf8(f.name.data(), int(f.name.size()))).arg(diff)));
    }
  }
  void deadReckoningHorizonFromTheCovariance() {
    // GIVEN the default scenario's filter after 5 min WHEN GPS and Loran-C are gone THEN the 95% error
    // reaches a limit in finite time, later for a larger limit, and sooner without the log.
    Scenario s = test::builtinScenario("default");
    SimulationEngine e(s, 1);
    while (toSeconds(e.timeUs()) < 300) e.step();
    nav::DeadReckoningAids aids;
    aids.speedlog = aids.gyro = true;
    aids.speedlogVarM2PerS2 = s.speedlog.whiteVarM2PerS2;
    aids.gyroVarRad2 = s.gyro.sdRad * s.gyro.sdRad;
    const double now = nav::positionError95M(e.drkf().belief());
    QVERIFY(now > 0.0 && now < 50.0);
    const auto t100 = nav::timeToPositionLimitS(e.drkf(), aids, 100.0, 7200.0);
    const auto t200 = nav::timeToPositionLimitS(e.drkf(), aids, 200.0, 7200.0);
    QVERIFY(t100 && t200);
    QVERIFY2(*t100 > 10.0 && *t200 > *t100, qPrintable(QString("%1 %2").arg(*t100).arg(*t200)));
    aids.speedlog = false;
    const auto noLog = nav::timeToPositionLimitS(e.drkf(), aids, 100.0, 7200.0);
    QVERIFY(noLog && *noLog < *t100);
    QCOMPARE(*nav::timeToPositionLimitS(e.drkf(), aids, now * 0.5, 7200.0), 0.0);
    QVERIFY(!nav::timeToPositionLimitS(e.drkf(), aids, 1e7, 600.0).has_value());
    // THEN the horizon agrees with what the filter really does when GPS and Loran-C go off.
    e.setSensorPower(SensorId::Gps, false);
    e.setSensorPower(SensorId::LoranC, false);
    aids.speedlog = true;
    const double start = toSeconds(e.timeUs());
    const double predicted = *nav::timeToPositionLimitS(e.drkf(), aids, 100.0, 7200.0);
    while (!e.finished() && nav::positionError95M(e.drkf().belief()) < 100.0) e.step();
    const double actual = toSeconds(e.timeUs()) - start;
    QVERIFY2(predicted <= actual * 1.05 + 5.0 && predicted >= actual * 0.5,
             qPrintable(QString("predicted %1 s, filter %2 s").arg(predicted).arg(actual)));
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
