// reckoner-cli live (docs/cli.md, docs/connections.md) run as a user runs it, fed a real recording
// (../shared/data/nmea/gpsd-bundg_zeus_9.log, read at test time, never copied) over each kind of
// connection: a file played faster than real time, UDP and TCP on loopback, a serial port through a
// socat pseudo-terminal pair, and a real gpsd (Debian's) fed over UDP. Each run's ownship.csv must
// equal `replay` of the same sentences to 1 cm and 1e-6 in sd. The TCP peer is also pulled mid-run:
// the source reconnects by itself and the sentences missed show as dead reckoning.
//
// Every wait is on a condition (the status lines live prints on stderr, files, sockets), capped
// generously so a loaded machine only makes the test slower.
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>
#include <QUdpSocket>

#include <cmath>
#include <csignal>
#include <functional>
#include <vector>

#include "app/cli_process.h"
#include "support/campaign_tools.h"

using reckoner::test::runCli;
namespace test = reckoner::test;

namespace {

constexpr int kCapMs = 120000;
const QString kZeus = QStringLiteral(RECKONER_SHARED_DIR "/data/nmea/gpsd-bundg_zeus_9.log");

/// The recording's sentences (comment lines left out), grouped into chunks that each start at a
/// sentence with its own time ($GPRMC, $GPGGA, $GPZDA, $GPGLL): a chunk is written in one go, as an
/// instrument sends its burst, so untimed sentences arrive with the timed one before them.
std::vector<QByteArray> chunksOf(const QString& path) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) return {};
  std::vector<QByteArray> chunks;
  const QRegularExpression timed(R"(^\$..(RMC|GGA|ZDA|GLL),)");
  while (!f.atEnd()) {
    QByteArray line = f.readLine();
    if (line.startsWith('#') || line.trimmed().isEmpty()) continue;
    if (!line.endsWith('\n')) line += "\r\n";
    if (chunks.empty() || timed.match(QString::fromLatin1(line)).hasMatch()) chunks.emplace_back();
    chunks.back() += line;
  }
  return chunks;
}

int lineCount(const std::vector<QByteArray>& chunks) {
  int n = 0;
  for (const auto& c : chunks) n += static_cast<int>(c.count('\n'));
  return n;
}

/// A running `reckoner-cli live`, its stderr status lines read as they come.
class LiveRun {
 public:
  explicit LiveRun(const QStringList& args, const QString& statusInterval = QStringLiteral("0.1")) {
    p_.setReadChannel(QProcess::StandardError);  // the status lines: waitForReadyRead wakes on them
    p_.start(QStringLiteral(RECKONER_CLI), QStringList{"live", "--status-interval", statusInterval} + args);
  }
  ~LiveRun() {
    if (p_.state() != QProcess::NotRunning) {
      p_.kill();
      p_.waitForFinished(kCapMs);
    }
  }
  LiveRun(const LiveRun&) = delete;
  LiveRun& operator=(const LiveRun&) = delete;

