// reckoner-cli fed what a careless or hostile user feeds it (issue 15), as a user would run it: every
// run under a CPU-time and memory limit (support/resource_limits.h), so a hang or an unbounded
// allocation fails the test instead of the machine. Each case asserts what must hold: exit code 2 and
// one error line naming the file (and line or field), quoting at most 200 characters of input, or exit
// 0 with the damage counted in summary.json.
//
// The program under test is RECKONER_CLI; the environment variable RECKONER_CLI_UNDER_TEST replaces it
// (to run the same cases against another build, e.g. the one before a fix).
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <sys/stat.h>

#include "io/iso8601.h"
#include "io/nmea.h"
#include "sim/nmea_export.h"
#include "sim/replay.h"
#include "support/drkf_fixtures.h"
#include "support/resource_limits.h"

using namespace reckoner;

namespace {
struct Result {
  int code = -1;
  bool finished = false;  ///< exited by itself inside the limits (not killed)
  QString out, err;
};

QString cliPath() {
  const QByteArray env = qgetenv("RECKONER_CLI_UNDER_TEST");
  return env.isEmpty() ? QString(RECKONER_CLI) : QString::fromLocal8Bit(env);
}

Result cli(const QStringList& args) {
  QProcess p;
  test::limitChildren(p);
  p.start(cliPath(), args);
  // A guard only: the CPU limit ends a busy child; this ends one that blocks (a FIFO) without CPU.
  const bool done = p.waitForFinished(180000 * (test::slowdown() > 1 ? 5 : 1));
  if (!done) {
    p.kill();
    p.waitForFinished();
  }
  Result r;
  r.finished = done && p.exitStatus() == QProcess::NormalExit;
  r.code = p.exitCode();
  r.out = QString::fromUtf8(p.readAllStandardOutput());
  r.err = QString::fromUtf8(p.readAllStandardError());
  return r;
}

QByteArray read(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

QString write(const QTemporaryDir& dir, const QString& name, const QByteArray& text) {
  QString path = dir.filePath(name);
  QFile f(path);
  if (!f.open(QIODevice::WriteOnly)) qFatal("cannot write %s", qPrintable(path));
  f.write(text);
  return path;
}

/// The error-line contract: exit 2, one line on stderr (warnings aside), starting with the program's
/// prefix and naming `file`, no control characters, at most 200 characters quoted from the input.
bool isOneErrorLine(const Result& r, const QString& file, QString& why) {
  const auto fail = [&why](const QString& w) {
    why = w;
    return false;
  };
  if (!r.finished) return fail("did not finish inside the limits");
  if (r.code != 2) return fail(QString("exit code %1, stderr: %2").arg(r.code).arg(r.err.left(300)));
  QStringList lines = r.err.split('\n', Qt::SkipEmptyParts);
  lines.removeIf([](const QString& l) { return l.startsWith("reckoner-cli: warning: "); });
  if (lines.size() != 1) return fail(QString("%1 error lines: %2").arg(lines.size()).arg(r.err.left(300)));
  const QString& l = lines.front();
  if (!l.startsWith("reckoner-cli: error: ")) return fail("not an error line: " + l.left(300));
  if (!file.isEmpty() && !l.contains(file)) return fail("does not name " + file + ": " + l.left(300));
  for (const QChar c : l)
    if (c.unicode() < 0x20 || c.unicode() == 0x7F) return fail("control character in: " + l.left(300));
  if (l.size() > 1000) return fail(QString("%1 characters long").arg(l.size()));
  // Quoted input: at most 200 characters, each escape (\xNN) counting as one.
  static const QRegularExpression quote("'((?:[^'\\\\]|\\\\x[0-9A-F]{2}|\\\\.)*)'");
  static const QRegularExpression escape("\\\\x[0-9A-F]{2}|\\\\.");
  for (auto it = quote.globalMatch(l); it.hasNext();) {
    QString q = it.next().captured(1);
    q.replace(escape, "e");
    if (q.size() > 200) return fail(QString("quotes %1 characters of input").arg(q.size()));
  }
  return true;
}

const char* kScenario = R"({
  "format": "reckoner-scenario/1",
  "name": "hostile",
  "origin": {"lat_deg": 49.29, "lon_deg": -123.11},
  "duration_s": 60,
  "step_s": 1,
  "current": {"sigma_mps": 0.1, "beta_per_s": 0.01},
  "own_ship": {"velocity_mps": [3, 4], "schedule": [{"t_s": 10, "turn_rate_dps": 1.5}]},
  "sensors": {
    "gps": {"rate_hz": 1, "position_variance_m2": 25, "velocity_variance_m2_s2": 0.01},
    "speedlog": {"markov_variance_m2_s2": 0.01, "markov_beta_per_s": 0.01, "white_variance_m2_s2": 0.01},
    "gyro": {"sd_deg": 0.5},
    "radar": {"sweep_period_s": 2.5, "range_sd_m": 20, "bearing_sd_deg": 0.5, "clutter_per_km2": 0.001}
  },
  "targets": [{"id": 1, "position_m": [3000, 3000], "velocity_mps": [-3, 0]}],
  "filter": {"initial_velocity_sd_mps": 0.5},
  "tracker": {"filter_changes": [{"t_s": 30, "filter": "imm"}]}
})";

