// reckoner-cli's conventions (docs/cli.md): `--help` and `COMMAND --help` exit 0 and list every option
// with its unit; every option spelling the command line has ever had is still there; bad input is one
// line on stderr and exit code 2; --json puts the summary on stdout.
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMap>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

#include "cli_process.h"

class TestCliHelp : public QObject {
  Q_OBJECT

  using Result = reckoner::test::CliResult;
  static Result cli(const QStringList& args) { return reckoner::test::runCli(args); }

  /// Every command and, as --help must show it, each of its options with the name of its value (the
  /// unit) and its positional arguments. The spellings are the command line's contract: scripts and
  /// the other tests call them.
  static QMap<QString, QStringList> expectedOptions() {
    const QStringList monteCarlo{"--runs N", "--threads K", "--seed N"};
    return {
        {"run",
         {"SCENARIO", "--seed N", "--own-ship-filter drkf|geodetic|lsq", "--profile paper|imo|realistic",
          "--nmea-out DEST", "--date YYYY-MM-DD", "--enc PATH", "--out DIR", "--quiet", "--json"}},
        {"montecarlo",
         QStringList{"SCENARIO", "--profile paper|imo|realistic", "--out DIR", "--quiet", "--json"} +
             monteCarlo},
        {"replay",
         {"--nmea FILE", "--radar FILE.csv", "--recording FILE.sqlite", "--config SCENARIO",
          "--assume-association", "--max-gap S", "--date YYYY-MM-DD", "--variation DEG",
          "--profile paper|imo|realistic", "--adaptive-gnss on|off", "--nmea-out DEST", "--out DIR",
          "--quiet", "--json"}},
        {"export", {"SCENARIO", "--seed N", "--date YYYY-MM-DD", "--out DIR", "--quiet"}},
        {"compare", QStringList{"SCENARIO", "--targets LIST", "--out DIR", "--quiet"} + monteCarlo},
        {"own-ship-compare", QStringList{"SCENARIO"} + monteCarlo},
        {"radar-fix", QStringList{"SCENARIO", "--enc PATH"} + monteCarlo},
        {"imo", QStringList{"SCENARIO"} + monteCarlo},
        {"fusion", QStringList{"SCENARIO", "--add-ais A|B", "--min-correct F"} + monteCarlo},
        {"trial",
         {"SCENARIO", "--at S", "--course DEG", "--speed KN", "--delay S", "--cpa-limit NM",
          "--tcpa-limit MIN", "--seed N", "--verify", "--runs N"}},
        {"seed001",
         {"--runs N", "--turn", "--seed N", "--window S", "--pfa P", "--q Q", "--bearing-sd DEG",
          "--init paper|two-point", "--correction none|paper|refilter", "--jump-sd M/S"}},
        {"seed003", {"--runs N", "--alpha A", "--sweep S", "--noise M", "--seed N"}},
        {"manoeuvre-report", {"--runs N", "--turn DEG", "--speed-change KN", "--seed N", "--imo-runs N"}},
        {"chart info", {"PATH"}},
        {"chart render",
         {"PATH", "--center LAT,LON", "--scale N", "--size WxH", "--palette day|dusk|night",
          "--category base|standard|all", "--safety-contour M", "--out FILE.png", "--repeat K"}},
        {"chart pick", {"PATH", "--at LAT,LON", "--scale N", "--tolerance PX"}},
        {"ais decode", {"FILE", "--json"}},
        {"route check",
         {"ROUTE", "--enc PATH", "--safety-contour M", "--safety-depth M", "--no-special-areas", "--json"}},
        {"live",
         {"--udp PORT",
          "--tcp HOST:PORT",
          "--serial DEV[:BAUD]",
          "--gpsd HOST:PORT",
          "--file PATH",
          "--source SPEC",
          "--radar-udp PORT",
          "--radar-tcp HOST:PORT",
          "--file-rate X",
          "--duration S",
          "--reorder-horizon S",
          "--status-interval S",
          "--config SCENARIO",
          "--assume-association",
          "--max-gap S",
          "--date YYYY-MM-DD",
          "--variation DEG",
          "--profile paper|imo|realistic",
          "--adaptive-gnss on|off",
          "--nmea-out DEST",
          "--record FILE.sqlite",
          "--record-max-hours H",
          "--nmea-out-ais",
          "--no-nmea-out-alerts",
          "--route FILE",
          "--enc PATH",
          "--safety-contour M",
          "--draught M",
          "--out DIR",
          "--quiet"}},
        {"validate", {"SCENARIO"}},
        {"scenarios", {}},
    };
  }

  /// The names under "Subcommands:" in a help text.
  static QStringList subcommandsIn(const QString& help) {
    QStringList names;
    bool in = false;
    for (const QString& line : help.split('\n')) {
      if (line.startsWith("Subcommands:")) {
        in = true;
      } else if (in && line.startsWith("  ")) {
        names << line.trimmed().split(' ').front();
      } else if (in) {
        break;
      }
    }
    return names;
  }

  /// Every command, groups opened: "run", ..., "chart info", "chart render", ...
  static QStringList commands(const QStringList& prefix = {}) {
    const Result r = cli(prefix + QStringList{"--help"});
    QStringList out;
    if (r.code != 0) return {"<" + prefix.join(' ') + " --help failed>"};
    const QStringList subs = subcommandsIn(r.out);
    if (subs.isEmpty()) return {prefix.join(' ')};
    for (const QString& s : subs) out << commands(prefix + QStringList{s});
    return out;
  }

