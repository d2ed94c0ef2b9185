// reckoner-cli ais decode (docs/cli.md, docs/ais.md) run as a user runs it: the real recording
// ../shared/data/ais/gpsd-sample.aivdm decoded with --json and compared field by field with gpsd's own
// decoder gpsdecode (an independent oracle; the test skips without it or without the recording), the
// text output, the summary of skipped lines on stderr, and an unreadable file.
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <set>

#include "app/cli_process.h"
#include "support/ais_corpus.h"
#include "support/compare_near.h"

using reckoner::test::runCli;

namespace {

const QString kSample = QStringLiteral(RECKONER_SHARED_DIR "/data/ais/gpsd-sample.aivdm");

std::vector<QJsonObject> jsonLines(const QString& text) {
  std::vector<QJsonObject> out;
  for (const QString& line : text.split('\n', Qt::SkipEmptyParts)) {
    QJsonParseError e{};
    const QJsonDocument doc = QJsonDocument::fromJson(line.toUtf8(), &e);
    if (e.error == QJsonParseError::NoError && doc.isObject()) out.push_back(doc.object());
  }
  return out;
}

/// Compares gpsdecode's field (in its units) with ours; a gpsd value in `notAvailable` (or, for
/// positions, off the globe) must be absent here. Counts the fields compared.
struct FieldCompare {
  const QJsonObject& gpsd;
  const QJsonObject& ours;
  int compared = 0;

