// The AIS target table (core/tracking/ais_targets.h) and its alerts (core/alerts/ais_alert.h): static and
// dynamic data merged per MMSI with "not available" fields left absent, CPA/TCPA against a geometry
// worked by hand, the lost rule of ITU-R M.1371 Table 1 by class and speed, the capacity limits, the
// 359 -> 1 degree COG crossing, and the real recording of ../shared/data/ais fed through, its target
// count checked against the distinct MMSIs that gpsd's gpsdecode reports.
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QTest>

#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <utility>

#include "alerts/ais_alert.h"
#include "common/angles.h"
#include "common/units.h"
#include "io/ais.h"
#include "support/compare_near.h"
#include "tracking/ais_targets.h"

using namespace reckoner;
using namespace reckoner::track;

namespace {

// Origin on the central meridian of UTM zone 30 (3 W): along it the grid convergence is 0.
constexpr double kLat0 = 50.0, kLon0 = -3.0;

TimeUs sec(double s) {
  return fromSeconds(s);
}

io::AisMessage report(std::uint32_t mmsi, int type, geo::GeoPoint p, std::optional<double> sogKn,
                      std::optional<double> cogDeg, std::optional<int> headingDeg = std::nullopt) {
  io::AisMessage m;
  m.type = type;
  m.mmsi = mmsi;
  m.latDeg = p.latDeg;
  m.lonDeg = p.lonDeg;
  m.sogKn = sogKn;
  m.cogDeg = cogDeg;
  m.headingDeg = headingDeg;
  if (type <= 3) m.navStatus = 0;
  return m;
}

/// A point dx east, dy north of the origin in the test's frame (grid metres).
geo::GeoPoint at(const geo::LocalFrame& f, double dxM, double dyM) {
  return f.toGeodetic({dxM, dyM});
}

AisTarget classA(double sogKn, int navStatus = 0, std::optional<double> rot = std::nullopt) {
  AisTarget t;
  t.cls = AisClass::A;
  t.sogKn = sogKn;
  t.navStatus = navStatus;
  t.rotDegMin = rot;
  return t;
}

}  // namespace

class TestAisTargets : public QObject {
  Q_OBJECT
 private slots:
  void staticAndDynamicDataMergePerMmsi() {
    // GIVEN a class A position report, then its type 5 static and voyage data
    const geo::LocalFrame f(kLat0, kLon0);
    AisTargetTable table;
    table.feed(report(244123456, 1, at(f, 0, 1000), 12.3, 45.0, 47), sec(0));
    io::AisMessage s;
    s.type = 5;
    s.mmsi = 244123456;
    s.name = "NORTH STAR";
    s.callsign = "PD1234";
    s.imo = 9123456;
    s.shipType = 70;
    s.toBowM = 100;
    s.toSternM = 20;
    s.toPortM = 10;
    s.toStarboardM = 8;
    s.draughtM = 7.5;
    s.destination = "ROTTERDAM";
    s.etaMonth = 5;
    s.etaDay = 17;
    table.feed(s, sec(2));
    // WHEN a later position report arrives
    table.feed(report(244123456, 3, at(f, 0, 1100), 12.5, 46.0, 48), sec(6));
    // THEN one target holds both, the latest dynamic data and the static data
    QCOMPARE(table.size(), std::size_t{1});
    const AisTarget* t = table.find(244123456);
    QVERIFY(t);
    QCOMPARE(t->cls, AisClass::A);
    QCOMPARE(*t->sogKn, 12.5);
    QCOMPARE(*t->headingDeg, 48);
    QCOMPARE(t->info.name, std::string("NORTH STAR"));
    QCOMPARE(t->info.callsign, std::string("PD1234"));
    QCOMPARE(*t->info.imo, 9123456u);
    QCOMPARE(*t->info.shipType, 70);
    QCOMPARE(*t->info.lengthM(), 120.0);
    QCOMPARE(*t->info.beamM(), 18.0);
    QCOMPARE(*t->info.draughtM, 7.5);
    QCOMPARE(t->info.destination, std::string("ROTTERDAM"));
    QCOMPARE(*t->info.etaMonth, 5);
    QVERIFY(!t->info.etaHour);
    QCOMPARE(t->reports, std::uint64_t{3});
    QCOMPARE(t->lastReportUs, sec(6));
    QCOMPARE(t->firstReportUs, sec(0));
    // AND a later type 5 whose dimensions are all 0 (as the decoder gives "not available") keeps the
    // hull; one with a 0 among others (the reference point at the bow) replaces the set
    io::AisMessage unset = s;
    unset.toBowM = unset.toSternM = unset.toPortM = unset.toStarboardM = 0;
    table.feed(unset, sec(7));
    QCOMPARE(*table.find(244123456)->info.lengthM(), 120.0);
    QCOMPARE(*table.find(244123456)->info.beamM(), 18.0);
    io::AisMessage atBow = s;
    atBow.toBowM = 0;
    atBow.toSternM = 110;
    table.feed(atBow, sec(8));
    QCOMPARE(*table.find(244123456)->info.toBowM, 0);
    QCOMPARE(*table.find(244123456)->info.lengthM(), 110.0);
  }

