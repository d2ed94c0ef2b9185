// Alert management after MSC.302(87): every kind raised, silenced, acknowledged and (where it
// escalates) escalated; acknowledgement never removes an alert whose condition holds; a rectified
// alarm waits for its acknowledgement; the CPA/TCPA condition's hysteresis; bounded history.
#include <QTest>

#include <stdexcept>

#include "alerts/alert_manager.h"
#include "alerts/cpa_alert.h"
#include "support/compare_near.h"

using namespace reckoner;
using namespace reckoner::alerts;

namespace {

TimeUs sec(double s) {
  return fromSeconds(s);
}

constexpr AlertKind kAllKinds[] = {AlertKind::CpaTcpa,
                                   AlertKind::GuardZone,
                                   AlertKind::LostTarget,
                                   AlertKind::LostAisTarget,
                                   AlertKind::PositionSourceLost,
                                   AlertKind::DeadReckoningLimit,
                                   AlertKind::PositionDiscrepancy,
                                   AlertKind::SensorNoise,
                                   AlertKind::Capacity,
                                   AlertKind::AisCpaTcpa,
                                   AlertKind::SafetyContourAhead,
                                   AlertKind::DangerAhead,
                                   AlertKind::Grounded,
                                   AlertKind::OffTrack,
                                   AlertKind::WaypointApproach,
                                   AlertKind::Arrival,
                                   AlertKind::DrFilterReset,
                                   AlertKind::TrackFilterReset,
                                   AlertKind::AisDistress};

track::Cpa cpaAt(double cpaM, double tcpaS) {
  track::Cpa c;
  c.defined = true;
  c.cpaM = cpaM;
  c.tcpaS = tcpaS;
  return c;
}

}  // namespace

class TestAlertManager : public QObject {
  Q_OBJECT
 private slots:
  void everyKindIsRaisedSilencedAcknowledgedAndEscalated() {
    QCOMPARE(static_cast<int>(std::size(kAllKinds)), kAlertKindCount);
    for (const AlertKind kind : kAllKinds) {
      const AlertKindTraits& traits = traitsOf(kind);
      QVERIFY(*traits.name);
      AlertManager m;
      const AlertId id{kind, 7};
      // GIVEN the condition holds WHEN reported THEN the alert is raised unacknowledged
      m.report(sec(10), id, true, "condition");
      const Alert* a = m.find(id);
      QVERIFY(a);
      QCOMPARE(a->state, AlertState::Unacknowledged);
      QCOMPARE(a->priority, traits.priority);
      QCOMPARE(m.raisedCount(kind), 1);
      if (traits.priority == Priority::Caution) {
        // a caution is shown, never audible, needs no acknowledgement and goes with its condition
        QVERIFY(!m.audible());
        QVERIFY(!m.silence(sec(11), id));
        QVERIFY(!m.acknowledge(sec(11), id));
        m.report(sec(12), id, false);
        QVERIFY(!m.find(id));
        continue;
      }
      QVERIFY(m.audible());
      // WHEN silenced THEN quiet for 30 s, then audible again while unacknowledged
      QVERIFY(m.silence(sec(11), id));
      QCOMPARE(m.find(id)->state, AlertState::Silenced);
      QVERIFY(!m.audible());
      m.tick(sec(40.9));
      QVERIFY(!m.audible());
      m.tick(sec(41));
      QCOMPARE(m.find(id)->state, AlertState::Unacknowledged);
      QVERIFY(m.audible());
      // WHEN an escalating warning stays unacknowledged 60 s THEN it is an alarm
      m.tick(sec(69.9));
      QCOMPARE(m.find(id)->priority, traits.priority);
      m.tick(sec(70));
      if (traits.escalates) {
        QCOMPARE(m.find(id)->priority, Priority::Alarm);
        QVERIFY(m.find(id)->escalated);
      } else {
        QCOMPARE(m.find(id)->priority, traits.priority);
      }
      // WHEN acknowledged while the condition holds THEN it stays, steady and quiet
      QVERIFY(m.acknowledge(sec(80), id));
      QCOMPARE(m.find(id)->state, AlertState::Acknowledged);
      QVERIFY(!m.audible());
      QVERIFY(!m.acknowledge(sec(81), id));  // once only
      m.tick(sec(500));
      QVERIFY(m.find(id));
      // WHEN the condition ends THEN it is gone; WHEN it returns THEN it is raised anew
      m.report(sec(600), id, false);
      QVERIFY(!m.find(id));
      m.report(sec(610), id, true, "again");
      QCOMPARE(m.find(id)->state, AlertState::Unacknowledged);
      QCOMPARE(m.find(id)->priority, traits.priority);
      QCOMPARE(m.raisedCount(kind), 2);
    }
  }

  void acknowledgingNeverRemovesAHoldingCondition() {
    AlertManager m;
    const AlertId danger{AlertKind::CpaTcpa, 116};
    m.report(sec(1), danger, true, "track 116: CPA 0.07 NM");
    for (int k = 0; k < 10; ++k) {
      m.acknowledge(sec(2 + k), danger);
      m.report(sec(2 + k), danger, true);
      QVERIFY(m.find(danger));
    }
    QCOMPARE(m.alerts().size(), std::size_t{1});
  }