  /// Waits until a status line satisfies pred (false when the program ended or the cap passed).
  bool waitStatus(const std::function<bool(const QString&)>& pred) {
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < kCapMs) {
      read();
      if (!last_.isEmpty() && pred(last_)) return true;
      if (p_.state() == QProcess::NotRunning) return false;
      p_.waitForReadyRead(200);
    }
    return false;
  }
  /// The number of sentence lines the last status line counts.
  [[nodiscard]] long lines() const {
    static const QRegularExpression re(R"(^live: (\d+) lines)");
    const auto m = re.match(last_);
    return m.hasMatch() ? m.captured(1).toLong() : -1;
  }
  bool waitLines(long n) {
    return waitStatus([this, n](const QString&) { return lines() >= n; });
  }
  /// The number of radar lines the last status line counts.
  [[nodiscard]] long radarLines() const {
    static const QRegularExpression re(R"(, (\d+) radar lines)");
    const auto m = re.match(last_);
    return m.hasMatch() ? m.captured(1).toLong() : -1;
  }
  bool waitLines(long n, long radar) {
    return waitStatus([this, n, radar](const QString&) { return lines() >= n && radarLines() >= radar; });
  }
  /// SIGINT, as a user's Ctrl-C; the exit code (-1 when it did not end).
  int interrupt() {
    ::kill(static_cast<pid_t>(p_.processId()), SIGINT);
    if (!p_.waitForFinished(kCapMs)) return -1;
    read();
    return p_.exitStatus() == QProcess::NormalExit ? p_.exitCode() : -1;
  }
  [[nodiscard]] const QString& lastStatus() const { return last_; }
  [[nodiscard]] const QString& err() const { return err_; }
  QProcess& process() { return p_; }

 private:
  void read() {
    err_ += QString::fromUtf8(p_.readAllStandardError());
    const auto lines = err_.split('\n', Qt::SkipEmptyParts);
    for (auto it = lines.rbegin(); it != lines.rend(); ++it)
      if (it->startsWith("live: ")) {
        last_ = *it;
        break;
      }
  }
  QProcess p_;
  QString err_, last_;
};

/// tests/support's reader, failing the test (not throwing) on a file that cannot be read.
bool readCsvInto(const QString& path, test::Csv& out) {
  try {
    out = test::readCsv(path);
    return true;
  } catch (const std::exception& e) {
    qWarning("%s", e.what());
    return false;
  }
}

/// A CSV of a live run against the replay's (ownship.csv, targets.csv): the same rows and columns;
/// estimated positions and velocities to 1 cm (per second), standard deviations and every other number
/// to 1e-6, text equal.
void compareCsv(const QString& liveFile, const QString& replayFile, std::size_t minRows) {
  test::Csv live, rep;
  QVERIFY(readCsvInto(liveFile, live) && readCsvInto(replayFile, rep));
  QVERIFY(rep.rows.size() >= minRows);
  QVERIFY(live.column == rep.column);
  QCOMPARE(live.rows.size(), rep.rows.size());
  double worstM = 0.0, worstSd = 0.0;
  for (std::size_t r = 0; r < rep.rows.size(); ++r) {
    for (const auto& [name, c] : rep.column) {
      const QString mine = QString::fromStdString(live.rows[r][c]),
                    theirs = QString::fromStdString(rep.rows[r][c]);
      bool ok1 = false, ok2 = false;
      const double a = mine.toDouble(&ok1), b = theirs.toDouble(&ok2);
      if (!ok1 || !ok2) {
        QCOMPARE(mine, theirs);
        continue;
      }
      const QString n = QString::fromStdString(name);
      const bool metres = n.startsWith("est_") && (n.endsWith("_m") || n.endsWith("_mps"));
      const bool degrees = n.endsWith("_deg") && n.startsWith("est_l");
      const double d = std::abs(a - b) * (degrees ? 111000.0 : 1.0);  // degrees to metres, roughly
      if (metres || degrees)
        worstM = std::max(worstM, d);
      else
        worstSd = std::max(worstSd, d);
      const double tol = metres || degrees ? 0.01 : 1e-6;
      if (d > tol) QFAIL(qPrintable(QString("row %1 %2: live %3 replay %4").arg(r).arg(n, mine, theirs)));
    }
  }
  qInfo("%s: %zu rows equal: worst position/velocity difference %.3g m, worst other %.3g",
        qPrintable(QFileInfo(liveFile).fileName()), rep.rows.size(), worstM, worstSd);
}

void compareOwnShip(const QString& liveDir, const QString& replayDir) {
  compareCsv(liveDir + "/ownship.csv", replayDir + "/ownship.csv", 100);
}

quint16 freeUdpPort() {
  QUdpSocket s;
  s.bind(QHostAddress::LocalHost, 0);
  return s.localPort();
}

