// Playback of a voyage record in the window (docs/gui.md, "Playback"; issue 21): a record made here by
// the recorder on a live run (a simulated run's NMEA and radar plots with real AIS sentences, five
// minutes) is played back with Live ▸ Play back a record…: paused at its start; played at the fastest
// speed to its end, where the window's latest estimate is the last recorded one, bit for bit, and the
// track table and AIS have their targets; a seek back to the middle starts the run again (the history
// begins anew) and its estimate there is the recorded one; a jump to the next alert puts the clock on
// the mark and the alert in the list; ending the playback goes back to the simulation. A record that
// cannot be read is refused naming it. Screenshot: screenshots/playback.png.
#include <QComboBox>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>
#include <QToolBar>
#include <QToolButton>
#include <algorithm>
#include <filesystem>

#include "files/live_run.h"
#include "files/voyage_record.h"
#include "files/voyage_recorder.h"
#include "main_window_test_helpers.h"
#include "support/recorded_runs.h"
#include "ui/panels/playback_bar.h"

using namespace reckoner;
using namespace reckoner::ui;
using namespace reckoner::ui::test;

namespace {

const QString kAis = QStringLiteral(RECKONER_SHARED_DIR "/data/ais/gpsd-sample.aivdm");
const UtcUs kDay = *io::parseIso8601("2026-11-23T00:00:00Z");

template <class T>
T* child(const MainWindow& w, const char* name) {
  auto* c = w.findChild<T*>(QString::fromLatin1(name));
  if (!c) qFatal("no %s", name);
  return c;
}

const LiveFrame::Playback& playback(const MainWindow& w) {
  static const LiveFrame::Playback none;
  const auto& p = w.history().latest().playback;
  return p ? *p : none;
}

}  // namespace