  void notAvailableFieldsStayAbsent() {
    // GIVEN a class B station: 24A with its name, then 24B without one, then a report without heading
    const geo::LocalFrame f(kLat0, kLon0);
    AisTargetTable table;
    io::AisMessage a;
    a.type = 24;
    a.mmsi = 235000001;
    a.part = 'A';
    a.name = "SEA WITCH";
    table.feed(a, sec(0));
    io::AisMessage b;
    b.type = 24;
    b.mmsi = 235000001;
    b.part = 'B';
    b.callsign = "MABC1";
    b.shipType = 36;
    table.feed(b, sec(1));
    table.feed(report(235000001, 18, at(f, 500, 0), 5.0, 10.0, 12), sec(2));
    table.feed(report(235000001, 18, at(f, 510, 0), std::nullopt, std::nullopt), sec(32));
    // THEN the name survives the part B, and what the latest report lacks is absent, not 0
    const AisTarget* t = table.find(235000001);
    QVERIFY(t);
    QCOMPARE(t->cls, AisClass::B);
    QCOMPARE(t->info.name, std::string("SEA WITCH"));
    QCOMPARE(t->info.callsign, std::string("MABC1"));
    QVERIFY(!t->info.imo);
    QVERIFY(!t->info.lengthM());
    QVERIFY(!t->info.draughtM);
    QVERIFY(!t->sogKn);
    QVERIFY(!t->cogDeg);
    QVERIFY(!t->headingDeg);
    QVERIFY(!t->rotDegMin);
    QVERIFY(!t->navStatus);
    QVERIFY(!t->orientationDeg());
    QVERIFY(!t->positionNotFix);
    // AND without SOG and COG there is a range but no CPA
    table.update(sec(33), f, {f.origin(), 0.0, 0.0});
    t = table.find(235000001);
    QVERIFY(t->rangeValid);
    QVERIFY(!t->cpaValid);
    RK_COMPARE_NEAR(t->rangeM, 510.0, 0.5);
    RK_COMPARE_NEAR(radToDeg(t->bearingRad), 90.0, 0.1);
  }

  void aPositionThatIsNotAFixIsMarkedUntilTheNextFix() {
    const geo::LocalFrame f(kLat0, kLon0);
    AisTargetTable table;
    io::AisMessage m = report(244000002, 1, at(f, 0, 1000), 8.0, 45.0);
    m.positionNotFix = 62;  // dead reckoning
    table.feed(m, sec(0));
    QCOMPARE(table.find(244000002)->positionNotFix, std::optional<int>(62));
    QVERIFY(table.find(244000002)->hasPosition());
    table.feed(report(244000002, 1, at(f, 0, 1040), 8.0, 45.0), sec(10));
    QVERIFY(!table.find(244000002)->positionNotFix);
  }

  void aTargetAtRestWithoutCogHasItsCpa() {
    // GIVEN an anchored ship 2 NM ahead, 200 m to starboard of own ship's track, reporting SOG 0 and COG
    // "not available" (as anchored ships and class B boats at rest do), and own ship at 12 kn on 000
    const geo::LocalFrame f(kLat0, kLon0);
    AisTargetTable table;
    table.feed(report(244000001, 1, at(f, 200.0, 3704.0), 0.0, std::nullopt), sec(0));
    const double v = knotsToMps(12.0);
    // WHEN the table is updated
    table.update(sec(0), f, {f.origin(), 0.0, v});
    // THEN the CPA is the track's distance from the point, 200 m, at 3704 m / v: dangerous
    const AisTarget* t = table.find(244000001);
    QVERIFY(t->cpaValid);
    RK_COMPARE_NEAR(t->cpa.cpaM, 200.0, 0.5);
    RK_COMPARE_NEAR(t->cpa.tcpaS, 3704.0 / v, 0.5);
    QVERIFY(t->dangerous);
    // AND 0.1 kn without a course is still at rest; 0.2 kn without one, or no SOG, gives no CPA
    for (const auto& [sog, cpa] :
         {std::pair<std::optional<double>, bool>{0.1, true}, {0.2, false}, {std::nullopt, false}}) {
      table.feed(report(244000001, 1, at(f, 200.0, 3704.0), sog, std::nullopt), sec(1));
      table.update(sec(1), f, {f.origin(), 0.0, v});
      QCOMPARE(table.find(244000001)->cpaValid, cpa);
      QCOMPARE(table.find(244000001)->dangerous, cpa);
    }
  }