  void number(const char* theirs, const char* mine, double tol, const std::set<double>& notAvailable = {},
              double limit = 1e300) {
    if (!gpsd.contains(theirs)) return;
    ++compared;
    if (gpsd[theirs].isString()) {  // gpsd's words for the reserved values: "nan", speed "fast"
      const QString word = gpsd[theirs].toString();
      if (word == "nan") {
        QVERIFY2(!ours.contains(mine), mine);
      } else {
        QCOMPARE(word, QString("fast"));  // SOG 1022: 102.2 kn or more (ITU-R M.1371)
        RK_COMPARE_NEAR(ours[mine].toDouble(), 102.2, tol);
      }
      return;
    }
    const double g = gpsd[theirs].toDouble();
    if (notAvailable.count(g) || std::abs(g) > limit) {
      QVERIFY2(!ours.contains(mine), mine);
      return;
    }
    QVERIFY2(ours.contains(mine), mine);
    RK_COMPARE_NEAR(ours[mine].toDouble(), g, tol);
  }
  void text(const char* theirs, const char* mine, const QString& notAvailable = QString()) {
    if (!gpsd.contains(theirs)) return;
    ++compared;
    const QString g = gpsd[theirs].toString();
    if (g.isEmpty() || g == notAvailable) {
      QVERIFY2(!ours.contains(mine), mine);
      return;
    }
    QCOMPARE(ours[mine].toString(), g);
  }
  void flag(const char* theirs, const char* mine) {
    if (!gpsd.contains(theirs)) return;
    ++compared;
    QCOMPARE(ours[mine].toBool(), gpsd[theirs].toBool());
  }
};

/// gpsdecode 3.22's scaled "turn" is rounded to whole degrees per minute and loses the sign (a left
/// turn of raw -20 prints 18); its unscaled output (-u, `raw`) keeps the raw signed value. So the
/// magnitude is compared with the scaled value to 0.5 and the sign with the raw one.
void compareTurn(const QJsonObject& g, const QJsonObject& raw, const QJsonObject& o, int& compared) {
  if (!g.contains("turn")) return;
  ++compared;
  const QString t = g["turn"].toVariant().toString();
  if (t == "nan") {
    QVERIFY(!o.contains("rot_deg_min") && !o.contains("rot_fast"));
  } else if (t == "fastleft" || t == "fastright") {
    QCOMPARE(o["rot_fast"].toString(), t == "fastleft" ? QString("left") : QString("right"));
  } else {
    const double mine = o["rot_deg_min"].toDouble();
    RK_COMPARE_NEAR(std::abs(mine), g["turn"].toDouble(), 0.5);
    QCOMPARE(raw["turn"].toInt() < 0, mine < 0);
  }
}

/// gpsdecode's "eta" "MM-DDTHH:MMZ", ours without the Z; "timestamp" "YYYY-MM-DDTHH:MM:SSZ" as our utc.
void compareTimes(const QJsonObject& g, const QJsonObject& o, int& compared) {
  if (g.contains("eta")) {
    ++compared;
    QString eta = g["eta"].toString();
    eta.chop(1);
    const bool na =
        eta.startsWith("00") || eta.mid(3, 2) == "00" || eta.mid(6, 2) == "24" || eta.mid(9, 2) == "60";
    if (na)
      QVERIFY(!o.contains("eta"));
    else
      QCOMPARE(o["eta"].toString(), eta);
  }
  if (g.contains("timestamp")) {
    ++compared;
    const QString ts = g["timestamp"].toString();
    const QRegularExpressionMatch m =
        QRegularExpression("^(\\d+)-(\\d\\d)-(\\d\\d)T(\\d\\d):(\\d\\d):(\\d\\d)Z$").match(ts);
    QVERIFY(m.hasMatch());
    const bool na = m.captured(1).toInt() == 0 || m.captured(2) == "00" || m.captured(3) == "00" ||
                    m.captured(4) == "24" || m.captured(5) == "60" || m.captured(6) == "60";
    if (na)
      QVERIFY(!o.contains("utc"));
    else
      QCOMPARE(o["utc"].toString(), ts);
  }
}

/// gpsdecode's "second" is the raw time stamp: ours is "second" below 60, nothing at 60 (not available),
/// "position_not_fix" at 61-63.
void compareSecond(const QJsonObject& g, const QJsonObject& o, int& compared) {
  if (!g.contains("second")) return;
  ++compared;
  const int s = g["second"].toInt();
  QCOMPARE(o.contains("second"), s < 60);
  QCOMPARE(o.contains("position_not_fix"), s > 60);
  if (s < 60) QCOMPARE(o["second"].toInt(), s);
  if (s > 60) QCOMPARE(o["position_not_fix"].toInt(), s);
}

int compareMessage(const QJsonObject& g, const QJsonObject& raw, const QJsonObject& o) {
  const int type = g["type"].toInt();
  FieldCompare c{g, o};
  const bool lr = type == 27;
  c.number("mmsi", "mmsi", 0);
  c.number("lat", "lat_deg", lr ? 0.051 : 1e-6, {91.0}, 90.0);
  c.number("lon", "lon_deg", lr ? 0.051 : 1e-6, {181.0}, 180.0);
  c.number("speed", "sog_kn", 1e-9, {lr ? 63.0 : 102.3});
  c.number("course", "cog_deg", 1e-9, {lr ? 511.0 : 360.0});
  c.number("heading", "heading_deg", 0, {511.0});
  if (!lr) c.number("status", "nav_status", 0);
  if (type != 24 || g["part"].toString() == "A") c.text("shipname", "name");
  c.text("name", "name");
  c.text("callsign", "callsign");
  c.text("destination", "destination");
  c.number("imo", "imo", 0, {0.0});
  c.number("shiptype", "ship_type", 0, {0.0});
  c.number("to_bow", "to_bow_m", 0);
  c.number("to_stern", "to_stern_m", 0);
  c.number("to_port", "to_port_m", 0);
  c.number("to_starboard", "to_starboard_m", 0);
  c.number("draught", "draught_m", 1e-9, {0.0});
  c.number("epfd", "epfd", 0, {0.0});
  c.number("aid_type", "aid_type", 0);
  c.flag("virtual_aid", "virtual");
  c.flag("off_position", "off_position");
  c.text("text", "text");
  compareTurn(g, raw, o, c.compared);
  compareTimes(g, o, c.compared);
  compareSecond(g, o, c.compared);
  return c.compared;
}

/// Decodes `file` with gpsdecode and with `reckoner-cli ais decode --json`, compares them message by
/// message (every type we decode must appear, each gpsdecode message of those types must be ours with
/// equal fields) and returns the number of fields compared. `expected` (if >= 0) is the message count.
int compareWithGpsdecode(const QString& file, int expected = -1, bool everyType = true) {
  const QString gpsdecode = QStandardPaths::findExecutable("gpsdecode");
  if (gpsdecode.isEmpty()) {
    QTest::qFail("gpsdecode (Debian gpsd-clients, scripts/bootstrap.sh) is not installed", __FILE__,
                 __LINE__);
    return 0;
  }
  const std::set<int> supported{1, 2, 3, 4, 5, 14, 18, 19, 21, 24, 27};
  const auto decode = [&](QStringList args) {
    QProcess p;
    p.setStandardInputFile(file);
    p.start(gpsdecode, args << "--split24");  // type 24 parts A and B each as they come, as ours
    std::vector<QJsonObject> out;
    if (!p.waitForFinished(120000)) return out;
    for (const QJsonObject& o : jsonLines(QString::fromUtf8(p.readAllStandardOutput())))
      if (supported.count(o["type"].toInt())) out.push_back(o);
    return out;
  };
  const std::vector<QJsonObject> theirs = decode({});
  const std::vector<QJsonObject> raw = decode({"-u"});
  const auto r = runCli({"ais", "decode", file, "--json"});
  const std::vector<QJsonObject> ours = jsonLines(r.out);
  const bool sizes = r.code == 0 && ours.size() == theirs.size() && raw.size() == theirs.size() &&
                     static_cast<int>(ours.size()) == r.out.count('\n') &&
                     (expected < 0 || static_cast<int>(ours.size()) == expected);
  if (!sizes) {
    QTest::qFail(qPrintable(QString("exit %1, %2 messages ours, %3 gpsdecode's, expected %4; %5")
                                .arg(r.code)
                                .arg(ours.size())
                                .arg(theirs.size())
                                .arg(expected)
                                .arg(r.err)),
                 __FILE__, __LINE__);
    return 0;
  }
  int compared = 0;
  std::set<int> types;
  for (std::size_t i = 0; i < ours.size(); ++i) {
    const bool sameType = ours[i]["type"].toInt() == theirs[i]["type"].toInt();
    if (sameType) compared += compareMessage(theirs[i], raw[i], ours[i]);
    if (!sameType || QTest::currentTestFailed()) {
      qWarning("message %zu: gpsdecode %s ours %s", i,
               QJsonDocument(theirs[i]).toJson(QJsonDocument::Compact).constData(),
               QJsonDocument(ours[i]).toJson(QJsonDocument::Compact).constData());
      if (!sameType) QTest::qFail("message types differ", __FILE__, __LINE__);
      return 0;
    }
    types.insert(ours[i]["type"].toInt());
  }
  qInfo("%d fields of %zu messages of %s compared with gpsdecode", compared, ours.size(),
        qPrintable(QFileInfo(file).fileName()));
  if (everyType && types != supported)
    QTest::qFail("not every decoded type is in the file", __FILE__, __LINE__);
  return compared;
}

}  // namespace

