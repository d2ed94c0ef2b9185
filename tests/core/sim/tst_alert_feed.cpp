// The alert conditions of a run, read from its frames: the default scenario's GPS outage raises POSITION
// SOURCE LOST for exactly its dead-reckoning stretch and it waits for acknowledgement; every dangerous
// target the tracker flags raises a CPA/TCPA alarm for that track; a DR limit is reported while the 95%
// radius is above it; settings a scenario implies; impossible settings are named.
#include <QTest>

#include <algorithm>
#include <map>
#include <stdexcept>

#include "common/units.h"
#include "files/scenario_json.h"
#include "navigation/dr_horizon.h"
#include "resources/embedded.h"
#include "sim/alert_feed.h"
#include "support/compare_near.h"

using namespace reckoner;
using namespace reckoner::sim;
using alerts::AlertKind;

namespace {

Scenario builtin(const char* name) {
  const auto* f = resources::findScenario(name);
  if (!f) qFatal("no built-in scenario %s", name);
  return files::parseScenario(f->text, std::string("builtin:") + name);
}

struct Run {
  std::vector<alerts::AlertLogEntry> log;
  std::vector<track::TrackEvent> events;
  std::vector<std::pair<TimeUs, bool>> deadReckoning;  ///< changes of f.deadReckoning.active
  double maxError95M = 0.0;
};

Run runWithAlerts(const Scenario& s, AlertFeedSettings settings, alerts::AlertManager& m,
                  bool acknowledgeEverything = false) {
  SimulationEngine engine(s, 1);
  AlertFeed feed(settings);
  Run r;
  bool dr = false;
  while (!engine.finished()) {
    const SimFrame f = engine.step();
    feed.feed(f, m);
    if (acknowledgeEverything)
      for (const alerts::Alert& a : m.alerts()) m.acknowledge(f.timeUs, a.id);
    r.events.insert(r.events.end(), f.trackEvents.begin(), f.trackEvents.end());
    if (f.deadReckoning.active != dr) r.deadReckoning.emplace_back(f.timeUs, dr = f.deadReckoning.active);
    r.maxError95M = std::max(r.maxError95M, nav::positionError95M(f.estimate));
    const auto taken = m.takeLog();
    r.log.insert(r.log.end(), taken.begin(), taken.end());
  }
  return r;
}

int count(const Run& r, AlertKind kind, alerts::AlertLogEntry::Event e) {
  return static_cast<int>(std::count_if(r.log.begin(), r.log.end(), [&](const alerts::AlertLogEntry& x) {
    return x.id.kind == kind && x.event == e;
  }));
}

}  // namespace

class TestAlertFeed : public QObject {
  Q_OBJECT
 private slots:
  void theGpsOutageRaisesPositionSourceLostAndWaitsForAcknowledgement() {
    // GIVEN the default scenario (a GPS outage on the way in) WHEN run with nobody acknowledging
    const Scenario s = builtin("default");
    alerts::AlertManager m;
    const Run r = runWithAlerts(s, alertFeedSettingsFor(s), m);
    using E = alerts::AlertLogEntry::Event;
    QVERIFY(!r.deadReckoning.empty());
    // THEN the alarm is raised when dead reckoning starts and rectified when it ends, once per stretch
    int stretches = 0;
    for (std::size_t k = 0; k < r.deadReckoning.size(); ++k) stretches += r.deadReckoning[k].second ? 1 : 0;
    QCOMPARE(count(r, AlertKind::PositionSourceLost, E::Raised), stretches);
    const auto first = std::find_if(r.log.begin(), r.log.end(), [](const alerts::AlertLogEntry& x) {
      return x.id.kind == AlertKind::PositionSourceLost;
    });
    QVERIFY(first != r.log.end());
    QCOMPARE(first->event, E::Raised);
    QCOMPARE(first->timeUs, r.deadReckoning.front().first);
    QCOMPARE(first->priority, alerts::Priority::Alarm);
    // AND, never acknowledged, it is still shown at the end (rectified) when the fix came back
    if (!r.deadReckoning.back().second) {
      const alerts::Alert* a = m.find({AlertKind::PositionSourceLost, 0});
      QVERIFY(a);
      QCOMPARE(a->state, alerts::AlertState::Rectified);
    }
  }