  void cpaMatchesAHandComputedGeometry() {
    // GIVEN own ship at the origin steering 000 at 10 kn and a target 4 NM north steering 090 at 10 kn:
    //   r = (0, 7408) m, v = (v0, -v0) with v0 = 10 kn; TCPA = r.v... = 7408 v0 / (2 v0^2) = 720.0 s,
    //   CPA = |(v0 720, 7408 - v0 720)| = |(3704, 3704)| = 5238.4 m.
    const geo::LocalFrame f(kLat0, kLon0);
    AisTableLimits limits;
    limits.cpaLimitM = 6000.0;
    AisTargetTable table(limits);
    table.feed(report(211000001, 1, at(f, 0, 7408.0), 10.0, 90.0, 90), sec(0));
    const double v0 = knotsToMps(10.0);
    // WHEN the table is updated at the report's time
    table.update(sec(0), f, {f.origin(), 0.0, v0});
    // THEN CPA and TCPA are those, the target is dangerous and activated automatically
    const AisTarget* t = table.find(211000001);
    QVERIFY(t->cpaValid);
    RK_COMPARE_NEAR(t->cpa.tcpaS, 720.0, 1.0);
    RK_COMPARE_NEAR(t->cpa.cpaM, 3704.0 * std::sqrt(2.0), 5.0);
    RK_COMPARE_NEAR(t->rangeM, 7408.0, 0.5);
    QVERIFY(t->dangerous);
    QVERIFY(t->activated && t->autoActivated);
    // AND 360 s later, the target dead reckoned from its report, the TCPA is 360 s shorter
    table.update(sec(360), f, {at(f, 0, v0 * 360.0), 0.0, v0});
    t = table.find(211000001);
    RK_COMPARE_NEAR(t->cpa.tcpaS, 360.0, 1.0);
    RK_COMPARE_NEAR(t->cpa.cpaM, 3704.0 * std::sqrt(2.0), 5.0);
    // AND with a CPA limit under 5238 m the same target is not dangerous
    limits.cpaLimitM = 5000.0;
    AisTargetTable strict(limits);
    strict.feed(report(211000001, 1, at(f, 0, 7408.0), 10.0, 90.0, 90), sec(0));
    strict.update(sec(0), f, {f.origin(), 0.0, v0});
    QVERIFY(!strict.find(211000001)->dangerous);
    QVERIFY(!strict.find(211000001)->activated);
  }

  void cogCrossingNorthIsContinuous() {
    // GIVEN two targets 2 NM north of a stopped own ship, steering 359 and 001 at 12 kn
    const geo::LocalFrame f(kLat0, kLon0);
    AisTargetTable table;
    table.feed(report(1, 1, at(f, 0, 3704.0), 12.0, 359.0), sec(0));
    table.feed(report(2, 1, at(f, 0, 3704.0), 12.0, 1.0), sec(0));
    // WHEN 10 minutes pass
    table.update(sec(600), f, {f.origin(), 0.0, 0.0});
    // THEN both have run 2 NM on, 1 degree either side of north, mirror images of each other
    const AisTarget *a = table.find(1), *b = table.find(2);
    RK_COMPARE_NEAR(a->rangeM, b->rangeM, 1e-6);
    RK_COMPARE_NEAR(a->rangeM, 7408.0, 2.0);
    RK_COMPARE_NEAR(radToDeg(angleDiff(a->bearingRad, 0.0)), -0.5, 0.01);
    RK_COMPARE_NEAR(radToDeg(angleDiff(b->bearingRad, 0.0)), 0.5, 0.01);
    QVERIFY(a->cpa.tcpaS < 0.0 && b->cpa.tcpaS < 0.0);  // opening: the closest approach is past
    RK_COMPARE_NEAR(a->cpa.cpaM, b->cpa.cpaM, 1e-6);
    RK_COMPARE_NEAR(a->cpa.cpaM, 3704.0 * std::sin(degToRad(1.0)), 0.5);
    // AND without a heading the symbol is oriented by COG
    QCOMPARE(*a->orientationDeg(), 359.0);
  }

  void reportingIntervalsFollowTableOne() {
    QCOMPARE(reportingIntervalS(classA(0.2, 1)), 180.0);  // at anchor
    QCOMPARE(reportingIntervalS(classA(0.0, 5)), 180.0);  // moored
    QCOMPARE(reportingIntervalS(classA(4.0, 1)), 10.0);   // "at anchor" but moving faster than 3 kn
    QCOMPARE(reportingIntervalS(classA(10.0)), 10.0);
    RK_COMPARE_NEAR(reportingIntervalS(classA(10.0, 0, 8.0)), 10.0 / 3.0, 1e-12);
    QCOMPARE(reportingIntervalS(classA(10.0, 0, 2.0)), 10.0);  // under the turning threshold
    QCOMPARE(reportingIntervalS(classA(18.0)), 6.0);
    QCOMPARE(reportingIntervalS(classA(18.0, 0, -20.0)), 2.0);
    QCOMPARE(reportingIntervalS(classA(25.0)), 2.0);
    AisTarget fast = classA(10.0);
    fast.rotFast = -1;
    RK_COMPARE_NEAR(reportingIntervalS(fast), 10.0 / 3.0, 1e-12);
    AisTarget b;
    b.cls = AisClass::B;
    b.sogKn = 5.0;
    QCOMPARE(reportingIntervalS(b), 30.0);
    b.sogKn = 1.5;
    QCOMPARE(reportingIntervalS(b), 180.0);
    b.cls = AisClass::BaseStation;
    QCOMPARE(reportingIntervalS(b), 10.0);
    b.cls = AisClass::AidToNavigation;
    QCOMPARE(reportingIntervalS(b), 180.0);
  }