class TestPlaybackWindow : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() {
    isolateFromTheUser("tst_playback_window");
    if (!QFile::exists(kAis)) QSKIP("../shared/data/ais is absent");
    QVERIFY(dir_.isValid());
    record_ = dir_.path().toStdString() + "/voyage.sqlite";
    const sim::LiveOptions lo = reckoner::test::radarLiveOptions();
    files::RecorderSettings s;
    s.program = "tst_playback_window";
    s.options = lo;
    s.sources = {{0, "nmea1", "nmea", "udp://:10110?name=nmea1"},
                 {0, "radar1", "radar", "udp://:2000?role=radar"}};
    const std::string out = dir_.path().toStdString() + "/live";
    std::filesystem::create_directories(out);
    files::VoyageRecorder recorder(record_, s, kDay);
    files::LiveRun run(lo, out, &recorder);
    for (const auto& b : reckoner::test::simulatedBatches(300, kDay, kAis.toStdString()))
      run.batch(b, b.front().receivedUtc);
    run.finish("live", kDay);
  }

  void playsSeeksAndJumpsToAlerts() {
    const files::VoyageRecord rec(record_);
    const auto recorded = rec.estimates(INT64_MIN, INT64_MAX);
    QVERIFY(recorded.size() > 250);
    MainWindow w(freshOptions());
    showAndWait(w);
    QVERIFY(w.startPlayback(QString::fromStdString(record_)));
    QTRY_VERIFY_WITH_TIMEOUT(w.isPlayback() && w.history().latest().playback.has_value(), kTimeoutMs);
    QVERIFY(child<QToolBar>(w, "playbackToolbar")->isVisible());
    QCOMPARE(playback(w).rate, 0.0);  // paused at the start
    // at the first estimate: the first fix and the reorder horizon (1 s) after it
    QVERIFY2(playback(w).clock < playback(w).first + 5 * kMicrosPerSecond,
             qPrintable(QString("%1 s in").arg(toSeconds(playback(w).clock - playback(w).first))));
    const std::vector<UtcUs> marks = PlaybackBar::alertTimes(playback(w));
    qInfo("record of %zu estimates, %zu alert log entries, %zu alerts raised", recorded.size(),
          rec.alerts().size(), marks.size());
    QVERIFY(!marks.empty());

    // Played at the fastest speed to the end
    auto* speed = child<QComboBox>(w, "playbackSpeed");
    speed->setCurrentIndex(speed->count() - 1);  // max
    child<QToolButton>(w, "playbackPlay")->click();
    QTRY_VERIFY_WITH_TIMEOUT(playback(w).atEnd && w.history().latest().frame.timeUs > 0, kTimeoutMs);
    RK_WAIT_VERIFY(settled(w));
    const sim::ReplayOwnRow& last = recorded.back();
    const LiveFrame& end = w.history().latest();
    QCOMPARE(end.liveUtc0 + end.frame.timeUs, last.utcUs);
    QCOMPARE(end.frame.estimate.x[est::drkf::kPosX], last.estimate.xM);
    QCOMPARE(end.frame.estimate.x[est::drkf::kPosY], last.estimate.yM);
    QVERIFY(!w.history().tracks().empty());
    QVERIFY(end.aisTargets && !end.aisTargets->empty());
    // every recorded alert log entry, in the window's alert history
    QCOMPARE(w.history().alertHistoryCount(), static_cast<std::uint64_t>(rec.alerts().size()));
    qInfo(
        "at the end: %zu tracks, %zu AIS targets, %zu own-ship samples, %llu alert log entries in the window",
        w.history().tracks().size(), end.aisTargets->size(), w.history().own().size(),
        static_cast<unsigned long long>(w.history().alertHistoryCount()));

    // A seek back to the middle: the run again from the start, to there
    const UtcUs mid = playback(w).first + (playback(w).last - playback(w).first) / 2;
    w.controller()->seekPlayback(mid);
    QTRY_VERIFY_WITH_TIMEOUT(!playback(w).atEnd && playback(w).clock == mid, kTimeoutMs);
    const LiveFrame& m = w.history().latest();
    const UtcUs at = m.liveUtc0 + m.frame.timeUs;
    const auto it =
        std::find_if(recorded.begin(), recorded.end(), [&](const auto& r) { return r.utcUs == at; });
    QVERIFY(it != recorded.end());
    QCOMPARE(m.frame.estimate.x[est::drkf::kPosX], it->estimate.xM);
    QVERIFY(w.history().own().size() < recorded.size() * 3 / 4);  // the history began anew
    qInfo("seek to the middle: estimate at %s equal to the recorded one; %zu samples in the history",
          io::formatIso8601(at).c_str(), w.history().own().size());

    // The next alert: the clock on its mark, the alert raised in the list
    // (the bar shows the clock the window shows: after its repaint tick)
    RK_WAIT_VERIFY(settled(w));
    const auto next = std::upper_bound(marks.begin(), marks.end(), playback(w).clock);
    if (next != marks.end()) {
      child<QToolButton>(w, "playbackNextAlert")->click();
      QTRY_VERIFY_WITH_TIMEOUT(playback(w).clock == *next, kTimeoutMs);
      QVERIFY(w.history().alertHistoryCount() > 0);
    }
    // The previous alert: back (a seek back) to the mark before the clock
    RK_WAIT_VERIFY(settled(w));
    const auto previous = std::lower_bound(marks.begin(), marks.end(), playback(w).clock);
    if (previous != marks.begin()) {
      child<QToolButton>(w, "playbackPreviousAlert")->click();
      QTRY_VERIFY_WITH_TIMEOUT(playback(w).clock == *std::prev(previous), kTimeoutMs);
    }
    RK_WAIT_VERIFY(settled(w));
    saveWindowShot(w, QStringLiteral("playback"));

    // Ending it goes back to the simulation
    child<QToolButton>(w, "playbackClose")->click();
    QTRY_VERIFY_WITH_TIMEOUT(!w.isLive() && !w.history().empty() && !w.history().latest().live, kTimeoutMs);
    QVERIFY(!child<QToolBar>(w, "playbackToolbar")->isVisible());
  }

  void aRecordThatCannotBeReadIsRefusedNamingIt() {
    const QString bad = dir_.path() + "/not-a-record.sqlite";
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("this is not a database\n");
    f.close();
    MainWindow w(freshOptions());
    showAndWait(w);
    QVERIFY(w.startPlayback(bad));
    QTRY_VERIFY_WITH_TIMEOUT(w.lastError().contains(QStringLiteral("not-a-record.sqlite")), kTimeoutMs);
    QVERIFY(!w.startPlayback(dir_.path() + "/none.sqlite"));
    QVERIFY(w.lastError().contains(QStringLiteral("none.sqlite")));
  }

 private:
  QTemporaryDir dir_;
  std::string record_;
};

QTEST_MAIN(TestPlaybackWindow)
#include "tst_playback_window.moc"
