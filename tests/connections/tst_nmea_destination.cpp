// The NMEA output's destinations (connections/nmea_destination.h) over loopback, and what independent
// readers make of the sentences: GIVEN a destination spec THEN bad ones are named; udp:// lines arrive
// as sent; a tcp:// server feeds a reading client everything and drops one that stops reading with its
// queue bounded; a file holds the lines; a real gpsd (Debian's, on free loopback ports) fed over UDP
// reports Reckoner's own-ship fix to 1e-7 degrees, its heading and GST, and dead reckoning (mode E,
// quality 6) as its DR status; reckoner-cli run and replay write --nmea-out to a file and over UDP.
#include <QJsonDocument>
#include <QJsonObject>
#include <QNetworkDatagram>
#include <QProcess>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>
#include <QUdpSocket>

#include <algorithm>
#include <cstddef>
#include <stdexcept>

#include "common/units.h"
#include "io/nmea.h"
#include "io/nmea_out.h"
#include "nmea_destination.h"
#include "sim/nmea_output.h"
#include "support/compare_near.h"

using namespace reckoner;
using reckoner::conn::DestinationSpec;
using reckoner::conn::NmeaDestination;

namespace {

std::vector<std::string> someLines(int n) {
  std::vector<std::string> v;
  v.reserve(static_cast<std::size_t>(std::max(n, 0)));
  for (int i = 0; i < n; ++i) v.push_back(io::nmea::hdt("HE", 0.5 * i));
  return v;
}

quint16 freeTcpPort() {
  QTcpServer s;
  if (!s.listen(QHostAddress::LocalHost, 0)) qFatal("no free TCP port");
  return s.serverPort();
}
quint16 freeUdpPort() {
  QUdpSocket s;
  if (!s.bind(QHostAddress::LocalHost, 0)) qFatal("no free UDP port");
  return s.localPort();
}

/// Lines of the datagrams received so far.
QStringList receiveLines(QUdpSocket& s) {
  QStringList out;
  while (s.hasPendingDatagrams()) {
    const QByteArray d = s.receiveDatagram().data();
    for (const QByteArray& l : d.split('\n'))
      if (!l.trimmed().isEmpty()) out << QString::fromLatin1(l.trimmed());
  }
  return out;
}

int runCli(const QStringList& args, QByteArray* out = nullptr) {
  QProcess p;
  p.start(RECKONER_CLI, args);
  if (!p.waitForFinished(300000)) return -1;
  if (out) *out = p.readAllStandardOutput() + p.readAllStandardError();
  return p.exitCode();
}

}  // namespace

class TestNmeaDestination : public QObject {
  Q_OBJECT
 private slots:
  void specsParsedAndBadOnesNamed() {
    DestinationSpec d = conn::parseDestination("udp://127.0.0.1:10110");
    QCOMPARE(d.kind, DestinationSpec::Kind::Udp);
    QCOMPARE(d.host, QString("127.0.0.1"));
    QCOMPARE(d.port, quint16(10110));
    d = conn::parseDestination("tcp://:10110");
    QCOMPARE(d.kind, DestinationSpec::Kind::TcpServer);
    QVERIFY(d.host.isEmpty());
    d = conn::parseDestination("out/nmea.txt");
    QCOMPARE(d.kind, DestinationSpec::Kind::File);
    QCOMPARE(d.path, QString("out/nmea.txt"));
    const auto message = [](const char* spec) {
      try {
        conn::parseDestination(spec);
      } catch (const std::invalid_argument& e) {
        return std::string(e.what());
      }
      return std::string();
    };
    QVERIFY(message("udp://127.0.0.1").find("HOST:PORT") != std::string::npos);
    QVERIFY(message("udp://:10110").find("needs a host") != std::string::npos);
    QVERIFY(message("udp://h:99999").find("port must be 0-65535") != std::string::npos);
    QVERIFY(message("udp://h:x").find("\"x\"") != std::string::npos);
    QVERIFY(message("serial:///dev/ttyS0").find("unknown scheme") != std::string::npos);
    QVERIFY(message("").find("empty") != std::string::npos);
    bool threw = false;
    try {
      NmeaDestination bad(conn::parseDestination("/nonexistent-dir/x.nmea"));
    } catch (const std::runtime_error& e) {
      threw = std::string(e.what()).find("/nonexistent-dir/x.nmea") != std::string::npos;
    }
    QVERIFY(threw);
  }

