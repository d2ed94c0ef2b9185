// reckoner-cli route check as a user runs it: a route file written by Reckoner's RTZ writer and one
// GPX written here, checked against the NOAA cell US5WA22M (Tacoma); the table, JSON Lines (each line
// one object with the documented fields), exit 0 with findings; usage errors and a bad route file give
// exit 2 and one line naming the file; the turns that do not fit between their legs, as
// geo::turnsThatDoNotFit finds them, in the table and as JSON objects of kind "turn".
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "app/cli_process.h"
#include "common/angles.h"
#include "geo/route.h"
#include "geo/route_turns.h"
#include "io/route_files.h"
#include "support/compare_near.h"
#include "support/route_fixtures.h"

using namespace reckoner;
using reckoner::test::runCli;

namespace {

const QString kEnc = QStringLiteral(RECKONER_SHARED_DIR "/data/enc/US5WA22M");

geo::Route routeOf(const std::vector<geo::GeoPoint>& points, double xtlNm) {
  return reckoner::test::routeOf(points, xtlNm, "cli test");
}

}  // namespace

class TestRouteCli : public QObject {
  Q_OBJECT
  QTemporaryDir dir_;
  QString path(const char* name) const { return dir_.filePath(QString::fromLatin1(name)); }

 private slots:
  void initTestCase() {
    QVERIFY(dir_.isValid());
    io::writeRouteFile(path("land.rtz").toStdString(),
                       routeOf({{47.300, -122.470}, {47.285, -122.460}, {47.250, -122.470}}, 0.05));
    io::writeRouteFile(path("channel.rtz").toStdString(), channel());
    io::writeRouteFile(path("tight.rtz").toStdString(), reckoner::test::zigzagInCommencementBay());
  }

  static geo::Route channel() {
    return routeOf({{47.2802, -122.4162},
                    {47.273194, -122.404889},
                    {47.271028, -122.401361},
                    {47.265889, -122.393139},
                    {47.2588, -122.3818}},
                   0.015);
  }

  void jsonLinesOnePerFinding() {
    const auto r =
        runCli({"route", "check", path("land.rtz"), "--enc", kEnc, "--safety-contour", "9", "--json"});
    QCOMPARE(r.code, 0);
    const QStringList lines = r.out.split('\n', Qt::SkipEmptyParts);
    QVERIFY(lines.size() >= 3);
    bool land = false;
    for (const QString& line : lines) {
      QJsonParseError err{};
      const QJsonDocument doc = QJsonDocument::fromJson(line.toUtf8(), &err);
      QVERIFY2(err.error == QJsonParseError::NoError && doc.isObject(), qPrintable(line));
      const QJsonObject o = doc.object();
      QVERIFY2(o["kind"].toString() != "turn", qPrintable(line));  // the route's one turn fits
      for (const char* k :
           {"leg", "lat_deg", "lon_deg", "kind", "class", "depth_m", "cell", "lnam", "attributes"})
        QVERIFY2(o.contains(QLatin1String(k)), k);
      QCOMPARE(o["cell"].toString(), QStringLiteral("US5WA22M"));
      QCOMPARE(o["leg"].toInt(), 2);  // the first leg stays in the bay
      if (o["kind"].toString() == "land") {
        land = true;
        QCOMPARE(o["class"].toString(), QStringLiteral("LNDARE"));
        QVERIFY(o["depth_m"].isNull());
      }
      if (o["class"].toString() == "DEPARE") QVERIFY(o["depth_m"].isDouble());
    }
    QVERIFY(land);
  }

