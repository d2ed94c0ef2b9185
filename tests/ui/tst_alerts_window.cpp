// The window's alerts, driven as an officer would: the default scenario's CPA/TCPA alarm and its GPS
// outage appear in the Alerts dock and in the toolbar banner; "Acknowledge" acts on one alert and never
// removes one whose condition holds; "Silence" quiets for 30 s and the alarm sounds again; a rectified
// alarm stays until acknowledged; every change is in the history tab and the alert log file.
#include <QFile>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>

#include "main_window_test_helpers.h"
#include "ui/panels/alert_panel.h"
#include "ui/panels/alert_sound.h"

using namespace reckoner;
using namespace reckoner::ui;
using namespace reckoner::ui::test;
using alerts::AlertKind;
using alerts::AlertState;

namespace {

const alerts::Alert* firstOf(const MainWindow& w, AlertKind kind) {
  for (const auto& a : w.history().alerts())
    if (a.id.kind == kind) return &a;
  return nullptr;
}

QPushButton* button(MainWindow& w, const char* name) {
  return w.alertPanel()->findChild<QPushButton*>(QString::fromLatin1(name));
}

/// Selects the row of `id` in the alert list.
bool select(MainWindow& w, alerts::AlertId id) {
  QListWidget* list = w.alertPanel()->list();
  for (int r = 0; r < list->count(); ++r)
    if (list->item(r)->data(Qt::UserRole).value<alerts::AlertId>() == id) {
      list->setCurrentRow(r);
      return true;
    }
  return false;
}

/// Whether the alert `id` is in `state` (nullopt: gone) in the window's latest frame and list.
bool shows(MainWindow& w, alerts::AlertId id, std::optional<AlertState> state) {
  const alerts::Alert* a = w.history().alert(id);
  if (!state) return a == nullptr && !w.refreshPending();
  return a && a->state == *state && !w.refreshPending();
}

}  // namespace

