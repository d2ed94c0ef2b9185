// GIVEN / WHEN / THEN behaviour of NMEA parsing, UTC handling and the replay of recorded data.
#include <QTest>

#include <cmath>
#include <set>

#include "io/input_error.h"
#include "io/iso8601.h"
#include "io/nmea.h"
#include "metrics/track_stats.h"
#include "sim/nmea_export.h"
#include "sim/replay.h"
#include "support/compare_near.h"
#include "support/drkf_fixtures.h"

using namespace reckoner;
namespace nm = reckoner::io::nmea;

class TestReplay : public QObject {
  Q_OBJECT
 private slots:
  void parsesEverySentenceWeRead() {
    const auto rmc =
        nm::parse(nm::withChecksum("GPRMC,123519.50,A,4807.038,N,01131.000,W,022.4,084.4,230394,003.1,W"));
    QVERIFY(rmc.sentence);
    const auto& r = std::get<nm::Rmc>(rmc.sentence->body);
    QCOMPARE(rmc.sentence->talker, std::string("GP"));
    QVERIFY(r.valid);
    RK_COMPARE_NEAR(r.timeOfDayS, 12 * 3600 + 35 * 60 + 19.5, 1e-9);
    RK_COMPARE_NEAR(r.latDeg, 48 + 7.038 / 60, 1e-12);
    RK_COMPARE_NEAR(r.lonDeg, -(11 + 31.0 / 60), 1e-12);
    QCOMPARE(*r.sogKn, 22.4);
    QCOMPARE(r.date->year, 1994);
    QCOMPARE(r.date->month, 3);
    QCOMPARE(nm::parse("$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47").error,
             nm::Error::None);  // a published example, checksum included
    const auto gga =
        nm::parse(nm::withChecksum("GPGGA,123519,4807.038,S,01131.000,E,1,08,0.9,545.4,M,46.9,M,,"));
    QVERIFY(std::get<nm::Gga>(gga.sentence->body).latDeg < 0.0);
    QVERIFY(nm::parse(nm::withChecksum("GPVTG,054.7,T,034.4,M,005.5,N,010.2,K")).sentence);
    const auto gll = nm::parse(nm::withChecksum("LCGLL,4916.45,N,12311.12,W,225444,A"));
    QCOMPARE(gll.sentence->talker, std::string("LC"));
    RK_COMPARE_NEAR(
        std::get<nm::Hdt>(nm::parse(nm::withChecksum("HEHDT,274.07,T")).sentence->body).headingDeg, 274.07,
        1e-12);
    QCOMPARE(
        std::get<nm::Vhw>(nm::parse(nm::withChecksum("VWVHW,,T,,M,6.5,N,12.0,K")).sentence->body).speedKn,
        6.5);
    const auto vbw =
        std::get<nm::Vbw>(nm::parse(nm::withChecksum("VWVBW,6.1,0.2,A,6.3,-0.1,A")).sentence->body);
    QCOMPARE(*vbw.longGroundKn, 6.3);
    QCOMPARE(*vbw.transWaterKn, 0.2);
    const auto zda =
        std::get<nm::Zda>(nm::parse(nm::withChecksum("GPZDA,201530.00,04,07,2002,00,00")).sentence->body);
    QCOMPARE(zda.date->day, 4);
    QCOMPARE(zda.date->year, 2002);
  }
  void badLinesAreClassifiedNeverThrown() {
    QCOMPARE(nm::parse("$GPHDT,274.07,T*00").error, nm::Error::BadChecksum);
    QCOMPARE(nm::parse("$GPHDT,274.07,T").error, nm::Error::BadChecksum);  // no checksum
    QCOMPARE(nm::parse(nm::withChecksum("GPXDR,C,19.5,C,AIR")).error, nm::Error::Unknown);
    QCOMPARE(nm::parse(nm::withChecksum("PGRME,15.0,M,45.0,M,25.0,M")).error, nm::Error::Proprietary);
    for (const char* body : {"GPRMC,123519,A,4867.038,N,01131.000,E,0,0,230394,,",             // 67 minutes
                             "GPRMC,123519,A,4807.038,X,01131.000,E,0,0,230394,,",             // hemisphere
                             "GPRMC,123519,A,4807.038,N,01131.000,E,0,0,310294,,",             // 31 February
                             "GPGGA,256000,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,",  // 25 h
                             "HEHDT,abc,T", "HEHDT,400,T", "GPZDA,201530.00,04,13,2002,00,00", "GP"}) {
      const auto r = nm::parse(nm::withChecksum(body));
      QVERIFY2(r.error == nm::Error::Malformed, body);
      QVERIFY2(!r.reason.empty(), body);
    }
    QCOMPARE(nm::parse("").error, nm::Error::Empty);
    QCOMPARE(nm::parse("garbage").error, nm::Error::Malformed);
  }
  void badChecksumReasonIsOneLine() {
    // GIVEN a line whose two checksum characters are a line break and a control byte (found by
    // fuzz_nmea: the reason quoted them raw). WHEN parsed THEN the reason quotes them, on one line.
    const auto r = nm::parse(std::string("$GPHDT,274.07,T*\n\x01", 18));
    QCOMPARE(r.error, nm::Error::BadChecksum);
    QVERIFY2(r.reason.find_first_of("\r\n") == std::string::npos, r.reason.c_str());
    QVERIFY2(r.reason.find("'\\n\\x01'") != std::string::npos, r.reason.c_str());
    QVERIFY(nm::parse("$GPHDT,274.07,T*00").reason.ends_with("sentence says '00'"));
  }
  void outOfRangeSpeedCourseAndSdAreMalformed() {
    // GIVEN sentences with a negative RMC speed, a course of 1e300, a GST sd of 1e200 (squared to
    // infinity for the filter) — found by reading for fuzz_nmea_epochs: they reached the epochs.
    // WHEN parsed THEN each is Malformed with the field in its reason; in-range ones still parse.
    const std::pair<const char*, const char*> bad[] = {
        {"GPRMC,123519.50,A,4807.038,N,01131.000,W,-5.0,084.4,230394,,", "RMC speed: negative"},
        {"GPRMC,123519.50,A,4807.038,N,01131.000,W,5.0,1e300,230394,,", "RMC course: out of range"},
        {"GPVTG,361.0,T,,M,005.5,N,010.2,K", "VTG course: out of range"},
        {"GPGST,123519.50,1.0,2.0,1.0,45.0,1e200,1.5,3.0", "GST latitude sd: out of range"},
    };
    for (const auto& [body, reason] : bad) {
      const auto r = nm::parse(nm::withChecksum(body));
      QCOMPARE(r.error, nm::Error::Malformed);
      QVERIFY2(r.reason.find(reason) != std::string::npos, r.reason.c_str());
    }
    QVERIFY(
        nm::parse(nm::withChecksum("GPRMC,123519.50,A,4807.038,N,01131.000,W,0.0,360.0,230394,,")).sentence);
    QVERIFY(nm::parse(nm::withChecksum("GPGST,123519.50,1.0,2.0,1.0,45.0,1.2,1.5,3.0")).sentence);
  }
  void utcArithmetic() {
    QCOMPARE(io::daysFromCivil(1970, 1, 1), std::int64_t(0));
    QCOMPARE(io::daysFromCivil(2000, 3, 1), std::int64_t(11017));
    QCOMPARE(io::daysFromCivil(2024, 2, 29) + 1, io::daysFromCivil(2024, 3, 1));
    const auto t = io::parseIso8601("2024-02-29T23:59:59.250Z");
    QVERIFY(t.has_value());
    QCOMPARE(io::formatIso8601(*t), std::string("2024-02-29T23:59:59.250000Z"));
    QCOMPARE(io::formatIso8601(*t + 750000), std::string("2024-03-01T00:00:00.000000Z"));
    QVERIFY(!io::parseIso8601("2024-02-29 23:59:59Z"));
    QVERIFY(!io::parseIso8601("2024-02-29T23:59:59"));  // no Z: not UTC
    QVERIFY(!io::parseIso8601("2024-13-01T00:00:00Z"));
  }
  void replayReproducesTheSimulatedRun() {
    // GIVEN a simulated run written as NMEA and radar CSV WHEN replayed with the same settings and
    // target_id association THEN the own-ship estimate follows the same path (within centimetres:
    // the files round the values) and stays within 3 sd of the truth; every target gets a track.
    sim::Scenario s = test::builtinScenario("ttkf-matched");
    s.durationUs = 300 * kMicrosPerSecond;
    const auto utc0 = *io::parseIso8601("2026-11-23T10:00:00Z");
    const sim::ExportedRun e = sim::exportRun(s, 3, utc0);
    sim::ReplayOptions o;
    o.settings = s;
    o.originFromSettings = true;
    o.assumeAssociation = true;
    const auto r = sim::replay(e.nmea, "run.nmea", &e.radarCsv, "run.csv", o);
    QCOMPARE(r.stats.nmeaSkipped(), 0L);
    QCOMPARE(r.stats.radarBad, 0L);
    QCOMPARE(r.own.size(), e.truth.rows.size());
    double worst = 0.0;
    int within = 0;
    for (std::size_t k = 30; k < r.own.size(); ++k) {
      const auto& a = r.own[k];
      const auto& t = e.truth.rows[k];
      QCOMPARE(a.timeUs + (r.utc0 - utc0), t.timeUs);
      worst = std::max(worst, std::hypot(a.estimate.xM - t.estXM, a.estimate.yM - t.estYM));
      within += std::abs(a.estimate.xM - t.trueXM) <= 3 * a.estimate.sdXM &&
                std::abs(a.estimate.yM - t.trueYM) <= 3 * a.estimate.sdYM;
    }
    qInfo("replay vs simulated estimate: largest difference %.3f m; %d of %zu epochs within 3 sd of truth",
          worst, within, r.own.size() - 30);
    QVERIFY(worst < 1.0);  // dead reckoning integrates the rounded speed and heading of the files
    QVERIFY(within > 0.97 * static_cast<double>(r.own.size() - 30));
    std::set<int> tags;
    for (const auto& t : r.tracks) tags.insert(t.targetId);
    QCOMPARE(tags.size(), std::size_t(5));
  }
  void everyTrackerReplaysRadarSweepsAndSonarPings() {
    // GIVEN recorded runs of five targets with plots every 2 s (radar sweeps) and every 80 s (sonar
    // pings; the track keeping rules count pings as sweeps) WHEN each is replayed through each of the
    // four track filters (tracker.filter of the --config scenario; abg at alpha 0.1 for sweeps and
    // 0.6 for pings) with nearest-neighbour association THEN every target gets a track, and at the end
    // every target's track lies within 100 m (2 s) or 600 m (80 s) of the truth.
    for (const double period : {2.0, 80.0}) {
      sim::Scenario s = test::builtinScenario("ttkf-matched");
      s.durationUs = fromSeconds(period > 10 ? 2400.0 : 600.0);
      s.radar.sweepPeriodS = period;
      const auto utc0 = *io::parseIso8601("2026-11-23T10:00:00Z");
      const sim::ExportedRun e = sim::exportRun(s, 4, utc0);
      const TimeUs lastSweep = e.truth.targetRows.back().timeUs;
      for (int k = 0; k < track::kTrackerKindCount; ++k) {
        sim::ReplayOptions o;
        o.settings = s;
        o.settings.tracker.kind = static_cast<track::TrackerKind>(k);
        // Few, far-apart pings of manoeuvring targets want the short memory (seed 003's upper alpha).
        if (period > 10) o.settings.tracker.abg.alpha = 0.6;
        o.originFromSettings = true;
        const auto r = sim::replay(e.nmea, "run.nmea", &e.radarCsv, "run.csv", o);
        std::set<int> tags;
        for (const auto& t : r.tracks) tags.insert(t.targetId);
        double worst = 0.0;
        int found = 0;
        for (const auto& truth : e.truth.targetRows) {
          if (truth.timeUs != lastSweep) continue;
          double best = 1e12;
          for (std::size_t i = 0; i < r.tracks.size(); ++i) {
            const auto& t = r.tracks[i];
            // The replay closes its own sweeps: carry the estimate to the truth's time.
            const double dt = toSeconds(truth.timeUs - (r.trackRowUtc[i] - utc0));
            if (std::abs(dt) > 0.5 * period || t.status != track::TrackStatus::Confirmed) continue;
            best = std::min(
                best, std::hypot(t.estXM + t.estVxMps * dt - truth.xM, t.estYM + t.estVyMps * dt - truth.yM));
          }
          worst = std::max(worst, best);
          ++found;
        }
        qInfo("%4.0f s plots, %-22s: %zu targets tracked, worst final error %.1f m", period,
              track::trackerKindLabel(o.settings.tracker.kind), tags.size(), worst);
        QCOMPARE(found, 5);
        QVERIFY(tags.size() >= 5);
        QVERIFY(worst < (period > 10 ? 600.0 : 100.0));
      }
    }
  }
  void corruptLinesAreCountedAndSkipped() {
    sim::Scenario s = test::builtinScenario("imo-2");
    s.durationUs = 60 * kMicrosPerSecond;
    const auto e = sim::exportRun(s, 1, *io::parseIso8601("2026-01-01T00:00:00Z"));
    std::string nmea;
    int k = 0, flipped = 0;
    for (std::size_t start = 0; start < e.nmea.size();) {
      const std::size_t end = e.nmea.find('\n', start);
      std::string line = e.nmea.substr(start, end - start + 1);
      start = end + 1;
      if (++k % 10 == 5 && line.rfind("$HEHDT", 0) != 0 && line.rfind("$GPRMC", 0) != 0) {
        line[line.size() - 3] = line[line.size() - 3] == '0' ? '1' : '0';  // checksum digit
        ++flipped;
      }
      nmea += line;
    }
    nmea += "$GPXTE,A,A,0.67,L,N*6F\r\n";              // unknown (valid checksum)
    nmea += nm::withChecksum("HEHDT,999,T") + "\r\n";  // malformed
    nmea += "this is not NMEA\r\n";                    // malformed
    std::string radar = e.radarCsv + "2026-01-01T00:01:05Z,abc,10,\nnot,a,line\n";
    sim::ReplayOptions o;
    o.settings = s;
    const auto r = sim::replay(nmea, "bad.nmea", &radar, "bad.csv", o);
    QCOMPARE(r.stats.badChecksum, static_cast<long>(flipped));
    QCOMPARE(r.stats.unknownSentences, 1L);
    QCOMPARE(r.stats.malformed, 2L);
    QCOMPARE(r.stats.radarBad, 2L);
    QVERIFY(r.own.size() >= 59);
    // Unusable files are errors naming the file.
    try {
      sim::replay(nm::withChecksum("HEHDT,10,T") + "\n", "nodate.nmea", nullptr, "", o);
      QFAIL("accepted a file without a date");
    } catch (const io::InputError& err) {
      QVERIFY(QString(err.what()).startsWith("nodate.nmea: "));
    }
    const std::string badHeader = "time,range,bearing\n";
    try {
      sim::replay(e.nmea, "ok.nmea", &badHeader, "plots.csv", o);
      QFAIL("accepted a radar file with another header");
    } catch (const io::InputError& err) {
      QVERIFY2(QString(err.what()).contains("plots.csv:1: header"), err.what());
    }
  }
};

QTEST_APPLESS_MAIN(TestReplay)
#include "tst_replay.moc"
