// reckoner-cli route check as a user runs it: a route file written by Reckoner's RTZ writer and one
// GPX written here, checked against the NOAA cell US5WA22M (Tacoma); the table, JSON Lines (each line
// one object with the documented fields), exit 0 with findings; usage errors and a bad route file give
// exit 2 and one line naming the file.
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <fstream>

#include "app/cli_process.h"
#include "geo/route.h"
#include "io/route_files.h"
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
    io::writeRouteFile(path("channel.rtz").toStdString(), routeOf({{47.2802, -122.4162},
                                                                   {47.273194, -122.404889},
                                                                   {47.271028, -122.401361},
                                                                   {47.265889, -122.393139},
                                                                   {47.2588, -122.3818}},
                                                                  0.015));
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