  void everyDangerousTargetRaisesACpaAlarm() {
    // GIVEN the busy harbour (40 targets) WHEN run with every alert acknowledged at once
    const Scenario s = builtin("busy-harbour");
    alerts::AlertManager m;
    const Run r = runWithAlerts(s, alertFeedSettingsFor(s), m, true);
    using E = alerts::AlertLogEntry::Event;
    // THEN each track the tracker calls dangerous has a CPA/TCPA alarm of its own
    std::map<int, TimeUs> dangerous, alarmed;
    for (const auto& e : r.events)
      if (e.kind == track::TrackEvent::Kind::Dangerous) dangerous.emplace(e.trackId, e.timeUs);
    for (const auto& x : r.log)
      if (x.id.kind == AlertKind::CpaTcpa && x.event == E::Raised) alarmed.emplace(x.id.source, x.timeUs);
    const auto risingEdges = std::count_if(r.events.begin(), r.events.end(), [](const track::TrackEvent& e) {
      return e.kind == track::TrackEvent::Kind::Dangerous;
    });
    qInfo(
        "%zu dangerous tracks (%td rising edges), %zu with CPA/TCPA alarms, %d raised in all, %d lost-target "
        "warnings",
        dangerous.size(), risingEdges, alarmed.size(), count(r, AlertKind::CpaTcpa, E::Raised),
        count(r, AlertKind::LostTarget, E::Raised));
    QVERIFY(!dangerous.empty());
    for (const auto& [id, t] : dangerous) {
      QVERIFY2(alarmed.count(id), qPrintable(QString("track %1 dangerous but never alarmed").arg(id)));
      RK_COMPARE_NEAR(toSeconds(alarmed[id]), toSeconds(t), 3.0);  // within a sweep or so
    }
    // AND the hysteresis keeps the alarms no more numerous than the tracker's rising edges
    QVERIFY(count(r, AlertKind::CpaTcpa, E::Raised) <=
            static_cast<int>(std::count_if(r.events.begin(), r.events.end(), [](const auto& e) {
              return e.kind == track::TrackEvent::Kind::Dangerous;
            })));
    // AND acknowledged alarms were never removed while they held: every Cleared follows a Rectify of
    // the condition, i.e. no alert of a kind was raised twice without its condition ending in between
    QVERIFY(count(r, AlertKind::LostTarget, E::Raised) > 0);
  }

  /// GIVEN the built-in SART scenario (an active AIS-SART ahead, a MOB in test, a ferry with class A) WHEN
  /// run with nobody acknowledging THEN the distress alarm is raised once, for the SART alone, within its
  /// first burst, and still shown at the end; the MOB in test and the ferry raise none.
  void anActiveAisSartRaisesTheDistressAlarmAndTheTestOneNone() {
    const Scenario s = builtin("sart");
    alerts::AlertManager m;
    const Run r = runWithAlerts(s, alertFeedSettingsFor(s), m);
    using E = alerts::AlertLogEntry::Event;
    QCOMPARE(count(r, AlertKind::AisDistress, E::Raised), 1);
    const auto raised = std::find_if(r.log.begin(), r.log.end(), [](const alerts::AlertLogEntry& x) {
      return x.id.kind == AlertKind::AisDistress;
    });
    QCOMPARE(raised->id.source, 970012345);
    QCOMPARE(raised->priority, alerts::Priority::Alarm);
    // (raised by its first report: its "SART ACTIVE" text may come before its position, and then the
    // alarm has no range yet)
    QVERIFY2(raised->text.starts_with("AIS-SART 970012345 ACTIVE"), raised->text.c_str());
    QVERIFY(toSeconds(raised->timeUs) <= 62.0);  // the first burst starts within the first minute
    const alerts::Alert* a = m.find({AlertKind::AisDistress, 970012345});
    QVERIFY(a);
    QCOMPARE(a->state, alerts::AlertState::Unacknowledged);
    QVERIFY2(a->text.starts_with("AIS-SART 970012345 ACTIVE ") &&
                 a->text.find(" NM bearing ") != std::string::npos,
             a->text.c_str());
    QVERIFY(!m.find({AlertKind::AisDistress, 972001002}));
  }