class TestAlertsWindow : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { isolateFromTheUser("tst_alerts_window"); }

  void theAudibleSignalFollowsTheMostUrgentAudibleAlert() {
    alerts::Alert warning;
    warning.priority = alerts::Priority::Warning;
    alerts::Alert alarm;
    alarm.priority = alerts::Priority::Alarm;
    alerts::Alert caution;
    caution.priority = alerts::Priority::Caution;
    QCOMPARE(alertSoundPattern({}), AlertSoundPattern::Silent);
    QCOMPARE(alertSoundPattern({caution}), AlertSoundPattern::Silent);
    QCOMPARE(alertSoundPattern({caution, warning}), AlertSoundPattern::Warning);
    QCOMPARE(alertSoundPattern({warning, alarm}), AlertSoundPattern::Alarm);
    alarm.state = alerts::AlertState::Silenced;  // silenced or acknowledged: not audible
    QCOMPARE(alertSoundPattern({warning, alarm}), AlertSoundPattern::Warning);
    warning.state = alerts::AlertState::Acknowledged;
    QCOMPARE(alertSoundPattern({warning, alarm}), AlertSoundPattern::Silent);
    // An alarm's burst: three 150 ms tones with 100 ms between them, at 22.05 kHz, 16-bit mono, the
    // tones loud and the gaps silent.
    const int rate = 22050;
    const QByteArray pcm = renderAlertBurst(AlertSoundPattern::Alarm, rate);
    const AlertSoundTiming t = alertSoundTiming(AlertSoundPattern::Alarm);
    QCOMPARE(pcm.size(), 2 * (3 * (t.toneMs * rate / 1000) + 2 * (t.gapMs * rate / 1000)));
    const auto* samples = reinterpret_cast<const qint16*>(pcm.constData());
    const int toneEnd = t.toneMs * rate / 1000;
    qint16 peak = 0;
    for (int i = 0; i < toneEnd; ++i) peak = std::max<qint16>(peak, samples[i]);
    QVERIFY(peak > 10000);
    for (int i = toneEnd; i < toneEnd + t.gapMs * rate / 1000; ++i) QCOMPARE(samples[i], qint16(0));
    QVERIFY(renderAlertBurst(AlertSoundPattern::Silent, rate).isEmpty());
  }

  void anOfficerWorksTheAlertsOfTheDefaultRun() {
    MainWindow w(freshOptions());
    QFile::remove(w.alertLogPath());
    showAndWait(w);
    QVERIFY(!w.alarmBanner()->isVisible());
    QVERIFY(!button(w, "acknowledge")->isEnabled());

    // GIVEN the default run at 660 s, when target 3 closes to 0.2 NM in 4 min
    runUntil(w, 660.0);
    const alerts::Alert* cpa = firstOf(w, AlertKind::CpaTcpa);
    QVERIFY(cpa);
    const alerts::AlertId cpaId = cpa->id;
    QCOMPARE(cpa->state, AlertState::Unacknowledged);
    QCOMPARE(cpa->priority, alerts::Priority::Alarm);
    // THEN the banner shows it, and the list
    QTRY_VERIFY_WITH_TIMEOUT(w.alarmBanner()->isVisible(), kTimeoutMs);
    QVERIFY(w.alarmBanner()->text().startsWith(QStringLiteral("ALARM  CPA/TCPA  track")));
    QVERIFY(w.alertPanel()->list()->count() >= 1);
    QVERIFY(w.alertPanel()->list()->item(0)->font().bold());
    // AND the alarm's audible pattern is on (decided, never played in a test)
    QVERIFY(!w.alertSound()->canPlay());
    QCOMPARE(w.alertSound()->pattern(), AlertSoundPattern::Alarm);
    QVERIFY(w.alertSound()->burstCount() >= 1);
    saveWindowShot(w, QStringLiteral("alerts-cpa"));

    // WHEN acknowledged while the target is still dangerous THEN it stays, steady
    QVERIFY(button(w, "acknowledge")->isEnabled());
    QTest::mouseClick(button(w, "acknowledge"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(shows(w, cpaId, AlertState::Acknowledged), kTimeoutMs);
    QVERIFY(w.alarmBanner()->isVisible());
    QVERIFY(!w.alertPanel()->list()->item(0)->font().bold());

    // GIVEN the GPS outage at 963 s
    runUntil(w, 975.0);
    const alerts::AlertId fix{AlertKind::PositionSourceLost, 0};
    QVERIFY(shows(w, fix, AlertState::Unacknowledged));
    QVERIFY(w.history().latest().alertAudible);
    // WHEN silenced THEN quiet, and 30 s later (still unacknowledged) audible again
    QTest::mouseClick(button(w, "silence"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(shows(w, fix, AlertState::Silenced), kTimeoutMs);
    QVERIFY(!w.history().latest().alertAudible);
    QTRY_COMPARE_WITH_TIMEOUT(w.alertSound()->pattern(), AlertSoundPattern::Silent, kTimeoutMs);
    runUntil(w, 1010.0);
    QVERIFY(shows(w, fix, AlertState::Unacknowledged));
    QVERIFY(w.history().latest().alertAudible);

    // WHEN the fix comes back unacknowledged THEN the alarm stays, rectified, until acknowledged
    runUntil(w, 1400.0);
    QVERIFY(shows(w, fix, AlertState::Rectified));
    QVERIFY(select(w, fix));
    QVERIFY(button(w, "acknowledge")->isEnabled());
    QTest::mouseClick(button(w, "acknowledge"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(shows(w, fix, std::nullopt), kTimeoutMs);

    // AND the history tab and the log file tell the story
    QStringList history;
    for (int r = 0; r < w.alertPanel()->historyList()->count(); ++r)
      history << w.alertPanel()->historyList()->item(r)->text();
    const QString all = history.join('\n');
    for (const char* event : {"raised", "silenced", "silence ended", "rectified", "acknowledged", "cleared"})
      QVERIFY2(all.contains(QStringLiteral("POSITION SOURCE LOST  ") + QString::fromLatin1(event)), event);
    QVERIFY(all.contains(QStringLiteral("ALARM  CPA/TCPA  acknowledged")));
    QFile log(w.alertLogPath());
    QVERIFY(log.open(QIODevice::ReadOnly | QIODevice::Text));
    const QString text = QString::fromUtf8(log.readAll());
    QCOMPARE(text.count(QLatin1Char('\n')), static_cast<qsizetype>(history.size()));
    QVERIFY(text.contains(QStringLiteral("POSITION SOURCE LOST  raised: no position fix: dead reckoning")));
    qInfo("alert log %s: %lld lines", qPrintable(w.alertLogPath()), static_cast<long long>(history.size()));
  }
};

QTEST_MAIN(TestAlertsWindow)
#include "tst_alerts_window.moc"
