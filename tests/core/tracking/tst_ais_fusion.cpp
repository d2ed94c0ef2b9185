// AIS and radar in one picture (docs/fusion.md): the simulated transponder (reporting intervals of ITU-R
// M.1371 Table 1, latency and the UTC second, the antenna's place on the hull worked out by hand), the
// receiver's observation (the hull centre recovered from the antenna, the fix time from the second
// across a minute), the scenario format's AIS fields, and the evaluation on the AIS harbour: association
// of at least 99% of the eligible station-cycles with the right track, no swap between vessels more
// than 500 m apart, and the fused tracks' NEES in their band.
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/angles.h"
#include "common/units.h"
#include "files/scenario_json.h"
#include "io/input_error.h"
#include "resources/embedded.h"
#include "sensors/ais_transmitter.h"
#include "studies/ais_fusion_study.h"
#include "studies/imo_accuracy.h"
#include "support/compare_near.h"
#include "support/drkf_fixtures.h"
#include "tracking/ais_fusion.h"
#include "tracking/ais_targets.h"

using namespace reckoner;

namespace {
constexpr double kLat0 = 50.0, kLon0 = -3.0;  // on zone 30's central meridian: no convergence

/// A class A report at the origin, 10 kn on 090.
io::AisMessage eastAt10Kn() {
  io::AisMessage m;
  m.type = 1;
  m.mmsi = 211000001;
  m.latDeg = kLat0;
  m.lonDeg = kLon0;
  m.sogKn = 10.0;
  m.cogDeg = 90.0;
  return m;
}

sensors::AisHullState hull(double tS, double x, double y, double speedMps, double headingDeg,
                           double turnDps = 0.0) {
  sensors::AisHullState h;
  h.timeUs = fromSeconds(tS);
  const double hd = degToRad(headingDeg);
  h.position = {x + speedMps * std::sin(hd) * tS, y + speedMps * std::cos(hd) * tS};
  h.vxMps = speedMps * std::sin(hd);
  h.vyMps = speedMps * std::cos(hd);
  h.headingRad = hd;
  h.turnRateRadPerS = degToRad(turnDps);
  return h;
}

sensors::AisTransmitterSpec exact(sensors::AisStationClass cls) {
  auto s = sensors::AisTransmitterSpec::defaults(cls);
  s.mmsi = 235000001;
  s.positionSdM = s.velocitySdMps = s.headingSdDeg = 0.0;
  s.lossProbability = 0.0;
  return s;
}

std::vector<sensors::AisReception> transmit(const sensors::AisTransmitterSpec& spec, double speedMps,
                                            double headingDeg, double turnDps, double durationS) {
  const geo::LocalFrame frame(kLat0, kLon0);
  sensors::AisTransmitter tx(spec, 7, Rng(3, 4), 0);
  std::vector<sensors::AisReception> out;
  for (int t = 0; t <= static_cast<int>(durationS); ++t)
    tx.advance(hull(t, 100.0, 200.0, speedMps, headingDeg, turnDps), frame, out);
  return out;
}

std::vector<sensors::AisReception> positions(const std::vector<sensors::AisReception>& all) {
  std::vector<sensors::AisReception> p;
  for (const auto& r : all)
    if (r.message.latDeg) p.push_back(r);
  return p;
}
}  // namespace

class TstAisFusion : public QObject {
  Q_OBJECT
 private slots:
  void reportingIntervalsFollowTable1() {
    // GIVEN class A at 10 kn straight, turning, at 18 kn, and class B at 6 kn
    // THEN reports come every 10 s, 3 1/3 s, 6 s and 30 s.
    const double kn = kMpsPerKnot;
    const auto a = positions(transmit(exact(sensors::AisStationClass::A), 10 * kn, 30, 0, 600));
    const auto turning = positions(transmit(exact(sensors::AisStationClass::A), 10 * kn, 30, 1.0, 600));
    const auto fast = positions(transmit(exact(sensors::AisStationClass::A), 18 * kn, 30, 0, 600));
    const auto b = positions(transmit(exact(sensors::AisStationClass::B), 6 * kn, 30, 0, 600));
    RK_COMPARE_NEAR(static_cast<double>(a.size()), 60.0, 1.0);
    RK_COMPARE_NEAR(static_cast<double>(turning.size()), 180.0, 1.0);
    RK_COMPARE_NEAR(static_cast<double>(fast.size()), 100.0, 1.0);
    RK_COMPARE_NEAR(static_cast<double>(b.size()), 20.0, 1.0);
    QCOMPARE(a.front().message.type, 1);
    QCOMPARE(b.front().message.type, 18);
    QVERIFY(!b.front().message.headingDeg);
  }

