// GIVEN / WHEN / THEN: what real receivers and ships send (issue 16, part 1): more sentences and any
// talker, several sources of one quantity with a priority and a fallback, magnetic headings with their
// variation, receivers' accuracy (GST, HDOP), each source's clock, undated logs and week roll-overs.
#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/angles.h"
#include "files/track_output.h"
#include "io/input_error.h"
#include "io/iso8601.h"
#include "io/json.h"
#include "io/nmea.h"
#include "sim/nmea_export.h"
#include "sim/replay.h"
#include "sim/replay_input.h"
#include "support/compare_near.h"
#include "support/drkf_fixtures.h"
#include "support/resource_limits.h"
#include "support/text_lines.h"

using namespace reckoner;
namespace nm = reckoner::io::nmea;

namespace {
std::vector<std::string> linesOf(const std::string& text) {
  return test::splitLines(text, test::EmptyLines::Drop);
}
std::string joined(const std::vector<std::string>& lines) {
  return test::joinLines(lines);
}
std::vector<std::string> fieldsOf(const std::string& sentence) {
  const std::string body = sentence.substr(1, sentence.find('*') - 1);
  std::vector<std::string> f;
  for (std::size_t s = 0;;) {
    const std::size_t c = body.find(',', s);
    f.push_back(body.substr(s, c == std::string::npos ? std::string::npos : c - s));
    if (c == std::string::npos) break;
    s = c + 1;
  }
  return f;
}
std::string sentenceOf(const std::vector<std::string>& f) {
  std::string body;
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (i > 0) body += ',';
    body += f[i];
  }
  return nm::withChecksum(body);
}
bool startsWith(const std::string& s, const char* p) {
  return s.rfind(p, 0) == 0;
}
/// hhmmss.sss shifted by dt seconds (within the day).
std::string shifted(const std::string& hhmmss, double dt) {
  const double t = std::stoi(hhmmss.substr(0, 2)) * 3600.0 + std::stoi(hhmmss.substr(2, 2)) * 60.0 +
                   std::stod(hhmmss.substr(4)) + dt;
  char buf[16];
  std::snprintf(buf, sizeof buf, "%02d%02d%06.3f", static_cast<int>(t / 3600), static_cast<int>(t / 60) % 60,
                std::fmod(t, 60.0));
  return buf;
}
const sim::SourceStats* sourceOf(const sim::ReplayResult& r, const std::string& id) {
  for (const auto& s : r.sources)
    if (s.source == id) return &s;
  return nullptr;
}
}  // namespace

class TestReplaySources : public QObject {
  Q_OBJECT
  sim::Scenario scenario_;
  sim::ExportedRun run_;
  UtcUs utc0_ = 0;

  [[nodiscard]] sim::ReplayOptions options() const {
    sim::ReplayOptions o;
    o.settings = scenario_;
    o.originFromSettings = true;
    return o;
  }
  /// Largest distance of the estimate from the truth from row `from` on.
  [[nodiscard]] double worstError(const sim::ReplayResult& r, std::size_t from = 20) const {
    double worst = 0.0;
    for (std::size_t k = from; k < r.own.size(); ++k) {
      const TimeUs t = r.own[k].timeUs + (r.utc0 - utc0_);
      for (const auto& row : run_.truth.rows)
        if (row.timeUs == t)
          worst = std::max(worst,
                           std::hypot(r.own[k].estimate.xM - row.trueXM, r.own[k].estimate.yM - row.trueYM));
    }
    return worst;
  }

 private slots:
  void initTestCase() {
    test::limitThisProcess(300, std::size_t{4} << 30);
    scenario_ = test::builtinScenario("ttkf-matched");
    scenario_.durationUs = 300 * kMicrosPerSecond;
    scenario_.loran.fitted = false;  // GPS, log and gyro: the sources under test
    utc0_ = *io::parseIso8601("2026-11-23T10:00:00Z");
    run_ = sim::exportRun(scenario_, 7, utc0_);
  }

