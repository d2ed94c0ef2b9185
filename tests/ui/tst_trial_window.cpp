// The trial manoeuvre and the AIS picture in the window (docs/gui.md "Trial manoeuvre", "AIS and radar"):
// on the four-encounter scenario, Tracking > Trial manoeuvre shows the trial for the ordered course and
// speed, a drag of the vector handle proposes another one without ordering it (the run's helm order
// stays unset), and the chart shows the "T", the danger sectors and each target's closest approach; on
// the AIS harbour, the simulated transponders fill the AIS picture and associated stations are drawn
// once. Screenshots go to screenshots/ for a person to look at.
#include <QAction>
#include <QTest>

#include <algorithm>
#include <cmath>

#include "common/angles.h"
#include "common/units.h"
#include "main_window_test_helpers.h"
#include "support/compare_near.h"
#include "ui/main_window.h"

using namespace reckoner;
using namespace reckoner::ui;
using namespace reckoner::ui::test;

namespace {
MainWindowOptions options(const char* builtin) {
  MainWindowOptions o = freshOptions();
  o.scenarioPath = std::string("builtin:") + builtin;
  return o;
}
}  // namespace

class TestTrialWindow : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { isolateFromTheUser("tst_trial_window"); }

  void trialShownAndDraggedWithoutOrdering() {
    // GIVEN the four encounters at 300 s
    MainWindow w(options("trial-encounters"));
    showAndWait(w);
    runUntil(w, 300.0);
    QVERIFY(!w.history().latest().trial);
    // WHEN the trial is switched on
    auto* action = w.findChild<QAction*>(QStringLiteral("trialManoeuvre"));
    QVERIFY(action);
    action->trigger();
    QVERIFY(w.chart()->trialMode());
    // THEN the frame carries a trial for every confirmed track, at the present order
    QTRY_VERIFY_WITH_TIMEOUT(w.history().latest().trial != nullptr, kTimeoutMs);
    QCOMPARE(w.history().latest().trial->targets.size(), std::size_t{4});
    // WHEN the handle is dragged to 040, 10 kn
    QVERIFY(w.chart()->handlePosition().has_value());
    dragHandleTo(w, 40.0, 10.0);
    // THEN the trial follows the drag, and own ship was not ordered anything
    QTRY_VERIFY_WITH_TIMEOUT(
        std::abs(radToDeg(angleDiff(w.history().latest().trial->order.courseRad, degToRad(40.0)))) < 1.5,
        kTimeoutMs);
    const auto& trial = *w.history().latest().trial;
    RK_COMPARE_NEAR(mpsToKnots(trial.order.speedMps), 10.0, 0.3);
    RK_COMPARE_NEAR(trial.order.delayS, 30.0, 1e-9);
    QVERIFY(!w.history().latest().frame.order.has_value());
    int sectors = 0;
    for (auto d : trial.sectors.danger) sectors += d;
    QVERIFY(sectors > 0);
    qInfo("trial 040 at 10 kn: %d dangerous sector cells; the run's order untouched", sectors);
    saveWindowShot(w, QStringLiteral("trial_window"));
    // WHEN it is switched off THEN the frames carry none
    action->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(!w.history().latest().trial, kTimeoutMs);
  }

  void aisHarbourShowsTheStationsOnce() {
    MainWindow w(options("ais-harbour"));
    showAndWait(w);
    runUntil(w, 240.0);
    const LiveFrame& live = w.history().latest();
    QVERIFY(live.aisTargets);
    QCOMPARE(live.aisTargets->size(), std::size_t{30});
    int associated = 0;
    for (const auto& t : live.frame.tracks) associated += t.aisMmsi != 0;
    QVERIFY2(associated >= 25, qPrintable(QString::number(associated)));
    saveWindowShot(w, QStringLiteral("ais_fusion_window"));
  }

  /// GIVEN the SART scenario run two minutes THEN the window's AIS picture has the active AIS-SART as a
  /// distress (activated) and the MOB in test, and its alert list the SART's alarm, unacknowledged; an
  /// acknowledgement keeps it (a distress waits for acknowledgement and stays while it holds).
  void anActiveAisSartIsShownWithItsAlarm() {
    MainWindow w(options("sart"));
    showAndWait(w);
    runUntil(w, 120.0);
    const LiveFrame& live = w.history().latest();
    QVERIFY(live.aisTargets);
    const auto find = [&](std::uint32_t mmsi) -> const track::AisTarget* {
      for (const auto& t : *live.aisTargets)
        if (t.mmsi == mmsi) return &t;
      return nullptr;
    };
    QVERIFY(find(970012345) && find(970012345)->distress() && find(970012345)->activated);
    QVERIFY(find(972001002) && find(972001002)->deviceTest);
    const auto alarm = std::find_if(live.alerts.begin(), live.alerts.end(), [](const alerts::Alert& a) {
      return a.id.kind == alerts::AlertKind::AisDistress;
    });
    QVERIFY(alarm != live.alerts.end());
    QCOMPARE(alarm->id.source, 970012345);
    QCOMPARE(alarm->state, alerts::AlertState::Unacknowledged);
    // WHEN acknowledged THEN it stays, and the symbol is steady (drawn in every phase: the screenshot
    // always shows it)
    const alerts::AlertId id = alarm->id;
    w.controller()->acknowledgeAlert(id);
    QTRY_VERIFY_WITH_TIMEOUT(
        w.history().alert(id) && w.history().alert(id)->state == alerts::AlertState::Acknowledged,
        kTimeoutMs);
    saveWindowShot(w, QStringLiteral("sart_window"));
  }
};

QTEST_MAIN(TestTrialWindow)
#include "tst_trial_window.moc"
