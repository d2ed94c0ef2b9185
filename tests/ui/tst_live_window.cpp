// The window's Live mode (docs/gui.md, "Live") as a user runs it: a UDP connection saved in the
// settings, Live > Live mode, and a real recording (../shared/data/nmea/gpsd-bundg_zeus_9.log, read at
// test time, never copied) sent over loopback UDP with AIS targets of our own encoding interleaved.
// Own ship appears on the chart from the live DRKF (no truth anywhere), the AIS dock and the chart show
// the targets, the data monitor the raw lines, the status bar the connection; the window is rendered to
// PNG to look at; stopping Live mode brings the simulation back. The run is recorded (Live > Record the
// live run…): the record holds every line, the estimates, an operator's CPA limits and the chart shown,
// and played through the same pipeline gives the same estimates. Waits are on conditions only.
#include <QDockWidget>
#include <QFile>
#include <QNetworkDatagram>
#include <QSettings>
#include <QTableView>
#include <QTemporaryDir>
#include <QUdpSocket>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "common/angles.h"
#include "common/units.h"
#include "files/live_run.h"
#include "files/recorded_actions.h"
#include "files/voyage_compare.h"
#include "files/voyage_record.h"
#include "io/nmea.h"
#include "io/text_file.h"
#include "main_window_test_helpers.h"
#include "support/ais_corpus.h"
#include "support/compare_near.h"
#include "support/text_lines.h"
#include "ui/panels/ais_table_model.h"
#include "ui/panels/connections_dialog.h"
#include "ui/panels/data_monitor.h"

using namespace reckoner;
using namespace reckoner::ui;
using namespace reckoner::ui::test;
namespace ais = reckoner::test::ais;

namespace {

quint16 freeUdpPort() {
  QUdpSocket s;
  s.bind(QHostAddress::LocalHost, 0);
  return s.localPort();
}

/// Class A position reports of a few targets around a point (1 to 2 NM off), on their courses.
std::vector<std::string> aisAround(double latDeg, double lonDeg, int count) {
  std::vector<std::string> out;
  for (int i = 0; i < count; ++i) {
    const double brg = degToRad(i * 360.0 / count), d = nmToMetres(1.0 + 0.2 * i);
    const double lat = latDeg + d * std::cos(brg) / 111250.0;
    const double lon = lonDeg + d * std::sin(brg) / (111320.0 * std::cos(degToRad(latDeg)));
    out.push_back(ais::sentence(ais::classA(1, 244100000 + i, 0, 0, 80, std::llround(lon * 600000.0),
                                            std::llround(lat * 600000.0), (i * 470) % 3600, (i * 47) % 360)));
  }
  return out;
}

}  // namespace

