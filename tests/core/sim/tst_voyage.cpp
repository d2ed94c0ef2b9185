// The voyage side of a run without charts (sim/voyage_watch.h): the autopilot follows a three-leg route
// on the DRKF's estimate (true cross-track error small on the legs, every leg taken, arrival), the
// route alerts through the alert feed (WAYPOINT APPROACH per waypoint, ARRIVAL, OFF TRACK when own ship
// leaves the track), XTE/RMB/APB in the run's NMEA output, the scenario file's voyage block written and
// read back; and the look-ahead's paths (navigation/look_ahead.h): their spread at every step is the
// predicted covariance.
#include <QTest>

#include <GeographicLib/Geodesic.hpp>
#include <cmath>

#include "alerts/alert_manager.h"
#include "common/angles.h"
#include "common/units.h"
#include "files/scenario_json.h"
#include "navigation/look_ahead.h"
#include "sim/alert_feed.h"
#include "sim/nmea_output.h"
#include "sim/scenario_run.h"
#include "sim/simulation_engine.h"
#include "support/compare_near.h"
#include "support/drkf_fixtures.h"

using namespace reckoner;

namespace {

geo::GeoPoint offset(const geo::GeoPoint& p, double azimuthDeg, double distM) {
  geo::GeoPoint q;
  GeographicLib::Geodesic::WGS84().Direct(p.latDeg, p.lonDeg, azimuthDeg, distM, q.latDeg, q.lonDeg);
  return q;
}

/// From the origin 2 km north-east, 2 km east, 2 km south-east, at 10 kn, the autopilot on.
sim::Scenario routeScenario(bool follow) {
  sim::Scenario s = test::builtinScenario("default");
  s.targets.clear();
  s.radar.fitted = false;
  s.gps.power = StepSchedule<bool>{true};
  s.loran.power = StepSchedule<bool>{true};
  s.speedlog.power = StepSchedule<bool>{true};
  s.speedlog.mode = StepSchedule<sensors::SpeedlogMode>{sensors::SpeedlogMode::GroundLock};
  s.ownShip.schedule.clear();
  s.ownShip.initialPosition = {0.0, 0.0};
  s.ownShip.initialVelocityMps = {3.6, 3.6};
  s.ownShip.initialHeadingRad.reset();
  s.durationUs = fromSeconds(1400.0);
  geo::Route r;
  r.name = "three legs";
  const geo::GeoPoint a = s.origin;
  const geo::GeoPoint b = offset(a, 45.0, 2000.0), c = offset(b, 90.0, 2000.0), d = offset(c, 135.0, 2000.0);
  int id = 1;
  for (const geo::GeoPoint& p : {a, b, c, d}) {
    geo::Waypoint w;
    w.id = id;
    w.name = "WP" + std::to_string(id++);
    w.position = p;
    w.leg.plannedSpeedKn = 10.0;
    r.waypoints.push_back(w);
  }
  s.voyage.route = r;
  s.voyage.followRoute = follow;
  return s;
}

}  // namespace

class TestVoyage : public QObject {
  Q_OBJECT
 private slots:
  void autopilotFollowsTheRoute() {
    const sim::Scenario s = routeScenario(true);
    sim::SimulationEngine engine(s, 3);
    sim::AlertFeed feed(sim::alertFeedSettingsFor(s));
    alerts::AlertManager m;
    double worstLegXtdM = 0.0;
    std::size_t lastLeg = 0;
    int legChanges = 0;
    bool arrived = false, offTrack = false;
    while (!engine.finished()) {
      const sim::SimFrame f = engine.step();
      feed.feed(f, m);
      QVERIFY(f.route.has_value());
      const nav::RouteStatus& r = *f.route;
      for (const auto& e : r.events)
        legChanges += e.kind == nav::RouteEventKind::LegChanged && e.previousTo != 0;
      arrived = arrived || r.arrived;
      offTrack = offTrack || r.offTrack;
      lastLeg = r.to;
      // the true ship against the leg, away from the turns and the start
      const geo::GeoPoint truth = engine.frame().toGeodetic(f.truth.position);
      const geo::LegFix fix = geo::legFix(*s.voyage.route, r.to, truth);
      if (toSeconds(f.timeUs) > 200.0 && r.trackPart == nav::TrackPart::Leg && fix.alongTrackM > 600.0 &&
          fix.alongTrackM < fix.legLengthM - 600.0)
        worstLegXtdM = std::max(worstLegXtdM, std::abs(fix.crossTrackM));
    }
    qInfo("worst true cross-track on the legs %.1f m; %d leg changes", worstLegXtdM, legChanges);
    QCOMPARE(legChanges, 2);
    QCOMPARE(lastLeg, std::size_t{3});
    QVERIFY(arrived);
    QVERIFY(!offTrack);
    QVERIFY(worstLegXtdM < 30.0);
    // the route alerts: an approach warning for each turn waypoint and the last, and the arrival
    for (int wp : {1, 2, 3})
      QVERIFY2(m.find({alerts::AlertKind::WaypointApproach, wp}), qPrintable(QString::number(wp)));
    QVERIFY(m.find({alerts::AlertKind::Arrival, 0}));
    QVERIFY(!m.find({alerts::AlertKind::OffTrack, 0}));
  }