  void targetsAreLostByTheirClassAndSpeed() {
    // GIVEN a class A ship at 10 kn (10 s interval) and a class B boat at 1 kn (180 s), lost after 5
    // intervals, removed 300 s after that
    const geo::LocalFrame f(kLat0, kLon0);
    AisTargetTable table;
    table.feed(report(100, 1, at(f, 0, 1000), 10.0, 0.0), sec(0));
    table.feed(report(200, 18, at(f, 1000, 0), 1.0, 0.0), sec(0));
    QCOMPARE(table.lostAfterS(*table.find(100)), 50.0);
    QCOMPARE(table.lostAfterS(*table.find(200)), 900.0);
    // WHEN both fall silent
    table.update(sec(49));
    QVERIFY(!table.find(100)->lost);
    table.update(sec(51));
    // THEN the ship is lost after 50 s, the boat not before 900 s
    QVERIFY(table.find(100)->lost);
    QVERIFY(!table.find(200)->lost);
    QCOMPARE(table.counts().lostEvents, std::uint64_t{1});
    table.update(sec(340));
    QVERIFY(table.find(100));
    table.update(sec(352));
    QVERIFY(!table.find(100));  // removed 300 s after it became lost
    QCOMPARE(table.counts().removed, std::uint64_t{1});
    table.update(sec(899));
    QVERIFY(!table.find(200)->lost);
    table.update(sec(901));
    QVERIFY(table.find(200)->lost);
    // AND a lost target that reports again is found
    table.feed(report(200, 18, at(f, 1000, 0), 1.0, 0.0), sec(902));
    QVERIFY(!table.find(200)->lost);
  }

  void longRangeReportsAreCoarseAndSlow() {
    // GIVEN a ship heard only by long-range broadcasts (type 27, every 3 minutes) at 12 kn
    const geo::LocalFrame f(kLat0, kLon0);
    AisTargetTable table;
    table.feed(report(300, 27, at(f, 0, 5000), 12.0, 90.0), sec(0));
    const AisTarget* t = table.find(300);
    QVERIFY(t->longRange);
    QCOMPARE(t->cls, AisClass::A);
    // THEN it is lost by the 3-minute interval, not by a class A ship's 10 s at 12 kn
    QCOMPARE(table.lostAfterS(*t), 900.0);
    table.update(sec(179));
    QVERIFY(!table.find(300)->lost);
    table.feed(report(300, 27, at(f, 600, 5000), 12.0, 90.0), sec(180));
    table.update(sec(200));
    QVERIFY(!table.find(300)->lost);
    // AND once a class A report comes, a type 27 does not replace its finer position while it is fresh
    table.feed(report(300, 1, at(f, 700, 5000), 12.3, 91.0, 91), sec(210));
    QVERIFY(!table.find(300)->longRange);
    QCOMPARE(table.lostAfterS(*table.find(300)), 50.0);
    table.feed(report(300, 27, at(f, 900, 5100), 12.0, 90.0), sec(215));
    t = table.find(300);
    QCOMPARE(*t->sogKn, 12.3);
    QCOMPARE(*t->headingDeg, 91);
    QCOMPARE(t->lastPositionUs, sec(210));
    QCOMPARE(t->reports, std::uint64_t{4});
    // AND a class B "SO" unit that sends type 27 stays class B
    table.feed(report(400, 18, at(f, 0, 0), 5.0, 0.0), sec(0));
    table.update(sec(400));  // lost: the type 27 then takes over
    table.feed(report(400, 27, at(f, 0, 100), 5.0, 0.0), sec(401));
    QCOMPARE(table.find(400)->cls, AisClass::B);
    QVERIFY(table.find(400)->longRange);
    QVERIFY(!table.find(400)->lost);
  }