  /// GIVEN an AIS-SART and a MOB in test WHEN transmitting for 10 minutes THEN each sends bursts of 8
  /// type 1 reports one second apart once a minute (status 14 active, 15 test; no heading, no ROT) and
  /// its type 14 text every 4 minutes; the table takes the first as a distress, the second as a test.
  void searchAndRescueDevicesSendBurstsAndTheirText() {
    auto sart = exact(sensors::AisStationClass::Sart);
    sart.mmsi = 970012345;
    auto mob = sart;
    mob.mmsi = 972001002;
    mob.test = true;
    QVERIFY(sart.check().empty() && mob.check().empty());
    for (const auto& spec : {sart, mob}) {
      const auto all = transmit(spec, 0.1, 135, 0, 600);
      const auto reports = positions(all);
      QVERIFY2(reports.size() >= 72 && reports.size() <= 80, qPrintable(QString::number(reports.size())));
      for (std::size_t i = 0; i < reports.size(); ++i) {
        const io::AisMessage& m = reports[i].message;
        QCOMPARE(m.type, 1);
        QCOMPARE(*m.navStatus, spec.test ? 15 : 14);
        QVERIFY(!m.headingDeg && !m.rotDegMin);
        if (i == 0) continue;
        const double gap = toSeconds(reports[i].rxUs - reports[i - 1].rxUs);
        RK_COMPARE_NEAR(gap, i % 8 == 0 ? 53.0 : 1.0, 1e-9);
      }
      std::vector<std::string> texts;
      for (const auto& r : all)
        if (r.message.type == 14) texts.push_back(r.message.text);
      QCOMPARE(texts.size(), std::size_t{3});
      QCOMPARE(texts.front(), std::string(spec.test ? "MOB TEST" : "SART ACTIVE"));
      track::AisTargetTable table;
      for (const auto& r : all) table.feed(r.message, r.rxUs);
      QCOMPARE(table.find(spec.mmsi)->distress(), !spec.test);
    }
    // A device needs a device's MMSI, and only a device has a test mode
    sart.mmsi = 235000001;
    QVERIFY(sart.check().starts_with("mmsi: "));
    auto a = exact(sensors::AisStationClass::A);
    a.test = true;
    QVERIFY(a.check().starts_with("test: "));
  }

  void latencyAndUtcSecond() {
    // Every report's fix is a whole second, latency within the class's range (plus the second's
    // rounding), its UTC second is the fix's, and the receiver recovers the fix time from it.
    for (auto cls : {sensors::AisStationClass::A, sensors::AisStationClass::B}) {
      const auto spec = exact(cls);
      for (const auto& r : positions(transmit(spec, 5.0, 10, 0, 900))) {
        QCOMPARE(r.fixUs % kMicrosPerSecond, TimeUs{0});
        const double latency = toSeconds(r.rxUs - r.fixUs);
        QVERIFY(latency >= spec.latencyMinS && latency <= spec.latencyMaxS + 1.0);
        QCOMPARE(*r.message.second, static_cast<int>((r.fixUs / kMicrosPerSecond) % 60));
        QCOMPARE(*track::aisFixTime(r.rxUs, r.message.second, 0), r.fixUs);
      }
    }
  }

  void fixTimeAcrossTheMinute() {
    QCOMPARE(*track::aisFixTime(fromSeconds(61.2), 59, 0), fromSeconds(59.0));
    QCOMPARE(*track::aisFixTime(fromSeconds(125.9), 5, 0), fromSeconds(125.0));
    // A clock whose zero is 30 s past a minute.
    QCOMPARE(*track::aisFixTime(fromSeconds(2.5), 31, fromSeconds(30.0)), fromSeconds(1.0));
    QVERIFY(!track::aisFixTime(fromSeconds(10), 60, 0));
    QVERIFY(!track::aisFixTime(fromSeconds(10), std::nullopt, 0));
  }

  void antennaOffsetWorkedByHand() {
    // A 120 m by 20 m ship heading north, antenna 100 m from the bow and 4 m from the port side: the
    // centre is 60 m from the bow and 10 m from the port side, so the antenna is 40 m aft and 6 m to
    // port of the centre.
    const auto o = sensors::antennaOffset(100, 20, 4, 16);
    QVERIFY(o.known);
    RK_COMPARE_NEAR(o.forwardM, -40.0, 1e-12);
    RK_COMPARE_NEAR(o.starboardM, -6.0, 1e-12);
    QVERIFY(!sensors::antennaOffset(0, 0, 0, 0).known);
  }

