// Route files (core/io/route_files.h, docs/routes.md "Route files"): RTZ written and read back equal; the
// writer's output element by element against the RTZ 1.1 schema's structure (read with pugixml, not with
// our reader); files in the conventions of other tools (tests/core/io/routes/, written by hand): RTZ 1.0
// with "sheduleElement" and defaults, RTZ 1.1 under a prefix with STM's extensions, RTZ 1.2 with
// extensions everywhere, GPX from a plotter and from a handheld; hostile and malformed input refused with
// one line naming the line and the field.
#include <QTemporaryDir>
#include <QTest>

#include <filesystem>
#include <pugixml.hpp>
#include <stdexcept>

#include "common/units.h"
#include "geo/route.h"
#include "io/input_error.h"
#include "io/iso8601.h"
#include "io/route_files.h"
#include "io/text_file.h"
#include "support/compare_near.h"

using namespace reckoner;

namespace {

const std::string kRoutes = RECKONER_ROUTES_DIR;

UtcUs utc(const char* iso) {
  const auto t = io::parseIso8601(iso);
  if (!t) qFatal("bad time in the test: %s", iso);
  return *t;
}

geo::Waypoint waypoint(int id, std::string name, double latDeg, double lonDeg) {
  geo::Waypoint w;
  w.id = id;
  w.name = std::move(name);
  w.position = {latDeg, lonDeg};
  return w;
}

/// A route using every field of the model, optional ones both set and unset, both geometries, names
/// with XML's special characters and white space, numbers that need all their digits.
geo::Route richRoute() {
  geo::Route r;
  r.name = "Bergen <-> Stavanger & \"inner lead\" 'A'";
  r.author = "Reckoner tests \xc3\xa9\xe2\x80\x93";
  r.status = "Planned";
  r.defaultTurnRadiusNm = 0.4;
  r.waypoints.push_back(waypoint(1, "Bergen", 60.39299999999999, 5.324123456789012));
  geo::Waypoint w2 = waypoint(2, "", 60.1, 5.0000001);
  w2.turnRadiusNm = 0.25;
  w2.leg = {geo::LegGeometry::GreatCircle,        0.3, 0.35, 12.5, 6.0, 10.0, 11.5,
            "Keep right\tof the fairway\nVHF 12 "};
  r.waypoints.push_back(w2);
  geo::Waypoint w3 = waypoint(30, " Midway <3> ", 59.8, 5.1);
  w3.leg.portXtlNm = 0.05;
  r.waypoints.push_back(w3);
  geo::Waypoint w4 = waypoint(4, "Far west", 59.5, -0.000001);
  w4.leg.geometry = geo::LegGeometry::GreatCircle;
  w4.leg.plannedSpeedKn = 0.0;  // set to zero, not unset
  w4.leg.safetyDepthM = 1e-7;
  w4.leg.safetyContourM = -2.5;
  r.waypoints.push_back(w4);
  geo::Waypoint w5 = waypoint(5, "Stavanger", -58.97, 179.99999999999997);
  w5.turnRadiusNm = 0.0;
  w5.leg.plannedSpeedKn = 8.0;
  r.waypoints.push_back(w5);
  geo::Schedule s1{1, "Manual and calculated", {}, {}};
  s1.manual = {{1, utc("2024-05-01T06:00:00Z"), std::nullopt, std::nullopt},
               {5, std::nullopt, utc("2024-05-02T18:30:00Z"), 10.0}};
  s1.calculated = {{1, utc("2024-05-01T06:00:00Z"), std::nullopt, 12.5},
                   {2, std::nullopt, utc("2024-05-01T07:23:45.678901Z"), 12.5},
                   {30, utc("2024-05-01T09:00:00Z"), utc("2024-05-01T08:59:59.999999Z"), 0.5},
                   {4, std::nullopt, std::nullopt, std::nullopt},
                   {5, std::nullopt, utc("1999-12-31T23:59:59Z"), 8.0}};
  geo::Schedule s2{7, "", {}, {{2, std::nullopt, std::nullopt, 11.0}}};
  r.schedules = {s1, s2};
  return r;
}

geo::Route readFile(const std::string& name) {
  return io::readRouteFile(kRoutes + "/" + name);
}

std::vector<pugi::xml_node> elementChildren(const pugi::xml_node& n) {
  std::vector<pugi::xml_node> out;
  for (const pugi::xml_node c : n.children())
    if (c.type() == pugi::node_element) out.push_back(c);
  return out;
}

QStringList names(const std::vector<pugi::xml_node>& nodes) {
  QStringList out;
  for (const auto& n : nodes) out << QString::fromUtf8(n.name());
  return out;
}

/// An RTZ 1.1 text: line 5 the first waypoint, line 6 `waypoint2`, line 7 the third, `after` from line 9.
std::string rtz(const std::string& waypoint2, const std::string& after = "") {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<route xmlns=\"http://www.cirm.org/RTZ/1/1\" version=\"1.1\">\n"
         "  <routeInfo routeName=\"T\"/>\n"
         "  <waypoints>\n"
         "    <waypoint id=\"1\"><position lat=\"60\" lon=\"5\"/></waypoint>\n"
         "    " +
         waypoint2 +
         "\n"
         "    <waypoint id=\"3\"><position lat=\"60.2\" lon=\"5.2\"/></waypoint>\n"
         "  </waypoints>\n" +
         after + "</route>\n";
}

const char* const kGoodWaypoint2 = R"(<waypoint id="2"><position lat="60.1" lon="5.1"/></waypoint>)";

std::string schedule(const std::string& element) {
  return "  <schedules><schedule id=\"1\"><manual>\n    " + element +
         "\n  </manual></schedule></schedules>\n";
}

/// Expects readRtz (or readGpxRoute for a text starting "<gpx") to throw one line containing `expected`,
/// with InputError::line() == line.
void expectError(const std::string& text, int line, const QString& expected) {
  try {
    if (text.rfind("<gpx", 0) == 0)
      io::readGpxRoute(text, "t.gpx");
    else
      io::readRtz(text, "t.rtz");
    QFAIL(qPrintable("accepted: " + expected));
  } catch (const io::InputError& e) {
    const QString msg = QString::fromStdString(e.what());
    QVERIFY2(msg.contains(expected), qPrintable(msg));
    QVERIFY2(!msg.contains('\n'), qPrintable(msg));
    QVERIFY2(e.line() == line, qPrintable(msg + " (line " + QString::number(e.line()) + ")"));
  }
}

/// A row of malformedRtzIsOneLineNamingLineAndField: the file's text, the line the error names and a
/// piece of its message.
void malformedRow(const char* name, const std::string& text, int line, const char* expected) {
  QTest::newRow(name) << QByteArray::fromStdString(text) << line << QString::fromUtf8(expected);
}

/// Malformed waypoints, legs and schedules inside an otherwise good RTZ route.
void addMalformedRtzContentRows() {
  malformedRow("bad lat", rtz(R"(<waypoint id="2"><position lat="95" lon="5.1"/></waypoint>)"), 6,
               "t.rtz:6: waypoint id=\"2\" position lat: must be a number in [-90, 90], got '95'");
  malformedRow("lon not a number", rtz(R"(<waypoint id="2"><position lat="60.1" lon="5,1"/></waypoint>)"), 6,
               "waypoint id=\"2\" position lon: must be a number in [-180, 180], got '5,1'");
  malformedRow("missing position", rtz(R"(<waypoint id="2" name="X"/>)"), 6,
               "waypoint id=\"2\" position: missing");
  malformedRow("missing lat", rtz(R"(<waypoint id="2"><position lon="5"/></waypoint>)"), 6,
               "position lat: missing");
  malformedRow(
      "two positions",
      rtz("<waypoint id=\"2\"><position lat=\"1\" lon=\"1\"/>\n<position lat=\"2\" lon=\"2\"/></waypoint>"),
      7, "waypoint id=\"2\" position: given twice");
  malformedRow("duplicate id", rtz(R"(<waypoint id="1"><position lat="60.1" lon="5.1"/></waypoint>)"), 6,
               "t.rtz:6: waypoint id=\"1\" id: used twice: the waypoint at line 5 has it too");
  malformedRow("missing id", rtz(R"(<waypoint name="x"><position lat="60.1" lon="5.1"/></waypoint>)"), 6,
               "waypoint 2 id: missing");
  malformedRow("id not an integer", rtz(R"(<waypoint id="2.5"><position lat="60.1" lon="5.1"/></waypoint>)"),
               6, "waypoint 2 id: must be an integer, got '2.5'");
  malformedRow(
      "negative XTD",
      rtz(R"(<waypoint id="2"><position lat="60.1" lon="5.1"/><leg portsideXTD="-0.1"/></waypoint>)"), 6,
      "waypoint id=\"2\" leg portsideXTD: must be a number >= 0, got '-0.1'");
  malformedRow(
      "bad geometry",
      rtz(R"(<waypoint id="2"><position lat="60.1" lon="5.1"/><leg geometryType="Great"/></waypoint>)"), 6,
      "leg geometryType: must be Loxodrome or Orthodrome, got 'Great'");
  malformedRow("control character",
               rtz("<waypoint id=\"2\" name=\"a&#1;b\"><position lat=\"60.1\" lon=\"5.1\"/></waypoint>"), 6,
               "waypoint id=\"2\" name: a control character in 'a\\x01b'");
  malformedRow("same place twice", rtz(R"(<waypoint id="2"><position lat="60" lon="5"/></waypoint>)"), 6,
               "t.rtz:6: waypoint 2 (id 2): at the same place as the waypoint before it");
  malformedRow("unknown waypoint in schedule",
               rtz(kGoodWaypoint2, schedule(R"(<scheduleElement waypointId="9"/>)")), 10,
               "schedule id=\"1\" manual scheduleElement waypointId: no waypoint of the route has id 9");
  malformedRow(
      "bad eta",
      rtz(kGoodWaypoint2, schedule(R"(<scheduleElement waypointId="2" eta="2024-13-01T00:00:00Z"/>)")), 10,
      "schedule id=\"1\" manual scheduleElement waypointId=\"2\" eta: must be a date and time");
  malformedRow(
      "year 0",
      rtz(kGoodWaypoint2, schedule(R"(<scheduleElement waypointId="2" etd="0000-01-01T00:00:00Z"/>)")), 10,
      "etd: must be a date and time");
  malformedRow("negative speed",
               rtz(kGoodWaypoint2, schedule(R"(<scheduleElement waypointId="2" speed="-1"/>)")), 10,
               "scheduleElement waypointId=\"2\" speed: must be a number >= 0");
  malformedRow("duplicate schedule",
               rtz(kGoodWaypoint2, "  <schedules>\n<schedule id=\"4\"/>\n<schedule id=\"4\"/></schedules>\n"),
               11, "schedule id=\"4\" id: used twice: the schedule at line 10 has it too");
}

/// Files wrong as a whole: too few or too many waypoints, version, root, encoding, size; and GPX.
void addMalformedFileRows() {
  malformedRow("one waypoint",
               "<route version=\"1.0\">\n<waypoints>\n<waypoint id=\"1\"><position lat=\"0\" "
               "lon=\"0\"/></waypoint>\n"
               "</waypoints></route>",
               2, "1 waypoint(s); a route needs at least two");
  malformedRow("version", "<?xml version=\"1.0\"?>\n<route version=\"2.0\"><waypoints/></route>", 2,
               "t.rtz:2: route version: RTZ 1.0, 1.1 and 1.2 are read, not '2.0'");
  malformedRow("no waypoints", "<route version=\"1.1\">\n<routeInfo/></route>", 1, "waypoints: missing");
  malformedRow("wrong root", "<?xml version=\"1.0\"?>\n\n<gpx version=\"1.1\"/>", 3,
               "the root element is 'gpx', not RTZ's <route>");
  malformedRow("wrong namespace", "<route xmlns=\"http://example.com/route\" version=\"1.1\"/>", 1,
               "not RTZ's <route>");
  malformedRow("not XML", "hello", 0, "t.rtz: no XML element in it");
  malformedRow("unclosed", "<route>\n<waypoints>\n</route>", 3, "t.rtz:3: not well-formed XML");
  malformedRow("two roots", "<route/>\n<route/>", 2, "a second root element");
  malformedRow("UTF-16", std::string("\xFF\xFE<\0r\0", 6), 1, "UTF-16");
  malformedRow("not UTF-8", "<route version=\"1.1\">\n<routeInfo routeName=\"\xC3(\"/></route>", 2,
               "not UTF-8");
  malformedRow("encoding", "<?xml version=\"1.0\" encoding=\"Shift_JIS\"?><route/>", 1,
               "declares 'shift_jis'");
  malformedRow("NUL", std::string("<route>\n<a") + '\0' + "/></route>", 2, "t.rtz:2: a NUL byte");
  malformedRow("zip", std::string("PK\x03\x04\x14\0\0\0", 8), 0, "zip archive");
  malformedRow("too big", std::string(io::kMaxRouteFileBytes + 1, ' '), 0,
               "is 16777217 bytes; the limit for a route file");
  std::string many = "<route version=\"1.1\"><waypoints>\n";
  for (int k = 0; k <= static_cast<int>(io::kMaxRouteWaypoints); ++k)
    many += "<waypoint id=\"" + std::to_string(k) + "\"><position lat=\"0\" lon=\"" +
            std::to_string(k % 100) + "\"/></waypoint>\n";
  malformedRow("too many waypoints", many + "</waypoints></route>", 10002, "more than 10000 waypoints");
  malformedRow("GPX bad lat", "<gpx version=\"1.1\">\n<rte>\n<rtept lat=\"-91\" lon=\"0\"/></rte></gpx>", 3,
               "t.gpx:3: rtept 1 lat: must be a number in [-90, 90], got '-91'");
  malformedRow("GPX missing lon",
               "<gpx version=\"1.1\"><rte><rtept lat=\"1\"/><rtept lat=\"1\" lon=\"2\"/></rte></gpx>", 1,
               "rtept 1 lon: missing");
  malformedRow("GPX track only",
               "<gpx version=\"1.1\">\n<trk><trkseg><trkpt lat=\"1\" lon=\"2\"/></trkseg></trk></gpx>", 1,
               "rte: no route (<rte>) in the file; tracks (<trk>)");
  malformedRow("GPX one point", "<gpx version=\"1.1\">\n<rte>\n<rtept lat=\"1\" lon=\"2\"/></rte></gpx>", 2,
               "a route needs at least two");
  malformedRow("GPX version", "<gpx version=\"2.0\"/>", 1,
               "gpx version: must be \"1.0\" or \"1.1\", got '2.0'");
}

}  // namespace