  void theDeadReckoningLimitHoldsWhileTheRadiusIsAbove() {
    const Scenario s = builtin("default");
    AlertFeedSettings settings = alertFeedSettingsFor(s);
    alerts::AlertManager probe;
    const double maxE95 = runWithAlerts(s, settings, probe).maxError95M;
    settings.drLimitM = 0.5 * maxE95;
    alerts::AlertManager m;
    const Run r = runWithAlerts(s, settings, m);
    using E = alerts::AlertLogEntry::Event;
    QVERIFY(count(r, AlertKind::DeadReckoningLimit, E::Raised) >= 1);
    // AND with no limit set there is no such alert
    QCOMPARE(
        count(runWithAlerts(s, alertFeedSettingsFor(s), probe), AlertKind::DeadReckoningLimit, E::Raised), 0);
  }

  void gpsAndLoranFurtherApartThanTheLimitRaiseOneDiscrepancy() {
    AlertFeedSettings settings;
    settings.positionDiscrepancyM = 185.0;
    AlertFeed feed(settings);
    alerts::AlertManager m;
    const alerts::AlertId id{AlertKind::PositionDiscrepancy, 0};
    // GIVEN own ship at 10 m/s east (velocity through the water, no current), GPS every second and a
    // Loran-C fix half a second later: the Loran-C fix is where GPS puts the ship then, plus an offset
    const auto frame = [](double tS, double loranOffsetM) {
      SimFrame f;
      f.timeUs = fromSeconds(tS);
      f.estimate.x.setZero();
      f.estimate.x[est::drkf::kVelX] = 10.0;
      f.estimate.P.setIdentity();
      sensors::GpsSample g;
      g.timeUs = fromSeconds(tS - 0.5);
      g.position = {10.0 * (tS - 0.5), 0.0};
      sensors::LoranSample l;
      l.timeUs = fromSeconds(tS);
      l.position = {10.0 * tS, loranOffsetM};
      f.measurements = {g, l};
      return f;
    };
    // WHEN they agree (the 5 m the ship ran between the fixes is not a discrepancy) THEN nothing
    for (int t = 1; t <= 20; ++t) feed.feed(frame(t, 20.0), m);
    QVERIFY(!m.find(id));
    // WHEN the Loran-C fix wanders 50 m either side of the limit for two minutes THEN one alert
    for (int t = 21; t <= 140; ++t) feed.feed(frame(t, 185.0 + (t % 2 == 0 ? 50.0 : -50.0)), m);
    QCOMPARE(m.raisedCount(AlertKind::PositionDiscrepancy), 1);
    QVERIFY(m.find(id));
    QVERIFY(m.find(id)->text.find("GPS and Loran-C") != std::string::npos);
    // WHEN they agree again (below 80% of the limit) THEN the condition ends after 30 s
    for (int t = 141; t <= 169; ++t) feed.feed(frame(t, 100.0), m);
    QVERIFY(m.find(id)->state != alerts::AlertState::Rectified);
    QVERIFY(m.find(id)->text.find("limit 185 m") != std::string::npos);
    for (int t = 170; t <= 172; ++t) feed.feed(frame(t, 100.0), m);
    QVERIFY(!m.find(id) || m.find(id)->state == alerts::AlertState::Rectified);
    // AND a stale fix is never compared: Loran-C gone for 11 s leaves GPS alone, no alert
    AlertFeed quiet(settings);
    alerts::AlertManager m2;
    SimFrame f = frame(1, 500.0);
    quiet.feed(f, m2);
    QVERIFY(m2.find(id));
    for (int t = 2; t <= 12; ++t) {
      SimFrame g = frame(t, 500.0);
      g.measurements.pop_back();  // no Loran-C
      quiet.feed(g, m2);
    }
    QVERIFY(!m2.find(id) || m2.find(id)->state == alerts::AlertState::Rectified);
  }