  void udpLinesArriveAsSent() {
    QUdpSocket rx;
    QVERIFY(rx.bind(QHostAddress::LocalHost, 0));
    NmeaDestination d(conn::parseDestination("udp://127.0.0.1:" + std::to_string(rx.localPort())));
    const auto lines = someLines(150);  // more than one datagram's worth (about 2.5 kB)
    d.write(lines);
    QStringList got;
    for (int i = 0; i < 200 && got.size() < 150; ++i) {
      if (!rx.hasPendingDatagrams()) rx.waitForReadyRead(100);
      got << receiveLines(rx);
    }
    QCOMPARE(got.size(), 150);
    for (int i = 0; i < 150; ++i) QCOMPARE(got[i].toStdString(), lines[static_cast<std::size_t>(i)]);
    QVERIFY(d.counters().datagrams >= 2);
    QCOMPARE(d.counters().sendErrors, 0L);
  }

  void tcpServesReadersAndDropsStalledClients() {
    NmeaDestination d(conn::parseDestination("tcp://127.0.0.1:0"), nullptr, qint64{64} * 1024);
    QVERIFY(d.port() != 0);
    QTcpSocket reader, stalled;
    QSignalSpy connected(&d, &NmeaDestination::clientConnected);
    reader.connectToHost(QHostAddress::LocalHost, d.port());
    QTRY_COMPARE_WITH_TIMEOUT(connected.count(), 1, 20000);
    stalled.setReadBufferSize(1);  // stops reading once a byte is waiting
    stalled.connectToHost(QHostAddress::LocalHost, d.port());
    QTRY_COMPARE_WITH_TIMEOUT(connected.count(), 2, 20000);
    QCOMPARE(d.clients(), 2);
    QByteArray received;
    connect(&reader, &QTcpSocket::readyRead, [&] { received += reader.readAll(); });
    const auto batch = someLines(1000);
    qint64 sentBytes = 0;
    for (const auto& l : batch) sentBytes += static_cast<qint64>(l.size()) + 2;
    int batches = 0;
    // The stalled client fills the kernel's buffers, then its queue: dropped at 64 KiB queued.
    while (d.counters().clientsDropped == 0 && batches < 5000) {
      d.write(batch);
      ++batches;
      QCoreApplication::processEvents();
      if (reader.bytesAvailable() == 0) reader.waitForReadyRead(1);
    }
    QCOMPARE(d.counters().clientsDropped, 1L);
    QCOMPARE(d.clients(), 1);
    for (int k = 0; k < 3; ++k) d.write(batch);
    batches += 3;
    QTRY_COMPARE_WITH_TIMEOUT(static_cast<qint64>(received.size()), batches * sentBytes, 60000);
    QVERIFY(received.startsWith(QByteArray::fromStdString(batch.front()) + "\r\n"));
  }

  void fileHoldsTheLines() {
    QTemporaryDir dir;
    const QString path = dir.filePath("out.nmea");
    {
      NmeaDestination d(conn::parseDestination(path.toStdString()));
      d.write(someLines(3));
      d.flush();
    }
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QByteArray all = f.readAll();
    QCOMPARE(all.count("\r\n"), 3);
    QVERIFY(all.startsWith(QByteArray::fromStdString(someLines(1)[0]) + "\r\n"));
  }

