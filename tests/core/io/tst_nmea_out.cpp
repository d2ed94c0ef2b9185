// The NMEA 0183 encoders of io/nmea_out.h against docs/outputs.md ("NMEA 0183 output"): every sentence
// passes its checksum, stays within 82 characters, and is read back field by field, by Reckoner's own
// reader (io/nmea.h parse) for RMC, GGA, VTG, HDT and GST and by field number for TTM, TLL, OSD, ALR,
// ALF and ALC; reserved characters in text are escaped; the error ellipse of a covariance is right.
#include <QTest>

#include <cmath>

#include "io/nmea.h"
#include "io/nmea_out.h"
#include "support/compare_near.h"

using namespace reckoner;
using namespace reckoner::io::nmea;

namespace {

// 2026-03-04T05:06:07.89Z
constexpr UtcUs kUtc = (20516LL * 86400LL + 5 * 3600 + 6 * 60 + 7) * 1000000LL + 890000;

std::vector<std::string> fieldsOf(const std::string& line) {
  const auto f = checkedFields(line);
  if (!f) qFatal("checksum or framing wrong: %s", line.c_str());
  if (line.size() > kMaxSentenceChars) qFatal("longer than 80 characters: %s", line.c_str());
  return *f;
}

template <class T>
T parsed(const std::string& line) {
  const ParseResult r = parse(line);
  if (!r.sentence) qFatal("not read back: %s (%s)", line.c_str(), r.reason.c_str());
  return std::get<T>(r.sentence->body);
}

}  // namespace

class TestNmeaOut : public QObject {
  Q_OBJECT
 private slots:
  void timeAndPositionFields() {
    QCOMPARE(nmeaTime(kUtc), std::string("050607.89"));
    QCOMPARE(nmeaDate(kUtc), std::string("040326"));
    QCOMPARE(nmeaLatitude(-33.5), std::string("3330.000000,S"));
    QCOMPARE(nmeaLongitude(-0.5), std::string("00030.000000,W"));
    QCOMPARE(nmeaLongitude(179.9999999999), std::string("18000.000000,E"));  // never 60 minutes
  }

  void rmcReadBackWithModeAndStatus() {
    // GIVEN a fix WHEN encoded with mode A THEN status A; with mode E (dead reckoning) status A too, the
    // mode saying it is no GNSS fix; with N status V.
    const std::string a = rmc("IN", {kUtc, 47.123456789, -122.5, 12.34, 359.996, 'A'});
    const auto f = fieldsOf(a);
    QCOMPARE(f[0], std::string("INRMC"));
    QCOMPARE(f.size(), std::size_t(13));
    QCOMPARE(f[1], std::string("050607.89"));
    QCOMPARE(f[2], std::string("A"));
    QCOMPARE(f[8], std::string("0.00"));  // 359.996 rounds to 360.00: written 0.00
    QCOMPARE(f[9], std::string("040326"));
    QCOMPARE(f[12], std::string("A"));
    const Rmc r = parsed<Rmc>(a);
    QVERIFY(r.valid);
    RK_COMPARE_NEAR(r.latDeg, 47.123456789, 1e-7);
    RK_COMPARE_NEAR(r.lonDeg, -122.5, 1e-9);
    RK_COMPARE_NEAR(*r.sogKn, 12.34, 1e-9);
    QCOMPARE(*r.mode, 'A');
    QVERIFY(gnssFix(r.mode));
    const Rmc e = parsed<Rmc>(rmc("IN", {kUtc, 47.0, 8.0, 5.0, 90.0, 'E'}));
    QVERIFY(e.valid);
    QCOMPARE(*e.mode, 'E');
    QVERIFY(!gnssFix(e.mode));
    QVERIFY(!parsed<Rmc>(rmc("IN", {kUtc, 47.0, 8.0, 5.0, 90.0, 'N'})).valid);
  }