  void longRangeReportIsCoarse() {
    // GIVEN the same report as a type 1 and as a type 27 (1/10 minute, whole knots and degrees), no
    // previous report, the UTC second known for the type 1
    const geo::LocalFrame frame(kLat0, kLon0);
    io::AisMessage m = eastAt10Kn();
    m.accuracy = true;
    const track::AisErrorModel e;
    const auto fine = track::aisObservation(m, fromSeconds(100), {}, frame, e, -1);
    m.type = 27;
    const auto coarse = track::aisObservation(m, fromSeconds(100), {}, frame, e, -1);
    QVERIFY(fine && coarse);
    // THEN the type 27's position variance is larger by (185.2 m)^2 / 12 and its velocity variance by
    // (1 kn)^2 / 12 + (1 degree x 10 kn)^2 / 12 less the (0.1 kn)^2 / 12 of the type 1
    const double v = knotsToMps(10.0);
    RK_COMPARE_NEAR(coarse->R(0, 0) - fine->R(0, 0), 185.2 * 185.2 / 12.0, 1e-6);
    RK_COMPARE_NEAR(coarse->R(2, 2) - fine->R(2, 2),
                    (knotsToMps(1.0) * knotsToMps(1.0) - knotsToMps(0.1) * knotsToMps(0.1) +
                     degToRad(1.0) * v * degToRad(1.0) * v) /
                        12.0,
                    1e-9);
  }

  void positionThatIsNotAFixIsNotFused() {
    // A report whose time stamp says the position was entered by hand, dead reckoned, or made with the
    // positioning system inoperative (61-63) gives no observation; the same report with a second does.
    const geo::LocalFrame frame(kLat0, kLon0);
    io::AisMessage m = eastAt10Kn();
    m.second = 20;
    QVERIFY(track::aisObservation(m, fromSeconds(100), {}, frame, {}, -1));
    for (const int code : {61, 62, 63}) {
      m.second.reset();
      m.positionNotFix = code;
      QVERIFY(!track::aisObservation(m, fromSeconds(100), {}, frame, {}, -1));
    }
  }

  void hullCentreRecoveredFromTheAntenna() {
    // With exact errors the observation gives back the hull's centre (to the message's resolution) at
    // any heading, including across north.
    const geo::LocalFrame frame(kLat0, kLon0);
    for (double heading : {0.0, 90.0, 225.0, 359.0, 1.0}) {
      auto spec = exact(sensors::AisStationClass::A);
      spec.toBowM = 100, spec.toSternM = 20, spec.toPortM = 4, spec.toStarboardM = 16;
      spec.headingSdDeg = 0.0;
      const auto all = transmit(spec, 6.0, heading, 0, 60);
      track::AisStatic info;
      info.toBowM = 100, info.toSternM = 20, info.toPortM = 4, info.toStarboardM = 16;
      int checked = 0;
      for (const auto& r : positions(all)) {
        const auto o = track::aisObservation(r.message, r.rxUs, info, frame, {}, -1);
        QVERIFY(o.has_value());
        QVERIFY(o->offsetCorrected);
        const auto h = hull(toSeconds(r.fixUs), 100.0, 200.0, 6.0, heading);
        test::NearContext ctx(QString("heading %1").arg(heading));
        // The heading is sent to the degree: 1 degree of 40 m is 0.7 m.
        RK_COMPARE_NEAR(o->z[0], h.position.xM, 1.0);
        RK_COMPARE_NEAR(o->z[1], h.position.yM, 1.0);
        RK_COMPARE_NEAR(o->z[2], h.vxMps, 0.06);
        RK_COMPARE_NEAR(o->z[3], h.vyMps, 0.06);
        QCOMPARE(o->fixUs, r.fixUs);
        ++checked;
      }
      QVERIFY(checked > 3);
    }
  }

  void scenarioFieldsReadAndWritten() {
    const sim::Scenario s = test::builtinScenario("ais-harbour");
    int a = 0, b = 0;
    for (const auto& t : s.targets)
      if (t.ais) ++(t.ais->cls == sensors::AisStationClass::A ? a : b);
    QCOMPARE(a, 20);
    QCOMPARE(b, 10);
    // The SART scenario's devices are read and written back with their mode
    const sim::Scenario sart = test::builtinScenario("sart");
    const sim::Scenario sartBack = files::parseScenario(files::writeScenario(sart), "written");
    QCOMPARE(sartBack.targets.size(), std::size_t{3});
    QCOMPARE(sartBack.targets[0].ais->cls, sensors::AisStationClass::Sart);
    QVERIFY(!sartBack.targets[0].ais->test);
    QVERIFY(sartBack.targets[1].ais->test);
    QCOMPARE(sartBack.targets[1].ais->mmsi, 972001002u);
    sim::Scenario edited = s;
    edited.tracker.aisAssociation.positionLimitM = 250.0;
    const sim::Scenario back = files::parseScenario(files::writeScenario(edited), "written");
    QCOMPARE(back.tracker.aisAssociation.positionLimitM, 250.0);
    for (std::size_t i = 0; i < s.targets.size(); ++i) {
      QCOMPARE(back.targets[i].ais.has_value(), s.targets[i].ais.has_value());
      if (!s.targets[i].ais) continue;
      QCOMPARE(back.targets[i].ais->mmsi, s.targets[i].ais->mmsi);
      QCOMPARE(back.targets[i].ais->toBowM, s.targets[i].ais->toBowM);
      QCOMPARE(back.targets[i].ais->latencyMaxS, s.targets[i].ais->latencyMaxS);
    }
  }

