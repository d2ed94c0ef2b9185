// Reckoner's NMEA output read by the Signal K project's parser (@signalk/nmea0183-signalk, pinned in
// tests/support/signalk/package.json and its lock, installed by the ctest fixture signalk_npm_ci):
// GIVEN own-ship sentences of known values and AIS lines passed through sim::NmeaOutput WHEN piped
// through tests/support/signalk/signalk_deltas.js (node) THEN Signal K's deltas carry the same position
// (1e-7 deg), course and speed over ground, heading, and the AIS target's MMSI, position, SOG, COG and
// heading. Fails (never skips) when node or the package is missing.
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTest>

#include <cmath>

#include "common/angles.h"
#include "common/units.h"
#include "sim/nmea_output.h"
#include "support/ais_corpus.h"
#include "support/compare_near.h"

using namespace reckoner;

namespace {

/// The values of a delta by Signal K path.
QMap<QString, QJsonValue> valuesOf(const QJsonObject& delta) {
  QMap<QString, QJsonValue> out;
  for (const QJsonValue& u : delta["updates"].toArray())
    for (const QJsonValue& v : u.toObject()["values"].toArray())
      out[v.toObject()["path"].toString()] = v.toObject()["value"];
  return out;
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

    QProcess node;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("NODE_PATH", RECKONER_SIGNALK_DIR "/node_modules");
    node.setProcessEnvironment(env);
    node.start("node", {RECKONER_SIGNALK_SCRIPT});
    QVERIFY2(node.waitForStarted(20000),
             "node (Debian's nodejs) is not installed: scripts/bootstrap.sh deps");
    for (const auto& l : lines) node.write(QByteArray::fromStdString(l) + "\r\n");
    node.closeWriteChannel();
    QVERIFY(node.waitForFinished(60000));
    const QByteArray err = node.readAllStandardError();
    QVERIFY2(node.exitCode() == 0, err.constData());

    QMap<QString, QJsonObject> byType;  // the last delta of each sentence type
    int deltas = 0;
    for (const QByteArray& l : node.readAllStandardOutput().split('\n')) {
      if (l.trimmed().isEmpty()) continue;
      const QJsonObject o2 = QJsonDocument::fromJson(l).object();
      QVERIFY2(!o2.contains("error"), l.constData());
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
};

QTEST_GUILESS_MAIN(TestNmeaSignalK)
#include "tst_nmea_signalk.moc"
