// reckoner-cli driven as a user drives it: files written, exit codes, one-line errors.
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>

#include <QTemporaryDir>
#include <QTest>

#include "cli_process.h"
#include "support/compare_near.h"

class TestCli : public QObject {
  Q_OBJECT

  using Result = reckoner::test::CliResult;
  static Result cli(const QStringList& args) { return reckoner::test::runCli(args); }
  static QByteArray read(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
  }
  static QString writeTemp(QTemporaryDir& dir, const QString& name, const QByteArray& text) {
    QString path = dir.filePath(name);
    QFile f(path);
    f.open(QIODevice::WriteOnly);
    f.write(text);
    return path;
  }
  static QByteArray scenarioText(const QString& name) {
    return read(QString(RECKONER_SCENARIO_DIR) + "/" + name);
  }

 private slots:
  void runWritesCsvAndSummary() {
    QTemporaryDir dir;
    const Result r = cli({"run", "builtin:table1-test1", "--seed", "3", "--out", dir.path()});
    QCOMPARE(r.code, 0);
    QVERIFY(r.out.contains("gps+loran_c+speedlog_gl+gyro"));
    const QList<QByteArray> lines = read(dir.filePath("ownship.csv")).split('\n');
    QCOMPARE(lines.front(),
             QByteArray("t_s,true_x_m,true_y_m,true_vx_mps,true_vy_mps,est_x_m,est_y_m,est_vx_mps,"
                        "est_vy_mps,sd_x_m,sd_y_m,sd_vx_mps,sd_vy_mps,est_lat_deg,est_lon_deg,nees,"
                        "sensors,rows"));
    QCOMPARE(lines.size(), 1500 + 2);  // header, 1500 rows, final newline
    QCOMPARE(lines[1].split(',').size(), 18);
    const QJsonObject s = QJsonDocument::fromJson(read(dir.filePath("summary.json"))).object();
    QCOMPARE(s["seed"].toInt(), 3);
    QCOMPARE(s["phases"].toArray().size(), 5);
    QVERIFY(s["wall_time_s"].toDouble() > 0.0);
    const QJsonObject dr = s["phases"].toArray()[2].toObject();
    QCOMPARE(dr["kind"].toString(), QString("dead_reckoning"));
    QVERIFY(dr["rmse_position_m"].toDouble() > 0.0 && dr["mean_nees"].toDouble() > 0.0);
  }
  void runWritesTargetsCsvWithTracking() {
    // GIVEN a scenario with radar targets WHEN run THEN targets.csv has the documented columns, one row
    // per track per sweep, clutter tracks without truth, and summary.json a tracking section.
    QTemporaryDir dir;
    const Result r = cli({"run", "builtin:imo-2", "--out", dir.path()});
    QCOMPARE(r.code, 0);
    QVERIFY(r.out.contains("continuity"));
    const QList<QByteArray> lines = read(dir.filePath("targets.csv")).split('\n');
    QCOMPARE(lines.front(),
             QByteArray(
                 "t_s,track_id,target_id,status,true_x_m,true_y_m,true_vx_mps,true_vy_mps,est_x_m,est_y_m,"
                 "est_vx_mps,est_vy_mps,sd_x_m,sd_y_m,sd_vx_mps,sd_vy_mps,est_lat_deg,est_lon_deg,course_deg,"
                 "speed_kn,cpa_nm,tcpa_min,nees,nis,ais_mmsi"));
    QVERIFY(lines.size() >= 119);  // 119 sweeps end within 240 s
    const QList<QByteArray> last = lines[lines.size() - 2].split(',');
    QCOMPARE(last.size(), 25);
    QCOMPARE(last[24], QByteArray(""));  // no AIS on imo-1
    QCOMPARE(last[2], QByteArray("1"));
    QCOMPARE(last[3], QByteArray("confirmed"));
    RK_COMPARE_NEAR(last[19].toDouble(), 14.14, 0.5);  // true speed 14.1 kn
    const QJsonObject t =
        QJsonDocument::fromJson(read(dir.filePath("summary.json"))).object()["tracking"].toObject();
    QVERIFY(t["continuity"].toDouble() > 0.99);
    QCOMPARE(t["targets"].toArray().size(), 1);
    QCOMPARE(t["far_swaps"].toInt(), 0);
  }
  void imoPrintsTheAccuracyTable() {
    const Result r = cli({"imo", "builtin:imo-1", "--runs", "30"});
    QCOMPARE(r.code, 0);
    QVERIFY(r.out.contains("relative course"));
    QVERIFY(r.out.contains("all cells pass"));
    const Result bad = cli({"imo", "builtin:table1-test1"});  // no radar target
    QCOMPARE(bad.code, 2);
    QVERIFY(bad.err.contains("needs a radar and a target"));
  }
  void seed001PrintsTheMonteCarloTable() {
    const Result r = cli({"seed001", "--runs", "20", "--turn"});
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.contains("threshold 9.21") && r.out.contains("first detection at or after 540 s"),
             qPrintable(r.out));
    QCOMPARE(r.out.count('\n'), 2 + 22 + 1);  // header, samples 2 to 23, detections
  }
  void seed003PrintsThe2drmsTable() {
    const Result r = cli({"seed003", "--runs", "3", "--alpha", "0.4"});
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.contains("varying course and speed") && r.out.contains("predicted 2drms"),
             qPrintable(r.out));
    const Result bad = cli({"seed003", "--alpha", "0.9"});
    QCOMPARE(bad.code, 2);
    QVERIFY(bad.err.contains("--alpha: expected a number"));
  }
  void manoeuvreReportPrintsFourTrackers() {
    const Result r = cli({"manoeuvre-report", "--runs", "5", "--turn", "30"});
    QCOMPARE(r.code, 0);
    for (const char* name : {"EKF + input estimation", "alpha-beta-gamma", "IMM (CV + CT)", "/PCRB"})
      QVERIFY2(r.out.contains(name), qPrintable(r.out));
  }
  void exportThenReplay() {
    // GIVEN a run exported as NMEA and radar CSV WHEN replayed THEN ownship.csv and targets.csv carry a
    // utc column and no truth, and summary.json counts the input; a missing file is exit code 2.
    QTemporaryDir dir;
    QCOMPARE(cli({"export", "builtin:imo-2", "--date", "2026-11-23", "--out", dir.path()}).code, 0);
    const Result r =
        cli({"replay", "--nmea", dir.filePath("ownship.nmea"), "--radar", dir.filePath("radar.csv"),
             "--config", "builtin:imo-2", "--out", dir.filePath("replay")});
    QCOMPARE(r.code, 0);
    QVERIFY(r.out.contains("0 skipped"));
    const QList<QByteArray> own = read(dir.filePath("replay/ownship.csv")).split('\n');
    QVERIFY(own.front().startsWith("t_s,utc,est_x_m"));
    QVERIFY(own[1].split(',')[1].startsWith("2026-11-23T00:00:01"));
    const QList<QByteArray> tg = read(dir.filePath("replay/targets.csv")).split('\n');
    QVERIFY(tg.front().startsWith("t_s,utc,track_id,target_id,status,est_x_m"));
    QVERIFY(tg.size() > 100);
    const QJsonObject s = QJsonDocument::fromJson(read(dir.filePath("replay/summary.json"))).object();
    QCOMPARE(s["nmea"].toObject()["bad_checksum"].toInt(), 0);
    QVERIFY(s["radar"].toObject()["plots"].toInt() > 100);
    const Result missing = cli({"replay", "--nmea", dir.filePath("nope.nmea"), "--out", dir.path()});
    QCOMPARE(missing.code, 2);
    QVERIFY(missing.err.contains("nope.nmea"));
  }
  void chartInfo() {
    // A bad path: exit 2, the file named. The real cells, when ../shared is there: JSON per cell.
    const Result bad = cli({"chart", "info", "/nonexistent/cell.000"});
    QCOMPARE(bad.code, 2);
    QVERIFY(bad.err.contains("/nonexistent/cell.000: no such file or folder"));
    const QString enc = RECKONER_SCENARIO_DIR "/../../../shared/data/enc/US5BOSDC";
    if (!QDir(enc).exists()) QSKIP("../shared/data/enc is absent");
    const Result r = cli({"chart", "info", enc});
    QCOMPARE(r.code, 0);
    const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
    const QJsonObject cell = o["cells"].toArray()[0].toObject();
    QCOMPARE(cell["name"].toString(), QString("US5BOSDC"));
    QCOMPARE(cell["compilation_scale"].toInt(), 12000);
    QCOMPARE(cell["feature_counts"].toObject()["BOYLAT"].toInt(), 4);
    QVERIFY(o["failures"].toArray().isEmpty());
  }
  void sameSeedSameBytes() {
    QTemporaryDir a, b;
    QCOMPARE(cli({"run", "builtin:default", "--seed", "9", "--out", a.path(), "--quiet"}).code, 0);
    QCOMPARE(cli({"run", "builtin:default", "--seed", "9", "--out", b.path(), "--quiet"}).code, 0);
    QCOMPARE(read(a.filePath("ownship.csv")), read(b.filePath("ownship.csv")));
  }
  void monteCarloSummary() {
    QTemporaryDir dir;
    const Result r = cli({"montecarlo", "builtin:matched-model", "--runs", "4", "--threads", "2", "--out",
                          dir.filePath("mc")});
    QCOMPARE(r.code, 0);
    const QJsonObject s = QJsonDocument::fromJson(read(dir.filePath("mc/summary.json"))).object();
    QCOMPARE(s["runs"].toInt(), 4);
    const QJsonArray bounds = s["nees_bounds"].toArray();
    QCOMPARE(bounds.size(), 2);
    QVERIFY(bounds[0].toDouble() < 11.0 && bounds[1].toDouble() > 11.0);
    QCOMPARE(s["per_time"].toObject()["mean_nees"].toArray().size(), 1500);
    QCOMPARE(s["phases"].toArray().size(), 5);
    QVERIFY(r.out.contains("speedlog_bl+gyro"));
    QVERIFY(s.contains("all_phases_inside"));
    QVERIFY(read(dir.filePath("mc/montecarlo.csv")).startsWith("t_s,rmse_position_m"));
  }
  void ownShipFiltersRunAndCompare() {
    // run --own-ship-filter writes that filter's rows; own-ship-compare prints the three filters.
    QTemporaryDir dir;
    const Result r =
        cli({"run", "builtin:seed002-matched", "--own-ship-filter", "geodetic", "--out", dir.path()});
    QCOMPARE(r.code, 0);
    QVERIFY(r.out.contains("own-ship filter geodetic"));
    const QList<QByteArray> lines = read(dir.filePath("ownship.csv")).split('\n');
    QCOMPARE(lines.size(), 1500 + 2);
    const Result c = cli({"own-ship-compare", "builtin:seed002-matched", "--runs", "4"});
    QCOMPARE(c.code, 0);
    for (const char* name : {"drkf", "geodetic", "lsq"}) QVERIFY2(c.out.contains(name), qPrintable(c.out));
  }
  void badInputIsOneLineAndExitCode2_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("expected");
    QTest::newRow("missing file") << QStringList{"run", "/no/such.json", "--out", "/tmp/x"}
                                  << "/no/such.json: cannot open";
    QTest::newRow("no command") << QStringList{} << "no command given";
    QTest::newRow("unknown command") << QStringList{"fly"} << "unknown command 'fly'";
    QTest::newRow("missing --out") << QStringList{"run", "builtin:default"} << "--out DIR is required";
    QTest::newRow("bad runs") << QStringList{"montecarlo", "builtin:default", "--runs",
                                             "ten",        "--out",           "/tmp/x"}
                              << "--runs: expected an integer";
    QTest::newRow("zero runs") << QStringList{"montecarlo", "builtin:default", "--runs",
                                              "0",          "--out",           "/tmp/x"}
                               << "--runs: expected an integer";
    QTest::newRow("unknown builtin") << QStringList{"run", "builtin:nope", "--out", "/tmp/x"}
                                     << "unknown built-in scenario 'nope'";
    QTest::newRow("unknown option") << QStringList{"run", "builtin:default", "--fast"}
                                    << "unknown option '--fast'";
    QTest::newRow("seed001 bad pfa") << QStringList{"seed001", "--pfa", "2"} << "--pfa: expected a number";
    QTest::newRow("seed001 bad init")
        << QStringList{"seed001", "--init", "guess"} << "--init: expected paper or two-point";
    QTest::newRow("seed001 bad correction") << QStringList{"seed001", "--correction", "magic"}
                                            << "--correction: expected none, paper or refilter";
    QTest::newRow("unknown own-ship filter")
        << QStringList{"run", "builtin:default", "--own-ship-filter", "ukf", "--out", "/tmp/x"}
        << "--own-ship-filter: expected drkf, geodetic or lsq, got 'ukf'";
  }
  void badInputIsOneLineAndExitCode2() {
    QFETCH(QStringList, args);
    QFETCH(QString, expected);
    const Result r = cli(args);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(expected), qPrintable(r.err));
    QVERIFY2(r.err.startsWith("reckoner-cli: error: "), qPrintable(r.err));
  }
  void badScenarioFilesAreNamed_data() {
    QTest::addColumn<QByteArray>("from");
    QTest::addColumn<QByteArray>("to");
    QTest::addColumn<QString>("expected");
    QTest::newRow("malformed JSON") << QByteArray("\"duration_s\": 1500,")
                                    << QByteArray("\"duration_s\": 1500") << "bad.json:10: malformed JSON";
    QTest::newRow("unknown field") << QByteArray("\"step_s\": 1,")
                                   << QByteArray("\"step_s\": 1, \"speed\": 2,")
                                   << "bad.json:10: speed: unknown field";
    QTest::newRow("negative variance")
        << QByteArray("\"white_variance_m2\": 25") << QByteArray("\"white_variance_m2\": -25")
        << "sensors.loran_c.white_variance_m2: must be positive, got -25";
    QTest::newRow("unknown sensor") << QByteArray("\"gyro\": {") << QByteArray("\"compass\": {}, \"gyro\": {")
                                    << "sensors.compass: unknown sensor 'compass'";
  }
  void badScenarioFilesAreNamed() {
    QFETCH(QByteArray, from);
    QFETCH(QByteArray, to);
    QFETCH(QString, expected);
    QTemporaryDir dir;
    QByteArray text = scenarioText("matched-model.json");
    QVERIFY(text.contains(from));
    const QString path = writeTemp(dir, "bad.json", text.replace(from, to));
    const Result r = cli({"run", path, "--out", dir.filePath("out")});
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(expected), qPrintable(r.err));
    QCOMPARE(r.err.count('\n'), 1);
  }
  void listsAndValidatesBuiltins() {
    const Result list = cli({"scenarios"});
    QCOMPARE(list.code, 0);
    QVERIFY(list.out.contains("builtin:default") && list.out.contains("builtin:table1-test5"));
    QCOMPARE(cli({"validate", "builtin:matched-model", QString(RECKONER_SCENARIO_DIR) + "/table1-test2.json"})
                 .code,
             0);
  }
};

QTEST_GUILESS_MAIN(TestCli)
#include "tst_cli.moc"