  void badFieldsNamed_data() {
    QTest::addColumn<QString>("ais");
    QTest::addColumn<QString>("path");
    QTest::newRow("class") << R"({"class": "C", "mmsi": 1})"
                           << "targets[0].ais.class";
    QTest::newRow("mmsi") << R"({"class": "A", "mmsi": 0})"
                          << "targets[0].ais.mmsi";
    QTest::newRow("antenna") << R"({"class": "A", "mmsi": 5, "antenna_m": [1, 2, 300, 4]})"
                             << "targets[0].ais.antenna_m[2]";
    QTest::newRow("latency") << R"({"class": "B", "mmsi": 5, "latency_s": [3, 1]})"
                             << "targets[0].ais.latency_s";
    QTest::newRow("unknown") << R"({"class": "B", "mmsi": 5, "speed": 3})"
                             << "targets[0].ais.speed";
    QTest::newRow("sart mmsi") << R"({"class": "SART", "mmsi": 235000001})"
                               << "targets[0].ais.mmsi";
    QTest::newRow("test of a ship") << R"({"class": "A", "mmsi": 5, "test": true})"
                                    << "targets[0].ais.test";
    QTest::newRow("test not a boolean") << R"({"class": "SART", "mmsi": 970000001, "test": 1})"
                                        << "targets[0].ais.test";
  }
  void badFieldsNamed() {
    QFETCH(QString, ais);
    QFETCH(QString, path);
    // The four-encounter scenario with its first target's transponder replaced.
    QJsonObject root =
        QJsonDocument::fromJson(
            QByteArray(resources::findScenario("trial-encounters")->text.data(),
                       static_cast<qsizetype>(resources::findScenario("trial-encounters")->text.size())))
            .object();
    QJsonArray targets = root["targets"].toArray();
    QJsonObject first = targets[0].toObject();
    first["ais"] = QJsonDocument::fromJson(ais.toUtf8()).object();
    targets[0] = first;
    root["targets"] = targets;
    const std::string text = QJsonDocument(root).toJson().toStdString();
    try {
      files::parseScenario(text, "bad.json");
      QFAIL("accepted");
    } catch (const io::InputError& e) {
      QVERIFY2(std::string(e.what()).find(path.toStdString()) != std::string::npos, e.what());
      QVERIFY2(std::string(e.what()).find("bad.json") != std::string::npos, e.what());
    }
  }

  void harbourAssociationAndFusion() {
    // GIVEN the AIS harbour (40 radar targets, 30 with AIS), two runs
    // THEN at least 99% of the eligible station-cycles are associated with their own vessel's track, no
    // swap between vessels more than 500 m apart, every association fuses, and the fused tracks' NEES
    // (target position and velocity) is in its band: errors inside the sd, the sd not far above them.
    const sim::Scenario s = test::builtinScenario("ais-harbour");
    studies::FusionStudyOptions o;
    o.runs = 2;
    o.threads = 2;
    const auto r = studies::evaluateFusion(s, o);
    QVERIFY2(r.correctFraction() >= 0.99, qPrintable(QString::number(r.correctFraction())));
    QCOMPARE(r.swapsFar, 0L);
    QVERIFY(r.eligible > 50000);
    QVERIFY(r.fusedReports > 5000);
    QVERIFY(r.associationEvents >= 50);
    const auto& fused = r.accuracy[static_cast<int>(studies::FusionSource::Fused)];
    QVERIFY(fused.samplesAt3 >= 50);
    QVERIFY2(fused.meanNeesAt3 > 1.0 && fused.meanNeesAt3 < 8.0,
             qPrintable(QString::number(fused.meanNeesAt3)));
    // Fusion helps the radar track: the fused 3-minute true speed and CPA beat radar-only.
    const auto& radar = r.accuracy[static_cast<int>(studies::FusionSource::RadarOnly)];
    const int speed = static_cast<int>(studies::ImoQuantity::TrueSpeed),
              cpa = static_cast<int>(studies::ImoQuantity::Cpa);
    QVERIFY(fused.p95At3[speed] < radar.p95At3[speed]);
    QVERIFY(fused.p95At3[cpa] < radar.p95At3[cpa]);
  }
};

QTEST_APPLESS_MAIN(TstAisFusion)
#include "tst_ais_fusion.moc"