  void ggaQuality() {
    GgaOut g;
    g.utc = kUtc;
    g.latDeg = -12.25;
    g.lonDeg = 130.75;
    g.quality = 6;
    const std::string line = gga("IN", g);
    const auto f = fieldsOf(line);
    QCOMPARE(f.size(), std::size_t(15));
    QCOMPARE(f[6], std::string("6"));
    QCOMPARE(f[7], std::string(""));
    QCOMPARE(f[10], std::string("M"));
    const Gga r = parsed<Gga>(line);
    QCOMPARE(r.quality, 6);
    QVERIFY(!gnssFix(r.quality));
    RK_COMPARE_NEAR(r.latDeg, -12.25, 1e-9);
    RK_COMPARE_NEAR(r.lonDeg, 130.75, 1e-9);
    RK_COMPARE_NEAR(r.timeOfDayS, 5 * 3600 + 6 * 60 + 7.89, 1e-6);
  }

  void vtgHdtGst() {
    const std::string v = vtg("IN", {271.5, 10.0, 'E'});
    const auto f = fieldsOf(v);
    QCOMPARE(f.size(), std::size_t(10));
    QCOMPARE(f[2], std::string("T"));
    QCOMPARE(f[7], std::string("18.52"));
    QCOMPARE(f[9], std::string("E"));
    const Vtg r = parsed<Vtg>(v);
    RK_COMPARE_NEAR(*r.cogTrueDeg, 271.5, 1e-9);
    RK_COMPARE_NEAR(r.sogKn, 10.0, 1e-9);
    QCOMPARE(*r.mode, 'E');
    RK_COMPARE_NEAR(parsed<Hdt>(hdt("IN", -0.5)).headingDeg, 359.5, 1e-9);  // wrapped into [0, 360)

    GstOut g;
    g.utc = kUtc;
    g.majorSdM = 12.5;
    g.minorSdM = 3.25;
    g.majorOrientationDeg = 45.0;
    g.latSdM = 9.0;
    g.lonSdM = 9.5;
    const std::string line = gst("IN", g);
    const auto gf = fieldsOf(line);
    QCOMPARE(gf.size(), std::size_t(9));
    QCOMPARE(gf[2], std::string(""));  // rms of the range inputs: not a filter's figure
    QCOMPARE(gf[8], std::string(""));  // altitude: not estimated
    const Gst r2 = parsed<Gst>(line);
    RK_COMPARE_NEAR(*r2.majorSdM, 12.5, 1e-9);
    RK_COMPARE_NEAR(*r2.minorSdM, 3.25, 1e-9);
    RK_COMPARE_NEAR(*r2.majorOrientationDeg, 45.0, 1e-9);
    RK_COMPARE_NEAR(*r2.latSdM, 9.0, 1e-9);
    RK_COMPARE_NEAR(*r2.lonSdM, 9.5, 1e-9);
    QVERIFY(!r2.rmsM);
  }

  void errorEllipseOfCovariance() {
    // North-south only: orientation 0; east-west: 90; a 45 degree ellipse from the cross term.
    ErrorEllipse e = errorEllipse(100.0, 4.0, 0.0);
    RK_COMPARE_NEAR(e.majorSdM, 10.0, 1e-12);
    RK_COMPARE_NEAR(e.minorSdM, 2.0, 1e-12);
    RK_COMPARE_NEAR(e.orientationDeg, 0.0, 1e-12);
    e = errorEllipse(4.0, 100.0, 0.0);
    RK_COMPARE_NEAR(e.orientationDeg, 90.0, 1e-12);
    // Axes (sd 10 along 45 deg, sd 2 along 135 deg): C = R diag(100, 4) R^T, c_ne = (100 - 4) / 2.
    e = errorEllipse(52.0, 52.0, 48.0);
    RK_COMPARE_NEAR(e.majorSdM, 10.0, 1e-12);
    RK_COMPARE_NEAR(e.minorSdM, 2.0, 1e-12);
    RK_COMPARE_NEAR(e.orientationDeg, 45.0, 1e-12);
    e = errorEllipse(52.0, 52.0, -48.0);
    RK_COMPARE_NEAR(e.orientationDeg, 135.0, 1e-12);
  }