class TestRouteFiles : public QObject {
  Q_OBJECT
 private slots:
  void writtenAndReadBackIsTheSameRoute() {
    // GIVEN a route with every field WHEN written as RTZ and read back THEN it is equal, and writing it
    // again gives the same text.
    const geo::Route r = richRoute();
    QVERIFY(r.problems().empty());
    const std::string text = io::writeRtz(r);
    const geo::Route back = io::readRtz(text, "rich.rtz");
    QVERIFY(back == r);
    QCOMPARE(io::writeRtz(back), text);
    // The first waypoint's leg is kept too when it holds something (it is written then).
    geo::Route first = r;
    first.waypoints[0].leg.note = "departure";
    first.waypoints[0].leg.geometry = geo::LegGeometry::GreatCircle;
    QVERIFY(io::readRtz(io::writeRtz(first), "first.rtz") == first);
    // A route without schedules, names or optional fields.
    geo::Route plain;
    plain.waypoints = {waypoint(0, "", 0.0, 0.0), waypoint(-3, "", -90.0, -180.0),
                       waypoint(9, "", 90.0, 180.0)};
    QVERIFY(io::readRtz(io::writeRtz(plain), "plain.rtz") == plain);
  }

  void writerFollowsTheRtz11Schema() {
    // GIVEN the rich route written WHEN its XML is read element by element THEN namespace, version,
    // order of elements and the required attributes are those of the RTZ 1.1 schema.
    const std::string text = io::writeRtz(richRoute());
    QVERIFY(text.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>", 0) == 0);
    pugi::xml_document doc;
    QVERIFY(doc.load_buffer(text.data(), text.size()));
    QCOMPARE(names(elementChildren(doc)), QStringList{"route"});
    const pugi::xml_node root = doc.child("route");
    QCOMPARE(QString(root.attribute("xmlns").value()), QString("http://www.cirm.org/RTZ/1/1"));
    QCOMPARE(QString(root.attribute("version").value()), QString("1.1"));
    QCOMPARE(names(elementChildren(root)), (QStringList{"routeInfo", "waypoints", "schedules"}));
    QVERIFY(!root.child("routeInfo").attribute("routeName").empty());
    const auto waypoints = elementChildren(root.child("waypoints"));
    QCOMPARE(names(waypoints),
             (QStringList{"defaultWaypoint", "waypoint", "waypoint", "waypoint", "waypoint", "waypoint"}));
    QCOMPARE(QString(waypoints[0].attribute("radius").value()), QString("0.4"));
    for (std::size_t k = 1; k < waypoints.size(); ++k) {
      const pugi::xml_node w = waypoints[k];
      QVERIFY(!w.attribute("id").empty());
      const QStringList children = names(elementChildren(w));
      const QStringList expected = k == 1 ? QStringList{"position"} : QStringList{"position", "leg"};
      QCOMPARE(children, expected);  // position first, then the leg (none on the first waypoint here)
      for (const char* a : {"lat", "lon"}) {
        const QString v = w.child("position").attribute(a).value();
        QVERIFY2(!v.isEmpty() && !v.contains('e') && !v.contains('E'), qPrintable(v));  // xs:decimal
      }
      if (k == 1) continue;
      const QString geometry = w.child("leg").attribute("geometryType").value();
      QVERIFY(geometry == "Loxodrome" || geometry == "Orthodrome");
    }
    QCOMPARE(QString(waypoints[1].child("position").attribute("lat").value()), QString("60.39299999999999"));
    QCOMPARE(QString(waypoints[4].child("leg").attribute("safetyDepth").value()), QString("0.0000001"));
    QCOMPARE(QString(waypoints[2].child("leg").attribute("geometryType").value()), QString("Orthodrome"));
    QVERIFY(waypoints[3].child("leg").attribute("speedMax").empty());  // unset: not written
    const auto schedules = elementChildren(root.child("schedules"));
    QCOMPARE(names(schedules), (QStringList{"schedule", "schedule"}));
    QCOMPARE(names(elementChildren(schedules[0])), (QStringList{"manual", "calculated"}));
    QCOMPARE(names(elementChildren(schedules[1])), QStringList{"calculated"});
    for (const pugi::xml_node list : {schedules[0].child("manual"), schedules[0].child("calculated")})
      for (const pugi::xml_node e : elementChildren(list)) {
        QCOMPARE(QString(e.name()), QString("scheduleElement"));
        QVERIFY(!e.attribute("waypointId").empty());
      }
    QCOMPARE(QString(schedules[0].child("manual").first_child().attribute("etd").value()),
             QString("2024-05-01T06:00:00.000000Z"));
    // No schedules: no <schedules>.
    geo::Route plain = richRoute();
    plain.schedules.clear();
    pugi::xml_document doc2;
    const std::string text2 = io::writeRtz(plain);
    QVERIFY(doc2.load_buffer(text2.data(), text2.size()));
    QCOMPARE(names(elementChildren(doc2.child("route"))), (QStringList{"routeInfo", "waypoints"}));
  }

  void writerRefusesWhatTheReaderWouldRefuse() {
    geo::Route one = richRoute();
    one.waypoints.resize(1);
    one.schedules.clear();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, io::writeRtz(one));
    geo::Route badSchedule = richRoute();
    badSchedule.schedules[0].manual[0].waypointId = 99;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, io::writeRtz(badSchedule));
    geo::Route nanSpeed = richRoute();
    nanSpeed.schedules[1].calculated[0].speedKn = std::numeric_limits<double>::quiet_NaN();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, io::writeRtz(nanSpeed));
    // Control characters cannot be in XML 1.0: they are left out.
    geo::Route control = richRoute();
    control.name =
        "a\x01"
        "b";
    QCOMPARE(io::readRtz(io::writeRtz(control), "c.rtz").name, std::string("ab"));
  }

  void readsRtz10WithSheduleElementAndDefaults() {
    const geo::Route r = readFile("rtz10_defaults.rtz");
    QCOMPARE(r.name, std::string("Fjord Approach"));
    QCOMPARE(r.author, std::string("Bridge team"));
    QCOMPARE(r.status, std::string("Planned"));
    QCOMPARE(r.defaultTurnRadiusNm, 0.3);
    QCOMPARE(r.waypoints.size(), std::size_t(4));
    QCOMPARE(r.waypoints[2].id, 5);
    QCOMPARE(r.waypoints[0].position.latDeg, 60.123456);
    QVERIFY(!r.waypoints[0].turnRadiusNm);
    QCOMPARE(r.waypoints[1].turnRadiusNm, std::optional<double>(0.5));
    // Waypoint 2's leg: its own portsideXTD, the rest from <defaultWaypoint>.
    const geo::LegPlan& leg2 = r.waypoints[1].leg;
    QCOMPARE(leg2.portXtlNm, 0.1);
    QCOMPARE(leg2.starboardXtlNm, 0.2);
    QCOMPARE(leg2.safetyContourM, std::optional<double>(10.0));
    QCOMPARE(leg2.safetyDepthM, std::optional<double>(12.0));
    QCOMPARE(leg2.plannedSpeedKn, std::optional<double>(12.0));
    QVERIFY(!leg2.minSpeedKn);
    const geo::LegPlan& leg3 = r.waypoints[2].leg;
    QCOMPARE(leg3.plannedSpeedKn, std::optional<double>(8.0));
    QCOMPARE(leg3.minSpeedKn, std::optional<double>(4.0));
    QCOMPARE(leg3.note, std::string("Reduce speed; meeting traffic"));
    QCOMPARE(r.waypoints[3].leg.safetyContourM, std::optional<double>(5.0));
    QCOMPARE(r.waypoints[3].leg.portXtlNm, 0.15);
    QCOMPARE(r.schedules.size(), std::size_t(1));
    const geo::Schedule& s = r.schedules[0];
    QCOMPARE(s.name, std::string("Planned"));
    QCOMPARE(s.manual.size(), std::size_t(3));
    QVERIFY(s.calculated.empty());
    QCOMPARE(s.manual[0].etd, std::optional<UtcUs>(utc("2024-05-01T06:00:00Z")));
    QCOMPARE(s.manual[1].speedKn, std::optional<double>(11.5));
    QCOMPARE(s.manual[2].waypointId, 7);
    QCOMPARE(s.manual[2].eta, std::optional<UtcUs>(utc("2024-05-01T08:30:00Z")));
    // Written as 1.1 and read back: the same route (defaults now on every waypoint).
    QVERIFY(io::readRtz(io::writeRtz(r), "again.rtz") == r);
  }

  void readsRtz11UnderAPrefixWithStmExtensions() {
    const geo::Route r = readFile("rtz11_stm_prefixed.rtz");
    QCOMPARE(r.name, std::string("Gothenburg - Kiel"));
    QCOMPARE(r.status, std::string("7"));
    QCOMPARE(r.defaultTurnRadiusNm, 0.8);
    QCOMPARE(r.waypoints.size(), std::size_t(4));
    QCOMPARE(r.waypoints[1].name, std::string("WP2"));
    QCOMPARE(r.waypoints[1].leg.geometry, geo::LegGeometry::GreatCircle);
    QCOMPARE(r.waypoints[1].leg.starboardXtlNm, 0.4);
    QCOMPARE(r.waypoints[3].leg.geometry, geo::LegGeometry::RhumbLine);
    QCOMPARE(r.waypoints[3].leg.portXtlNm, 0.27);
    QCOMPARE(r.waypoints[3].leg.safetyDepthM, std::optional<double>(11.5));
    QCOMPARE(r.schedules.size(), std::size_t(1));
    const auto& c = r.schedules[0].calculated;
    QCOMPARE(c.size(), std::size_t(4));
    QVERIFY(r.schedules[0].manual.empty());
    QCOMPARE(c[1].eta, std::optional<UtcUs>(utc("2024-06-10T22:45:00Z")));
    QCOMPARE(c[2].eta, std::optional<UtcUs>(utc("2024-06-11T01:15:00Z")));  // +02:00
  }

  void readsRtz12WithExtensionsEverywhere() {
    const geo::Route r = readFile("rtz12_extensions.rtz");
    QCOMPARE(r.waypoints.size(), std::size_t(4));
    QCOMPARE(r.waypoints[1].id, 20);
    QVERIFY(r.waypoints[1].name.empty());
    QCOMPARE(r.waypoints[1].leg.note, std::string("Ocean passage"));
    QCOMPARE(r.waypoints[1].leg.minSpeedKn, std::optional<double>(10.0));
    QCOMPARE(r.waypoints[2].leg.geometry, geo::LegGeometry::GreatCircle);
    QCOMPARE(r.waypoints[0].position.lonDeg, -6.445);
    QCOMPARE(r.waypoints[0].turnRadiusNm, std::optional<double>(2.0));
    QCOMPARE(r.defaultTurnRadiusNm, geo::Route{}.defaultTurnRadiusNm);  // no <defaultWaypoint>
    const geo::Schedule& s = r.schedules.at(0);
    QCOMPARE(s.manual.size(), std::size_t(2));
    QCOMPARE(s.manual[1].eta, std::optional<UtcUs>(utc("2024-09-08T13:30:00Z")));  // -04:00
    QCOMPARE(s.calculated.size(), std::size_t(4));
    QCOMPARE(s.calculated[1].eta, std::optional<UtcUs>(utc("2024-09-02T14:15:30.5Z")));
    QCOMPARE(s.calculated[2].eta, std::optional<UtcUs>(utc("2024-09-06T02:00:00Z")));  // +01:00
    QCOMPARE(s.calculated[2].speedKn, std::optional<double>(15.4));
    // Leg lengths of the great circle legs are the geodesic's: Bishop Rock -> 47.5N 20W is ~ 560 NM.
    RK_COMPARE_NEAR(geo::legLengthM(r, 1) / kMetresPerNauticalMile, 560.0, 15.0);
  }

  void foreignAndNestedElementsAreNotWaypoints() {
    // GIVEN a waypoint in another namespace directly in <waypoints>, and an RTZ-looking waypoint inside
    // an extension THEN neither is read; unknown attributes and elements are passed over.
    const geo::Route r = io::readRtz(
        rtz(R"(<stm:waypoint xmlns:stm="http://stmvalidation.eu/STM/1/0/0" id="9">)"
            R"(<stm:position lat="1" lon="1"/></stm:waypoint>)"
            "\n    "
            R"(<waypoint id="2" future="x"><position lat="60.1" lon="5.1" alt="3"/><note/>)"
            R"(<extensions><extension><waypoint id="8"><position lat="2" lon="2"/></waypoint></extension>)"
            R"(</extensions></waypoint>)"),
        "t.rtz");
    QCOMPARE(r.waypoints.size(), std::size_t(3));
    QCOMPARE(r.waypoints[1].id, 2);
  }

  void readsGpxRoutes() {
    const geo::Route o = readFile("opencpn_route.gpx");
    QCOMPARE(o.name, std::string("Harbour to anchorage"));
    QCOMPARE(o.waypoints.size(), std::size_t(3));
    QCOMPARE(o.waypoints[1].name, std::string("Brockton Point"));  // trimmed
    QCOMPARE(o.waypoints[2].name, std::string("Anchorage & holding"));
    QCOMPARE(o.waypoints[1].position.latDeg, 49.3005);
    QCOMPARE(o.waypoints[1].position.lonDeg, -123.14025);
    QCOMPARE(o.waypoints[2].id, 3);
    QCOMPARE(o.waypoints[2].leg, geo::LegPlan{});
    QVERIFY(o.schedules.empty());
    // The first route of a file with waypoints, a track and two routes; then the second by index, whose
    // Garmin autorouted points (gpxx:rpt) are not route points.
    const geo::Route g = readFile("garmin_routes.gpx");
    QCOMPARE(g.name, std::string("To Frioul"));
    QCOMPARE(g.author, std::string("Skipper Example"));
    QCOMPARE(g.waypoints.size(), std::size_t(2));
    const std::string text = io::readTextFile(kRoutes + "/garmin_routes.gpx");
    const geo::Route g2 = io::readGpxRoute(text, "garmin_routes.gpx", 1);
    QCOMPARE(g2.name, std::string("Coast run"));
    QCOMPARE(g2.waypoints.size(), std::size_t(4));
    QCOMPARE(g2.waypoints[3].name, std::string("LA CIOTAT"));
    // GPX 1.0, no namespace prefix games, the author as text; read -> RTZ -> read keeps it.
    const geo::Route v10 = io::readGpxRoute(
        "<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?>\n"
        "<gpx version=\"1.0\" creator=\"x\" "
        "xmlns=\"http://www.topografix.com/GPX/1/0\"><author>Jos\xE9</author>\n"
        "<rte><name>Caf\xE9</name><rtept lat=\"1\" lon=\"2\"/><rtept lat=\"1.5\" lon=\"2.5\"/></rte></gpx>",
        "v10.gpx");
    QCOMPARE(v10.author, std::string("Jos\xc3\xa9"));
    QCOMPARE(v10.name, std::string("Caf\xc3\xa9"));
    QVERIFY(io::readRtz(io::writeRtz(v10), "v10.rtz") == v10);
  }

  void routeFilesAreChosenByContentAndWritten() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string base = dir.path().toStdString();
    // GIVEN a route written to a file WHEN read THEN equal; GPX content under .rtz and RTZ under .xml are
    // read by what they are.
    io::writeRouteFile(base + "/r.rtz", richRoute());
    QVERIFY(io::readRouteFile(base + "/r.rtz") == richRoute());
    io::writeTextFile(base + "/r.xml", io::readTextFile(base + "/r.rtz"));
    QVERIFY(io::readRouteFile(base + "/r.xml") == richRoute());
    io::writeTextFile(base + "/g.rtz", io::readTextFile(kRoutes + "/opencpn_route.gpx"));
    QCOMPARE(io::readRouteFile(base + "/g.rtz").waypoints.size(), std::size_t(3));
    // A file over the limit is refused before it is read (sparse: nothing written).
    const std::string big = base + "/big.gpx";
    io::writeTextFile(big, "<gpx/>");
    std::filesystem::resize_file(big, io::kMaxRouteFileBytes + 1);
    try {
      io::readRouteFile(big);
      QFAIL("read a file over the limit");
    } catch (const io::InputError& e) {
      QVERIFY2(QString(e.what()).startsWith(QString::fromStdString(big + ": is 16777217 bytes; the limit")),
               e.what());
    }
    try {
      io::readRouteFile(base + "/missing.rtz");
      QFAIL("read a missing file");
    } catch (const io::InputError& e) {
      QCOMPARE(QString(e.what()),
               QString::fromStdString(base + "/missing.rtz: cannot open: No such file or directory"));
    }
    QVERIFY_THROWS_EXCEPTION(io::InputError, io::writeRouteFile(base + "/no/such/dir/r.rtz", richRoute()));
  }

  void malformedRtzIsOneLineNamingLineAndField_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<int>("line");
    QTest::addColumn<QString>("expected");
    addMalformedRtzContentRows();
    addMalformedFileRows();
  }
  void malformedRtzIsOneLineNamingLineAndField() {
    QFETCH(QByteArray, text);
    QFETCH(int, line);
    QFETCH(QString, expected);
    expectError(text.toStdString(), line, expected);
  }

  void gpxRouteIndexOutOfRange() {
    const std::string text = io::readTextFile(kRoutes + "/garmin_routes.gpx");
    try {
      io::readGpxRoute(text, "g.gpx", 2);
      QFAIL("read route 2 of 2");
    } catch (const io::InputError& e) {
      QVERIFY2(QString(e.what()).contains("route 2 asked for; the file has 2 route(s), numbered from 0"),
               e.what());
    }
  }
};

QTEST_GUILESS_MAIN(TestRouteFiles)
#include "tst_route_files.moc"