  void theDefaultRunHasNoDiscrepancyAtTheDefaultLimitButATightOneFindsLoranErrors() {
    // The default scenario's Loran-C error is a Gauss-Markov process of 33 m sd per axis: far inside
    // 0.1 NM, and often outside 30 m.
    const Scenario s = builtin("default");
    AlertFeedSettings settings = alertFeedSettingsFor(s);
    using E = alerts::AlertLogEntry::Event;
    alerts::AlertManager m;
    QCOMPARE(count(runWithAlerts(s, settings, m), AlertKind::PositionDiscrepancy, E::Raised), 0);
    settings.positionDiscrepancyM = 30.0;
    alerts::AlertManager tight;
    const int raised = count(runWithAlerts(s, settings, tight), AlertKind::PositionDiscrepancy, E::Raised);
    qInfo("a 30 m discrepancy limit: %d alerts in the default run", raised);
    QVERIFY(raised >= 1);
  }

  void newTracksInAGuardZoneRaiseItsWarningWhileThereAreZones() {
    // GIVEN the default run acquiring in one zone all round own ship out to 6 NM, and from 600 s on
    // (the operator removed it) in the whole picture
    Scenario s = builtin("default");
    s.tracker.zones = {track::AcquisitionZone{0.0, nmToMetres(6.0), 0.0, 0.0}};
    s.tracker.zoneChanges = {{fromSeconds(600.0), {}}};
    alerts::AlertManager m;
    const Run r = runWithAlerts(s, alertFeedSettingsFor(s), m);
    using E = alerts::AlertLogEntry::Event;
    // THEN the new tracks before 600 s raised GUARD ZONE, none after
    int before = 0, after = 0;
    for (const auto& e : r.log)
      if (e.id.kind == AlertKind::GuardZone && e.event == E::Raised)
        ++(e.timeUs < fromSeconds(600.0) ? before : after);
    qInfo("GUARD ZONE raised %d times before the zone was removed, %d after", before, after);
    QVERIFY(before >= 3);
    QCOMPARE(after, 0);
  }

  void settingsComeFromTheScenarioAndAreChecked() {
    Scenario s = builtin("default");
    s.tracker.dangerCpaM = 926.0;
    s.tracker.dangerTcpaS = 360.0;
    AlertFeedSettings a = alertFeedSettingsFor(s);
    QCOMPARE(a.cpa.cpaM, 926.0);
    QCOMPARE(a.cpa.tcpaS, 360.0);
    QVERIFY(a.guardZones);
    a.drLimitM = -1.0;
    try {
      AlertFeed feed(a);
      QFAIL("a negative DR limit was accepted");
    } catch (const std::invalid_argument& e) {
      QVERIFY(std::string(e.what()).find("dr_limit_m") != std::string::npos);
    }
    a.drLimitM = 0.0;
    a.positionDiscrepancyM = std::nan("");
    try {
      AlertFeed feed(a);
      QFAIL("a NaN discrepancy limit was accepted");
    } catch (const std::invalid_argument& e) {
      QVERIFY(std::string(e.what()).find("position_discrepancy_m") != std::string::npos);
    }
  }
};

QTEST_GUILESS_MAIN(TestAlertFeed)
#include "tst_alert_feed.moc"
