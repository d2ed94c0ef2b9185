// The NMEA 0183 encoders of io/nmea_out.h against docs/outputs.md ("NMEA 0183 output"): every sentence
// passes its checksum, stays within 82 characters, and is read back field by field, by Reckoner's own
// reader (io/nmea.h parse) for RMC, GGA, VTG, HDT and GST and by field number for TTM, TLL, OSD, ALR,
// ALF and ALC; XTE, RMB and APB by field number too, split by a reader written here (its own checksum
// and field split) and accepted by Reckoner's reader as well-framed sentences of a type it does not
// read; reserved characters in text are escaped; the error ellipse of a covariance is right.
#include <QTest>

#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "io/nmea.h"
#include "io/nmea_out.h"
#include "support/compare_near.h"

using namespace reckoner;
using namespace reckoner::io::nmea;

namespace {

// 2026-03-04T05:06:07.89Z
constexpr UtcUs kUtc = (20516LL * 86400LL + 5LL * 3600 + 6LL * 60 + 7) * 1000000LL + 890000;

std::vector<std::string> fieldsOf(const std::string& line) {
  const auto f = checkedFields(line);
  if (!f) qFatal("checksum or framing wrong: %s", line.c_str());
  if (line.size() > kMaxSentenceChars) qFatal("longer than 80 characters: %s", line.c_str());
  return *f;
}

/// The fields of a route-following sentence as a reader that shares no code with io/ sees them: '$',
/// the XOR checksum of everything between '$' and '*' equal to the two hex digits after '*', at most 80
/// characters, then a plain split at every comma. Also checks that Reckoner's reader takes the line as
/// a well-framed sentence (checksum and address right) of a type it does not read.
std::vector<std::string> independentFields(const std::string& line) {
  if (line.empty() || line[0] != '$') qFatal("no '$': %s", line.c_str());
  const std::size_t star = line.find('*');
  if (star == std::string::npos || star + 3 != line.size()) qFatal("no checksum: %s", line.c_str());
  unsigned sum = 0;
  for (std::size_t i = 1; i < star; ++i) sum ^= static_cast<unsigned char>(line[i]);
  if (sum != std::stoul(line.substr(star + 1), nullptr, 16)) qFatal("checksum wrong: %s", line.c_str());
  if (line.size() > 80) qFatal("longer than 80 characters: %s", line.c_str());
  if (parse(line).error != Error::Unknown) qFatal("Reckoner's reader refuses: %s", line.c_str());
  std::vector<std::string> out;
  std::istringstream body(line.substr(1, star - 1));
  std::string field;
  while (std::getline(body, field, ',')) out.push_back(field);
  if (line[star - 1] == ',') out.emplace_back();  // getline drops a last empty field
  if (out != fieldsOf(line)) qFatal("the two readers disagree: %s", line.c_str());
  return out;
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

  void ttmNeverLongerThan82Characters() {
    // GIVEN the longest values a run can give: a track number of eight digits, a TCPA of 33,000 minutes
    // (a slow closing speed), a distance and speed beyond any radar's
    TtmOut t;
    t.number = 42;
    t.distanceNm = 1.0e6;
    t.bearingDeg = 359.9;
    t.speedKn = 5000.0;
    t.courseDeg = 359.9;
    t.cpaNm = 12345.678;
    t.tcpaMin = -33000.0;
    t.name = "TRK12345678";
    t.status = 'T';
    t.utc = kUtc;
    t.acquisition = 'A';
    const std::string line = ttm("RA", t);
    // THEN the sentence with CR LF is at most 82 characters, the numbers at their bounds, the name cut
    QVERIFY2(line.size() + 2 <= 82, line.c_str());
    const auto f = fieldsOf(line);
    QCOMPARE(f.size(), std::size_t(16));
    QCOMPARE(f[2], std::string("999.999"));
    QCOMPARE(f[5], std::string("999.99"));
    QCOMPARE(f[8], std::string("999.999"));
    QCOMPARE(f[9], std::string("-9999.99"));
    QVERIFY2(!f[11].empty() && std::string("TRK12345678").starts_with(f[11]), f[11].c_str());
    QVERIFY(f[11].size() < 11);
    // AND an ordinary line keeps the whole name of a five-digit track id (a day of clutter's tentative
    // tracks), while one of eight digits is cut even there (81 characters with it)
    t.distanceNm = 3.2;
    t.speedKn = 12.0;
    t.cpaNm = 0.4;
    t.tcpaMin = 12.5;
    QVERIFY(fieldsOf(ttm("RA", t))[11].size() < 11);
    t.name = "TRK12345";
    QCOMPARE(fieldsOf(ttm("RA", t))[11], std::string("TRK12345"));
  }

  void tllOfAnUnknownPositionHasEmptyFields() {
    // A track whose estimate is not finite (a diverged filter) or out of range: empty fields, never "nan"
    for (const auto& [lat, lon] :
         {std::pair{std::nan(""), 10.0}, std::pair{10.0, std::numeric_limits<double>::infinity()},
          std::pair{95.0, 200.0}}) {
      const std::string line = tll("RA", {7, lat, lon, "TRK7", kUtc, 'T', false});
      QVERIFY2(line.find("nan") == std::string::npos && line.find("inf") == std::string::npos, line.c_str());
      const auto f = fieldsOf(line);
      QCOMPARE(f.size(), std::size_t(10));
      if (!std::isfinite(lat) || std::abs(lat) > 90.0) {
        QCOMPARE(f[2], std::string(""));
        QCOMPARE(f[3], std::string(""));
      }
      if (!std::isfinite(lon) || std::abs(lon) > 180.0) {
        QCOMPARE(f[4], std::string(""));
        QCOMPARE(f[5], std::string(""));
      }
    }
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
    entries.reserve(12);
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

  void latLonMinuteDecimals() {
    QCOMPARE(nmeaLatitude(49.0 + 17.24 / 60.0, 4), std::string("4917.2400,N"));
    QCOMPARE(nmeaLongitude(-(123.0 + 9.57 / 60.0), 4), std::string("12309.5700,W"));
    QCOMPARE(nmeaLatitude(10.9999995, 4), std::string("1100.0000,N"));  // never 60 minutes at 4 decimals
    QCOMPARE(nmeaLatitude(10.999999, 4), std::string("1059.9999,N"));
    QCOMPARE(nmeaLatitude(-0.5, 0), std::string("0030,S"));
  }

  void xteFieldByField() {
    // GIVEN own ship 0.256 NM left of the track WHEN encoded THEN steer R, 2 decimals, checksum known.
    const std::string line = xte("IN", {0.256, true, true, 'A'});
    QCOMPARE(line, std::string("$INXTE,A,A,0.26,R,N,A*09"));
    auto f = independentFields(line);
    QCOMPARE(f.size(), std::size_t(7));
    QCOMPARE(f[0], std::string("INXTE"));
    QCOMPARE(f[1], std::string("A"));  // Loran-C blink / general warning flag
    QCOMPARE(f[2], std::string("A"));  // Loran-C cycle lock
    QCOMPARE(f[3], std::string("0.26"));
    QCOMPARE(f[4], std::string("R"));
    QCOMPARE(f[5], std::string("N"));
    QCOMPARE(f[6], std::string("A"));
    // Right of the track (the sign of the magnitude is ignored), dead reckoning: status A, mode E.
    f = independentFields(xte("IN", {-1.5, false, true, 'E'}));
    QCOMPARE(f[1], std::string("A"));
    QCOMPARE(f[3], std::string("1.50"));
    QCOMPARE(f[4], std::string("L"));
    QCOMPARE(f[6], std::string("E"));
    // Simulator mode: valid data, but not a position to steer on: status V, the mode kept.
    f = independentFields(xte("IN", {0.1, false, true, 'S'}));
    QCOMPARE(f[1], std::string("V"));
    QCOMPARE(f[2], std::string("V"));
    QCOMPARE(f[3], std::string("0.10"));
    QCOMPARE(f[6], std::string("S"));
    // Not valid: both statuses V, nothing to steer on, mode N.
    f = independentFields(xte("IN", {0.3, true, false, 'A'}));
    QCOMPARE(f.size(), std::size_t(7));
    QCOMPARE(f[1], std::string("V"));
    QCOMPARE(f[2], std::string("V"));
    QCOMPARE(f[3], std::string(""));
    QCOMPARE(f[4], std::string(""));
    QCOMPARE(f[5], std::string("N"));
    QCOMPARE(f[6], std::string("N"));
    // Absent (NaN) and huge values: empty, and bounded.
    f = independentFields(xte("IN", {std::nan(""), true, true, 'A'}));
    QCOMPARE(f[3], std::string(""));
    QCOMPARE(f[4], std::string(""));
    QCOMPARE(independentFields(xte("IN", {1e300, true, true, 'A'}))[3], std::string("999.99"));
  }

  void rmbFieldByField() {
    RmbOut r;
    r.valid = true;
    r.crossTrackNm = 0.66;
    r.steerRight = false;
    r.originId = "003";
    r.destinationId = "004";
    r.destLatDeg = 49.0 + 17.24 / 60.0;
    r.destLonDeg = -(123.0 + 9.57 / 60.0);
    r.rangeToDestNm = 1.3;
    r.bearingToDestTrueDeg = 52.5;
    r.closingVelocityKn = 0.5;
    const std::string line = rmb("IN", r);
    QCOMPARE(line, std::string("$INRMB,A,0.66,L,003,004,4917.2400,N,12309.5700,W,1.30,52.5,0.5,V,A*5D"));
    auto f = independentFields(line);
    QCOMPARE(f.size(), std::size_t(15));
    QCOMPARE(f[0], std::string("INRMB"));
    QCOMPARE(f[1], std::string("A"));
    QCOMPARE(f[2], std::string("0.66"));
    QCOMPARE(f[3], std::string("L"));
    QCOMPARE(f[4], std::string("003"));  // origin
    QCOMPARE(f[5], std::string("004"));  // destination
    QCOMPARE(f[6], std::string("4917.2400"));
    QCOMPARE(f[7], std::string("N"));
    QCOMPARE(f[8], std::string("12309.5700"));
    QCOMPARE(f[9], std::string("W"));
    QCOMPARE(f[10], std::string("1.30"));
    QCOMPARE(f[11], std::string("52.5"));
    QCOMPARE(f[12], std::string("0.5"));
    QCOMPARE(f[13], std::string("V"));
    QCOMPARE(f[14], std::string("A"));

    // The standard's limits (9.99 NM cross-track, 999.9 NM range), bearing wrapped, moving away, arrived.
    r.crossTrackNm = 12.3;
    r.steerRight = true;
    r.rangeToDestNm = 1234.5;
    r.bearingToDestTrueDeg = 359.96;
    r.closingVelocityKn = -3.26;
    r.arrived = true;
    r.mode = 'E';
    f = independentFields(rmb("IN", r));
    QCOMPARE(f[1], std::string("A"));
    QCOMPARE(f[2], std::string("9.99"));
    QCOMPARE(f[3], std::string("R"));
    QCOMPARE(f[10], std::string("999.90"));
    QCOMPARE(f[11], std::string("0.0"));
    QCOMPARE(f[12], std::string("-3.3"));
    QCOMPARE(f[13], std::string("A"));
    QCOMPARE(f[14], std::string("E"));

    // Not valid: V, the leg's data kept, everything measured from own ship empty, not arrived, mode N.
    r.valid = false;
    f = independentFields(rmb("IN", r));
    QCOMPARE(f.size(), std::size_t(15));
    QCOMPARE(f[1], std::string("V"));
    QCOMPARE(f[2], std::string(""));
    QCOMPARE(f[3], std::string(""));
    QCOMPARE(f[4], std::string("003"));
    QCOMPARE(f[5], std::string("004"));
    QCOMPARE(f[6], std::string("4917.2400"));
    QCOMPARE(f[10], std::string(""));
    QCOMPARE(f[11], std::string(""));
    QCOMPARE(f[12], std::string(""));
    QCOMPARE(f[13], std::string("V"));
    QCOMPARE(f[14], std::string("N"));
  }

  void rmbIdsEscapedCutAndFitted() {
    RmbOut r;
    r.valid = true;
    r.originId = "WP,1";        // escaped: exactly 6 characters
    r.destinationId = "A*B*C";  // never half an escape: "A^2AB"
    auto f = independentFields(rmb("IN", r));
    QCOMPARE(f[4], std::string("WP^2C1"));
    QCOMPARE(f[5], std::string("A^2AB"));
    r.destinationId = "HARBOUR ENTRANCE";
    QCOMPARE(independentFields(rmb("IN", r))[5], std::string("HARBOU"));
    // The longest numbers and two 6-character ids would make 81 characters: the origin's id loses one.
    r.crossTrackNm = 9.99;
    r.steerRight = false;
    r.originId = "ORIGIN";
    r.destinationId = "DEST01";
    r.destLatDeg = -89.99;
    r.destLonDeg = -179.99;
    r.rangeToDestNm = 999.9;
    r.bearingToDestTrueDeg = 359.9;
    r.closingVelocityKn = -5000.0;
    r.arrived = true;
    const std::string line = rmb("IN", r);
    QCOMPARE(line.size(), kMaxSentenceChars);
    f = independentFields(line);
    QCOMPARE(f[4], std::string("ORIGI"));
    QCOMPARE(f[5], std::string("DEST01"));
    QCOMPARE(f[12], std::string("-999.9"));
  }

  void apbFieldByField() {
    ApbOut a;
    a.valid = true;
    a.crossTrackNm = 0.1;
    a.steerRight = true;
    a.bearingOriginToDestDeg = 11.0;
    a.bearingMagnetic = true;
    a.destinationId = "DEST";
    a.bearingPresentToDestDeg = 11.0;
    a.headingToSteerDeg = 11.0;
    const std::string line = apb("IN", a);
    QCOMPARE(line, std::string("$INAPB,A,A,0.10,R,N,V,V,11.0,M,DEST,11.0,M,11.0,M,A*6F"));
    auto f = independentFields(line);
    QCOMPARE(f.size(), std::size_t(16));
    QCOMPARE(f[0], std::string("INAPB"));
    QCOMPARE(f[1], std::string("A"));
    QCOMPARE(f[2], std::string("A"));
    QCOMPARE(f[3], std::string("0.10"));
    QCOMPARE(f[4], std::string("R"));
    QCOMPARE(f[5], std::string("N"));
    QCOMPARE(f[6], std::string("V"));  // arrival circle
    QCOMPARE(f[7], std::string("V"));  // perpendicular
    QCOMPARE(f[8], std::string("11.0"));
    QCOMPARE(f[9], std::string("M"));
    QCOMPARE(f[10], std::string("DEST"));
    QCOMPARE(f[11], std::string("11.0"));
    QCOMPARE(f[12], std::string("M"));
    QCOMPARE(f[13], std::string("11.0"));
    QCOMPARE(f[14], std::string("M"));
    QCOMPARE(f[15], std::string("A"));

    // True directions wrapped into [0, 360), arrival and perpendicular, an id escaped and cut.
    a.bearingMagnetic = false;
    a.bearingOriginToDestDeg = 359.96;
    a.bearingPresentToDestDeg = -90.0;
    a.headingToSteerDeg = 721.3;
    a.arrivalCircleEntered = true;
    a.perpendicularPassed = true;
    a.steerRight = false;
    a.destinationId = "N,1 BUOY";
    f = independentFields(apb("IN", a));
    QCOMPARE(f[4], std::string("L"));
    QCOMPARE(f[6], std::string("A"));
    QCOMPARE(f[7], std::string("A"));
    QCOMPARE(f[8], std::string("0.0"));
    QCOMPARE(f[9], std::string("T"));
    QCOMPARE(f[10], std::string("N^2C1 "));
    QCOMPARE(f[11], std::string("270.0"));
    QCOMPARE(f[12], std::string("T"));
    QCOMPARE(f[13], std::string("1.3"));
    QCOMPARE(f[14], std::string("T"));

    // Not valid: V, V; nothing to steer on; no arrival; the leg's bearing and id kept; mode N.
    a.valid = false;
    f = independentFields(apb("IN", a));
    QCOMPARE(f.size(), std::size_t(16));
    QCOMPARE(f[1], std::string("V"));
    QCOMPARE(f[2], std::string("V"));
    QCOMPARE(f[3], std::string(""));
    QCOMPARE(f[4], std::string(""));
    QCOMPARE(f[6], std::string("V"));
    QCOMPARE(f[7], std::string("V"));
    QCOMPARE(f[8], std::string("0.0"));
    QCOMPARE(f[10], std::string("N^2C1 "));
    QCOMPARE(f[11], std::string(""));
    QCOMPARE(f[13], std::string(""));
    QCOMPARE(f[15], std::string("N"));

    // The longest numbers and id stay within 80 characters.
    a.valid = true;
    a.crossTrackNm = 1e9;
    a.destinationId = std::string(40, 'W');
    const std::string longest = apb("IN", a);
    QVERIFY(longest.size() <= kMaxSentenceChars);
    QCOMPARE(independentFields(longest)[3], std::string("999.99"));
    QCOMPARE(independentFields(longest)[10], std::string("WWWWWW"));
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
