// Reckoner's NMEA output read by the Signal K project's parser (@signalk/nmea0183-signalk, pinned in
// tests/support/signalk/package.json and its lock, installed by the ctest fixture signalk_npm_ci):
// GIVEN own-ship sentences of known values and AIS lines passed through sim::NmeaOutput WHEN piped
// through tests/support/signalk/signalk_deltas.js (node) THEN Signal K's deltas carry the same position
// (1e-7 deg), course and speed over ground, heading, and the AIS target's MMSI, position, SOG, COG and
// heading. GIVEN route-following sentences of known values (io::nmea xte, rmb, apb) THEN its deltas
// carry the same cross-track error (Signal K's sign: negative left of the track, so steer right),
// destination id and position, range, bearing, closing velocity and heading to steer, and it takes
// nothing from an XTE or APB whose status is V. Fails (never skips) when node or the package is missing.
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTest>

#include <cmath>

#include "common/angles.h"
#include "common/units.h"
#include "io/nmea_out.h"
#include "sim/nmea_output.h"
#include "support/ais_corpus.h"
#include "support/compare_near.h"

using namespace reckoner;

namespace {

/// The values of a delta by Signal K path.
QMap<QString, QJsonValue> valuesOf(const QJsonObject& delta) {
  QMap<QString, QJsonValue> out;
  for (const auto& u : delta["updates"].toArray())
    for (const auto& v : u.toObject()["values"].toArray())
      out[v.toObject()["path"].toString()] = v.toObject()["value"];
  return out;
}

/// Pipes the lines through tests/support/signalk/signalk_deltas.js; out: one object per line,
/// {"line", "delta"} or {"line", "error"}.
void runSignalK(const std::vector<std::string>& lines, std::vector<QJsonObject>& out) {
  QProcess node;
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.insert("NODE_PATH", RECKONER_SIGNALK_DIR "/node_modules");
  node.setProcessEnvironment(env);
  node.start("node", {RECKONER_SIGNALK_SCRIPT});
  QVERIFY2(node.waitForStarted(20000), "node (Debian's nodejs) is not installed: scripts/bootstrap.sh deps");
  for (const auto& l : lines) node.write(QByteArray::fromStdString(l) + "\r\n");
  node.closeWriteChannel();
  QVERIFY(node.waitForFinished(60000));
  const QByteArray err = node.readAllStandardError();
  QVERIFY2(node.exitCode() == 0, err.constData());
  for (const QByteArray& l : node.readAllStandardOutput().split('\n'))
    if (!l.trimmed().isEmpty()) out.push_back(QJsonDocument::fromJson(l).object());
  QCOMPARE(out.size(), lines.size());
}

}  // namespace