  void readsTheSentencesRealShipsSend() {
    const auto ths = nm::parse(nm::withChecksum("HETHS,123.4,A"));
    QCOMPARE(std::get<nm::Ths>(ths.sentence->body).headingDeg, 123.4);
    QCOMPARE(nm::parse(nm::withChecksum("HETHS,123.4,X")).error, nm::Error::Malformed);
    const auto hdg = std::get<nm::Hdg>(nm::parse(nm::withChecksum("HCHDG,229.8,1.5,W,1.3,E")).sentence->body);
    QCOMPARE(hdg.sensorDeg, 229.8);
    QCOMPARE(*hdg.deviationDeg, -1.5);
    QCOMPARE(*hdg.variationDeg, 1.3);
    QVERIFY(
        !std::get<nm::Hdg>(nm::parse(nm::withChecksum("SDHDG,229.8,,,1.3,E")).sentence->body).deviationDeg);
    QCOMPARE(nm::parse(nm::withChecksum("HCHDG,229.8,1.5,X,1.3,E")).error, nm::Error::Malformed);
    QCOMPARE(std::get<nm::Hdm>(nm::parse(nm::withChecksum("HCHDM,228.5,M")).sentence->body).headingDeg,
             228.5);
    const auto vhw =
        std::get<nm::Vhw>(nm::parse(nm::withChecksum("SDVHW,231.3,T,229.9,M,6.6,N,12.3,K")).sentence->body);
    QCOMPARE(*vhw.headingTrueDeg, 231.3);
    QCOMPARE(*vhw.headingMagneticDeg, 229.9);
    const auto rot = std::get<nm::Rot>(nm::parse(nm::withChecksum("TIROT,-12.5,A")).sentence->body);
    QVERIFY(rot.valid && rot.degPerMin == -12.5);
    const auto gns =
        nm::parse(nm::withChecksum("GNGNS,014035.00,4332.69262,S,17235.48549,E,RR,13,0.9,25.63,11.24,,"));
    QVERIFY(gns.sentence);
    QVERIFY(nm::gnssFix(std::string_view(std::get<nm::Gns>(gns.sentence->body).modes)));
    QVERIFY(!nm::gnssFix(std::string_view("EN")));
    QVERIFY(!nm::gnssFix(std::string_view("NN")));
    QCOMPARE(nm::parse(nm::withChecksum("GNGNS,014035.00,4332.69262,S,17235.48549,E,XZ,13,0.9,,,,")).error,
             nm::Error::Malformed);
    const auto gst = std::get<nm::Gst>(
        nm::parse(nm::withChecksum("GPGST,172814.0,0.006,0.023,0.020,273.6,0.023,0.020,0.031"))
            .sentence->body);
    QCOMPARE(*gst.latSdM, 0.023);
    QCOMPARE(std::get<nm::Dtm>(nm::parse(nm::withChecksum("GPDTM,W84,,0.0,N,0.0,E,0.0,W84")).sentence->body)
                 .localDatum,
             std::string("W84"));
    QVERIFY(!std::get<nm::Zda>(nm::parse(nm::withChecksum("GPZDA,094737,,,,,")).sentence->body).date);
    QCOMPARE(
        *std::get<nm::Rmc>(
             nm::parse(nm::withChecksum("GPRMC,094737,A,5251.0093,N,00518.8170,E,5.6,230.5,200818,1.4,W,A"))
                 .sentence->body)
             .variationDeg,
        -1.4);
    for (const char* talker : {"GP", "GN", "GL", "GA", "GB", "BD", "II"})
      QVERIFY(nm::parse(nm::withChecksum(std::string(talker) + "HDT,1.0,T")).sentence);
  }