  void aRectifiedAlarmWaitsForItsAcknowledgement() {
    AlertManager m;
    const AlertId fix{AlertKind::PositionSourceLost, 0};
    m.report(sec(1), fix, true, "no position fix");
    m.report(sec(5), fix, false);
    // THEN the officer still sees the alarm he missed, quiet
    QCOMPARE(m.find(fix)->state, AlertState::Rectified);
    QVERIFY(!m.audible());
    // AND its return makes it unacknowledged (and audible) again, counted as a new occurrence
    m.report(sec(6), fix, true);
    QCOMPARE(m.find(fix)->state, AlertState::Unacknowledged);
    QCOMPARE(m.raisedCount(AlertKind::PositionSourceLost), 2);
    m.report(sec(7), fix, false);
    QVERIFY(m.acknowledge(sec(8), fix));
    QVERIFY(!m.find(fix));
    // AND so does a lost target, a warning the officer must not miss
    const AlertId lost{AlertKind::LostTarget, 3};
    m.report(sec(10), lost, true);
    m.report(sec(11), lost, false);
    QVERIFY(m.find(lost));
    QCOMPARE(m.find(lost)->state, AlertState::Rectified);
    // BUT a CPA/TCPA alarm ends with its condition (MSC.302(87) 7.3.7), and so does a DR-limit warning
    const AlertId cpa{AlertKind::CpaTcpa, 3}, dr{AlertKind::DeadReckoningLimit, 0};
    m.report(sec(10), cpa, true);
    m.report(sec(10), dr, true);
    m.report(sec(11), cpa, false);
    m.report(sec(11), dr, false);
    QVERIFY(!m.find(cpa));
    QVERIFY(!m.find(dr));
  }

  void anAcknowledgedWarningDoesNotEscalate() {
    AlertManager m;
    const AlertId zone{AlertKind::GuardZone, 1};
    m.report(sec(0), zone, true);
    QVERIFY(m.acknowledge(sec(5), zone));
    m.tick(sec(1000));
    QCOMPARE(m.find(zone)->priority, Priority::Warning);
    // AND a silenced one does: escalation is audible again
    const AlertId lost{AlertKind::LostTarget, 2};
    m.report(sec(1000), lost, true);
    QVERIFY(m.silence(sec(1001), lost));
    m.tick(sec(1060));
    QCOMPARE(m.find(lost)->priority, Priority::Alarm);
    QCOMPARE(m.find(lost)->state, AlertState::Unacknowledged);
    QCOMPARE(m.audiblePriority(), Priority::Alarm);
  }

  void theListPutsTheMostUrgentFirstThenTheNewest() {
    AlertManager m;
    m.report(sec(1), {AlertKind::LostTarget, 1}, true);
    m.report(sec(2), {AlertKind::SensorNoise, 0}, true);
    m.report(sec(3), {AlertKind::CpaTcpa, 9}, true);
    m.report(sec(4), {AlertKind::CpaTcpa, 2}, true);
    m.report(sec(5), {AlertKind::LostTarget, 5}, true);
    m.acknowledge(sec(6), {AlertKind::CpaTcpa, 2});
    const std::vector<Alert> list = m.alerts();
    QCOMPARE(list.size(), std::size_t{5});
    QCOMPARE(list[0].id, (AlertId{AlertKind::CpaTcpa, 9}));     // unacknowledged alarm
    QCOMPARE(list[1].id, (AlertId{AlertKind::CpaTcpa, 2}));     // acknowledged alarm
    QCOMPARE(list[2].id, (AlertId{AlertKind::LostTarget, 5}));  // newer warning
    QCOMPARE(list[3].id, (AlertId{AlertKind::LostTarget, 1}));
    QCOMPARE(list[4].id, (AlertId{AlertKind::SensorNoise, 0}));
  }

  void theLogTellsTheStoryAndStaysBounded() {
    AlertConfig c;
    c.historyLimit = 10;
    AlertManager m(c);
    const AlertId id{AlertKind::LostTarget, 4};
    m.report(sec(1), id, true, "track 4");
    m.silence(sec(2), id);
    m.acknowledge(sec(3), id);
    m.report(sec(4), id, false);
    using E = AlertLogEntry::Event;
    const std::vector<AlertLogEntry> log = m.takeLog();
    QCOMPARE(log.size(), std::size_t{4});
    QCOMPARE(log[0].event, E::Raised);
    QCOMPARE(log[1].event, E::Silenced);
    QCOMPARE(log[2].event, E::Acknowledged);
    QCOMPARE(log[3].event, E::Cleared);
    QCOMPARE(log[0].text, std::string("track 4"));
    QCOMPARE(log[3].timeUs, sec(4));
    QVERIFY(m.takeLog().empty());
    for (int k = 0; k < 100; ++k) m.report(sec(10 + k), {AlertKind::LostTarget, k}, true);
    QCOMPARE(m.untakenLogEntries(), std::size_t{10});
    const std::vector<AlertLogEntry> kept = m.takeLog();
    QCOMPARE(kept.size(), std::size_t{10});
    QCOMPARE(kept.front().id, (AlertId{AlertKind::LostTarget, 90}));  // the newest ten
    QCOMPARE(kept.back().id, (AlertId{AlertKind::LostTarget, 99}));
    QCOMPARE(m.untakenLogEntries(), std::size_t{0});
    QCOMPARE(m.droppedLogEntries(), std::size_t{90});
  }