QByteArray variant(const char* from, const char* to) {
  QByteArray s(kScenario);
  const auto at = s.indexOf(from);
  if (at < 0) qFatal("test text not found: %s", from);
  return s.replace(at, static_cast<qsizetype>(qstrlen(from)), to);
}
}  // namespace

class TestHostileInputs : public QObject {
  Q_OBJECT
  QTemporaryDir dir_;
  QString nmea_, radar_;  // an exported run to damage
  QList<QByteArray> nmeaLines_, radarLines_;

  QString damagedNmea(const QString& name, const QList<QByteArray>& lines) {
    return write(dir_, name, lines.join("\r\n") + "\r\n");
  }
  QJsonObject replaySummary(const QString& nmea, const QString& radar, const QString& out, Result& r) {
    QStringList args{"replay", "--nmea", nmea, "--out", dir_.filePath(out), "--quiet"};
    if (!radar.isEmpty()) args << "--radar" << radar;
    r = cli(args);
    return QJsonDocument::fromJson(read(dir_.filePath(out + "/summary.json"))).object();
  }
  static bool finiteCsv(const QByteArray& csv) {
    return !csv.isEmpty() && !csv.contains("nan") && !csv.contains("inf");
  }

 private slots:
  void initTestCase() {
    QVERIFY(dir_.isValid());
    qInfo("program under test: %s", qPrintable(cliPath()));
    sim::Scenario s = test::builtinScenario("ttkf-matched");
    s.durationUs = 600 * kMicrosPerSecond;
    const auto e = sim::exportRun(s, 2, *io::parseIso8601("2026-11-23T10:00:00Z"));
    nmea_ = write(dir_, "run.nmea", QByteArray::fromStdString(e.nmea));
    radar_ = write(dir_, "run.csv", QByteArray::fromStdString(e.radarCsv));
    nmeaLines_ = QByteArray::fromStdString(e.nmea).split('\n');
    radarLines_ = QByteArray::fromStdString(e.radarCsv).split('\n');
    for (auto& l : nmeaLines_) l = l.trimmed();
    nmeaLines_.removeAll(QByteArray());
    radarLines_.removeAll(QByteArray());
  }

