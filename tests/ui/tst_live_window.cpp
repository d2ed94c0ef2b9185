// The window's Live mode (docs/gui.md, "Live") as a user runs it: a UDP connection saved in the
// settings, Live > Live mode, and a real recording (../shared/data/nmea/gpsd-bundg_zeus_9.log, read at
// test time, never copied) sent over loopback UDP with AIS targets of our own encoding interleaved.
// Own ship appears on the chart from the live DRKF (no truth anywhere), the AIS dock and the chart show
// the targets, the data monitor the raw lines, the status bar the connection; the window is rendered to
// PNG to look at; stopping Live mode brings the simulation back. Waits are on conditions only.
#include <QDockWidget>
#include <QFile>
#include <QNetworkDatagram>
#include <QSettings>
#include <QTableView>
#include <QUdpSocket>
#include <QtTest>
#include <cmath>
#include <string>
#include <vector>

#include "common/angles.h"
#include "common/units.h"
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
    QVERIFY(w.setLiveNmeaOut(QStringLiteral("udp://127.0.0.1:%1").arg(rx.localPort())));
    // WHEN Live mode starts and the recording is sent in bursts, a few AIS targets with it
    QVERIFY(w.startLive());
    QVERIFY(w.isLive());
    QTRY_VERIFY_WITH_TIMEOUT(w.hub()->status().front().state == conn::State::Connected, kTimeoutMs);
    qInfo("connected");
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
        QCOMPARE(tx.writeDatagram(burst, QHostAddress::LocalHost, port), burst.size());
        burst.clear();
        // the hub keeps up: never more than a few hundred lines ahead of what it delivered
        QTRY_VERIFY_WITH_TIMEOUT(static_cast<int>(w.hub()->status().front().lines) >= sent - 200, kTimeoutMs);
      }
      burst += QByteArray::fromStdString(l + "\r\n");
      ++sent;
      if (timed && ++rmc % 5 == 0)
        for (const std::string& a : targets) {
          burst += QByteArray::fromStdString(a + "\r\n");
          ++sent;
        }
    }
    QCOMPARE(tx.writeDatagram(burst, QHostAddress::LocalHost, port), burst.size());
    qInfo("sent %d lines; the hub delivered %llu", sent,
          static_cast<unsigned long long>(w.hub()->status().front().lines));
    // THEN the live frames come: own ship from the live DRKF, no truth, the run's origin for the chart
    QTRY_VERIFY_WITH_TIMEOUT(w.history().latest().live && w.history().own().size() > 100, kTimeoutMs);
    qInfo("own-ship samples %zu", w.history().own().size());
    const LiveFrame& live = w.history().latest();
    QVERIFY(!live.frame.hasTruth);
    QVERIFY(live.liveOrigin.has_value());
    QVERIFY(std::isnan(w.history().own().back().truePos[0]));
    RK_COMPARE_NEAR(live.liveOrigin->latDeg, 52.85, 0.01);
    // AND the AIS dock lists the six targets, with range and CPA from own ship
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
    // AND the NMEA output carries own ship, every sentence read back by the project's reader
    int rmcOut = 0, ggaOut = 0;
    QTRY_VERIFY_WITH_TIMEOUT(
        [&] {
          while (rx.hasPendingDatagrams()) {
            const QByteArray d = rx.receiveDatagram().data();
            for (const QByteArray& l : d.split('\n')) {
              const std::string line = l.trimmed().toStdString();
              if (line.empty()) continue;
              const io::nmea::ParseResult p = io::nmea::parse(line);
              if (p.error == io::nmea::Error::BadChecksum || p.error == io::nmea::Error::Malformed)
                return false;
              rmcOut += line.rfind("$INRMC,", 0) == 0;
              ggaOut += line.rfind("$INGGA,", 0) == 0;
            }
          }
          return rmcOut > 20 && ggaOut > 20;
        }(),
        kTimeoutMs);
    qInfo("NMEA output: %d RMC, %d GGA read back", rmcOut, ggaOut);
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
  }
};

QTEST_MAIN(TstLiveWindow)
#include "tst_live_window.moc"