  void gpsdReadsOwnShip() {
    // GIVEN a real gpsd listening for NMEA on a UDP port and serving JSON on a TCP port (both loopback).
    const quint16 jsonPort = freeTcpPort(), nmeaPort = freeUdpPort();
    QProcess gpsd;
    gpsd.setProcessChannelMode(QProcess::MergedChannels);
    gpsd.start("/usr/sbin/gpsd",
               {"-N", "-n", "-S", QString::number(jsonPort), QString("udp://127.0.0.1:%1").arg(nmeaPort)});
    QVERIFY2(gpsd.waitForStarted(10000), "cannot start /usr/sbin/gpsd (Debian package gpsd)");
    QTcpSocket json;
    for (int i = 0; i < 200 && json.state() != QAbstractSocket::ConnectedState; ++i) {
      json.connectToHost(QHostAddress::LocalHost, jsonPort);
      if (!json.waitForConnected(100)) {
        json.abort();
        QTest::qWait(50);
      }
    }
    QCOMPARE(json.state(), QAbstractSocket::ConnectedState);
    json.write("?WATCH={\"enable\":true,\"json\":true}\n");

    sim::NmeaOutput out;
    NmeaDestination d(conn::parseDestination("udp://127.0.0.1:" + std::to_string(nmeaPort)));
    sim::OwnShipFix fix;
    fix.utcUs = 1767225600LL * 1000000LL;  // 2026-01-01T00:00:00Z
    fix.latDeg = 47.26986515;
    fix.lonDeg = -122.44990683;
    fix.sogKn = 12.47;
    fix.cogTrueDeg = 39.19;
    fix.headingTrueDeg = 41.5;
    fix.varNorthM2 = 4.0;
    fix.varEastM2 = 9.0;
    fix.covNorthEastM2 = 1.0;

    QByteArray buffer;
    const auto waitFor = [&](const std::function<bool(const QJsonObject&)>& want) {
      for (int i = 0; i < 300; ++i) {
        fix.utcUs += 1000000;
        d.write(out.ownShip(fix));
        json.waitForReadyRead(100);
        buffer += json.readAll();
        int nl = 0;
        while ((nl = static_cast<int>(buffer.indexOf('\n'))) >= 0) {
          QJsonObject o = QJsonDocument::fromJson(buffer.left(nl)).object();
          buffer.remove(0, nl + 1);
          if (want(o)) return o;
        }
      }
      return QJsonObject();
    };
    // WHEN Reckoner sends a fix THEN gpsd reports it: position, course, speed, heading, GST.
    const QJsonObject tpv =
        waitFor([](const QJsonObject& o) { return o["class"] == "TPV" && o.contains("lat"); });
    QVERIFY2(!tpv.isEmpty(), "gpsd reported no position");
    RK_COMPARE_NEAR(tpv["lat"].toDouble(), fix.latDeg, 1e-7);
    RK_COMPARE_NEAR(tpv["lon"].toDouble(), fix.lonDeg, 1e-7);
    QVERIFY(tpv["mode"].toInt() >= 2);
    QVERIFY(!tpv.contains("status") || tpv["status"].toInt() != 5);
    RK_COMPARE_NEAR(tpv["track"].toDouble(), fix.cogTrueDeg, 0.01);
    RK_COMPARE_NEAR(tpv["speed"].toDouble(), knotsToMps(fix.sogKn), 0.01);
    const QJsonObject att = waitFor([](const QJsonObject& o) { return o["class"] == "ATT"; });
    RK_COMPARE_NEAR(att["heading"].toDouble(), 41.5, 0.01);
    const QJsonObject gst = waitFor([](const QJsonObject& o) { return o["class"] == "GST"; });
    const io::nmea::ErrorEllipse e = io::nmea::errorEllipse(4.0, 9.0, 1.0);
    RK_COMPARE_NEAR(gst["major"].toDouble(), e.majorSdM, 0.01);
    RK_COMPARE_NEAR(gst["minor"].toDouble(), e.minorSdM, 0.01);
    RK_COMPARE_NEAR(gst["orient"].toDouble(), e.orientationDeg, 0.1);
    RK_COMPARE_NEAR(gst["lat"].toDouble(), 2.0, 0.01);
    RK_COMPARE_NEAR(gst["lon"].toDouble(), 3.0, 0.01);

    // WHEN it dead reckons THEN gpsd says so (status 5, DR), with the position still there.
    fix.deadReckoning = true;
    fix.latDeg += 0.001;
    const QJsonObject dr =
        waitFor([](const QJsonObject& o) { return o["class"] == "TPV" && o["status"].toInt() == 5; });
    QVERIFY2(!dr.isEmpty(), "gpsd never reported dead reckoning");
    QVERIFY(dr.contains("lat"));
    RK_COMPARE_NEAR(dr["lat"].toDouble(), fix.latDeg, 1e-7);
    gpsd.terminate();
    QVERIFY(gpsd.waitForFinished(10000));
  }