  void impossibleSettingsAreNamed() {
    AlertConfig c;
    c.silenceS = 0.0;
    try {
      AlertManager m(c);
      QFAIL("a zero silence was accepted");
    } catch (const std::invalid_argument& e) {
      QVERIFY(std::string(e.what()).find("silence_s") != std::string::npos);
    }
    c = {};
    c.escalateAfterS = std::numeric_limits<double>::quiet_NaN();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, AlertManager{c});
    CpaAlertLimits l;
    l.cpaMarginM = -1.0;
    try {
      CpaAlertCondition cond(l);
      QFAIL("a negative margin was accepted");
    } catch (const std::invalid_argument& e) {
      QVERIFY(std::string(e.what()).find("cpa_margin_m") != std::string::npos);
    }
  }

  void aTargetHoveringAtTheCpaLimitRaisesOneAlert() {
    // GIVEN a target whose CPA oscillates 50 m around the 1 NM limit, sweep after sweep, closing
    const auto run = [](const CpaAlertLimits& limits) {
      CpaAlertCondition condition(limits);
      AlertManager m;
      for (int sweep = 0; sweep < 200; ++sweep) {
        const double cpaM = limits.cpaM + (sweep % 2 == 0 ? -50.0 : 50.0);
        const double tcpaS = 600.0 - 2.4 * sweep;
        const track::Cpa c = cpaAt(cpaM, tcpaS);
        const TimeUs now = sec(2.4 * sweep);
        m.report(now, {AlertKind::CpaTcpa, 5}, condition.update(5, now, c), cpaAlertText(5, c));
        m.tick(now);
      }
      return m.raisedCount(AlertKind::CpaTcpa);
    };
    // THEN with the hysteresis it is one alert
    QCOMPARE(run(CpaAlertLimits{}), 1);
    // AND without it, one per approach (the test can tell the difference)
    CpaAlertLimits bare;
    bare.cpaMarginM = 0.0;
    bare.clearAfterS = 0.0;
    QCOMPARE(run(bare), 100);
  }

  void theCpaConditionEndsWhenTheTargetIsClearlyOutside() {
    CpaAlertLimits l;
    l.clearAfterS = 0.0;
    CpaAlertCondition c(l);
    QVERIFY(!c.update(1, sec(0), cpaAt(2000.0, 300.0)));  // outside the CPA limit
    QVERIFY(!c.update(1, sec(1), cpaAt(500.0, 800.0)));   // too far in time
    QVERIFY(!c.update(1, sec(2), cpaAt(500.0, -5.0)));    // passed
    QVERIFY(c.update(1, sec(3), cpaAt(500.0, 300.0)));
    QVERIFY(c.update(1, sec(4), cpaAt(1900.0, 300.0)));  // within the margin
    QVERIFY(c.update(1, sec(5), cpaAt(500.0, -20.0)));   // just past: still holding
    QVERIFY(!c.update(1, sec(6), cpaAt(500.0, -31.0)));  // clearly past
    QVERIFY(c.update(2, sec(7), cpaAt(100.0, 10.0)));    // per track
    QVERIFY(c.update(2, sec(8), cpaAt(std::numeric_limits<double>::quiet_NaN(), 10.0)));  // NaN keeps it
    c.forget(2);
    QVERIFY(!c.update(2, sec(9), cpaAt(3000.0, 10.0)));
    QCOMPARE(cpaAlertText(7, cpaAt(0.25 * 1852.0, 390.0)), std::string("track 7: CPA 0.25 NM in 6.5 min"));
  }

  void aNoisyTcpaMustStayOutsideBeforeTheConditionEnds() {
    // GIVEN a holding condition (clear_after_s 20) WHEN the TCPA jumps out for a sweep, then back
    CpaAlertCondition c;
    QVERIFY(c.update(1, sec(0), cpaAt(1000.0, 120.0)));
    QVERIFY(c.update(1, sec(2), cpaAt(1000.0, 900.0)));
    QVERIFY(c.update(1, sec(4), cpaAt(1000.0, 110.0)));
    // THEN it holds; only 20 s clearly outside end it
    QVERIFY(c.update(1, sec(10), cpaAt(1000.0, 900.0)));
    QVERIFY(c.update(1, sec(29.9), cpaAt(1000.0, 900.0)));
    QVERIFY(!c.update(1, sec(30), cpaAt(1000.0, 900.0)));
  }
};

QTEST_GUILESS_MAIN(TestAlertManager)
#include "tst_alert_manager.moc"