  void headingSourcesFollowThePriorityAndFallBack() {
    // GIVEN THS, HDT and a magnetic HDG beside each other, THS lost from 100 to 160 s WHEN replayed THEN
    // THS is used while it reports, HDT (the next in priority) after it has been silent for the hold,
    // THS again once back for the hold; HDG stays standby throughout; the estimate stays on the truth.
    std::vector<std::string> out;
    for (const auto& l : linesOf(run_.nmea)) {
      if (!startsWith(l, "$HEHDT")) {
        out.push_back(l);
        continue;
      }
      auto f = fieldsOf(l);
      const double h = std::stod(f[1]);
      const std::size_t epoch =
          std::count_if(out.begin(), out.end(), [](const std::string& s) { return startsWith(s, "$IIZDA"); });
      if (epoch < 100 || epoch > 160) out.push_back(sentenceOf({"GPTHS", f[1], "A"}));
      out.push_back(l);
      char hdg[16];
      std::snprintf(hdg, sizeof hdg, "%.1f", std::fmod(h - 5.0 + 360.0, 360.0));
      out.push_back(sentenceOf({"HCHDG", hdg, "", "", "5.0", "E"}));
    }
    const auto r = sim::replay(joined(out), "headings.nmea", nullptr, "", options());
    const auto* ths = sourceOf(r, "GP:THS");
    const auto* hdt = sourceOf(r, "HE:HDT");
    const auto* hdg = sourceOf(r, "HC:HDG");
    QVERIFY(ths && hdt && hdg);
    qInfo("THS used %ld, HDT used %ld standby %ld, HDG used %ld standby %ld", ths->used, hdt->used,
          hdt->standby, hdg->used, hdg->standby);
    QVERIFY(ths->used >= 230 && ths->used <= 240);
    QVERIFY(hdt->used >= 55 &&
            hdt->used <= 62);  // the 60 s without THS less the 3 s hold, plus the hold back
    QCOMPARE(hdg->used, 0L);
    QVERIFY(hdg->standby > 290);
    QVERIFY(worstError(r) < 30.0);
  }

  void magneticHeadingsTakeTheirVariation() {
    // GIVEN only a magnetic heading (HDM, 5 deg W variation) WHEN replayed with the variation in RMC
    // THEN the gyro rows are the true heading; WHEN the file gives no variation THEN the headings are
    // counted without one and a warning names --variation; WHEN --variation gives it THEN they are used.
    const auto build = [&](bool rmcVariation) {
      std::vector<std::string> out;
      for (const auto& l : linesOf(run_.nmea)) {
        if (startsWith(l, "$HEHDT")) {
          char hdm[16];
          std::snprintf(hdm, sizeof hdm, "%.2f", std::fmod(std::stod(fieldsOf(l)[1]) + 5.0 + 360.0, 360.0));
          out.push_back(sentenceOf({"HCHDM", hdm, "M"}));
        } else if (startsWith(l, "$GPRMC") && rmcVariation) {
          auto f = fieldsOf(l);
          f[10] = "5.0";
          f[11] = "W";
          out.push_back(sentenceOf(f));
        } else {
          out.push_back(l);
        }
      }
      return joined(out);
    };
    const auto with = sim::replay(build(true), "hdm.nmea", nullptr, "", options());
    QCOMPARE(with.stats.noVariation, 0L);
    QVERIFY(with.updates[nav::kGyro].accepted > 250);
    QVERIFY(worstError(with) < 30.0);
    const auto without = sim::replay(build(false), "hdm.nmea", nullptr, "", options());
    QVERIFY(without.stats.noVariation > 250);
    QVERIFY(std::any_of(without.warnings.begin(), without.warnings.end(),
                        [](const std::string& w) { return w.find("--variation") != std::string::npos; }));
    sim::ReplayOptions o = options();
    o.variationDeg = -5.0;
    const auto given = sim::replay(build(false), "hdm.nmea", nullptr, "", o);
    QCOMPARE(given.stats.noVariation, 0L);
    QCOMPARE(given.updates[nav::kGyro].accepted, with.updates[nav::kGyro].accepted);
  }