  void offTrackWithoutTheAutopilot() {
    // the same route, the ship holding 045: off track after the first waypoint
    const sim::Scenario s = routeScenario(false);
    sim::SimulationEngine engine(s, 3);
    sim::AlertFeed feed(sim::alertFeedSettingsFor(s));
    alerts::AlertManager m;
    bool raised = false;
    while (!engine.finished()) {
      feed.feed(engine.step(), m);
      raised = raised || m.find({alerts::AlertKind::OffTrack, 0}) != nullptr;
    }
    QVERIFY(raised);
  }

  void autopilotSentences() {
    const sim::Scenario s = routeScenario(true);
    sim::RunNmeaOutput out(s, 1'700'000'000'000'000);
    int xte = 0, rmb = 0, apb = 0;
    sim::runScenario(
        s, 3, [&](const sim::SimFrame& f, const sim::OwnShipRow& row, std::span<const sim::TrackRow> t) {
          for (const std::string& l : out.frame(f, row, t)) {
            xte += l.rfind("$ECXTE,", 0) == 0;
            rmb += l.rfind("$ECRMB,", 0) == 0;
            apb += l.rfind("$ECAPB,", 0) == 0;
          }
        });
    QVERIFY(xte > 1000);
    QCOMPARE(rmb, xte);
    QCOMPARE(apb, xte);
  }

  void scenarioFileRoundTrip() {
    sim::Scenario s = routeScenario(true);
    s.voyage.draughtM = 7.5;
    s.voyage.safetyDepthM = 12.0;
    s.voyage.route->waypoints[2].leg.geometry = geo::LegGeometry::GreatCircle;
    s.voyage.route->waypoints[1].turnRadiusNm = 0.3;
    const sim::Scenario back = files::parseScenario(files::writeScenario(s), "voyage.json");
    QVERIFY(back.voyage.route.has_value());
    QVERIFY(*back.voyage.route == *s.voyage.route);
    QCOMPARE(back.voyage.followRoute, true);
    QCOMPARE(back.voyage.draughtM, 7.5);
    QCOMPARE(*back.voyage.safetyDepthM, 12.0);
    // a bad waypoint is named with its place
    std::string text = files::writeScenario(s);
    const auto at = text.find("\"lat_deg\"", text.find("\"waypoints\""));
    text.insert(text.find(':', at) + 1, " 95.0, \"lon_deg_x\":");
    try {
      files::parseScenario(text, "bad.json");
      QFAIL("no error");
    } catch (const io::InputError& e) {
      QVERIFY2(std::string(e.what()).find("voyage.route.waypoints[0].lon_deg_x") != std::string::npos,
               e.what());
    }
    // a waypoint out of range: the route's own check, naming the waypoint
    s.voyage.route->waypoints[0].position.latDeg = 95.0;
    try {
      files::parseScenario(files::writeScenario(s), "bad.json");
      QFAIL("no error");
    } catch (const io::InputError& e) {
      QVERIFY2(std::string(e.what()).find("waypoint 1") != std::string::npos, e.what());
    }
  }

  void lookAheadSpreadIsThePredictedCovariance() {
    sim::SimulationEngine engine(routeScenario(false), 5);
    for (int i = 0; i < 120; ++i) engine.step();
    const nav::LookAheadPrediction p = nav::predictLookAhead(engine.drkf(), nav::LookAheadSettings{});
    QVERIFY(p.valid);
    QCOMPARE(p.timesS.back(), 360.0);
    for (std::size_t k : {std::size_t{0}, p.timesS.size() / 2, p.timesS.size() - 1}) {
      est::Vec<2> mean = est::Vec<2>::Zero();
      for (const auto& path : p.paths) mean += est::Vec<2>(path[k].xM, path[k].yM);
      mean /= static_cast<double>(p.paths.size());
      est::Mat<2> cov = est::Mat<2>::Zero();
      for (const auto& path : p.paths) {
        const est::Vec<2> d(path[k].xM - mean[0], path[k].yM - mean[1]);
        cov += d * d.transpose();
      }
      cov /= static_cast<double>(p.paths.size() - 1);
      const double sd = std::sqrt(p.covariance[k].trace());
      RK_COMPARE_NEAR(mean[0], p.mean[k].xM, 0.05 * sd);
      RK_COMPARE_NEAR(mean[1], p.mean[k].yM, 0.05 * sd);
      RK_COMPARE_NEAR(std::sqrt(cov.trace()), sd, 0.05 * sd);
    }
  }
};

QTEST_GUILESS_MAIN(TestVoyage)
#include "tst_voyage.moc"