  // ---- replay of damaged NMEA --------------------------------------------------------------------
  void replayAfterGapIsFiniteAndCountsTheRestart() {
    QList<QByteArray> cut;
    int epoch = -1;
    for (const auto& l : nmeaLines_) {
      if (l.startsWith("$IIZDA")) ++epoch;
      if (epoch < 150 || epoch >= 350) cut << l;
    }
    Result r;
    const auto s = replaySummary(damagedNmea("gap.nmea", cut), {}, "gap", r);
    QVERIFY2(r.finished && r.code == 0, qPrintable(r.err));
    QVERIFY(finiteCsv(read(dir_.filePath("gap/ownship.csv"))));
    QCOMPARE(s["own_ship_filter"].toObject()["restarts"].toObject()["after_gap"].toInt(), 1);
    const auto gps = s["own_ship_filter"].toObject()["updates"].toObject()["gps_position"].toObject();
    QVERIFY2(gps["accepted"].toInt() >= 300, qPrintable(QString::number(gps["accepted"].toInt())));
  }
  void replayDropsOneSentenceStampedAhead() {
    QList<QByteArray> lines = nmeaLines_;
    int seen = 0;
    for (auto& l : lines) {
      if (!l.startsWith("$GPRMC") || ++seen != 100) continue;
      const QByteArray body = l.mid(1, l.indexOf('*') - 1);
      QList<QByteArray> f = body.split(',');
      f[1] =
          f[1].left(2) + QByteArray::number(f[1].mid(2, 2).toInt() + 20).rightJustified(2, '0') + f[1].mid(4);
      l = QByteArray::fromStdString(io::nmea::withChecksum(f.join(',').toStdString()));
    }
    Result r;
    const auto s = replaySummary(damagedNmea("jump.nmea", lines), {}, "jump", r);
    QVERIFY2(r.finished && r.code == 0, qPrintable(r.err));
    QCOMPARE(s["nmea"].toObject()["skipped"].toInt(), 1);
    QCOMPARE(s["nmea"].toObject()["time_jumps"].toInt(), 1);
    const QByteArray csv = read(dir_.filePath("jump/ownship.csv"));
    QVERIFY(finiteCsv(csv));
    QCOMPARE(csv.count('\n'), 600 + 1);
  }
  void replayOfAReversedFileUsesItAll() {
    QList<QByteArray> lines = nmeaLines_.mid(0, 300);
    std::reverse(lines.begin(), lines.end());
    Result r;
    const auto s = replaySummary(damagedNmea("reversed.nmea", lines), {}, "reversed", r);
    QVERIFY2(r.finished && r.code == 0, qPrintable(r.err));
    QVERIFY2(s["nmea"].toObject()["sentences_used"].toInt() >= 295, qPrintable(r.err));
  }
  void replayRefusesAnImpossibleSpeed() {
    QList<QByteArray> lines = nmeaLines_;
    for (auto& l : lines)
      if (l.startsWith("$GPRMC")) {
        QList<QByteArray> f = l.mid(1, l.indexOf('*') - 1).split(',');
        f[7] = "1000000.0";
        l = QByteArray::fromStdString(io::nmea::withChecksum(f.join(',').toStdString()));
        break;
      }
    Result r;
    replaySummary(damagedNmea("fast.nmea", lines), {}, "fast", r);
    QVERIFY2(r.finished && r.code == 0, qPrintable(r.err));
    const QList<QByteArray> first = read(dir_.filePath("fast/ownship.csv")).split('\n')[1].split(',');
    QVERIFY2(std::hypot(first[4].toDouble(), first[5].toDouble()) < 30.0, first.join(',').constData());
  }
  void estimatedFixesAreNotGnssFixes() {
    // Only GGA of quality 6 (estimated): no GNSS fix to start from.
    QList<QByteArray> lines;
    for (const auto& l : nmeaLines_)
      if (l.startsWith("$GPGGA") || l.startsWith("$IIZDA")) {
        QList<QByteArray> f = l.mid(1, l.indexOf('*') - 1).split(',');
        if (l.startsWith("$GPGGA")) f[6] = "6";
        lines << QByteArray::fromStdString(io::nmea::withChecksum(f.join(',').toStdString()));
      }
    const QString path = damagedNmea("estimated.nmea", lines);
    QString why;
    const Result r = cli({"replay", "--nmea", path, "--out", dir_.filePath("est")});
    QVERIFY2(isOneErrorLine(r, path, why), qPrintable(why));
    QVERIFY2(r.err.contains("no position fix"), qPrintable(r.err));
  }

  // ---- radar CSV ------------------------------------------------------------------------------------
  void radarLabelsAreAccepted() {
    QList<QByteArray> lines = radarLines_;
    for (int i = 1; i < lines.size(); ++i)
      if (!lines[i].endsWith(',')) lines[i].insert(lines[i].lastIndexOf(',') + 1, "T");
    const QString path = write(dir_, "labels.csv", lines.join('\n') + '\n');
    Result r;
    const QStringList args{
        "replay", "--nmea", nmea_, "--radar", path, "--assume-association", "--out", dir_.filePath("labels"),
        "--quiet"};
    r = cli(args);
    QVERIFY2(r.finished && r.code == 0, qPrintable(r.err));
    const QJsonObject s = QJsonDocument::fromJson(read(dir_.filePath("labels/summary.json"))).object();
    QCOMPARE(s["radar"].toObject()["bad"].toInt(), 0);
    QVERIFY(read(dir_.filePath("labels/targets.csv")).contains(",T1,"));
  }
  void radarWithoutUsableLineIsOneError() {
    const QString path =
        write(dir_, "allbad.csv", "utc,range_m,bearing_deg\nnot,a,plot\n2026-11-23T10:00:01Z,x,1\n");
    QString why;
    const Result r = cli({"replay", "--nmea", nmea_, "--radar", path, "--out", dir_.filePath("allbad")});
    QVERIFY2(isOneErrorLine(r, path + ":2:", why), qPrintable(why));
  }
  void radarYearFlipAndDuplicatesFinishInsideTheLimits() {
    QList<QByteArray> flipped = radarLines_;
    flipped[flipped.size() / 2][0] = '6';
    Result r;
    auto s = replaySummary(nmea_, write(dir_, "year.csv", flipped.join('\n') + '\n'), "year", r);
    QVERIFY2(r.finished && r.code == 0, qPrintable(r.err));
    QCOMPARE(s["radar"].toObject()["time_jumps"].toInt(), 1);
    QList<QByteArray> dup = radarLines_;
    for (int k = 0; k < 5000; ++k) dup.insert(100, radarLines_[100]);
    s = replaySummary(nmea_, write(dir_, "dup.csv", dup.join('\n') + '\n'), "dup", r);
    QVERIFY2(r.finished && r.code == 0, qPrintable(r.err));
    QCOMPARE(s["radar"].toObject()["duplicates"].toInt(), 5000);
  }
  void byteOrderMarksAreIgnored() {
    Result r;
    const auto s = replaySummary(write(dir_, "bom.nmea", "\xEF\xBB\xBF" + read(nmea_)),
                                 write(dir_, "bom.csv", "\xEF\xBB\xBF" + read(radar_)), "bom", r);
    QVERIFY2(r.finished && r.code == 0, qPrintable(r.err));
    QCOMPARE(s["nmea"].toObject()["skipped"].toInt(), 0);
  }