  void ttmFieldByField() {
    TtmOut t;
    t.number = 7;
    t.distanceNm = 3.4567;
    t.bearingDeg = 359.96;
    t.speedKn = 11.5;
    t.courseDeg = 180.25;
    t.cpaNm = 0.5;
    t.tcpaMin = -3.25;
    t.name = "TRK12";
    t.status = 'Q';
    t.utc = kUtc;
    t.acquisition = 'M';
    const auto f = fieldsOf(ttm("RA", t));
    QCOMPARE(f.size(), std::size_t(16));
    QCOMPARE(f[0], std::string("RATTM"));
    QCOMPARE(f[1], std::string("07"));
    QCOMPARE(f[2], std::string("3.457"));
    QCOMPARE(f[3], std::string("0.0"));  // 359.96 -> 360.0 -> 0.0
    QCOMPARE(f[4], std::string("T"));
    QCOMPARE(f[5], std::string("11.50"));
    QCOMPARE(f[6], std::string("180.2"));
    QCOMPARE(f[7], std::string("T"));
    QCOMPARE(f[8], std::string("0.500"));
    QCOMPARE(f[9], std::string("-3.25"));
    QCOMPARE(f[10], std::string("N"));
    QCOMPARE(f[11], std::string("TRK12"));
    QCOMPARE(f[12], std::string("Q"));
    QCOMPARE(f[13], std::string(""));
    QCOMPARE(f[14], std::string("050607.89"));
    QCOMPARE(f[15], std::string("M"));
    // Without relative motion CPA and TCPA are empty, never a number.
    t.cpaNm.reset();
    t.tcpaMin.reset();
    const auto g = fieldsOf(ttm("RA", t));
    QCOMPARE(g[8], std::string(""));
    QCOMPARE(g[9], std::string(""));
  }

  void tllAndOsd() {
    const auto f = fieldsOf(tll("RA", {42, -45.5, 170.25, "TRK3", kUtc, 'L', false}));
    QCOMPARE(f.size(), std::size_t(10));
    QCOMPARE(f[1], std::string("42"));
    QCOMPARE(f[2], std::string("4530.000000"));
    QCOMPARE(f[3], std::string("S"));
    QCOMPARE(f[4], std::string("17015.000000"));
    QCOMPARE(f[5], std::string("E"));
    QCOMPARE(f[6], std::string("TRK3"));
    QCOMPARE(f[7], std::string("050607.89"));
    QCOMPARE(f[8], std::string("L"));
    QCOMPARE(f[9], std::string(""));

    OsdOut o;
    o.headingTrueDeg = 12.3;
    o.courseTrueDeg = 14.5;
    o.speedKn = 9.87;
    o.setTrueDeg = 200.0;
    o.driftKn = 0.75;
    const auto g = fieldsOf(osd("RA", o));
    QCOMPARE(g.size(), std::size_t(10));
    QCOMPARE(g[1], std::string("12.3"));
    QCOMPARE(g[2], std::string("A"));
    QCOMPARE(g[3], std::string("14.5"));
    QCOMPARE(g[4], std::string("P"));
    QCOMPARE(g[5], std::string("9.87"));
    QCOMPARE(g[6], std::string("P"));
    QCOMPARE(g[7], std::string("200.0"));
    QCOMPARE(g[8], std::string("0.75"));
    QCOMPARE(g[9], std::string("N"));
    o.headingTrueDeg.reset();
    const auto h = fieldsOf(osd("RA", o));
    QCOMPARE(h[1], std::string(""));
    QCOMPARE(h[2], std::string("V"));
  }