/// Replays the recording (the reference) into dir/replay; false when it failed.
bool replayReference(const QString& dir, const QString& nmea) {
  const auto r = runCli({"replay", "--nmea", nmea, "--out", dir + "/replay", "--quiet"});
  if (r.code != 0) qWarning("%s", qPrintable(r.err));
  return r.code == 0;
}

void requireTool(const QString& program) {
  if (QStandardPaths::findExecutable(program).isEmpty() && !QFile::exists(program))
    QFAIL(qPrintable(program + " is missing (scripts/bootstrap.sh deps installs it)"));
}

}  // namespace

class TestLiveCli : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    if (!QFile::exists(kZeus)) QSKIP(qPrintable(kZeus + " is absent (../shared/data/nmea)"));
    chunks_ = chunksOf(kZeus);
    if (qEnvironmentVariableIsSet("RECKONER_KEEP_TEST_FILES")) dir_.setAutoRemove(false);
    QVERIFY(chunks_.size() > 100);
    QVERIFY(dir_.isValid());
    QVERIFY(replayReference(dir_.path(), kZeus));
  }

  void fileAtTenTimesRealTimeEqualsReplay() {
    // GIVEN the recording as a file source played ten times faster than it was recorded
    // WHEN live runs it to its end (a run of files alone stops there)
    const QString out = dir_.path() + "/file";
    const auto r = runCli({"live", "--file", kZeus, "--file-rate", "10", "--out", out, "--quiet",
                           "--nmea-out", dir_.path() + "/live-out.nmea"});
    QCOMPARE(r.code, 0);
    // THEN its own-ship estimate is the replay's, and so is its NMEA output, sentence for sentence
    compareOwnShip(out, dir_.path() + "/replay");
    const auto ref = runCli({"replay", "--nmea", kZeus, "--out", dir_.path() + "/replay-nmea", "--quiet",
                             "--nmea-out", dir_.path() + "/replay-out.nmea"});
    QCOMPARE(ref.code, 0);
    QFile mine(dir_.path() + "/live-out.nmea"), theirs(dir_.path() + "/replay-out.nmea");
    QVERIFY(mine.open(QIODevice::ReadOnly) && theirs.open(QIODevice::ReadOnly));
    // (live also sends its alerts, which a replay has none of: ALR, ALF and the ALC list, set apart)
    QByteArray a, alerts;
    for (const QByteArray& l : mine.readAll().split('\n')) {
      if (l.isEmpty()) continue;
      const QByteArray kind = l.mid(3, 3);
      (kind == "ALR" || kind == "ALF" || kind == "ALC" ? alerts : a) += l + '\n';
    }
    const QByteArray b = theirs.readAll();
    QVERIFY(b.count('\n') > 500);
    QCOMPARE(a, b);
    QVERIFY(alerts.startsWith("$INALC,"));  // the alert list, sent at the start and every 30 s
  }

  void udpEqualsReplay() {
    // GIVEN live listening on a loopback UDP port
    const quint16 port = freeUdpPort();
    const QString out = dir_.path() + "/udp";
    LiveRun live({"--udp", QString::number(port), "--out", out});
    QVERIFY2(live.waitStatus([](const QString& s) { return s.contains("udp1 connected"); }),
             qPrintable(live.err()));
    // WHEN each burst of the recording is sent as one datagram (no faster than live takes them in, so
    // that a loaded machine drops nothing from the socket's buffer)
    QUdpSocket tx;
    long sent = 0;
    for (const QByteArray& c : chunks_) {
      QCOMPARE(tx.writeDatagram(c, QHostAddress::LocalHost, port), c.size());
      sent += c.count('\n');
      if (sent - live.lines() > 200) QVERIFY2(live.waitLines(sent - 50), qPrintable(live.lastStatus()));
    }
    QVERIFY2(live.waitLines(lineCount(chunks_)), qPrintable(live.lastStatus()));
    QCOMPARE(live.interrupt(), 0);
    // THEN the estimate equals the replay of the file
    compareOwnShip(out, dir_.path() + "/replay");
  }

  void tcpEqualsReplay() {
    // GIVEN a TCP server on loopback (an NMEA multiplexer) and live connected to it
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    const QString out = dir_.path() + "/tcp";
    LiveRun live({"--tcp", "127.0.0.1:" + QString::number(server.serverPort()), "--out", out});
    QVERIFY(server.waitForNewConnection(kCapMs));
    QTcpSocket* peer = server.nextPendingConnection();
    // WHEN the recording is written burst by burst
    for (const QByteArray& c : chunks_) {
      peer->write(c);
      if (peer->bytesToWrite() > qint64{64} * 1024) QVERIFY(peer->waitForBytesWritten(kCapMs));
    }
    while (peer->bytesToWrite() > 0) QVERIFY(peer->waitForBytesWritten(kCapMs));
    QVERIFY2(live.waitLines(lineCount(chunks_)), qPrintable(live.lastStatus()));
    QCOMPARE(live.interrupt(), 0);
    // THEN the estimate equals the replay of the file
    compareOwnShip(out, dir_.path() + "/replay");
  }

  void serialPtyEqualsReplay() {
    requireTool("socat");
    // GIVEN a pseudo-terminal pair (socat) and live reading one end at 38400 baud
    QProcess socat;
    const QString a = dir_.path() + "/ttyA", b = dir_.path() + "/ttyB";
    socat.start("socat", {"pty,raw,echo=0,link=" + a, "pty,raw,echo=0,link=" + b});
    QVERIFY(socat.waitForStarted(kCapMs));
    QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(a) && QFile::exists(b), kCapMs);
    const QString out = dir_.path() + "/serial";
    LiveRun live({"--serial", b + ":38400", "--out", out});
    QVERIFY2(live.waitStatus([](const QString& s) { return s.contains("serial1 connected"); }),
             qPrintable(live.err()));
    // WHEN the recording is written into the other end, burst by burst
    QFile tty(a);
    QVERIFY(tty.open(QIODevice::WriteOnly | QIODevice::Unbuffered));
    long sent = 0;
    for (const QByteArray& c : chunks_) {
      QCOMPARE(tty.write(c), c.size());
      sent += c.count('\n');
      if (sent - live.lines() > 200) QVERIFY2(live.waitLines(sent - 50), qPrintable(live.lastStatus()));
    }
    QVERIFY2(live.waitLines(lineCount(chunks_)), qPrintable(live.lastStatus()));
    QCOMPARE(live.interrupt(), 0);
    tty.close();
    socat.terminate();
    socat.waitForFinished(kCapMs);
    // THEN the estimate equals the replay of the file
    compareOwnShip(out, dir_.path() + "/replay");
  }

  void gpsdEqualsReplayOfWhatItRelays() {
    requireTool("/usr/sbin/gpsd");
    // GIVEN a real gpsd on free loopback ports reading NMEA from UDP, live watching it, and a watcher
    // of the test's own that records what gpsd relays (gpsd passes on what it understands: Debian
    // 12's 3.22 leaves out some heading sentences, docs/connections.md)
    const quint16 udp = freeUdpPort();
    QTcpServer probe;
    QVERIFY(probe.listen(QHostAddress::LocalHost, 0));
    const quint16 gpsdPort = probe.serverPort();
    probe.close();
    QProcess gpsd;
    gpsd.start("/usr/sbin/gpsd", {"-N", "-n", "-b", "-S", QString::number(gpsdPort), "-F",
                                  dir_.path() + "/gpsd.sock", "udp://127.0.0.1:" + QString::number(udp)});
    QVERIFY(gpsd.waitForStarted(kCapMs));
    QTcpSocket watcher;
    QElapsedTimer t;
    t.start();
    do {
      watcher.abort();
      watcher.connectToHost(QHostAddress::LocalHost, gpsdPort);
    } while (!watcher.waitForConnected(1000) && t.elapsed() < kCapMs);
    QCOMPARE(watcher.state(), QAbstractSocket::ConnectedState);
    watcher.write("?WATCH={\"enable\":true,\"raw\":1}\n");
    const QString out = dir_.path() + "/gpsd";
    LiveRun live({"--gpsd", "127.0.0.1:" + QString::number(gpsdPort), "--out", out});
    QVERIFY2(live.waitStatus([](const QString& s) { return s.contains("gpsd1 connected"); }),
             qPrintable(live.err()));
    QByteArray relayed;
    const auto sentences = [&] {
      while (watcher.waitForReadyRead(0) || watcher.bytesAvailable() > 0) {
        if (!watcher.canReadLine()) break;
        const QByteArray l = watcher.readLine();
        if (l.startsWith('$') || l.startsWith('!')) relayed += l;
      }
      return relayed.count('\n');
    };
    // WHEN, once both the watcher and live see what gpsd is sent (before that, what is sent there is
    // lost; the probe, a waypoint-arrival sentence, means nothing to the estimator), the recording is
    // sent to gpsd a sentence a datagram (gpsd reads one a packet)
    QUdpSocket tx;
    const QByteArray probeLine = "$GPAAM,,,,N,*38\r\n";
    QVERIFY(live.waitStatus([&](const QString&) {
      tx.writeDatagram(probeLine, QHostAddress::LocalHost, udp);
      return live.lines() > 0 && sentences() > 0;
    }));
    std::size_t next = 0;
    long sent = 0;
    for (; next < chunks_.size(); ++next) {
      for (const QByteArray& line : chunks_[next].split('\n'))
        if (!line.isEmpty()) tx.writeDatagram(line + '\n', QHostAddress::LocalHost, udp);
      sent += chunks_[next].count('\n');
      if (sent - sentences() > 100)
        QVERIFY2(live.waitStatus([&](const QString&) { return sent - sentences() < 50; }),
                 qPrintable(live.lastStatus()));
    }
    // gpsd has passed on the last sentence (the recording ends with a timed one) to both
    const QByteArray last = chunks_.back().left(chunks_.back().indexOf('\n'));
    QVERIFY(live.waitStatus([&](const QString&) {
      sentences();
      return relayed.contains(last.trimmed()) && live.lines() >= relayed.count('\n');
    }));
    QCOMPARE(live.interrupt(), 0);
    gpsd.terminate();
    gpsd.waitForFinished(kCapMs);
    qInfo("gpsd relayed %lld of %d sentences", static_cast<long long>(relayed.count('\n')),
          lineCount(chunks_));
    QFile capture(dir_.path() + "/relayed.nmea");
    QVERIFY(capture.open(QIODevice::WriteOnly));
    capture.write(relayed);
    capture.close();
    // THEN the estimate equals the replay of what gpsd relayed
    QVERIFY(replayReference(dir_.path() + "/gpsd-ref", capture.fileName()));
    compareOwnShip(out, dir_.path() + "/gpsd-ref/replay");
  }

  void radarPlotsOverUdpGiveTheReplaysTracks() {
    // GIVEN a simulated run exported as a recording (own-ship NMEA and radar plots) and its replay
    const QString exp = dir_.path() + "/radar-export";
    QCOMPARE(runCli({"export", "builtin:imo-2", "--date", "2026-11-23", "--out", exp, "--quiet"}).code, 0);
    // (both with the scenario's settings: a replay without them measures the antenna's rotation from the
    // plots, which live cannot do before it has them: docs/outputs.md, "Live input")
    QCOMPARE(runCli({"replay", "--nmea", exp + "/ownship.nmea", "--radar", exp + "/radar.csv", "--config",
                     "builtin:imo-2", "--out", exp + "/replay", "--quiet"})
                 .code,
             0);
    // AND live with the NMEA on one UDP port and the radar plots on another
    const quint16 nmeaPort = freeUdpPort(), radarPort = freeUdpPort();
    const QString out = dir_.path() + "/radar-live";
    LiveRun live(
        {"--udp", QString::number(nmeaPort), "--radar-udp", QString::number(radarPort), "--config",
         "builtin:imo-2", "--out", out},
        QStringLiteral("0.02"));  // a status line each 20 ms: the test waits on one per second of data
    QVERIFY2(live.waitStatus([](const QString& s) {
      return s.contains("udp1 connected") && s.contains("radar2 connected");
    }),
             qPrintable(live.err()));
    // WHEN both are sent in time order, as a radar and the instruments deliver them: each second's
    // sentences, the plots stamped before them first
    const std::vector<QByteArray> chunks = chunksOf(exp + "/ownship.nmea");
    QFile radarFile(exp + "/radar.csv");
    QVERIFY(radarFile.open(QIODevice::ReadOnly));
    QList<QByteArray> rows = radarFile.readAll().split('\n');
    while (!rows.isEmpty() && rows.back().trimmed().isEmpty()) rows.removeLast();
    QVERIFY(rows.size() > 100);
    QUdpSocket tx;
    long nmea = 0, radar = 1;
    QCOMPARE(tx.writeDatagram(rows.front() + "\n", QHostAddress::LocalHost, radarPort),
             rows.front().size() + 1);
    qsizetype next = 1;
    const QRegularExpression hms(R"(^\$..(?:ZDA|RMC|GGA),(\d\d)(\d\d)(\d\d\.?\d*))");
    for (const QByteArray& c : chunks) {
      const auto m = hms.match(QString::fromLatin1(c));
      if (m.hasMatch()) {
        const QString at =
            QStringLiteral("2026-11-23T%1:%2:%3").arg(m.captured(1), m.captured(2), m.captured(3));
        for (; next < rows.size() && QString::fromLatin1(rows[next]).section(',', 0, 0).chopped(1) < at;
             ++next) {
          QCOMPARE(tx.writeDatagram(rows[next] + "\n", QHostAddress::LocalHost, radarPort),
                   rows[next].size() + 1);
          ++radar;
        }
      }
      QCOMPARE(tx.writeDatagram(c, QHostAddress::LocalHost, nmeaPort), c.size());
      nmea += c.count('\n');
      QVERIFY2(live.waitLines(nmea, radar), qPrintable(live.lastStatus()));  // kept in step
    }
    for (; next < rows.size(); ++next, ++radar)
      tx.writeDatagram(rows[next] + "\n", QHostAddress::LocalHost, radarPort);
    QVERIFY2(live.waitLines(nmea, radar), qPrintable(live.lastStatus()));
    QCOMPARE(live.interrupt(), 0);
    // THEN targets.csv and ownship.csv are the replay's
    compareCsv(out + "/targets.csv", exp + "/replay/targets.csv", 20);
    compareOwnShip(out, exp + "/replay");
  }

  void pulledCableReconnectsAndTheGapIsDeadReckoning() {
    // GIVEN the GNSS sentences ($GP...) over TCP from a multiplexer and the rest (compass, log) over
    // UDP, as a bridge wires them, and live on both
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    const quint16 udp = freeUdpPort();
    const QString out = dir_.path() + "/pulled";
    LiveRun live({"--tcp", "127.0.0.1:" + QString::number(server.serverPort()), "--udp", QString::number(udp),
                  "--out", out, "--reorder-horizon", "0"});
    QVERIFY(server.waitForNewConnection(kCapMs));
    QTcpSocket* peer = server.nextPendingConnection();
    QVERIFY2(live.waitStatus([](const QString& s) { return s.contains("udp1 connected"); }),
             qPrintable(live.err()));
    QUdpSocket tx;
    long sent = 0;
    const auto send = [&](const QByteArray& chunk, bool gnss, bool rest, bool wait = true) {
      QByteArray gps, other;
      for (const QByteArray& l : chunk.split('\n'))
        if (!l.isEmpty()) (l.startsWith("$GP") ? gps : other) += l + '\n';
      if (gnss && !gps.isEmpty()) {
        peer->write(gps);
        peer->waitForBytesWritten(kCapMs);
        sent += gps.count('\n');
      }
      if (rest && !other.isEmpty()) {
        tx.writeDatagram(other, QHostAddress::LocalHost, udp);
        sent += other.count('\n');
      }
      return !wait || live.waitLines(sent);  // the two sockets kept in step
    };
    const std::size_t pull = chunks_.size() * 2 / 5, back = chunks_.size() * 3 / 5;
    for (std::size_t i = 0; i < pull; ++i)
      QVERIFY2(send(chunks_[i], true, true), qPrintable(live.lastStatus()));
    // WHEN the GNSS cable is pulled (the peer closes, half a sentence in flight) while the compass and
    // the log go on for a few seconds of real time
    peer->write("$GPRMC,0947");
    peer->waitForBytesWritten(kCapMs);
    peer->close();
    QVERIFY2(live.waitStatus([](const QString& s) { return !s.contains("tcp2 connected"); }),
             qPrintable(live.lastStatus()));
    QElapsedTimer gap;
    gap.start();
    // (6 s of wall time: while the GNSS is out the receive clock times the epochs, and dead reckoning is
    // declared after 3 s without a fix; 30 chunks at 200 ms each cannot end it sooner)
    for (std::size_t i = pull; gap.elapsed() < 6000 && i < back; ++i) {
      QVERIFY(send(chunks_[i], false, true));
      QTest::qWait(200);  // the feed's own pace: the instruments send in real time
    }
    // and the multiplexer takes connections again: the source comes back by itself
    if (!server.hasPendingConnections()) QVERIFY(server.waitForNewConnection(kCapMs));
    peer = server.nextPendingConnection();
    QVERIFY2(live.waitStatus([](const QString& s) { return s.contains("tcp2 connected"); }),
             qPrintable(live.lastStatus()));
    for (std::size_t i = back; i < chunks_.size(); ++i)
      QVERIFY(send(chunks_[i], true, true, i % 8 == 7 || i + 1 == chunks_.size()));
    QCOMPARE(live.interrupt(), 0);
    // THEN the gap is dead reckoning and raised POSITION SOURCE LOST, which the fix coming back rectified
    gapIsDeadReckoning(out);
  }

 private:
  /// The rows of the gap are dead reckoning (no GNSS among their sensors), those before and after have
  /// the GNSS; the gap raised POSITION SOURCE LOST in alerts.csv, and the fix coming back rectified it.
  static void gapIsDeadReckoning(const QString& out) {
    test::Csv own;
    QVERIFY(readCsvInto(out + "/ownship.csv", own));
    int before = 0, dr = 0, after = 0;
    for (const auto& row : own.rows) {
      const bool gnss = own.get(row, "sensors").find("gps") != std::string::npos;
      if (gnss && dr == 0) ++before;
      if (!gnss) ++dr;
      if (gnss && dr > 0) ++after;
    }
    qInfo("rows: %d with the GNSS, %d dead reckoning while the cable was out, %d after it came back", before,
          dr, after);
    QVERIFY(before > 10);
    QVERIFY(dr >= 4);
    QVERIFY(after > 10);
    test::Csv alerts;
    QVERIFY(readCsvInto(out + "/alerts.csv", alerts));
    int raised = 0, rectified = 0;
    for (const auto& row : alerts.rows) {
      if (alerts.get(row, "kind") != "POSITION SOURCE LOST") continue;
      raised += alerts.get(row, "event") == "raised";
      rectified += alerts.get(row, "event") == "rectified" || alerts.get(row, "event") == "cleared";
    }
    qInfo("alerts.csv: POSITION SOURCE LOST raised %d, rectified or cleared %d", raised, rectified);
    QCOMPARE(raised, 1);
    QCOMPARE(rectified, 1);
  }

  QTemporaryDir dir_{QDir::tempPath() + "/tst_live_cli-XXXXXX"};
  std::vector<QByteArray> chunks_;
};

QTEST_GUILESS_MAIN(TestLiveCli)
#include "tst_live_cli.moc"