  // ---- scenario values that passed validation and then hung, overflowed or gave NaN ---------------
  void scenarioValuesOutsidePhysicalSenseAreOneError_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QString>("field");
    const auto row = [](const char* name, const char* from, const char* to, const char* field) {
      QTest::newRow(name) << variant(from, to) << QString(field);
    };
    row("sweep 1e-7 s", "\"sweep_period_s\": 2.5", "\"sweep_period_s\": 1e-7",
        "sensors.radar.sweep_period_s");
    row("sweep 1e13 s", "\"sweep_period_s\": 2.5", "\"sweep_period_s\": 1e13",
        "sensors.radar.sweep_period_s");
    row("rate 1e6 Hz", "\"rate_hz\": 1,", "\"rate_hz\": 1e6,", "sensors.gps.rate_hz");
    row("rate 1e-13 Hz", "\"rate_hz\": 1,", "\"rate_hz\": 1e-13,", "sensors.gps.rate_hz");
    row("clutter 1e15", "\"clutter_per_km2\": 0.001", "\"clutter_per_km2\": 1e15",
        "sensors.radar.clutter_per_km2");
    row("clutter 1e6", "\"clutter_per_km2\": 0.001", "\"clutter_per_km2\": 1e6",
        "sensors.radar.clutter_per_km2");
    row("step 1e-6 s", "\"step_s\": 1,", "\"step_s\": 1e-6,", "step_s");
    row("time 1e13 s", "{\"t_s\": 10, \"turn", "{\"t_s\": 1e13, \"turn",
        "own_ship.schedule[0].t_s: time 1e+13 s lies beyond duration_s");
    row("filter change 1e13 s", "{\"t_s\": 30, \"filter\"", "{\"t_s\": 1e13, \"filter\"",
        "tracker.filter_changes[0].t_s: time 1e+13 s lies beyond duration_s");
    row("GPS variance 0", "\"position_variance_m2\": 25", "\"position_variance_m2\": 0",
        "sensors.gps.position_variance_m2");
    row("beta 1e300", "\"beta_per_s\": 0.01},\n  \"own", "\"beta_per_s\": 1e300},\n  \"own",
        "current.beta_per_s");
    row("velocity sd 1e9", "\"initial_velocity_sd_mps\": 0.5", "\"initial_velocity_sd_mps\": 1e9",
        "filter.initial_velocity_sd_mps");
    row("speed 1e6 m/s", "\"velocity_mps\": [3, 4]", "\"velocity_mps\": [1e6, 4]", "own_ship.velocity_mps");
    row("capacity 1e6", "\"filter_changes\"", "\"capacity\": 1000000, \"filter_changes\"",
        "tracker.capacity");
    row("invalid UTF-8 name", "\"name\": \"hostile\"", "\"name\": \"host\xff\xfeile\"", "");
  }
  void scenarioValuesOutsidePhysicalSenseAreOneError() {
    QFETCH(QByteArray, text);
    QFETCH(QString, field);
    const QString path = write(dir_, "s.json", text);
    QString why;
    const Result r = cli({"run", path, "--out", dir_.filePath("run-out"), "--quiet"});
    QVERIFY2(isOneErrorLine(r, path + ":", why), qPrintable(why));
    QVERIFY2(r.err.contains(field), qPrintable(r.err));
  }
  void zeroVariancesThatAreModelsRunFinite_data() {
    // A Loran-C without correlated error and a constant-velocity filter are models, not mistakes:
    // accepted, and their runs finite (every NEES was NaN: the zero-variance states made P singular).
    QTest::addColumn<QByteArray>("text");
    QTest::newRow("as given") << QByteArray(kScenario);
    QTest::newRow("Loran-C without Markov error")
        << variant("\"gyro\": {\"sd_deg\": 0.5},",
                   "\"gyro\": {\"sd_deg\": 0.5}, \"loran_c\": {\"markov_variance_m2\": 0, "
                   "\"markov_beta_per_s\": 0.25, \"white_variance_m2\": 25},");
    QTest::newRow("filter without acceleration") << variant(
        "\"initial_velocity_sd_mps\": 0.5",
        "\"initial_velocity_sd_mps\": 0.5, \"acceleration\": {\"sigma_mps2\": 0, \"beta_per_s\": 1}");
  }
  void zeroVariancesThatAreModelsRunFinite() {
    QFETCH(QByteArray, text);
    const QString path = write(dir_, "ok.json", text);
    const Result r = cli({"run", path, "--out", dir_.filePath("ok"), "--quiet"});
    QVERIFY2(r.finished && r.code == 0, qPrintable(r.err));
    QVERIFY(finiteCsv(read(dir_.filePath("ok/ownship.csv"))));
  }
  void seed002MatchedHasANees() {
    const Result r = cli({"run", "builtin:seed002-matched", "--out", dir_.filePath("s002"), "--quiet"});
    QVERIFY2(r.finished && r.code == 0, qPrintable(r.err));
    const QList<QByteArray> rows = read(dir_.filePath("s002/ownship.csv")).split('\n');
    QCOMPARE(rows.size(), 1500 + 2);
    for (int i = 1; i < rows.size() - 1; ++i) QVERIFY2(rows[i].split(',')[15] != "nan", rows[i].constData());
    const QJsonObject s = QJsonDocument::fromJson(read(dir_.filePath("s002/summary.json"))).object();
    for (const auto& p : s["phases"].toArray()) QVERIFY(p.toObject()["mean_nees"].isDouble());
  }

  // ---- JSON ---------------------------------------------------------------------------------------
  void manyKeysAreCheckedInLinearTime() {
    // 300,000 keys: the quadratic duplicate check took minutes (past the CPU limit); now under a second.
    QByteArray text = "{\"format\": \"reckoner-scenario/1\"";
    for (int k = 0; k < 300000; ++k) text += ", \"k" + QByteArray::number(k) + "\": 0";
    text += "}";
    const QString path = write(dir_, "keys.json", text);
    QString why;
    const Result r = cli({"validate", path});
    QVERIFY2(isOneErrorLine(r, path, why), qPrintable(why));
  }
  void hugeInputIsQuotedShort() {
    // A 400 KB sensor name full of control characters (valid JSON: \u0001 escapes) is quoted cut and
    // escaped on one line (the whole name was echoed twice, control characters and all).
    QByteArray name;
    for (int i = 0; i < 40000; ++i) name += "abcd\\u0001\\n";
    const QByteArray text = variant("\"gyro\": {", "\"" + name + "\": {}, \"gyro\": {");
    const QString path = write(dir_, "huge.json", text);
    QString why;
    const Result r = cli({"validate", path});
    QVERIFY2(isOneErrorLine(r, path, why), qPrintable(why));
    QVERIFY2(r.err.size() < 1000, qPrintable(QString::number(r.err.size())));
  }

  // ---- inputs that are not files ------------------------------------------------------------------
  void fifosAndDirectoriesAreRefused() {
    const QString fifo = dir_.filePath("fifo");
    QCOMPARE(::mkfifo(fifo.toLocal8Bit().constData(), 0600), 0);
    const QString folder = dir_.filePath("folder");
    QVERIFY(QDir().mkpath(folder));
    for (const QString& path : {fifo, folder}) {
      const std::vector<QStringList> cases{
          {"replay", "--nmea", path, "--out", dir_.filePath("x")},
          {"replay", "--nmea", nmea_, "--radar", path, "--out", dir_.filePath("x")},
          {"replay", "--nmea", nmea_, "--config", path, "--out", dir_.filePath("x")},
          {"run", path, "--out", dir_.filePath("x")},
          {"validate", path}};
      for (const QStringList& args : cases) {
        QString why;
        const Result r = cli(args);
        QVERIFY2(isOneErrorLine(r, path, why), qPrintable(args.join(' ') + ": " + why));
      }
    }
    QString why;
    const Result chart = cli({"chart", "info", fifo});
    QVERIFY2(isOneErrorLine(chart, fifo, why), qPrintable(why));
  }
};

QTEST_GUILESS_MAIN(TestHostileInputs)
#include "tst_hostile_inputs.moc"
