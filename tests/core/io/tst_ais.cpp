// The AIS decoder (core/io/ais.h, docs/ais.md): a real sentence decoded by hand, messages of every
// supported type built bit by bit here (their fields known) and decoded back, not-available values,
// truncated payloads, malformed sentences and fragment floods, and the real recording
// ../shared/data/ais/gpsd-sample.aivdm against the values written in its '#' comment lines.
#include <QFile>
#include <QTest>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "io/ais.h"
#include "support/ais_corpus.h"
#include "support/compare_near.h"

using namespace reckoner::io;
using namespace reckoner::test::ais;

namespace {

std::optional<AisMessage> decodeOne(const std::string& line, AisCounters* counters = nullptr) {
  AisDecoder d;
  auto m = d.feed(line);
  if (counters) *counters = d.counters();
  return m;
}

}  // namespace

class TestAis : public QObject {
  Q_OBJECT
 private slots:
  void decodesARealType1ByHand() {
    // gpsd sample, type 1. Armour: '1'->1 '5'->5 'R'->34 'T'->36 'g'->47 't'->60 ... ('0'..'W' minus 48,
    // '`'..'w' minus 56). Bits 0-5 000001: type 1. Bits 8-37 010110001010010010111111110000 = 371798000.
    // ROT bits 42-49 10000001 = -127 (turning left fast, no rate). SOG bits 50-59 0001111011 = 123 ->
    // 12.3 kn. Lon bits 61-88 = -74037230 / 600000 = -123.3953833. Lat bits 89-115 = 29028980 / 600000
    // = 48.3816333. COG bits 116-127 = 2240 -> 224.0. Heading bits 128-136 = 215.
    const auto m = decodeOne("!AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,0*4A");
    QVERIFY(m.has_value());
    QCOMPARE(m->type, 1);
    QCOMPARE(m->mmsi, 371798000u);
    QVERIFY(!m->rotDegMin.has_value());
    QCOMPARE(m->rotFast, -1);
    RK_COMPARE_NEAR(*m->sogKn, 12.3, 1e-9);
    RK_COMPARE_NEAR(*m->lonDeg, -74037230 / 600000.0, 1e-12);
    RK_COMPARE_NEAR(*m->latDeg, 29028980 / 600000.0, 1e-12);
    RK_COMPARE_NEAR(*m->cogDeg, 224.0, 1e-9);
    QCOMPARE(*m->headingDeg, 215);
    QCOMPARE(*m->navStatus, 0);
  }
  void decodesClassAWithRateOfTurn() {
    // ROT_AIS 64: (64 / 4.733)^2 = 13.52208^2 = 182.8466 deg/min to the right; -20: (20 / 4.733)^2 = 17.856
    // to the left.
    for (const int type : {1, 2, 3}) {
      const auto m = decodeOne(sentence(classA(type, 244740981, 5, 64, 101, 3442480, 31919541, 3599, 359)));
      QVERIFY(m.has_value());
      QCOMPARE(m->type, type);
      QCOMPARE(m->mmsi, 244740981u);
      QCOMPARE(*m->navStatus, 5);
      RK_COMPARE_NEAR(*m->rotDegMin, 182.8466, 1e-3);
      RK_COMPARE_NEAR(*m->sogKn, 10.1, 1e-9);
      RK_COMPARE_NEAR(*m->lonDeg, 5.7374667, 1e-7);
      RK_COMPARE_NEAR(*m->latDeg, 53.199235, 1e-7);
      RK_COMPARE_NEAR(*m->cogDeg, 359.9, 1e-9);
      QCOMPARE(*m->headingDeg, 359);
      QCOMPARE(*m->second, 33);
    }
    const auto left = decodeOne(sentence(classA(1, 1, 0, -20, 0, 0, 0, 0, 0)));
    RK_COMPARE_NEAR(*left->rotDegMin, -17.8561, 1e-3);
    QCOMPARE(decodeOne(sentence(classA(1, 1, 0, 127, 0, 0, 0, 0, 0)))->rotFast, 1);
  }
  void notAvailableValuesAreEmpty() {
    // lat 91 = 0x3412140, lon 181 = 0x6791AC0, SOG 1023, COG 3600, heading 511, ROT -128.
    const auto m = decodeOne(sentence(classA(1, 1, 15, -128, 1023, 0x6791AC0, 0x3412140, 3600, 511)));
    QVERIFY(m.has_value());
    QVERIFY(!m->latDeg && !m->lonDeg && !m->sogKn && !m->cogDeg && !m->headingDeg && !m->rotDegMin);
    QCOMPARE(m->rotFast, 0);
    // Type 27: lon 181 * 600 = 108600, lat 91 * 600 = 54600, SOG 63, COG 511.
    const auto lr = decodeOne(sentence(longRange(108600, 54600, 63, 511)));
    QVERIFY(lr.has_value());
    QVERIFY(!lr->latDeg && !lr->lonDeg && !lr->sogKn && !lr->cogDeg);
  }
  void timeStampsThatAreNotSecondsSayHowThePositionWasMade() {
    // 0-59 a second; 60 not available; 61 manual input, 62 dead reckoning, 63 inoperative (ITU-R
    // M.1371-5 Table 50, gpsd's AIVDM notes): no second, and the position marked as no fix
    for (const auto& [stamp, second, notFix] :
         {std::tuple{59, std::optional<int>(59), std::optional<int>()},
          std::tuple{60, std::optional<int>(), std::optional<int>()},
          std::tuple{61, std::optional<int>(), std::optional<int>(61)},
          std::tuple{62, std::optional<int>(), std::optional<int>(62)},
          std::tuple{63, std::optional<int>(), std::optional<int>(63)}}) {
      const auto m = decodeOne(sentence(classA(1, 244740981, 0, 0, 101, 3442480, 31919541, 900, 90, stamp)));
      QVERIFY(m.has_value());
      QCOMPARE(m->second, second);
      QCOMPARE(m->positionNotFix, notFix);
      QVERIFY(m->latDeg.has_value());  // the position itself is kept
    }
  }
  void decodesBaseStation() {
    const auto m = decodeOne(sentence(baseStation()));
    QVERIFY(m.has_value());
    QCOMPARE(m->mmsi, 3669702u);
    QCOMPARE(*m->year, 2007);
    QCOMPARE(*m->month, 5);
    QCOMPARE(*m->day, 14);
    QCOMPARE(*m->hour, 19);
    QCOMPARE(*m->minute, 57);
    QCOMPARE(*m->utcSecond, 39);
    RK_COMPARE_NEAR(*m->lonDeg, -45811417 / 600000.0, 1e-12);
    RK_COMPARE_NEAR(*m->latDeg, 22130260 / 600000.0, 1e-12);
    QCOMPARE(*m->epfd, 7);
  }
  void decodesStaticAndVoyageInTwoFragments() {
    const auto [payload, fill] = staticVoyage().armoured();
    QCOMPARE(payload.size() * 6 - static_cast<std::size_t>(fill), std::size_t{424});
    AisDecoder d;
    QVERIFY(!d.feed(sentence(payload.substr(0, 60), 0, "2,1,3")).has_value());
    QCOMPARE(d.partialsInFlight(), std::size_t{1});
    const auto m = d.feed(sentence(payload.substr(60), fill, "2,2,3"));
    QVERIFY(m.has_value());
    QCOMPARE(d.partialsInFlight(), std::size_t{0});
    QCOMPARE(*m->imo, 9134270u);
    QCOMPARE(m->callsign, std::string("3FOF8"));
    QCOMPARE(m->name, std::string("EVER DIADEM"));
    QCOMPARE(*m->shipType, 70);
    QCOMPARE(*m->toBowM, 225);
    QCOMPARE(*m->toSternM, 70);
    QCOMPARE(*m->toPortM, 1);
    QCOMPARE(*m->toStarboardM, 31);
    QCOMPARE(*m->epfd, 1);
    QCOMPARE(*m->etaMonth, 5);
    QCOMPARE(*m->etaDay, 15);
    QCOMPARE(*m->etaHour, 14);
    QCOMPARE(*m->etaMinute, 0);
    RK_COMPARE_NEAR(*m->draughtM, 12.2, 1e-9);
    QCOMPARE(m->destination, std::string("NEW YORK"));
  }
  void decodesClassB() {
    const auto b = decodeOne(sentence(classB(18)));
    QVERIFY(b.has_value());
    QCOMPARE(b->mmsi, 338087471u);
    RK_COMPARE_NEAR(*b->sogKn, 0.1, 1e-9);
    RK_COMPARE_NEAR(*b->lonDeg, -44443279 / 600000.0, 1e-12);
    RK_COMPARE_NEAR(*b->latDeg, 24410724 / 600000.0, 1e-12);
    RK_COMPARE_NEAR(*b->cogDeg, 79.6, 1e-9);
    QVERIFY(!b->headingDeg);
    const auto x = decodeOne(sentence(classB(19)));
    QVERIFY(x.has_value());
    QCOMPARE(x->type, 19);
    QCOMPARE(x->name, std::string("CAPT.J.RIMES"));
    QCOMPARE(*x->shipType, 70);
    QCOMPARE(*x->toBowM, 5);
    QCOMPARE(*x->toSternM, 21);
    QCOMPARE(*x->toPortM, 4);
    QCOMPARE(*x->toStarboardM, 4);
  }
  void decodesAidToNavigationWithNameExtension() {
    const auto m = decodeOne(sentence(aidToNavigation("CHINA ROSE MURPHY EX", "PRESS ALERT")));
    QVERIFY(m.has_value());
    QCOMPARE(*m->aidType, 20);
    QCOMPARE(m->name, std::string("CHINA ROSE MURPHY EXPRESS ALERT"));
    RK_COMPARE_NEAR(*m->lonDeg, -73619155 / 600000.0, 1e-12);
    RK_COMPARE_NEAR(*m->latDeg, 28752371 / 600000.0, 1e-12);
    QCOMPARE(*m->toBowM, 5);
    QVERIFY(*m->offPosition);
    QVERIFY(*m->virtualAid);
    const auto shortName = decodeOne(sentence(aidToNavigation("IBC G BUOY", "")));
    QCOMPARE(shortName->name, std::string("IBC G BUOY"));
  }
  void decodesStaticReportParts() {
    const auto a = decodeOne(sentence(staticReport(0)));
    QVERIFY(a.has_value());
    QCOMPARE(*a->part, 'A');
    QCOMPARE(a->name, std::string("PROGUY"));
    const auto b = decodeOne(sentence(staticReport(1)));
    QVERIFY(b.has_value());
    QCOMPARE(*b->part, 'B');
    QCOMPARE(*b->shipType, 60);
    QCOMPARE(b->vendor, std::string("1D0"));
    QCOMPARE(b->callsign, std::string("TC6163"));
    QCOMPARE(*b->toBowM, 0);
    QCOMPARE(*b->toSternM, 15);
    QCOMPARE(*b->toStarboardM, 5);
  }
  void decodesLongRange() {
    // lon 82214 / 600 = 137.0233 deg, lat 2904 / 600 = 4.84 deg, SOG 57 kn, COG 167 deg.
    const auto m = decodeOne(sentence(longRange(82214, 2904, 57, 167)));
    QVERIFY(m.has_value());
    QCOMPARE(m->repeat, 1);
    QCOMPARE(m->mmsi, 206914217u);
    QCOMPARE(*m->navStatus, 2);
    RK_COMPARE_NEAR(*m->lonDeg, 137.0233333, 1e-6);
    RK_COMPARE_NEAR(*m->latDeg, 4.84, 1e-9);
    RK_COMPARE_NEAR(*m->sogKn, 57.0, 1e-9);
    RK_COMPARE_NEAR(*m->cogDeg, 167.0, 1e-9);
    const auto south = decodeOne(sentence(longRange(-82214, -2904, 0, 0)));
    RK_COMPARE_NEAR(*south->lonDeg, -137.0233333, 1e-6);
    RK_COMPARE_NEAR(*south->latDeg, -4.84, 1e-9);
  }
  /// GIVEN type 14 safety-related broadcasts of an AIS-SART, of the longest text and of none WHEN
  /// decoded THEN the text is as sent, at most 161 characters (the 1008 bits of five slots).
  void decodesSafetyBroadcast() {
    const auto m = decodeOne(sentence(safetyBroadcast(970012345, "SART ACTIVE")));
    QVERIFY(m.has_value());
    QCOMPARE(m->type, 14);
    QCOMPARE(m->mmsi, 970012345u);
    QCOMPARE(m->text, std::string("SART ACTIVE"));
    QVERIFY(!m->latDeg && !m->navStatus);
    QCOMPARE(decodeOne(sentence(safetyBroadcast(1, std::string(161, 'W'))))->text, std::string(161, 'W'));
    QCOMPARE(decodeOne(sentence(safetyBroadcast(1, std::string(170, 'W'))))->text, std::string(161, 'W'));
    QCOMPARE(decodeOne(sentence(safetyBroadcast(1, "")))->text, std::string());
  }
  void truncatedPayloadsAreCountedForEveryType_data() {
    QTest::addColumn<int>("which");
    QTest::addColumn<int>("minimum");
    QTest::newRow("1") << 1 << 149;
    QTest::newRow("4") << 4 << 149;
    QTest::newRow("5") << 5 << 420;
    QTest::newRow("14") << 14 << 40;
    QTest::newRow("18") << 18 << 148;
    QTest::newRow("19") << 19 << 306;
    QTest::newRow("21") << 21 << 272;
    QTest::newRow("24A") << 240 << 160;
    QTest::newRow("24B") << 241 << 162;
    QTest::newRow("27") << 27 << 94;
  }
  void truncatedPayloadsAreCountedForEveryType() {
    QFETCH(int, which);
    QFETCH(int, minimum);
    const std::map<int, PayloadBuilder> full{{1, classA(1, 1, 0, 0, 0, 0, 0, 0, 0)},
                                             {4, baseStation()},
                                             {5, staticVoyage()},
                                             {14, safetyBroadcast(1, "SART TEST")},
                                             {18, classB(18)},
                                             {19, classB(19)},
                                             {21, aidToNavigation("A", "")},
                                             {240, staticReport(0)},
                                             {241, staticReport(1)},
                                             {27, longRange(0, 0, 0, 0)}};
    PayloadBuilder p = full.at(which);
    QVERIFY(decodeOne(sentence(PayloadBuilder(p).truncate(static_cast<std::size_t>(minimum)))).has_value());
    AisCounters c;
    QVERIFY(!decodeOne(sentence(p.truncate(static_cast<std::size_t>(minimum - 1))), &c).has_value());
    QCOMPARE(c.tooShort, std::uint64_t{1});
    QVERIFY(!decodeOne(sentence(PayloadBuilder(p).truncate(20)), &c).has_value());
    QCOMPARE(c.tooShort, std::uint64_t{1});
  }
  void malformedSentencesAreCounted() {
    const std::string good = "!AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,0*4A";
    AisDecoder d;
    QVERIFY(d.feed(good).has_value());
    QVERIFY(d.feed(withSum("BSVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,0")).has_value());  // another talker
    d.feed("!AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,0*4B");                            // checksum
    d.feed("!AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,0");                               // no checksum
    d.feed(sentence("15RTgt0PAso;90TKcjM8h6g2X8CQ", 0));                                  // 'X' armour
    d.feed(sentence("15RTgt0PAso;90TKcjM8h6g2x8CQ", 0));                                  // 'x' armour
    d.feed(sentence("15RTgt0PAso;90TKcjM8h6g208CQ", 6));                                  // fill 6
    d.feed(withSum("AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,0,9"));                     // 8 fields
    d.feed(withSum("AIVDM,2,3,,A,15RTgt0PAso;90TKcjM8h6g208CQ,0"));                       // fragment 3 of 2
    d.feed(withSum("AIVDM,1,1,,C,15RTgt0PAso;90TKcjM8h6g208CQ,0"));                       // channel C
    // Found by fuzz_ais: an address field shorter than a talker threw std::out_of_range.
    d.feed(withSum("M,VDO,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,0"));
    d.feed("$GPRMC,123519,A,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,W*6A");
    d.feed("# a comment");
    d.feed(std::string(1 << 20, 'A'));                                // a 1 MB line
    d.feed(sentence("H42O55i18tMET00000000000000", 2).substr(0, 5));  // cut short
    const AisCounters& c = d.counters();
    QCOMPARE(c.decoded, std::uint64_t{2});
    QCOMPARE(c.badChecksum, std::uint64_t{2});
    QCOMPARE(c.badArmour, std::uint64_t{2});
    QCOMPARE(c.badFill, std::uint64_t{1});
    QCOMPARE(c.malformed, std::uint64_t{4});
    QCOMPARE(c.notAis, std::uint64_t{3});
    QCOMPARE(c.tooLong, std::uint64_t{1});
    QCOMPARE(c.lines, std::uint64_t{15});
  }
  void unsupportedTypesAreCounted() {
    AisCounters c;
    QVERIFY(!decodeOne("!AIVDM,1,1,,A,702R5`hwCjq8,0*6B", &c).has_value());  // type 7
    QCOMPARE(c.unsupportedType, std::uint64_t{1});
  }
  void fragmentsOutOfOrderOrAloneAreOrphans() {
    const auto [payload, fill] = staticVoyage().armoured();
    const std::string first = sentence(payload.substr(0, 60), 0, "2,1,3");
    const std::string second = sentence(payload.substr(60), fill, "2,2,3");
    AisDecoder d;
    QVERIFY(!d.feed(second).has_value());  // no first part
    QCOMPARE(d.counters().orphanFragments, std::uint64_t{1});
    d.feed(first);
    d.feed(first);  // the first again: the earlier partial never finished
    QCOMPARE(d.counters().orphanFragments, std::uint64_t{2});
    QVERIFY(d.feed(second).has_value());
    // Three parts given 1, 3, 2: the partial is discarded at 3, and 2 then has no partial.
    const std::string p1 = sentence(payload.substr(0, 30), 0, "3,1,4"),
                      p2 = sentence(payload.substr(30, 30), 0, "3,2,4"),
                      p3 = sentence(payload.substr(60), fill, "3,3,4");
    QVERIFY(!d.feed(p1) && !d.feed(p3) && !d.feed(p2));
    QCOMPARE(d.counters().orphanFragments, std::uint64_t{4});
    QCOMPARE(d.partialsInFlight(), std::size_t{0});
    QVERIFY(!d.feed(p1) && !d.feed(p2) && d.feed(p3));
    // Another channel is another message.
    QVERIFY(!d.feed(first) && !d.feed(sentence(payload.substr(60), fill, "2,2,3", 'B')));
    QCOMPARE(d.partialsInFlight(), std::size_t{1});
  }
  void oldPartialsExpire() {
    const auto [payload, fill] = staticVoyage().armoured();
    const std::string first = sentence(payload.substr(0, 60), 0, "2,1,3");
    const std::string second = sentence(payload.substr(60), fill, "2,2,3");
    AisDecoder byLines(AisDecoder::Limits{5, 1e9, kAisMaxPartials});
    byLines.feed(first);
    for (int i = 0; i < 5; ++i) byLines.feed("noise");
    QVERIFY(!byLines.feed(second).has_value());
    QCOMPARE(byLines.counters().expiredPartials, std::uint64_t{1});
    QCOMPARE(byLines.counters().orphanFragments, std::uint64_t{1});
    AisDecoder byTime(AisDecoder::Limits{1000, 10.0, kAisMaxPartials});
    byTime.feed(first, 100.0);
    QVERIFY(byTime.feed(second, 109.0).has_value());
    byTime.feed(first, 200.0);
    QVERIFY(!byTime.feed(second, 211.0).has_value());
    QCOMPARE(byTime.counters().expiredPartials, std::uint64_t{1});
  }
  void aFloodOfFirstFragmentsStaysBounded() {
    AisDecoder d;
    const std::string channels = "AB12";
    for (int i = 0; i < 10000; ++i) {
      const std::string frag = std::to_string(2 + i % 8) + ",1," + std::to_string(i / 8 % 10);
      d.feed(sentence("55?MbV02;H;s<HtKR20EHE:0@T4@Dn2222222216L961O5Gf0NSQEp6ClRp8", 0, frag,
                      channels[static_cast<std::size_t>(i / 80 % 4)]));
      QVERIFY(d.partialsInFlight() <= kAisMaxPartials);
    }
    const AisCounters& c = d.counters();
    QCOMPARE(d.partialsInFlight(), kAisMaxPartials);
    QCOMPARE(c.orphanFragments + c.expiredPartials + c.evictedPartials + d.partialsInFlight(),
             std::uint64_t{10000});
    QVERIFY(c.evictedPartials > 0);
    QCOMPARE(c.decoded, std::uint64_t{0});
  }
  void realRecordingMatchesItsComments();
};