  void capacityLimitsDropTheFurthestSleepingTargets() {
    // GIVEN room for 10 sleeping and 3 activated targets, filled with ten sleeping ones 1..10 km away
    const geo::LocalFrame f(kLat0, kLon0);
    AisTableLimits limits;
    limits.maxSleeping = 10;
    limits.maxActivated = 3;
    AisTargetTable table(limits);
    for (std::uint32_t i = 1; i <= 10; ++i)
      table.feed(report(i, 1, at(f, 0, 1000.0 * i), 1.0, 180.0), sec(0));
    table.update(sec(0), f, {f.origin(), 0.0, 0.0});
    AisTableCounts c = table.counts();
    QCOMPARE(c.sleeping, std::size_t{10});
    QVERIFY(c.nearCapacity);
    // WHEN a nearer one arrives, THEN the furthest (10 km) is dropped
    table.feed(report(11, 1, at(f, 0, 500.0), 1.0, 180.0), sec(1));
    QVERIFY(table.find(11));
    QVERIFY(!table.find(10));
    QCOMPARE(table.counts().droppedAtCapacity, std::uint64_t{1});
    // WHEN a further one arrives, THEN it is the one not kept
    table.feed(report(12, 1, at(f, 0, 20000.0), 1.0, 180.0), sec(1));
    QVERIFY(!table.find(12));
    QCOMPARE(table.size(), std::size_t{10});
    QCOMPARE(table.counts().droppedAtCapacity, std::uint64_t{2});
    // AND three activations pass, the fourth is refused and counted
    QVERIFY(table.activate(1));
    QVERIFY(table.activate(2));
    QVERIFY(table.activate(3));
    QVERIFY(!table.activate(4));
    QVERIFY(!table.activate(999));  // unknown
    c = table.counts();
    QCOMPARE(c.activated, std::size_t{3});
    QCOMPARE(c.activationRefused, std::uint64_t{1});
    // AND activated targets leave room among the sleeping: a new one is added without a drop
    table.feed(report(13, 1, at(f, 0, 30000.0), 1.0, 180.0), sec(2));
    QVERIFY(table.find(13));
    QCOMPARE(table.counts().droppedAtCapacity, std::uint64_t{2});
    // AND deactivating and selecting work on known targets only
    QVERIFY(table.activate(1, false));
    QVERIFY(!table.find(1)->activated);
    QVERIFY(table.select(2));
    QVERIFY(table.find(2)->selected);
    QVERIFY(table.select(3));
    QVERIFY(!table.find(2)->selected);
    QVERIFY(!table.select(999));
    QVERIFY(table.find(3)->selected);
    // AND a limit of 0 is refused naming the field
    limits.maxActivated = 0;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, AisTargetTable{limits});
  }

  void ownShipIsKeptApart() {
    const geo::LocalFrame f(kLat0, kLon0);
    AisTargetTable table;
    QVERIFY(isOwnShipSentence("!AIVDO,1,1,,,B5NLCa000>fdwc63f?aBKwPUoP06,0*15"));
    QVERIFY(isOwnShipSentence("\\s:base,c:1428796800*5B\\!AIVDO,1,1,,,B5NLCa000>fdwc63f?aBKwPUoP06,0*15"));
    QVERIFY(!isOwnShipSentence("!AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,0*4A"));
    QVERIFY(!isOwnShipSentence("VDO"));
    table.feed(report(366000001, 1, at(f, 0, 0), 8.0, 10.0), sec(0), true);
    table.feed(report(0, 1, at(f, 0, 0), 8.0, 10.0), sec(0));
    QCOMPARE(table.size(), std::size_t{0});
    QVERIFY(table.ownShip());
    QCOMPARE(table.ownShip()->mmsi, 366000001u);
    QCOMPARE(table.counts().ownShipMessages, std::uint64_t{1});
    QCOMPARE(table.counts().invalidMmsi, std::uint64_t{1});
  }

  void alertsFollowTheTable() {
    // GIVEN a dangerous target and a table near capacity
    const geo::LocalFrame f(kLat0, kLon0);
    AisTableLimits limits;
    limits.maxActivated = 1;  // the dangerous one fills it
    AisTargetTable table(limits);
    table.feed(report(211000001, 1, at(f, 0, 3000.0), 10.0, 180.0), sec(0));
    table.feed(report(211000002, 1, at(f, 8000, 8000.0), 10.0, 0.0), sec(0));
    alerts::AlertManager m;
    alerts::AisAlertFeed feed;
    table.update(sec(0), f, {f.origin(), 0.0, 0.0});
    feed.report(m, sec(0), table);
    // THEN an AIS CPA/TCPA alarm for it alone, and the capacity caution (source 1)
    const alerts::Alert* cpa = m.find({alerts::AlertKind::AisCpaTcpa, 211000001});
    QVERIFY(cpa);
    QCOMPARE(cpa->priority, alerts::Priority::Alarm);
    QVERIFY2(cpa->text.find("211000001") != std::string::npos, cpa->text.c_str());
    QVERIFY(!m.find({alerts::AlertKind::AisCpaTcpa, 211000002}));
    QVERIFY(m.find({alerts::AlertKind::Capacity, alerts::kAisCapacitySource}));
    // WHEN the activated target falls silent, THEN LOST AIS TARGET replaces its CPA alarm
    QVERIFY(table.find(211000001)->activated);
    table.feed(report(211000002, 1, at(f, 8000, 8300.0), 10.0, 0.0), sec(60));
    table.update(sec(60), f, {f.origin(), 0.0, 0.0});
    feed.report(m, sec(60), table);
    QVERIFY(m.find({alerts::AlertKind::LostAisTarget, 211000001}));
    QCOMPARE(m.find({alerts::AlertKind::LostAisTarget, 211000001})->priority, alerts::Priority::Warning);
    // (the CPA alert ends when its hysteresis time has passed)
    table.update(sec(90), f, {f.origin(), 0.0, 0.0});
    feed.report(m, sec(90), table);
    QVERIFY(!m.find({alerts::AlertKind::AisCpaTcpa, 211000001}));
  }

  /// GIVEN a table full to both limits (one activated, one sleeping target) WHEN an AIS-SART (MMSI
  /// 970xxyyyy, status 14) reports 1 NM north of own ship, drifting onto it THEN it is added past the
  /// limits, activated, never dangerous, lost after 5 of its 60 s intervals, and raises the distress
  /// alarm (no CPA alarm, though own ship runs onto it), held until acknowledged after it is lost, and it
  /// stays in the table; a MOB in test (status 15, "MOB TEST") raises nothing until its "MOB ACTIVE".
  void searchAndRescueDevicesRaiseTheirAlarm() {
    QCOMPARE(aisDeviceOf(970000000), AisDevice::Sart);
    QCOMPARE(aisDeviceOf(972123456), AisDevice::Mob);
    QCOMPARE(aisDeviceOf(974999999), AisDevice::Epirb);
    QCOMPARE(aisDeviceOf(969999999), AisDevice::None);
    QCOMPARE(aisDeviceOf(971000001), AisDevice::None);
    QCOMPARE(aisDeviceOf(97000000), AisDevice::None);  // 8 digits: a group call, not a device
    QCOMPARE(deviceTestText("SART TEST"), std::optional<bool>(true));
    QCOMPARE(deviceTestText("MOB ACTIVE"), std::optional<bool>(false));
    QCOMPARE(deviceTestText("RCVD YR TEST MSG"), std::optional<bool>(true));
    QCOMPARE(deviceTestText("SART ACTIVE NOT A TEST"), std::optional<bool>(false));
    QVERIFY(!deviceTestText("EP228 IX48"));
    const geo::LocalFrame f(kLat0, kLon0);
    AisTableLimits limits;
    limits.maxActivated = 1;
    limits.maxSleeping = 1;
    AisTargetTable table(limits);
    table.feed(report(211000001, 1, at(f, 3000, 3000), 10.0, 270.0), sec(0));  // dangerous: activated
    table.feed(report(211000002, 1, at(f, 9000, 9000), 10.0, 0.0), sec(0));
    const AisOwnShip own{f.origin(), 0.0, 5.0};  // north at 9.7 kn: onto the SART in 6 minutes
    table.update(sec(0), f, own);
    QVERIFY(table.find(211000001)->activated);
    io::AisMessage sart = report(970012345, 1, at(f, 0, 1852.0), 0.5, 180.0);
    sart.navStatus = 14;
    table.feed(sart, sec(1));
    const AisTarget* t = table.find(970012345);
    QVERIFY(t);
    QCOMPARE(t->device, AisDevice::Sart);
    QVERIFY(t->distress() && t->activated && t->autoActivated);
    QCOMPARE(table.counts().activated, std::size_t{2});  // past the limit of 1
    QCOMPARE(reportingIntervalS(*t), 60.0);
    QCOMPARE(table.lostAfterS(*t), 300.0);
    QVERIFY(!table.activate(970012345, false));  // a distress stays activated
    table.update(sec(1), f, own);
    t = table.find(970012345);
    // Own ship runs onto it within the CPA limits (CPA 0, TCPA 352 s) ...
    QVERIFY(t->cpaValid && t->cpa.cpaM < 10.0 && t->cpa.tcpaS > 300.0 && t->cpa.tcpaS < 400.0);
    QVERIFY(!t->dangerous);  // ... and it is no CPA target
    alerts::AlertManager m;
    alerts::AisAlertFeed feed;
    feed.report(m, sec(1), table);
    const alerts::Alert* a = m.find({alerts::AlertKind::AisDistress, 970012345});
    QVERIFY(a);
    QCOMPARE(a->priority, alerts::Priority::Alarm);
    QVERIFY2(a->text == "AIS-SART 970012345 ACTIVE 1.00 NM bearing 000", a->text.c_str());
    QVERIFY(!m.find({alerts::AlertKind::AisCpaTcpa, 970012345}));  // its alert is the distress alone
    QVERIFY(m.find({alerts::AlertKind::AisCpaTcpa, 211000001}));
    // WHEN a MOB reports in test THEN it is shown (sleeping room made) with no alarm
    io::AisMessage mob = report(972001002, 1, at(f, -500, 0), 0.0, std::nullopt);
    mob.navStatus = 15;
    table.feed(mob, sec(2));
    io::AisMessage text;
    text.type = 14;
    text.mmsi = 972001002;
    text.text = "MOB TEST";
    table.feed(text, sec(3));
    QVERIFY(table.find(972001002));
    QVERIFY(table.find(972001002)->deviceTest && !table.find(972001002)->distress());
    QCOMPARE(table.find(972001002)->safetyText, std::string("MOB TEST"));
    table.update(sec(3), f, own);
    feed.report(m, sec(3), table);
    QVERIFY(!m.find({alerts::AlertKind::AisDistress, 972001002}));
    // WHEN it says MOB ACTIVE THEN it is a distress, activated, with its alarm
    text.text = "MOB ACTIVE";
    table.feed(text, sec(4));
    table.update(sec(4), f, own);
    feed.report(m, sec(4), table);
    QVERIFY(table.find(972001002)->distress() && table.find(972001002)->activated);
    QVERIFY(m.find({alerts::AlertKind::AisDistress, 972001002}));
    // WHEN the SART falls silent 5 intervals THEN it is lost: its alarm is rectified, held until acknowledged
    table.feed(mob, sec(299));  // the MOB's status 15 again, 295 s after its ACTIVE: still a distress
    QVERIFY(table.find(972001002)->distress());
    table.update(sec(302), f, own);
    feed.report(m, sec(302), table);
    QVERIFY(table.find(970012345)->lost);
    QCOMPARE(m.find({alerts::AlertKind::AisDistress, 970012345})->state, alerts::AlertState::Rectified);
    // AND it stays in the table at its last position long after the removal time of other targets
    table.update(sec(3600), f, own);
    QVERIFY(table.find(970012345) && table.find(970012345)->lost);
    QVERIFY(!table.find(211000001));
    QVERIFY(m.find({alerts::AlertKind::LostAisTarget, 970012345}));
    QCOMPARE(m.find({alerts::AlertKind::AisDistress, 972001002})->state, alerts::AlertState::Unacknowledged);
  }

  /// GIVEN a device whose position reports say status 15 (test) while its type 14 says ACTIVE WHEN they
  /// alternate THEN it stays a distress: a test sign counts only 5 minutes after the latest active one.
  void aDeviceSayingBothStaysActiveUntilItHasSaidTestForFiveMinutes() {
    const geo::LocalFrame f(kLat0, kLon0);
    AisTargetTable table;
    io::AisMessage pos = report(974000001, 1, at(f, 0, 1000), 0.2, 90.0);
    pos.navStatus = 15;
    io::AisMessage text;
    text.type = 14;
    text.mmsi = 974000001;
    text.text = "EPIRB ACTIVE";
    table.feed(pos, sec(0));
    QVERIFY(table.find(974000001)->deviceTest);  // test until it says otherwise
    table.feed(text, sec(1));
    for (int k = 0; k < 5; ++k) {
      table.feed(pos, sec(60.0 * k + 2));
      QVERIFY2(table.find(974000001)->distress(), qPrintable(QString::number(k)));
    }
    table.feed(pos, sec(302));  // 301 s after the last ACTIVE
    QVERIFY(table.find(974000001)->deviceTest);
  }

  /// GIVEN a feed of made-up device MMSIs past maxDevices THEN the table holds maxDevices of them: a
  /// device in test or lost gives its place, live distresses never do, the rest are counted and dropped.
  void devicesAreBoundedByTheirOwnLimit() {
    const geo::LocalFrame f(kLat0, kLon0);
    AisTableLimits limits;
    limits.maxDevices = 3;
    AisTargetTable table(limits);
    io::AisMessage test = report(970000001, 1, at(f, 0, 1000), 0.0, std::nullopt);
    test.navStatus = 15;
    table.feed(test, sec(0));
    for (std::uint32_t k = 2; k <= 3; ++k) {
      io::AisMessage d = report(970000000 + k, 1, at(f, 0, 1000.0 * k), 0.0, std::nullopt);
      d.navStatus = 14;
      table.feed(d, sec(k));
    }
    io::AisMessage fourth = report(970000004, 1, at(f, 0, 4000), 0.0, std::nullopt);
    fourth.navStatus = 14;
    table.feed(fourth, sec(5));  // takes the test device's place
    QVERIFY(!table.find(970000001) && table.find(970000004));
    fourth.mmsi = 970000005;
    table.feed(fourth, sec(6));  // every device a live distress: not added
    QVERIFY(!table.find(970000005));
    QCOMPARE(table.size(), std::size_t{3});
    QCOMPARE(table.counts().droppedAtCapacity, std::uint64_t{2});
    table.feed(report(211000001, 1, at(f, 0, 500), 5.0, 0.0), sec(7));  // ships are not held back
    QVERIFY(table.find(211000001));
    limits.maxDevices = 0;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, AisTargetTable{limits});
  }

  /// GIVEN an AIS CPA/TCPA alarm WHEN the limits are changed so that it no longer holds THEN the feed
  /// ends it (a feed made anew, as the live watch did, forgot it: the alarm stayed for ever).
  void newCpaLimitsEndTheAlarmsTheyNoLongerRaise() {
    const geo::LocalFrame f(kLat0, kLon0);
    AisTargetTable table;
    alerts::AlertManager m;
    alerts::AisAlertFeed feed;
    const AisOwnShip own{f.origin(), 0.0, 0.0};
    table.feed(report(211000001, 1, at(f, 0, 3000.0), 10.0, 180.0), sec(0));  // head on, TCPA 5.8 min
    table.update(sec(0), f, own);
    feed.report(m, sec(0), table);
    QVERIFY(m.find({alerts::AlertKind::AisCpaTcpa, 211000001}));
    alerts::CpaAlertLimits tight;
    tight.tcpaS = 60.0;
    feed.setLimits(tight);
    for (int s = 1; s <= 60; ++s) {
      table.feed(report(211000001, 1, at(f, 0, 3000.0 - 5.144 * s), 10.0, 180.0), sec(s));
      table.update(sec(s), f, own);
      feed.report(m, sec(s), table);
    }
    QVERIFY(!m.find({alerts::AlertKind::AisCpaTcpa, 211000001}));
  }

  void realRecordingCountsEveryStation() {
    const QString path = QStringLiteral(RECKONER_SHARED_DIR "/data/ais/gpsd-sample.aivdm");
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) QSKIP(qPrintable(path + " is absent (../shared/data/ais)"));
    // GIVEN the recording's sentences, fed through the decoder into the table one second apart
    io::AisDecoder decoder;
    AisTargetTable table;
    QByteArray vdm;
    TimeUs now = 0;
    while (!file.atEnd()) {
      const QByteArray raw = file.readLine();
      if (raw.startsWith('#')) continue;
      const std::string line = raw.trimmed().toStdString();
      const bool own = isOwnShipSentence(line);
      if (!own) vdm += raw;
      now += kMicrosPerSecond;
      if (auto m = decoder.feed(line, toSeconds(now))) table.feed(*m, now, own);
    }
    const geo::LocalFrame f(48.4, -123.4);
    table.update(now, f, {f.origin(), 1.0, 2.0});
    for (const AisTarget& t : table.targets()) {
      if (!t.rangeValid) continue;
      QVERIFY(std::isfinite(t.rangeM));
      if (t.cpaValid) QVERIFY(std::isfinite(t.cpa.cpaM) && std::isfinite(t.cpa.tcpaS));
    }
    QCOMPARE(table.counts().messages + table.counts().ownShipMessages + table.counts().invalidMmsi,
             decoder.counters().decoded);
    // THEN there is one target per distinct MMSI gpsdecode finds in the message types the table takes
    const QString gpsdecode = QStandardPaths::findExecutable("gpsdecode");
    if (gpsdecode.isEmpty()) QSKIP("gpsdecode (Debian gpsd-clients) is not installed");
    QProcess p;
    p.start(gpsdecode, {"-j", "--split24"});  // each type 24 part as it comes, as the table takes it
    QVERIFY(p.waitForStarted());
    p.write(vdm);
    p.closeWriteChannel();
    QVERIFY(p.waitForFinished(120000));
    std::set<std::uint32_t> mmsis;
    const std::set<int> taken{1, 2, 3, 4, 5, 14, 18, 19, 21, 24, 27};
    for (const QByteArray& l : p.readAllStandardOutput().split('\n')) {
      const QJsonObject o = QJsonDocument::fromJson(l).object();
      if (o.isEmpty() || !taken.contains(o.value("type").toInt())) continue;
      const auto mmsi = static_cast<std::uint32_t>(o.value("mmsi").toDouble());
      if (mmsi != 0) mmsis.insert(mmsi);
    }
    QVERIFY(mmsis.size() > 10);
    for (const AisTarget& t : table.targets())
      if (!mmsis.contains(t.mmsi)) qWarning("a target gpsdecode does not report: %u", t.mmsi);
    QCOMPARE(table.size(), mmsis.size());
    for (const std::uint32_t mmsi : mmsis) QVERIFY2(table.find(mmsi), qPrintable(QString::number(mmsi)));
  }
};

QTEST_GUILESS_MAIN(TestAisTargets)
#include "tst_ais_targets.moc"