class TestNmeaSignalK : public QObject {
  Q_OBJECT
 private slots:
  void signalKReadsOwnShipAndAis() {
    sim::NmeaOutputOptions o;
    o.ais = true;
    sim::NmeaOutput out(o);
    sim::OwnShipFix fix;
    fix.utcUs = 1767225600LL * 1000000LL;
    fix.latDeg = -33.8567844;
    fix.lonDeg = 151.2152967;
    fix.sogKn = 7.25;
    fix.cogTrueDeg = 359.5;
    fix.headingTrueDeg = 2.25;
    fix.varNorthM2 = fix.varEastM2 = 4.0;
    std::vector<std::string> lines = out.ownShip(fix);
    fix.utcUs += 1000000;
    fix.deadReckoning = true;
    for (auto& l : out.ownShip(fix)) lines.push_back(l);
    const auto ais =
        test::ais::sentence(test::ais::classA(1, 265547250, 0, 0, 139, 7099786, 34596212, 404, 41));
    for (auto& l : out.ais(ais)) lines.push_back(l);
    QCOMPARE(lines.back(), ais);

    std::vector<QJsonObject> outputs;
    runSignalK(lines, outputs);
    if (QTest::currentTestFailed()) return;

    QMap<QString, QJsonObject> byType;  // the last delta of each sentence type
    int deltas = 0;
    for (const QJsonObject& o2 : outputs) {
      QVERIFY2(!o2.contains("error"), qPrintable(o2["line"].toString() + ": " + o2["error"].toString()));
      if (o2["delta"].isNull()) continue;
      ++deltas;
      byType[o2["line"].toString().mid(3, 3)] = o2["delta"].toObject();
    }
    QVERIFY(deltas >= 7);
    const auto rmc = valuesOf(byType["RMC"]);
    const QJsonObject pos = rmc["navigation.position"].toObject();
    RK_COMPARE_NEAR(pos["latitude"].toDouble(), fix.latDeg, 1e-7);
    RK_COMPARE_NEAR(pos["longitude"].toDouble(), fix.lonDeg, 1e-7);
    RK_COMPARE_NEAR(rmc["navigation.courseOverGroundTrue"].toDouble(), degToRad(359.5), 1e-6);
    RK_COMPARE_NEAR(rmc["navigation.speedOverGround"].toDouble(), knotsToMps(7.25), 1e-3);
    const auto vtg = valuesOf(byType["VTG"]);
    RK_COMPARE_NEAR(vtg["navigation.courseOverGroundTrue"].toDouble(), degToRad(359.5), 1e-6);
    RK_COMPARE_NEAR(vtg["navigation.speedOverGround"].toDouble(), knotsToMps(7.25), 1e-3);
    RK_COMPARE_NEAR(valuesOf(byType["HDT"])["navigation.headingTrue"].toDouble(), degToRad(2.25), 1e-6);

    const QJsonObject vdm = byType["VDM"];
    QCOMPARE(vdm["context"].toString(), QString("vessels.urn:mrn:imo:mmsi:265547250"));
    const auto a = valuesOf(vdm);
    const QJsonObject apos = a["navigation.position"].toObject();
    RK_COMPARE_NEAR(apos["latitude"].toDouble(), 34596212 / 600000.0, 1e-6);
    RK_COMPARE_NEAR(apos["longitude"].toDouble(), 7099786 / 600000.0, 1e-6);
    RK_COMPARE_NEAR(a["navigation.speedOverGround"].toDouble(), knotsToMps(13.9), 1e-3);
    RK_COMPARE_NEAR(a["navigation.courseOverGroundTrue"].toDouble(), degToRad(40.4), 1e-4);
    RK_COMPARE_NEAR(a["navigation.headingTrue"].toDouble(), degToRad(41.0), 1e-4);
  }
  void signalKReadsRouteFollowing() {
    using namespace reckoner::io::nmea;
    // GIVEN own ship 0.25 NM left of the leg (steer right) toward WP12 at 49 17.24'N 123 09.57'W.
    std::vector<std::string> lines;
    lines.push_back(xte("EC", {0.25, true, true, 'A'}));
    RmbOut r;
    r.valid = true;
    r.crossTrackNm = 0.25;
    r.steerRight = true;
    r.originId = "WP11";
    r.destinationId = "WP12";
    r.destLatDeg = 49.0 + 17.24 / 60.0;
    r.destLonDeg = -(123.0 + 9.57 / 60.0);
    r.rangeToDestNm = 3.75;
    r.bearingToDestTrueDeg = 52.5;
    r.closingVelocityKn = 6.5;
    lines.push_back(rmb("EC", r));
    ApbOut a;
    a.valid = true;
    a.crossTrackNm = 0.5;
    a.steerRight = false;  // right of the leg: Signal K's positive
    a.arrivalCircleEntered = true;
    a.bearingOriginToDestDeg = 48.5;
    a.destinationId = "WP12";
    a.bearingPresentToDestDeg = 52.5;
    a.headingToSteerDeg = 47.5;
    lines.push_back(apb("EC", a));
    // AND the same XTE and APB not valid.
    lines.push_back(xte("EC", {0.25, true, false, 'A'}));
    a.valid = false;
    lines.push_back(apb("EC", a));

    // WHEN Signal K's parser reads them
    std::vector<QJsonObject> outputs;
    runSignalK(lines, outputs);
    if (QTest::currentTestFailed()) return;
    for (std::size_t i = 0; i < 3; ++i)
      QVERIFY2(!outputs[i].contains("error") && outputs[i]["delta"].isObject(),
               qPrintable(outputs[i]["line"].toString()));

    // THEN XTE: the cross-track error in metres, negative (left of the track).
    const auto x = valuesOf(outputs[0]["delta"].toObject());
    RK_COMPARE_NEAR(x["navigation.courseRhumbline.crossTrackError"].toDouble(), -nmToMetres(0.25), 1e-3);
    // RMB: the leg's next point, its distance, bearing and velocity made good, the previous point.
    const auto b = valuesOf(outputs[1]["delta"].toObject());
    const QJsonObject next = b["navigation.courseRhumbline.nextPoint.position"].toObject();
    RK_COMPARE_NEAR(next["latitude"].toDouble(), r.destLatDeg, 1e-7);
    RK_COMPARE_NEAR(next["longitude"].toDouble(), r.destLonDeg, 1e-7);
    RK_COMPARE_NEAR(b["navigation.courseRhumbline.crossTrackError"].toDouble(), -nmToMetres(0.25), 1e-3);
    RK_COMPARE_NEAR(b["navigation.courseRhumbline.nextPoint.distance"].toDouble(), nmToMetres(3.75), 1e-3);
    RK_COMPARE_NEAR(b["navigation.courseRhumbline.nextPoint.bearingTrue"].toDouble(), degToRad(52.5), 1e-6);
    RK_COMPARE_NEAR(b["navigation.courseRhumbline.nextPoint.velocityMadeGood"].toDouble(), knotsToMps(6.5),
                    1e-3);
    QCOMPARE(b["navigation.courseRhumbline.nextPoint.ID"].toString(), QString("WP12"));
    QCOMPARE(b["navigation.courseRhumbline.previousPoint.ID"].toString(), QString("WP11"));
    // APB: positive cross-track error (right of the track), the true bearings, the heading to steer,
    // the destination's id and the arrival circle alarm (no perpendicular alarm).
    const auto p = valuesOf(outputs[2]["delta"].toObject());
    RK_COMPARE_NEAR(p["navigation.courseRhumbline.crossTrackError"].toDouble(), nmToMetres(0.5), 1e-3);
    RK_COMPARE_NEAR(p["navigation.courseRhumbline.bearingOriginToDestinationTrue"].toDouble(), degToRad(48.5),
                    1e-6);
    RK_COMPARE_NEAR(p["navigation.courseRhumbline.nextPoint.bearingTrue"].toDouble(), degToRad(52.5), 1e-6);
    RK_COMPARE_NEAR(p["steering.autopilot.target.headingTrue"].toDouble(), degToRad(47.5), 1e-6);
    QCOMPARE(p["navigation.courseRhumbline.nextPoint.ID"].toString(), QString("WP12"));
    QCOMPARE(p["notifications.arrivalCircleEntered"].toObject()["state"].toString(), QString("alarm"));
    QVERIFY(p["notifications.perpendicularPassed"].isNull());
    // Not valid: Signal K refuses the XTE (status V) and finds nothing to steer on in the APB.
    QVERIFY2(outputs[3].contains("error"), qPrintable(outputs[3]["line"].toString()));
    QVERIFY2(!outputs[4].contains("error") && outputs[4]["delta"].isNull(),
             qPrintable(outputs[4]["line"].toString()));
  }
};

QTEST_GUILESS_MAIN(TestNmeaSignalK)
#include "tst_nmea_signalk.moc"