  void zdaSentFirstDoesNotLoseTheFixes() {
    // GIVEN a receiver that sends each second's ZDA first, stamped 10 ms after the fixes that follow
    // it WHEN replayed THEN every fix is used (they were all dropped as out of order before).
    std::vector<std::string> out;
    for (const auto& l : linesOf(run_.nmea)) {
      if (!startsWith(l, "$IIZDA")) {
        out.push_back(l);
        continue;
      }
      auto f = fieldsOf(l);
      f[1] = shifted(f[1], 0.010);
      out.push_back(sentenceOf(f));
    }
    const auto r = sim::replay(joined(out), "zda-first.nmea", nullptr, "", options());
    const auto plain = sim::replay(run_.nmea, "run.nmea", nullptr, "", options());
    QCOMPARE(r.updates[nav::kGpsPosition].accepted, plain.updates[nav::kGpsPosition].accepted);
    QCOMPARE(r.own.size(), plain.own.size());
  }

  void undatedLogReplaysOnTheDateGiven() {
    // GIVEN a log whose RMC and ZDA carry no date WHEN replayed THEN it replays with a warning on an
    // unknown date; WHEN --date is given THEN its rows are on that date.
    std::vector<std::string> out;
    for (const auto& l : linesOf(run_.nmea)) {
      auto f = fieldsOf(l);
      if (startsWith(l, "$GPRMC")) f[9] = "";
      if (startsWith(l, "$IIZDA")) f[2] = f[3] = f[4] = "";
      out.push_back(sentenceOf(f));
    }
    const auto r = sim::replay(joined(out), "undated.nmea", nullptr, "", options());
    QVERIFY(std::any_of(r.warnings.begin(), r.warnings.end(),
                        [](const std::string& w) { return w.find("--date") != std::string::npos; }));
    QCOMPARE(r.own.size(), run_.truth.rows.size());
    sim::ReplayOptions o = options();
    o.date = std::array<int, 3>{2026, 11, 23};
    const auto dated = sim::replay(joined(out), "undated.nmea", nullptr, "", o);
    QCOMPARE(io::formatIso8601(dated.utc0).substr(0, 10), std::string("2026-11-23"));
    QVERIFY(worstError(dated) < 30.0);
  }

  void weekRollOverIsCorrected() {
    // GIVEN a receiver with the week-number bug (its dates 1024 weeks early) WHEN replayed with --date
    // THEN the dates are corrected; GIVEN two receivers, one of them rolled over, THEN its dates are
    // corrected to the other's.
    std::vector<std::string> rolled;
    const auto back = [](const std::string& ddmmyy) {  // 1024 weeks = 7168 days earlier
      const int d = std::stoi(ddmmyy.substr(0, 2)), m = std::stoi(ddmmyy.substr(2, 2)),
                y = 2000 + std::stoi(ddmmyy.substr(4));
      const std::int64_t day = io::daysFromCivil(y, m, d) - 7168;
      const std::string iso = io::formatIso8601(day * 86400LL * 1000000LL);
      return iso.substr(8, 2) + iso.substr(5, 2) + iso.substr(2, 2);
    };
    for (const auto& l : linesOf(run_.nmea)) {
      auto f = fieldsOf(l);
      if (startsWith(l, "$GPRMC")) f[9] = back(f[9]);
      if (startsWith(l, "$IIZDA")) continue;  // only the rolled-over RMC dates the file
      rolled.push_back(sentenceOf(f));
    }
    sim::ReplayOptions o = options();
    o.date = std::array<int, 3>{2026, 11, 23};
    const auto r = sim::replay(joined(rolled), "rolled.nmea", nullptr, "", o);
    QCOMPARE(io::formatIso8601(r.utc0).substr(0, 10), std::string("2026-11-23"));
    QVERIFY(std::any_of(r.warnings.begin(), r.warnings.end(),
                        [](const std::string& w) { return w.find("roll-over") != std::string::npos; }));
    // Mixed: the ZDA of a good clock beside the rolled-over RMC.
    std::vector<std::string> mixed;
    for (const auto& l : linesOf(run_.nmea)) {
      auto f = fieldsOf(l);
      if (startsWith(l, "$GPRMC")) f[9] = back(f[9]);
      mixed.push_back(sentenceOf(f));
    }
    const auto m = sim::replay(joined(mixed), "mixed.nmea", nullptr, "", options());
    QCOMPARE(m.own.size(), run_.truth.rows.size());
    QCOMPARE(m.stats.timeJumps, 0L);
  }

