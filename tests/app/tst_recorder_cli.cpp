// reckoner-cli live --record and replay --recording (docs/recorder.md) run as a user runs them:
// - a 10-minute portion of a real recording (../shared/data/nmea, the icebreaker's, read at test time,
//   never copied) sent over loopback TCP at ten times its pace, the program killed with SIGKILL once the
//   record holds two minutes of estimates: every line sent more than a second before the kill is in the
//   record, which is a prefix of what was sent, and its replay computes every recorded estimate again;
// - a complete recording (own ship, radar plots and AIS over two TCP connections) replayed to the same
//   files byte for byte, its estimates equal to the recorded ones;
// - the size of a recording at full rate, and with --record-max-hours;
// - usage errors and a file that is no record.
// Every wait is on a condition (the record's contents, status lines, the program's end).
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QRegularExpression>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>
#include <QTime>
#include <QTimer>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <vector>

#include "app/cli_process.h"
#include "files/voyage_record.h"

using reckoner::test::runCli;
using namespace reckoner;

namespace {

constexpr int kCapMs = 60000;
const QString kIcebreaker =
    QStringLiteral(RECKONER_SHARED_DIR "/data/nmea/openrvdas-NBP1406_seap-2014-08-01.nmea");
const QString kAis = QStringLiteral(RECKONER_SHARED_DIR "/data/ais/gpsd-sample.aivdm");

UtcUs wallNow() {
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

/// One second of a recording: its lines (from its first timed sentence on) and that time, s of the day.
struct Chunk {
  double timeS = 0;
  QList<QByteArray> lines;
};

/// The recording's bursts: a new chunk at each ZDA (the icebreaker's and the export's first sentence of
/// a second).
std::vector<Chunk> chunksOf(const QString& path) {
  QFile f(path);
  std::vector<Chunk> out;
  if (!f.open(QIODevice::ReadOnly)) return out;
  const QRegularExpression zda(R"(^\$..ZDA,(\d\d)(\d\d)(\d\d(?:\.\d*)?),)");
  for (QByteArray line : f.readAll().split('\n')) {
    line = line.trimmed();
    if (line.isEmpty() || line.startsWith('#')) continue;
    const auto m = zda.match(QString::fromLatin1(line));
    if (m.hasMatch() || out.empty())
      out.push_back({m.hasMatch() ? (m.captured(1).toDouble() * 60 + m.captured(2).toDouble()) * 60 +
                                        m.captured(3).toDouble()
                                  : 0.0,
                     {}});
    out.back().lines.push_back(line);
  }
  return out;
}

/// Seconds of own-ship estimates the record holds now (0 while it cannot be read).
double estimateSeconds(const QString& path) {
  try {
    const files::VoyageRecord rec(path.toStdString());
    const auto span = rec.estimateSpan();
    return span ? toSeconds(span->last - span->first) : 0.0;
  } catch (const std::exception&) {
    return 0.0;
  }
}

/// A running reckoner-cli live.
struct Live {
  QProcess p;
  explicit Live(const QStringList& args) {
    p.setProcessChannelMode(QProcess::SeparateChannels);
    p.start(QStringLiteral(RECKONER_CLI), QStringList{"live"} + args);
  }
  ~Live() {
    if (p.state() != QProcess::NotRunning) {
      p.kill();
      p.waitForFinished(kCapMs);
    }
  }
  Live(const Live&) = delete;
  Live& operator=(const Live&) = delete;
  /// The last status line's "recorded N lines (M committed)": {N, M}, {-1, -1} before one.
  std::pair<long, long> recorded() {
    err += QString::fromUtf8(p.readAllStandardError());
    static const QRegularExpression re(R"(recorded (\d+) lines \((\d+) committed\))");
    std::pair<long, long> n{-1, -1};
    for (auto it = re.globalMatch(err); it.hasNext();) {
      const auto m = it.next();
      n = {m.captured(1).toLong(), m.captured(2).toLong()};
    }
    return n;
  }
  QString err;
};

/// Reads the whole file (empty when it cannot).
QByteArray contentsOf(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

/// A line sent to the program under test: when (wall clock) and at what time of the stream.
struct Sent {
  QByteArray line;
  UtcUs at;
  double streamS;
};

/// How many of the lines were sent at or before t.
std::size_t linesSentBy(const std::vector<Sent>& sent, UtcUs t) {
  return static_cast<std::size_t>(
      std::count_if(sent.begin(), sent.end(), [t](const Sent& s) { return s.at <= t; }));
}

/// `replay --recording` of a killed program's record computes every recorded estimate again, exactly.
void replayOfKilledRecordIsExact(const QString& db, const QString& out) {
  const auto r = runCli({"replay", "--recording", db, "--out", out});
  QCOMPARE(r.code, 0);
  QVERIFY2(r.out.contains(QRegularExpression(
               R"(own-ship rows [1-9]\d+ equal, 0 different, \d+ not recorded, 0 not replayed)")),
           qPrintable(r.out + r.err));
  QVERIFY2(r.out.contains("to a stop without an end (killed)"), qPrintable(r.out));
}

}  // namespace

class TestRecorderCli : public QObject {
  Q_OBJECT
  QTemporaryDir dir_;

 private slots:
  void initTestCase() {
    if (!QFile::exists(kIcebreaker) || !QFile::exists(kAis)) QSKIP("../shared/data is absent");
    if (qEnvironmentVariableIsSet("RECKONER_KEEP_TEST_FILES")) dir_.setAutoRemove(false);
    QVERIFY(dir_.isValid());
  }

  void killedMidRunLosesAtMostTheLastSecond_data() {
    QTest::addColumn<double>("rate");
    QTest::addColumn<double>("killAtS");
    // ten times the recording's pace: commits come from the stream clock (a second of it each); at its
    // own pace (1x) from the wall clock (0.5 s), the rule a ship's live feed meets
    QTest::newRow("x10, killed after 120 s of estimates") << 10.0 << 120.0;
    QTest::newRow("x1, killed after 15 s of estimates") << 1.0 << 15.0;
  }
  void killedMidRunLosesAtMostTheLastSecond() {
    QFETCH(double, rate);
    QFETCH(double, killAtS);
    // GIVEN ten minutes of the icebreaker's recording (from its second minute) and live recording what
    // a TCP server sends it
    std::vector<Chunk> all = chunksOf(kIcebreaker);
    QVERIFY(all.size() > 700);
    std::vector<Chunk> chunks(all.begin() + 60, all.begin() + 660);
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    const QString name = QStringLiteral("killed-x%1").arg(rate);
    const QString db = dir_.filePath(name + ".sqlite");
    Live live({"--tcp", "127.0.0.1:" + QString::number(server.serverPort()), "--record", db, "--out",
               dir_.filePath(name), "--status-interval", "0.02"});
    QVERIFY(server.waitForNewConnection(kCapMs));
    QTcpSocket* peer = server.nextPendingConnection();
    // WHEN the bursts are sent at the rate's pace, each line's send time noted ...
    std::vector<Sent> sent;
    std::size_t next = 0;
    const UtcUs start = wallNow();
    QTimer pace;
    QObject::connect(&pace, &QTimer::timeout, [&] {
      for (; next < chunks.size(); ++next) {
        const UtcUs due = start + fromSeconds((chunks[next].timeS - chunks.front().timeS) / rate);
        if (due > wallNow()) break;
        const UtcUs at = wallNow();
        for (const QByteArray& l : chunks[next].lines) {
          peer->write(l + "\r\n");
          sent.push_back({l, at, chunks[next].timeS});
        }
        peer->flush();
      }
    });
    pace.start(2);
    // ... and the program is killed (SIGKILL) once the record holds killAtS of estimates, at a moment
    // its status line shows lines taken in and not yet committed (the worst moment to die)
    long pending = 0;
    QTRY_VERIFY_WITH_TIMEOUT(
        estimateSeconds(db) >= killAtS && (pending = live.recorded().first - live.recorded().second) > 0,
        kCapMs);
    const UtcUs killedAt = wallNow();
    live.p.kill();
    QVERIFY(live.p.waitForFinished(kCapMs));
    pace.stop();
    QCOMPARE(live.p.exitStatus(), QProcess::CrashExit);
    // THEN the record opens (its write-ahead log recovered) and holds a prefix of what was sent ...
    const files::VoyageRecord rec(db.toStdString());
    QVERIFY(!rec.endUtc());  // no end written: killed
    const std::vector<files::RecordedInput> in = rec.inputs(0, SIZE_MAX);
    QVERIFY(!in.empty() && in.size() <= sent.size());
    UtcUs worstLatency = 0;
    for (std::size_t k = 0; k < in.size(); ++k) {
      QCOMPARE(QByteArray::fromStdString(in[k].line), sent[k].line);
      QCOMPARE(in[k].source, std::string("tcp1"));
      QVERIFY(in[k].receivedUtc >= sent[k].at && in[k].receivedUtc <= killedAt);
      worstLatency = std::max(worstLatency, in[k].receivedUtc - sent[k].at);
    }
    // ... with every line sent more than a second before the kill
    const auto sentBefore = [&](UtcUs t) { return linesSentBy(sent, t); };
    QVERIFY2(sentBefore(killedAt - kMicrosPerSecond) <= in.size(),
             qPrintable(QString("%1 lines sent a second before the kill, %2 recorded")
                            .arg(sentBefore(killedAt - kMicrosPerSecond))
                            .arg(in.size())));
    // Measured: the lines lost, how long before the kill the first of them was sent (wall time) and the
    // stream time they span (0: one burst of one time)
    const std::size_t lost = sentBefore(killedAt) - in.size();
    const double lostWallS = lost > 0 ? toSeconds(killedAt - sent[in.size()].at) : 0.0;
    const double lostStreamS =
        lost > 0 ? sent[sentBefore(killedAt) - 1].streamS - sent[in.size()].streamS : 0.0;
    qInfo(
        "killed after %.1f s of estimates with %ld lines pending: %zu lines recorded, %zu sent before the "
        "kill; lost %zu lines, sent in the last %.3f s before the kill, spanning %.1f s of stream time at "
        "x%.0f; worst send-to-receive %.1f ms",
        estimateSeconds(db), pending, in.size(), sentBefore(killedAt), lost, lostWallS, lostStreamS, rate,
        toSeconds(worstLatency) * 1e3);
    QVERIFY(lostWallS <= 1.0);
    QVERIFY(lostStreamS <= std::max(1.0, rate));
    // AND its replay computes every recorded estimate again, exactly
    replayOfKilledRecordIsExact(db, dir_.filePath(name + "-replay"));
  }

  void aCompleteRecordingReplaysToTheSameFiles() {
    // GIVEN a simulated run's NMEA and radar plots (export builtin:imo-2) with real AIS sentences among
    // the NMEA, and live recording them from two TCP servers
    const QString exp = dir_.filePath("export");
    QCOMPARE(runCli({"export", "builtin:imo-2", "--date", "2026-11-23", "--out", exp, "--quiet"}).code, 0);
    const std::vector<Chunk> chunks = chunksOf(exp + "/ownship.nmea");
    QList<QByteArray> radar = contentsOf(exp + "/radar.csv").trimmed().split('\n');
    QList<QByteArray> ais;
    for (const QByteArray& l : contentsOf(kAis).split('\n'))
      if (l.startsWith('!')) ais.push_back(l.trimmed());
    QVERIFY(chunks.size() > 200 && radar.size() > 100 && ais.size() > 100);
    QTcpServer nmeaServer, radarServer;
    QVERIFY(nmeaServer.listen(QHostAddress::LocalHost, 0) && radarServer.listen(QHostAddress::LocalHost, 0));
    const QString db = dir_.filePath("complete.sqlite"), out = dir_.filePath("complete");
    Live live({"--tcp", "127.0.0.1:" + QString::number(nmeaServer.serverPort()), "--radar-tcp",
               "127.0.0.1:" + QString::number(radarServer.serverPort()), "--config", "builtin:imo-2",
               "--record", db, "--out", out, "--status-interval", "0.05"});
    QVERIFY(nmeaServer.waitForNewConnection(kCapMs) && radarServer.waitForNewConnection(kCapMs));
    QTcpSocket* nmea = nmeaServer.nextPendingConnection();
    QTcpSocket* plots = radarServer.nextPendingConnection();
    // WHEN each second is sent in time order, the plots stamped before it first, an AIS sentence with it
    long lines = 0;
    qsizetype r = 1;
    plots->write(radar.front() + "\n");
    ++lines;
    for (std::size_t c = 0; c < chunks.size(); ++c) {
      const QString at =
          QStringLiteral("2026-11-23T") +
          QTime::fromMSecsSinceStartOfDay(static_cast<int>(chunks[c].timeS * 1000)).toString("HH:mm:ss");
      for (; r < radar.size() && QString::fromLatin1(radar[r]).left(19) < at; ++r, ++lines)
        plots->write(radar[r] + "\n");
      plots->flush();
      QTest::qWait(1);  // the plots ahead of the sentences, as a radar's
      if (c < static_cast<std::size_t>(ais.size())) {
        nmea->write(ais[static_cast<qsizetype>(c)] + "\r\n");
        ++lines;
      }
      for (const QByteArray& l : chunks[c].lines) {
        nmea->write(l + "\r\n");
        ++lines;
      }
      nmea->flush();
    }
    for (; r < radar.size(); ++r, ++lines) plots->write(radar[r] + "\n");
    plots->flush();
    // ... and the run is ended with SIGINT once all is recorded
    QTRY_VERIFY_WITH_TIMEOUT(live.recorded().second >= lines, kCapMs);
    ::kill(static_cast<pid_t>(live.p.processId()), SIGINT);
    QVERIFY(live.p.waitForFinished(kCapMs));
    QCOMPARE(live.p.exitCode(), 0);
    // THEN its replay writes the same files, byte for byte (none has a wall-clock field), and computes the
    // recorded estimates, track rows and alerts again, exactly
    const auto rep = runCli({"replay", "--recording", db, "--out", dir_.filePath("complete-replay")});
    QCOMPARE(rep.code, 0);
    qInfo("%s", qPrintable(rep.out.trimmed()));
    for (const char* what : {"own-ship rows", "track rows", "alert entries"})
      QVERIFY2(rep.out.contains(QRegularExpression(
                   QString(what) + R"( [1-9]\d* equal, 0 different, 0 not recorded, 0 not replayed)")),
               qPrintable(rep.out + rep.err));
    for (const char* f : {"ownship.csv", "targets.csv", "ais.csv", "alerts.csv", "summary.json"}) {
      const QByteArray mine = contentsOf(out + "/" + f),
                       again = contentsOf(dir_.filePath("complete-replay/") + f);
      QVERIFY2(mine.count('\n') > 1, f);
      QVERIFY2(mine == again, f);
    }
    // AND --json prints that summary.json
    const auto json =
        runCli({"replay", "--recording", db, "--out", dir_.filePath("complete-json"), "--json"});
    QCOMPARE(json.out.toUtf8().trimmed(), contentsOf(out + "/summary.json").trimmed());
  }

  void theSizeOfARecording() {
    // GIVEN the whole icebreaker recording (12 minutes, 7 sentences a second) played at full rate
    const QString db = dir_.filePath("size.sqlite"), pruned = dir_.filePath("pruned.sqlite");
    for (const auto& [file, extra] :
         {std::pair{db, QStringList{}}, std::pair{pruned, QStringList{"--record-max-hours", "0.05"}}}) {
      const auto r = runCli(QStringList{"live", "--file", kIcebreaker, "--file-rate", "1000000", "--record",
                                        file, "--out", file + ".out", "--status-interval", "0"} +
                            extra);
      QCOMPARE(r.code, 0);
    }
    // THEN its size per hour of data is measured (docs/recorder.md), and with 3 minutes kept at full rate
    // the older estimates are one a minute
    const files::VoyageRecord full(db.toStdString()), kept(pruned.toStdString());
    const auto span = full.inputSpan();
    const auto est = full.estimateSpan();
    QVERIFY(span && est);
    const double hours = toSeconds(est->last - est->first) / 3600.0;
    const auto rows = full.estimates(INT64_MIN, INT64_MAX).size(),
               keptRows = kept.estimates(INT64_MIN, INT64_MAX).size();
    const qint64 bytes = QFileInfo(db).size(), input = QFileInfo(kIcebreaker).size();
    qInfo(
        "%lld lines, %zu own-ship rows over %.3f h: %lld bytes (input %lld bytes): %.2f MB per hour; "
        "--record-max-hours 0.05 kept %zu rows (%lld bytes)",
        static_cast<long long>(full.inputCount()), rows, hours, static_cast<long long>(bytes),
        static_cast<long long>(input), static_cast<double>(bytes) / hours / 1e6, keptRows,
        static_cast<long long>(QFileInfo(pruned).size()));
    QVERIFY(rows > 700);
    QVERIFY(keptRows < rows && keptRows > 180);
    QVERIFY(static_cast<double>(bytes) < 5.0 * static_cast<double>(input));
  }

  void usageErrorsAndFilesThatAreNoRecord() {
    const QString db = dir_.filePath("size.sqlite");
    const QString text = dir_.filePath("not-a-record.sqlite");
    QFile t(text);
    QVERIFY(t.open(QIODevice::WriteOnly));
    t.write("$GPZDA,000000.70,01,08,2014,,*6F\n");
    t.close();
    struct Case {
      QStringList args;
      QString error;
    };
    const std::vector<Case> cases{
        {{"replay", "--recording", db, "--nmea", kIcebreaker, "--out", dir_.filePath("x")},
         "--recording cannot be given with --nmea or --radar"},
        {{"replay", "--recording", db, "--profile", "imo", "--out", dir_.filePath("x")},
         "--recording replays with the settings it recorded"},
        {{"replay", "--recording", text, "--out", dir_.filePath("x")}, text + ": not a SQLite database"},
        {{"replay", "--recording", dir_.filePath("none.sqlite"), "--out", dir_.filePath("x")},
         dir_.filePath("none.sqlite") + ": cannot open: no such file"},
        {{"live", "--file", kIcebreaker, "--record", db, "--out", dir_.filePath("x")},
         db + ": exists already: a voyage record is never written over"},
        {{"live", "--file", kIcebreaker, "--record-max-hours", "1", "--out", dir_.filePath("x")},
         "--record-max-hours needs --record FILE.sqlite"},
    };
    for (const Case& c : cases) {
      const auto r = runCli(c.args);
      QCOMPARE(r.code, 2);
      QVERIFY2(r.err.startsWith("reckoner-cli: error: ") && r.err.contains(c.error), qPrintable(r.err));
      QCOMPARE(r.err.count('\n'), 1);
    }
  }
};

QTEST_GUILESS_MAIN(TestRecorderCli)
#include "tst_recorder_cli.moc"