class TstLiveWindow : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { isolateFromTheUser("tst_live_window"); }

  void liveModeWithoutAConnectionSaysWhatToDo() {
    QSettings().clear();
    MainWindow w(freshOptions());
    showAndWait(w);
    QVERIFY(!w.startLive());
    QVERIFY(!w.isLive());
    QVERIFY2(w.lastError().contains("Live > Connections"), qPrintable(w.lastError()));
  }

  void aRecordingOverUdpShowsOwnShipAndAisTargetsWithoutTruth() {
    // GIVEN a UDP connection saved in the settings, and the window
    const quint16 port = freeUdpPort();
    {
      QSettings settings;
      saveConnections(settings, {conn::parseSource("udp://127.0.0.1:" + std::to_string(port) + "?name=bus")});
    }
    MainWindow w(freshOptions());
    showAndWait(w);
    QCOMPARE(w.hub()->sources().size(), std::size_t{1});
    // AND its NMEA output to a UDP port the test listens on (a bad destination is refused, naming it)
    QVERIFY(!w.setLiveNmeaOut(QStringLiteral("udp://127.0.0.1:x")));
    QVERIFY2(w.lastError().contains("port"), qPrintable(w.lastError()));
    QUdpSocket rx;
    QVERIFY(rx.bind(QHostAddress::LocalHost, 0));
    // Read as it comes, in every wait: datagrams left in the socket while the recording is sent would
    // fill its buffer on a loaded machine, and the kernel drops what does not fit.
    QByteArrayList received;
    connect(&rx, &QUdpSocket::readyRead, this, [&] {
      while (rx.hasPendingDatagrams()) received << rx.receiveDatagram().data();
    });
    QVERIFY(w.setLiveNmeaOut(QStringLiteral("udp://127.0.0.1:%1").arg(rx.localPort())));
    // AND Live > Record the live run… to a new file (an existing one is refused, naming it)
    QTemporaryDir recordDir;
    const QString record = recordDir.path() + "/live.sqlite";
    QVERIFY(!w.setLiveRecordPath(QString::fromLatin1(RECKONER_SHARED_DIR "/data/nmea/NOTICE.md")));
    QVERIFY(w.lastError().contains("NOTICE.md"));
    QVERIFY(w.setLiveRecordPath(record));
    // WHEN Live mode starts and the recording is sent in bursts, a few AIS targets with it
    QVERIFY(w.startLive());
    QVERIFY(w.isLive());
    QTRY_VERIFY_WITH_TIMEOUT(w.hub()->status().front().state == conn::State::Connected, kTimeoutMs);
    qInfo("connected");
    const int sent = sendZeus(w, port);
    QVERIFY2(sent > 0, "the recording was not sent, or the hub did not keep up");
    qInfo("sent %d lines; the hub delivered %llu", sent,
          static_cast<unsigned long long>(w.hub()->status().front().lines));
    // THEN the live frames come: own ship from the live DRKF, no truth, the run's origin for the chart
    QTRY_VERIFY_WITH_TIMEOUT(w.history().latest().live && w.history().own().size() > 100, kTimeoutMs);
    qInfo("own-ship samples %zu", w.history().own().size());
    const LiveFrame& live = w.history().latest();
    QVERIFY(!live.frame.hasTruth);
    QVERIFY(live.liveOrigin.has_value());
    QVERIFY(std::isnan(w.history().own().back().truePos[0]));
    w.controller()->setCpaLimits(926.0, 600.0);  // an operator action, for the record
    RK_COMPARE_NEAR(live.liveOrigin->latDeg, 52.85, 0.01);
    verifyAisAndNmeaOutput(w, received);
    if (QTest::currentTestFailed()) return;
    // AND the data monitor shows the raw lines, the clock says LIVE
    QTRY_VERIFY_WITH_TIMEOUT(w.dataMonitor()->model()->rowCount() > 100, kTimeoutMs);
    QTRY_VERIFY2_WITH_TIMEOUT(w.clock()->text().startsWith("LIVE"), qPrintable(w.clock()->text()),
                              kTimeoutMs);
    qInfo("monitor rows %d, clock %s", w.dataMonitor()->model()->rowCount(), qPrintable(w.clock()->text()));
    // AND the chart shows it all (looked at: screenshots/live_window.png)
    w.chart()->setRangeNm(1.5);
    if (auto* d = w.findChild<QDockWidget*>(QStringLiteral("aisDock"))) d->raise();
    saveWindowShot(w, QStringLiteral("live_window"));
    // WHEN Live mode stops THEN the simulation is back, with its truth
    w.stopLive();
    QVERIFY(!w.isLive());
    QTRY_VERIFY_WITH_TIMEOUT(
        !w.history().empty() && !w.history().latest().live && w.history().latest().frame.hasTruth,
        kTimeoutMs);
    QCOMPARE(w.aisModel()->rowCount(), 0);
    // AND the record holds the lines the run took, its estimates, the operator's action and the chart;
    // played through the same pipeline it gives the same estimates, tracks and alerts
    verifyRecord(record.toStdString(), sent);
  }

 private:
  /// The AIS dock lists the six targets, with range and CPA from own ship; the NMEA output carries own
  /// ship, every sentence read back by the project's reader.
  static void verifyAisAndNmeaOutput(MainWindow& w, const QByteArrayList& received) {
    QTRY_COMPARE_WITH_TIMEOUT(w.aisModel()->rowCount(), 6, kTimeoutMs);
    qInfo("AIS rows %d", w.aisModel()->rowCount());
    const auto aisState = [&w] {
      const LiveFrame& l = w.history().latest();
      if (!l.aisTargets || l.aisTargets->empty()) return QStringLiteral("no AIS targets");
      const track::AisTarget& t = l.aisTargets->front();
      return QStringLiteral(
                 "first target: range valid %1, lost %2; own ship from %3; AIS UTC %4, frame UTC %5")
          .arg(t.rangeValid)
          .arg(t.lost)
          .arg(static_cast<int>(l.ownShipSource))
          .arg(l.aisUtc)
          .arg(l.liveUtc0 + l.frame.timeUs);
    };
    QTRY_VERIFY2_WITH_TIMEOUT(w.history().latest().aisTargets && !w.history().latest().aisTargets->empty() &&
                                  w.history().latest().aisTargets->front().rangeValid,
                              qPrintable(aisState()), kTimeoutMs);
    for (const track::AisTarget& t : *w.history().latest().aisTargets)
      QVERIFY2(t.rangeM > nmToMetres(0.5) && t.rangeM < nmToMetres(3.0),
               qPrintable(QString::number(t.rangeM)));
    QCOMPARE(w.history().latest().ownShipSource, sim::LiveOwnShipSource::Drkf);
    int rmcOut = 0, ggaOut = 0, bad = 0;
    qsizetype seen = 0;
    QTRY_VERIFY_WITH_TIMEOUT(
        [&] {
          for (; seen < received.size(); ++seen) {
            for (const QByteArray& l : received[seen].split('\n')) {
              const std::string line = l.trimmed().toStdString();
              if (line.empty()) continue;
              const io::nmea::ParseResult p = io::nmea::parse(line);
              if (p.error == io::nmea::Error::BadChecksum || p.error == io::nmea::Error::Malformed) {
                qWarning("bad sentence out: %s", line.c_str());
                ++bad;
              }
              rmcOut += line.rfind("$INRMC,", 0) == 0;
              ggaOut += line.rfind("$INGGA,", 0) == 0;
            }
          }
          return rmcOut > 20 && ggaOut > 20;
        }(),
        kTimeoutMs);
    QCOMPARE(bad, 0);
    qInfo("NMEA output: %d RMC, %d GGA read back", rmcOut, ggaOut);
  }

  /// The Zeus recording sent to the live UDP port in bursts (one per RMC), a few AIS targets with every
  /// fifth, the hub kept up with; returns the lines sent.
  static int sendZeus(MainWindow& w, quint16 port) {
    const auto lines =
        reckoner::test::splitLines(io::readTextFile(RECKONER_SHARED_DIR "/data/nmea/gpsd-bundg_zeus_9.log"));
    const std::vector<std::string> targets = aisAround(52.8502, 5.3136, 6);
    QUdpSocket tx;
    QByteArray burst;
    int sent = 0, rmc = 0;
    for (const std::string& l : lines) {
      if (l.empty() || l.front() == '#') continue;
      const bool timed = l.rfind("$GPRMC,", 0) == 0;
      if (timed && !burst.isEmpty()) {
        if (tx.writeDatagram(burst, QHostAddress::LocalHost, port) != burst.size()) return -1;
        burst.clear();
        // the hub keeps up: never more than a few hundred lines ahead of what it delivered
        if (!QTest::qWaitFor([&] { return static_cast<int>(w.hub()->status().front().lines) >= sent - 200; },
                             kTimeoutMs))
          return -1;
      }
      burst += QByteArray::fromStdString(l + "\r\n");
      ++sent;
      if (timed && ++rmc % 5 == 0)
        for (const std::string& a : targets) {
          burst += QByteArray::fromStdString(a + "\r\n");
          ++sent;
        }
    }
    if (tx.writeDatagram(burst, QHostAddress::LocalHost, port) != burst.size()) return -1;
    return sent;
  }

  static void verifyRecord(const std::string& path, int sent) {
    QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(QString::fromStdString(path)), kTimeoutMs);
    std::optional<files::VoyageRecord> rec;
    QTRY_VERIFY_WITH_TIMEOUT((rec.emplace(path), rec->endUtc().has_value()), kTimeoutMs);
    const auto actions = rec->operatorActions();
    const auto chartsShown = rec->charts();
    qInfo(
        "record: %lld of %d lines, %zu estimates, %zu alert entries, %zu operator actions, %zu chart events",
        static_cast<long long>(rec->inputCount()), sent, rec->estimates(INT64_MIN, INT64_MAX).size(),
        rec->alerts().size(), actions.size(), chartsShown.size());
    QVERIFY(rec->inputCount() > sent * 9 / 10);
    QVERIFY(std::any_of(actions.begin(), actions.end(), [](const files::OperatorAction& a) {
      return a.action == "cpa_limits" && a.value.find("cpa_m=926") != std::string::npos;
    }));
    QVERIFY(std::any_of(chartsShown.begin(), chartsShown.end(), [](const files::ChartEvent& c) {
      return c.event == "loaded" && c.name == "RK5SOUND";
    }));
    QTemporaryDir out;
    files::LiveRun replay(rec->liveOptions(), out.path().toStdString());
    files::RecordComparer compare(*rec);
    files::ActionReplayer replayer(rec->operatorActions());
    rec->forEachBatch([&](std::int64_t batch, std::span<const files::InputLine> b) {
      compare.add(replay.batch(b, 0), replay.session().result().targetLabels);
      replayer.afterBatch(batch, replay.watch());
    });
    QCOMPARE(replayer.applied(), 1L);
    compare.add(replay.finish(rec->inputName(), 0), replay.session().result().targetLabels);
    const files::RecordComparison c = compare.finish();
    qInfo("replayed: own-ship rows %ld equal, %ld different; alert entries %ld equal, %ld different",
          c.ownEqual, c.ownDifferent, c.alertsEqual, c.alertsDifferent);
    QVERIFY2(c.equal(), c.firstDifference.c_str());
    QVERIFY(c.ownEqual > 100);
  }
};

QTEST_MAIN(TstLiveWindow)
#include "tst_live_window.moc"