  void secondReceiverWithItsOwnClockIsStandbyAndBackup() {
    // GIVEN a second GNSS receiver (talker GN) whose clock runs 3 s ahead and whose antenna sits 2 m
    // away WHEN replayed THEN its offset is found (3 s within its resolution) and corrected, the first
    // receiver is used and the second is standby (never fused); GIVEN the first silent for 60 s THEN
    // the second takes over after the hold, the estimate stays on the truth, and the share of time
    // each was active is reported.
    const auto build = [&](bool gap) {
      std::vector<std::string> out;
      int epoch = -1;
      for (const auto& l : linesOf(run_.nmea)) {
        if (startsWith(l, "$IIZDA")) ++epoch;
        const bool pos = startsWith(l, "$GPGGA") || startsWith(l, "$GPRMC");
        if (!(gap && pos && epoch >= 120 && epoch < 180)) out.push_back(l);
        if (startsWith(l, "$GPGGA")) {
          auto f = fieldsOf(l);
          f[0] = "GNGGA";
          f[1] = shifted(f[1], 3.0);
          out.push_back(sentenceOf(f));
        }
      }
      return joined(out);
    };
    const auto r = sim::replay(build(false), "two.nmea", nullptr, "", options());
    const auto* gn = sourceOf(r, "GN:GGA");
    const auto* gp = sourceOf(r, "GP:GGA");
    QVERIFY(gn && gp);
    qInfo("GN:GGA clock %+.2f s (+- %.2f), corrected %d; GP used %ld, GN used %ld standby %ld",
          gn->clockOffsetS, gn->clockResolutionS, gn->clockCorrected, gp->used, gn->used, gn->standby);
    RK_COMPARE_NEAR(gn->clockOffsetS, 3.0, gn->clockResolutionS + 0.05);
    QVERIFY(gn->clockCorrected);
    QCOMPARE(gn->used, 0L);
    QVERIFY(worstError(r) < 30.0);
    const auto g = sim::replay(build(true), "two-gap.nmea", nullptr, "", options());
    const auto* backup = sourceOf(g, "GN:GGA");
    qInfo("with the first silent: GN used %ld, active %.0f s", backup ? backup->used : -1L,
          backup ? backup->activeS : 0.0);
    QVERIFY(backup && backup->used >= 55 &&
            backup->used <= 63);  // the 60 s, less the hold, plus the hold back
    QVERIFY(backup->activeS > 50.0);
    QVERIFY(worstError(g) < 30.0);
    const auto& st = g.stats;
    QCOMPARE(st.nmeaLines, st.sentencesUsed + st.standby + st.repeated + st.notUsed + st.nmeaSkipped());
    const io::JsonValue j = io::parseJson(files::replaySummaryJson(g, "two-gap.nmea"));
    const io::JsonValue* srcs = j.find("sources");
    QVERIFY(srcs && srcs->isArray() && srcs->array.size() >= 5);
    QVERIFY(srcs->array[0].find("clock_offset_s") && srcs->array[0].find("active_share"));
  }