  void channelTable() {
    const auto r = runCli({"route", "check", path("channel.rtz"), "--enc", kEnc, "--safety-contour", "9"});
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.contains("on 4 leg(s): 0 dangerous"), qPrintable(r.out));
    // the security zone over the waterway is a caution; without special areas only it is left
    const auto r2 = runCli({"route", "check", path("channel.rtz"), "--enc", kEnc, "--safety-contour", "9",
                            "--no-special-areas"});
    QCOMPARE(r2.code, 0);
    QVERIFY(!r2.out.contains("CTNARE"));
    QVERIFY(r2.out.contains("RESARE"));
  }

  void turnsThatDoNotFit() {
    const geo::Route tight = reckoner::test::zigzagInCommencementBay();
    const std::vector<geo::TurnFit> expected = geo::turnsThatDoNotFit(tight);
    QCOMPARE(expected.size(), std::size_t{2});  // at WP2 and WP4; WP3 is a corner
    const auto r =
        runCli({"route", "check", path("tight.rtz"), "--enc", kEnc, "--safety-contour", "9", "--json"});
    QCOMPARE(r.code, 0);
    std::vector<QJsonObject> turns;
    for (const QString& line : r.out.split('\n', Qt::SkipEmptyParts)) {
      const QJsonObject o = QJsonDocument::fromJson(line.toUtf8()).object();
      if (o["kind"].toString() == "turn") turns.push_back(o);
    }
    QCOMPARE(turns.size(), expected.size());
    for (std::size_t i = 0; i < turns.size(); ++i) {
      const QJsonObject& o = turns[i];
      const geo::TurnFit& t = expected[i];
      const geo::Waypoint& w = tight.waypoints[t.waypoint];
      QCOMPARE(o["waypoint"].toInt(), static_cast<int>(t.waypoint));
      QCOMPARE(o["waypoint_id"].toInt(), w.id);
      QCOMPARE(o["name"].toString(), QString::fromStdString(w.name));
      QCOMPARE(o["dangerous"].toBool(), false);
      RK_COMPARE_NEAR(o["lat_deg"].toDouble(), w.position.latDeg, 1e-9);
      RK_COMPARE_NEAR(o["radius_nm"].toDouble(), 2.0, 1e-9);
      RK_COMPARE_NEAR(o["sailed_radius_nm"].toDouble(), t.radiusM / 1852.0, 1e-5);
      RK_COMPARE_NEAR(o["wheel_over_nm"].toDouble(), t.plannedWheelOverM / 1852.0, 1e-5);
      QCOMPARE(o["leg"].toInt(), static_cast<int>(t.waypoint));
      RK_COMPARE_NEAR(o["lon_deg"].toDouble(), w.position.lonDeg, 1e-9);
      RK_COMPARE_NEAR(o["change_deg"].toDouble(), radToDeg(geo::courseChangeRad(tight, t.waypoint)), 1e-4);
      QVERIFY(o["change_deg"].toDouble() < -80.0);  // the zigzag turns to port at WP2 and WP4
      RK_COMPARE_NEAR(o["leg_before_nm"].toDouble(), geo::legLengthM(tight, t.waypoint) / 1852.0, 1e-5);
      RK_COMPARE_NEAR(o["leg_after_nm"].toDouble(), geo::legLengthM(tight, t.waypoint + 1) / 1852.0, 1e-5);
      // sailed: half the shorter leg before the waypoint, on the radius tangent to both legs there
      const double half = 0.5 * std::min(o["leg_before_nm"].toDouble(), o["leg_after_nm"].toDouble());
      RK_COMPARE_NEAR(o["sailed_radius_nm"].toDouble(),
                      half / std::tan(std::abs(degToRad(o["change_deg"].toDouble())) / 2.0), 1e-4);
      QVERIFY(o["sailed_radius_nm"].toDouble() < o["radius_nm"].toDouble());
    }
    // The table: a row per turn under its heading, and the count in the last line.
    const auto table = runCli({"route", "check", path("tight.rtz"), "--enc", kEnc, "--safety-contour", "9"});
    QCOMPARE(table.code, 0);
    QVERIFY2(table.out.contains("turns that do not fit between their legs"), qPrintable(table.out));
    QVERIFY2(table.out.contains("; 2 turn(s) that do not fit"), qPrintable(table.out));
    QVERIFY(table.out.contains(QRegularExpression(QStringLiteral("\n2 +WP2 "))));
    QVERIFY(table.out.contains(QRegularExpression(QStringLiteral("\n4 +WP4 "))));
    // The channel on the default radius of 0.5 NM: every turn fits; the count says so.
    const auto fits = runCli({"route", "check", path("channel.rtz"), "--enc", kEnc, "--safety-contour", "9"});
    QVERIFY2(fits.out.contains("; 0 turn(s) that do not fit"), qPrintable(fits.out));
    QVERIFY(!fits.out.contains("turns that do not fit between"));
  }

  void gpxRoute() {
    {
      std::ofstream f(path("land.gpx").toStdString());
      f << "<?xml version=\"1.0\"?>\n<gpx version=\"1.1\" creator=\"hand\" "
           "xmlns=\"http://www.topografix.com/GPX/1/1\">"
           "<rte><name>ashore</name><rtept lat=\"47.285\" lon=\"-122.460\"><name>A</name></rtept>"
           "<rtept lat=\"47.250\" lon=\"-122.470\"><name>B</name></rtept></rte></gpx>\n";
    }
    const auto r = runCli({"route", "check", path("land.gpx"), "--enc", kEnc, "--json"});
    QCOMPARE(r.code, 0);
    QVERIFY(r.out.contains("\"kind\":\"land\""));
  }

  void errors() {
    auto r = runCli({"route", "check", path("land.rtz")});
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains("--enc is required"), qPrintable(r.err));
    {
      std::ofstream f(path("bad.rtz").toStdString());
      f << "<?xml version=\"1.0\"?>\n<route xmlns=\"http://www.cirm.org/RTZ/1/1\" version=\"1.1\">\n"
           "<waypoints>\n<waypoint id=\"1\"><position lat=\"95\" lon=\"0\"/></waypoint>\n"
           "<waypoint id=\"2\"><position lat=\"1\" lon=\"0\"/></waypoint>\n</waypoints>\n</route>\n";
    }
    r = runCli({"route", "check", path("bad.rtz"), "--enc", kEnc});
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains("bad.rtz") && r.err.contains("lat"), qPrintable(r.err));
    QCOMPARE(r.err.count('\n'), 1);
    r = runCli({"route", "check", path("land.rtz"), "--enc", path("nowhere")});
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains("nowhere"), qPrintable(r.err));
  }
};

QTEST_GUILESS_MAIN(TestRouteCli)
#include "tst_route_cli.moc"