namespace {

std::string key(const std::string& k) {
  std::string out;
  for (const char c : k)
    if (c != ' ' && c != '_') out.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  return out;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t|"), e = s.find_last_not_of(" \t|");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

/// Compares one comment value with the decode; false when the key is not one checked. The keys and
/// units are those of the recording's comments ("Speed Over Ground" and "Course Over Ground" there in
/// 1/10 units, "SOG" and "COG" in knots and degrees). ETA is not checked here: the type 5 comment's
/// ETAhour 16 comes from another decoder, gpsd's own decode gives 14 (tst_ais_cli compares ETA with
/// gpsdecode).
/// 1 when the value matches, 0 when it does not, -1 for a key not checked.
int checkField(const std::string& k, const std::string& v, const AisMessage& m) {
  const double x = std::atof(v.c_str());
  const auto near = [&](const std::optional<double>& got, double want, double tol) {
    return got && std::abs(*got - want) <= tol;
  };
  const auto intOpt = [&](const std::optional<int>& got, int na) {
    return static_cast<int>(x) == na ? !got.has_value() : got && *got == static_cast<int>(x);
  };
  bool ok = true;
  if (k == "userid" || k == "mmsi")
    ok = m.mmsi == static_cast<std::uint32_t>(x);
  else if (k == "longitude" || k == "positionlongitude")
    ok = near(m.lonDeg, x, 1e-6);
  else if (k == "latitude" || k == "positionlatitude")
    ok = near(m.latDeg, x, 1e-6);
  else if (k == "sog")
    ok = near(m.sogKn, x, 1e-9);
  else if (k == "speedoverground")
    ok = near(m.sogKn, x / 10, 1e-9);
  else if (k == "cog")
    ok = near(m.cogDeg, x, 1e-9);
  else if (k == "courseoverground")
    ok = near(m.cogDeg, x / 10, 1e-9);
  else if (k == "trueheading")
    ok = intOpt(m.headingDeg, 511);
  else if (k == "navigationstatus")
    ok = intOpt(m.navStatus, -1);
  else if (k == "rot")
    ok = x == -128            ? !m.rotDegMin && m.rotFast == 0
         : std::abs(x) == 127 ? m.rotFast == (x > 0 ? 1 : -1)
                              : near(m.rotDegMin, (x < 0 ? -1 : 1) * (x / 4.733) * (x / 4.733), 1e-9);
  else if (k == "name")
    ok = m.name == trim(v);
  else if (k == "callsign")
    ok = m.callsign == trim(v);
  else if (k == "destination")
    ok = m.destination == trim(v);
  else if (k == "imonumber")
    ok = m.imo && *m.imo == static_cast<std::uint32_t>(x);
  else if (k == "shipandcargo")
    ok = intOpt(m.shipType, 0);
  else if (k == "dima")
    ok = intOpt(m.toBowM, -1);
  else if (k == "dimb")
    ok = intOpt(m.toSternM, -1);
  else if (k == "dimc")
    ok = intOpt(m.toPortM, -1);
  else if (k == "dimd")
    ok = intOpt(m.toStarboardM, -1);
  else if (k == "draught")
    ok = near(m.draughtM, x, 1e-9);
  else if (k == "timeyear")
    ok = intOpt(m.year, 0);
  else if (k == "timehour")
    ok = intOpt(m.hour, 24);
  else if (k == "timesec")
    ok = intOpt(m.utcSecond, 60);
  else if (k == "aidtype")
    ok = intOpt(m.aidType, -1);
  else if (k == "text")
    ok = m.text == trim(v);
  else
    return -1;
  if (!ok) qWarning("type %d mmsi %u: %s is %s", m.type, m.mmsi, k.c_str(), v.c_str());
  return ok ? 1 : 0;
}

}  // namespace

void TestAis::realRecordingMatchesItsComments() {
  const QString path = QStringLiteral(RECKONER_SHARED_DIR "/data/ais/gpsd-sample.aivdm");
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) QSKIP(qPrintable(path + " is absent (../shared/data/ais)"));
  AisDecoder d;
  std::optional<AisMessage> last;
  std::map<int, int> checkedPerType;
  while (!f.atEnd()) {
    const std::string line = f.readLine().toStdString();
    if (line.rfind('#', 0) == 0 && last) {
      const auto colon = line.find(':');
      if (colon == std::string::npos) continue;
      const std::string k = key(line.substr(1, colon - 1));
      const int result =
          checkField(k, trim(line.substr(colon + 1, line.find_last_not_of("\r\n") - colon)), *last);
      QVERIFY2(result != 0, k.c_str());
      if (result > 0) ++checkedPerType[last->type];
      continue;
    }
    if (line.rfind('#', 0) != 0) last = d.feed(line);
  }
  for (const int type : {1, 2, 3, 4, 5, 18, 19, 21, 24}) {
    qInfo("type %d: %d comment values checked", type, checkedPerType[type]);
    QVERIFY2(checkedPerType[type] >= 5, qPrintable(QString::number(type)));
  }
  QVERIFY(checkedPerType[14] >= 2);  // the MMSI and the text of the commented type 14
  QCOMPARE(d.counters().decoded, std::uint64_t{31});
}

QTEST_APPLESS_MAIN(TestAis)
#include "tst_ais.moc"