  void alertsFieldByField() {
    const auto r = fieldsOf(alr("IN", {kUtc, 205, true, false, "CPA/TCPA: track 5, CPA 0.2 NM"}));
    QCOMPARE(r.size(), std::size_t(6));
    QCOMPARE(r[1], std::string("050607.89"));
    QCOMPARE(r[2], std::string("205"));
    QCOMPARE(r[3], std::string("A"));
    QCOMPARE(r[4], std::string("V"));
    QCOMPARE(r[5], std::string("CPA/TCPA: track 5^2C CPA 0.2 NM"));  // the comma escaped

    AlfOut a;
    a.sequence = 3;
    a.utc = kUtc;
    a.category = 'A';
    a.priority = 'A';
    a.state = 'S';
    a.manufacturer = "RKN";
    a.identifier = 1001;
    a.instance = 6;
    a.revision = 2;
    a.escalation = 1;
    a.title = "POSITION SOURCE LOST";  // longer than 16: cut
    a.description = std::string(200, 'x');
    const auto lines = alf("IN", a);
    QCOMPARE(lines.size(), std::size_t(2));
    const auto f1 = fieldsOf(lines[0]), f2 = fieldsOf(lines[1]);
    QCOMPARE(f1.size(), std::size_t(14));
    QCOMPARE(f1[1], std::string("2"));
    QCOMPARE(f1[2], std::string("1"));
    QCOMPARE(f1[3], std::string("3"));
    QCOMPARE(f1[4], std::string("050607.89"));
    QCOMPARE(f1[5], std::string("A"));
    QCOMPARE(f1[6], std::string("A"));
    QCOMPARE(f1[7], std::string("S"));
    QCOMPARE(f1[8], std::string("RKN"));
    QCOMPARE(f1[9], std::string("1001"));
    QCOMPARE(f1[10], std::string("6"));
    QCOMPARE(f1[11], std::string("2"));
    QCOMPARE(f1[12], std::string("1"));
    QCOMPARE(f1[13], std::string("POSITION SOURCE "));
    QCOMPARE(f2[2], std::string("2"));
    QCOMPARE(f2[3], std::string("3"));
    QCOMPARE(f2[4], std::string(""));
    QCOMPARE(f2[7], std::string(""));
    QCOMPARE(f2[9], std::string("1001"));
    QVERIFY(!f2[13].empty());
    QCOMPARE(f2[13].find_first_not_of('x'), std::string::npos);
    QCOMPARE(lines[1].size(), kMaxSentenceChars);  // the description cut to the longest sentence

    a.description.clear();
    QCOMPARE(alf("IN", a).size(), std::size_t(1));
    QCOMPARE(fieldsOf(alf("IN", a)[0])[1], std::string("1"));
  }

  void alertListSplitsAcrossSentences() {
    std::vector<AlcEntry> entries;
    for (int i = 0; i < 12; ++i) entries.push_back({"RKN", 1001 + i % 9, i + 1, 1 + i % 3});
    const auto lines = alc("IN", 4, entries);
    QVERIFY(lines.size() > 1);
    int seen = 0;
    for (std::size_t k = 0; k < lines.size(); ++k) {
      const auto f = fieldsOf(lines[k]);
      QCOMPARE(std::stoi(f[1]), static_cast<int>(lines.size()));
      QCOMPARE(std::stoi(f[2]), static_cast<int>(k + 1));
      QCOMPARE(f[3], std::string("4"));
      const int n = std::stoi(f[4]);
      QCOMPARE(f.size(), std::size_t(5 + 4 * n));
      for (int e = 0; e < n; ++e, ++seen) {
        QCOMPARE(f[5 + 4 * e], std::string("RKN"));
        QCOMPARE(std::stoi(f[6 + 4 * e]), 1001 + seen % 9);
        QCOMPARE(std::stoi(f[7 + 4 * e]), seen + 1);
        QCOMPARE(std::stoi(f[8 + 4 * e]), 1 + seen % 3);
      }
    }
    QCOMPARE(seen, 12);
    const auto none = alc("IN", 0, {});
    QCOMPARE(none.size(), std::size_t(1));
    QCOMPARE(fieldsOf(none[0]).size(), std::size_t(5));
    QCOMPARE(fieldsOf(none[0])[4], std::string("00"));
  }

  void escapingAndBadChecksums() {
    QCOMPARE(escapeText("a,b*c$d!e\\f^g~h\ri", 100), std::string("a^2Cb^2Ac^24d^21e^5Cf^5Eg^7Eh^0Di"));
    QCOMPARE(escapeText("ab,", 4), std::string("ab"));  // never half an escape
    std::string line = hdt("HE", 10.0);
    QVERIFY(checkedFields(line));
    QVERIFY(checkedFields(line + "\r\n"));
    line[3] = 'X';
    QVERIFY(!checkedFields(line));
    QVERIFY(!checkedFields("$HEHDT,10.0,T"));
    QVERIFY(!checkedFields("HEHDT,10.0,T*00"));
    QVERIFY(!checkedFields("$HEHDT,10.0,T*ZZ"));
    QVERIFY(!checkedFields(""));
  }
};

QTEST_GUILESS_MAIN(TestNmeaOut)
#include "tst_nmea_out.moc"