  void receiverAccuracySetsTheFixCovariance() {
    // GIVEN the receiver's GST (1 m each axis) WHEN replayed THEN the fix is taken with that variance
    // (the estimate's sd settles near it); GIVEN HDOP 3 and no GST THEN with 3 times the configured sd.
    const auto build = [&](const char* hdop, bool gst) {
      std::vector<std::string> out;
      for (const auto& l : linesOf(run_.nmea)) {
        auto f = fieldsOf(l);
        if (startsWith(l, "$GPGGA")) f[8] = hdop;
        out.push_back(sentenceOf(f));
        if (gst && startsWith(l, "$GPGGA"))
          out.push_back(sentenceOf({"GPGST", f[1], "1.0", "1.0", "1.0", "0.0", "1.0", "1.0", "2.0"}));
      }
      return joined(out);
    };
    const auto plain = sim::replay(build("1.0", false), "plain.nmea", nullptr, "", options());
    const auto fine = sim::replay(build("1.0", true), "gst.nmea", nullptr, "", options());
    const auto poor = sim::replay(build("3.0", false), "hdop.nmea", nullptr, "", options());
    const double sdPlain = plain.own[50].estimate.sdXM, sdFine = fine.own[50].estimate.sdXM,
                 sdPoor = poor.own[50].estimate.sdXM;
    qInfo("position sd after 50 s: configured %.2f m, GST 1 m %.2f m, HDOP 3 %.2f m", sdPlain, sdFine,
          sdPoor);
    QVERIFY(sdFine < 1.0 && sdFine < 0.5 * sdPlain);
    QVERIFY(sdPoor > 1.5 * sdPlain);
    QCOMPARE(fine.stats.notUsed, 0L);
  }

  void otherDatumIsAnErrorNamingTheLine() {
    auto lines = linesOf(run_.nmea);
    lines.insert(lines.begin() + 4, nm::withChecksum("GPDTM,W72,,0.0,N,0.0,E,0.0,W84"));
    try {
      sim::replay(joined(lines), "datum.nmea", nullptr, "", options());
      QFAIL("accepted positions on another datum");
    } catch (const io::InputError& e) {
      QVERIFY2(QString(e.what()).startsWith("datum.nmea:5: DTM: datum 'W72' is not WGS-84"), e.what());
    }
    lines[4] = nm::withChecksum("GPDTM,W84,,0.0,N,0.0,E,0.0,W84");
    QCOMPARE(sim::replay(joined(lines), "datum.nmea", nullptr, "", options()).stats.notUsed, 1L);
  }
  void rotationPeriodFromPlots() {
    // GIVEN three echoes seen once per turn of a 2.5 s antenna (each at its own bearing's moment, with
    // 20 m and 0.1 deg noise) and scattered clutter WHEN the period is read from the plots THEN it is
    // the antenna's; a few plots give none.
    using sim::replay_input::Plot;
    Rng rng(7, 1);
    std::vector<Plot> plots;
    const double bearings[] = {0.3, 2.0, 4.4};
    for (int turn = 0; turn < 40; ++turn) {
      for (int k = 0; k < 3; ++k) {
        const UtcUs t = static_cast<UtcUs>((turn * 2.5 + 2.5 * bearings[k] / (2 * kPi)) * 1e6);
        plots.push_back({t, 3000.0 + 800.0 * k + turn * 4.0 + rng.normal(0.0, 20.0),
                         bearings[k] + rng.normal(0.0, degToRad(0.1)), -1});
      }
      plots.push_back({static_cast<UtcUs>((turn * 2.5 + 2.5 * rng.uniform()) * 1e6),
                       500.0 + 8500.0 * rng.uniform(), 2 * kPi * rng.uniform(), -1});
    }
    std::sort(plots.begin(), plots.end(), [](const Plot& a, const Plot& b) { return a.utc < b.utc; });
    const auto period = sim::replay_input::rotationPeriodS(plots);
    QVERIFY(period);
    RK_COMPARE_NEAR(*period, 2.5, 0.05);
    plots.resize(12);
    QVERIFY(!sim::replay_input::rotationPeriodS(plots));
  }
};

QTEST_APPLESS_MAIN(TestReplaySources)
#include "tst_replay_sources.moc"