 private slots:
  void versionNamesTheProgramAndItsLibraries() {
    const Result r = cli({"--version"});
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.startsWith("reckoner-cli 0."), qPrintable(r.out));
    for (const char* lib : {"Eigen 3.", "GeographicLib ", "GDAL 3."})
      QVERIFY2(r.out.contains(QString::fromLatin1(lib)), qPrintable(r.out));
    QVERIFY(r.err.isEmpty());
  }

  void everyCommandIsDescribed() {
    const Result top = cli({"--help"});
    QCOMPARE(top.code, 0);
    QVERIFY2(top.out.contains("Exit codes"), qPrintable(top.out));
    const QStringList found = commands();
    const QStringList expected = expectedOptions().keys();
    QCOMPARE(QSet<QString>(found.begin(), found.end()), QSet<QString>(expected.begin(), expected.end()));
  }
  void everyCommandListsItsOptions_data() {
    QTest::addColumn<QString>("command");
    QTest::addColumn<QStringList>("options");
    const auto all = expectedOptions();
    for (auto it = all.begin(); it != all.end(); ++it)
      QTest::newRow(qPrintable(it.key())) << it.key() << it.value();
  }
  void everyCommandListsItsOptions() {
    QFETCH(QString, command);
    QFETCH(QStringList, options);
    const Result r = cli(command.split(' ') + QStringList{"--help"});
    QCOMPARE(r.code, 0);
    QVERIFY2(r.err.isEmpty(), qPrintable(r.err));
    QVERIFY2(r.out.contains("Usage: reckoner-cli " + command), qPrintable(r.out));
    for (const QString& o : options) {
      // Its own line: the option, the name of its value (its unit) and a description after it.
      // (A positional list shows as "PATH ...".)
      const QRegularExpression line(
          "^  " + QRegularExpression::escape(o) + "( \\.\\.\\.)?( {2,}\\S|\\n {10,}\\S)",
          QRegularExpression::MultilineOption);
      QVERIFY2(line.match(r.out).hasMatch(), qPrintable(command + ": no line for " + o + " in\n" + r.out));
    }
    // Nothing listed that the table above does not know (a new option gets its line there).
    const QRegularExpression anyOption("^  (--[a-z0-9-]+)", QRegularExpression::MultilineOption);
    for (auto m = anyOption.globalMatch(r.out); m.hasNext();) {
      const QString name = m.next().captured(1);
      if (name == "--help") continue;
      bool known = false;
      for (const QString& o : options) known = known || o == name || o.startsWith(name + ' ');
      QVERIFY2(known, qPrintable(command + ": " + name + " is not in the expected list"));
    }
  }
  void quietIsStillAcceptedWhereItDoesNothing() {
    const Result r = cli({"seed003", "--runs", "1", "--quiet"});
    QCOMPARE(r.code, 0);
    QVERIFY(r.out.contains("predicted 2drms"));
  }
  void badInputIsOneLineNamingOptionAndValue_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("expected");
    QTest::newRow("unknown option") << QStringList{"manoeuvre-report", "--fast"} << "unknown option '--fast'";
    QTest::newRow("bad value") << QStringList{"manoeuvre-report", "--speed-change", "fast"}
                               << "--speed-change: expected a number in [-30.000000, 30.000000], got 'fast'";
    QTest::newRow("no value") << QStringList{"seed003", "--alpha"} << "option '--alpha' needs a value";
    QTest::newRow("twice") << QStringList{"seed003", "--runs", "1", "--runs", "2"}
                           << "option '--runs' given twice";
    QTest::newRow("bad choice") << QStringList{"chart", "render", "x", "--palette", "red"}
                                << "--palette: expected day, dusk or night, got 'red'";
    QTest::newRow("unknown chart command")
        << QStringList{"chart", "draw"} << "unknown chart subcommand 'draw' (known: info, render, pick)";
    QTest::newRow("extra argument") << QStringList{"seed001", "extra"}
                                    << "seed001: unexpected argument 'extra'";
  }
  void badInputIsOneLineNamingOptionAndValue() {
    QFETCH(QStringList, args);
    QFETCH(QString, expected);
    const Result r = cli(args);
    QCOMPARE(r.code, 2);
    QCOMPARE(r.err, "reckoner-cli: error: " + expected + "\n");
    QVERIFY(r.out.isEmpty());
  }
  void jsonPutsTheSummaryOnStdout() {
    QTemporaryDir dir;
    const Result r = cli({"run", "builtin:table1-test1", "--seed", "3", "--out", dir.path(), "--json"});
    QCOMPARE(r.code, 0);
    QJsonParseError error{};
    const QJsonObject s = QJsonDocument::fromJson(r.out.toUtf8(), &error).object();
    QVERIFY2(error.error == QJsonParseError::NoError, qPrintable(r.out.left(400)));
    QCOMPARE(s["seed"].toInt(), 3);
    QVERIFY(QFile::exists(dir.filePath("ownship.csv")));
  }
};

QTEST_GUILESS_MAIN(TestCliHelp)
#include "tst_cli_help.moc"