  void cliRunAndReplaySend() {
    QTemporaryDir dir;
    const QString file = dir.filePath("run.nmea");
    QByteArray log;
    // GIVEN a short scenario with a GNSS outage WHEN run with --nmea-out FILE THEN the file has the
    // sentences, E / quality 6 in the outage.
    QCOMPARE(
        runCli({"run", "builtin:ttkf-matched", "--nmea-out", file, "--out", dir.filePath("run"), "--quiet"},
               &log),
        0);
    QFile f(file);
    QVERIFY(f.open(QIODevice::ReadOnly));
    int gga = 0, dr = 0;
    for (const QByteArray& l : f.readAll().split('\n')) {
      if (l.trimmed().isEmpty()) continue;
      const auto fields = io::nmea::checkedFields(l.trimmed().toStdString());
      QVERIFY2(fields, l.constData());
      if ((*fields)[0] != "INGGA") continue;
      ++gga;
      const double t = io::nmea::parseTimeOfDay((*fields)[1]).value();
      if (t > 205 && t < 399) {
        QCOMPARE((*fields)[6], std::string("6"));
        ++dr;
      }
    }
    QCOMPARE(gga, 600);
    QVERIFY(dr > 190);

    // WHEN a recording is replayed with --nmea-out udp:// THEN a UDP listener gets what the file gets.
    QCOMPARE(runCli({"export", "builtin:imo-1", "--out", dir.filePath("rec"), "--quiet"}), 0);
    const QString rec = dir.filePath("rec/ownship.nmea");
    QCOMPARE(runCli({"replay", "--nmea", rec, "--nmea-out", dir.filePath("replay.nmea"), "--out",
                     dir.filePath("r1"), "--quiet"}),
             0);
    QFile rf(dir.filePath("replay.nmea"));
    QVERIFY(rf.open(QIODevice::ReadOnly));
    QStringList expected;
    for (const QByteArray& l : rf.readAll().split('\n'))
      if (!l.trimmed().isEmpty()) expected << QString::fromLatin1(l.trimmed());
    QVERIFY(expected.size() > 1000);
    QUdpSocket rx;
    QVERIFY(rx.bind(QHostAddress::LocalHost, 0));
    QProcess p;
    p.start(RECKONER_CLI,
            {"replay", "--nmea", rec, "--nmea-out", QString("udp://127.0.0.1:%1").arg(rx.localPort()),
             "--out", dir.filePath("r2"), "--quiet"});
    QStringList got;
    for (int i = 0; i < 3000 && got.size() < expected.size(); ++i) {
      rx.waitForReadyRead(50);
      got << receiveLines(rx);
    }
    QVERIFY(p.waitForFinished(60000));
    QCOMPARE(p.exitCode(), 0);
    QCOMPARE(got.size(), expected.size());
    QCOMPARE(got, expected);
  }
};

QTEST_GUILESS_MAIN(TestNmeaDestination)
#include "tst_nmea_destination.moc"