class TestAisCli : public QObject {
  Q_OBJECT
 private slots:
  void sampleMatchesGpsdecode() {
    if (!QFile::exists(kSample)) QSKIP(qPrintable(kSample + " is absent (../shared/data/ais)"));
    const int compared = compareWithGpsdecode(kSample);
    QVERIFY(compared > 150);
  }
  /// GIVEN the project's own encoding of every decoded type with ordinary, edge and "not available"
  /// values (tests/support/ais_corpus.h) WHEN gpsdecode and `ais decode --json` read it THEN both
  /// decode every message, with equal fields.
  void corpusMatchesGpsdecode() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QFile f(dir.filePath("corpus.aivdm"));
    QVERIFY(f.open(QIODevice::WriteOnly));
    const auto lines = reckoner::test::ais::corpus();
    for (const auto& l : lines) f.write((l + "\r\n").c_str());
    f.close();
    const int compared = compareWithGpsdecode(f.fileName(), static_cast<int>(lines.size()) - 1);
    QVERIFY(compared > 120);
  }
  /// GIVEN a type 5 of 420 bits (70 characters, fill 0: the destination's last character and the DTE
  /// bit cut, as many transmitters send it) in two fragments WHEN gpsdecode and `ais decode --json` read
  /// it THEN both decode it, with equal fields (before, ours refused it as too short: no name, no hull).
  void typeFiveOf420BitsMatchesGpsdecode() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QFile f(dir.filePath("type5_420.aivdm"));
    QVERIFY(f.open(QIODevice::WriteOnly));
    const auto cut = reckoner::test::ais::staticVoyage().truncate(420);
    for (const auto& l : reckoner::test::ais::fragments(cut, 4)) f.write((l + "\r\n").c_str());
    f.close();
    QVERIFY(compareWithGpsdecode(f.fileName(), 1, false) >= 10);
    const auto r = runCli({"ais", "decode", f.fileName(), "--json"});
    QVERIFY2(r.out.contains("\"name\":\"EVER DIADEM\"") && r.out.contains("\"destination\":\"NEW YORK\""),
             qPrintable(r.out));
  }
  void textOutputAndSummary() {
    if (!QFile::exists(kSample)) QSKIP(qPrintable(kSample + " is absent (../shared/data/ais)"));
    const auto r = runCli({"ais", "decode", kSample});
    QCOMPARE(r.code, 0);
    const QStringList lines = r.out.split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 31);
    QVERIFY2(
        lines.front().startsWith("type=1 mmsi=371798000 lat_deg=48.3816333 lon_deg=-123.3953833 sog_kn=12.3"),
        qPrintable(lines.front()));
    QVERIFY2(r.err.contains("31 decoded") && r.err.contains("unsupported types"), qPrintable(r.err));
  }
  void badLinesAreCountedOnStderr() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QFile f(dir.filePath("bad.nmea"));
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("!AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,0*4A\n");  // good
    f.write("!AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,0*4B\n");  // checksum
    f.write("$GPGGA,not ais\n\n");
    f.write("!AIVDM,2,2,6,B,00000000000,2*21\n");  // a second part alone
    f.write(QByteArray(1 << 20, 'x') + "\n");
    f.close();
    const auto r = runCli({"ais", "decode", f.fileName(), "--json"});
    QCOMPARE(r.code, 0);
    QCOMPARE(r.out.count('\n'), 1);
    for (const char* s :
         {"6 lines", "1 decoded", "2 not AIS", "1 bad checksum", "1 too long", "1 orphan fragments"})
      QVERIFY2(r.err.contains(s), qPrintable(s + (": " + r.err)));
  }
  void anUnreadableFileIsNamed() {
    const auto r = runCli({"ais", "decode", "/nonexistent/x.aivdm"});
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains("/nonexistent/x.aivdm"), qPrintable(r.err));
    QVERIFY(r.out.isEmpty());
    QCOMPARE(runCli({"ais", "decode"}).code, 2);
  }
};

QTEST_APPLESS_MAIN(TestAisCli)
#include "tst_ais_cli.moc"
