// GIVEN / WHEN / THEN: a live run (sim/live_session.h) fed a recording line by line gives the rows of a
// file replay of it (sim/replay.h): the real recordings of ../shared/data/nmea, a simulated run, and the
// damaged streams a live source delivers (garbage, a clock jump, sentences a little out of order).
#include <QTest>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "io/iso8601.h"
#include "io/text_file.h"
#include "sim/live_session.h"
#include "sim/nmea_export.h"
#include "sim/replay.h"
#include "support/compare_near.h"
#include "support/drkf_fixtures.h"
#include "support/text_lines.h"

using namespace reckoner;

namespace {
std::vector<std::string> linesOf(const std::string& text) {
  return test::splitLines(text);
}
std::string joined(const std::vector<std::string>& lines) {
  return test::joinLines(lines);
}

struct LiveRun {
  std::vector<sim::ReplayOwnRow> rows;
  sim::ReplayResult result;
};

/// Feeds the text line by line, taking the rows now and then as a live consumer does.
LiveRun live(const std::string& text, const sim::ReplayOptions& o, double horizonS = 0.0) {
  sim::LiveOptions lo;
  lo.replay = o;
  lo.reorderHorizonS = horizonS;
  sim::LiveSession session(lo);
  LiveRun run;
  int n = 0;
  for (const std::string& l : linesOf(text)) {
    session.nmea(l);
    if (++n % 97 == 0)
      for (auto& r : session.takeOwnRows()) run.rows.push_back(r);
  }
  session.finish();
  for (auto& r : session.takeOwnRows()) run.rows.push_back(r);
  run.result = session.result();
  return run;
}

/// Every row equal, bit for bit: the same engine on the same epochs.
void compareRows(const std::vector<sim::ReplayOwnRow>& a, const std::vector<sim::ReplayOwnRow>& b) {
  QCOMPARE(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    QCOMPARE(a[k].timeUs, b[k].timeUs);
    QCOMPARE(a[k].utcUs, b[k].utcUs);
    QCOMPARE(a[k].estimate.xM, b[k].estimate.xM);
    QCOMPARE(a[k].estimate.yM, b[k].estimate.yM);
    QCOMPARE(a[k].estimate.sdXM, b[k].estimate.sdXM);
    QCOMPARE(a[k].estimate.sdYM, b[k].estimate.sdYM);
    QCOMPARE(a[k].sensors, b[k].sensors);
    QCOMPARE(a[k].rowsApplied, b[k].rowsApplied);
  }
}

void compareCounts(const sim::ReplayStats& a, const sim::ReplayStats& b) {
  QCOMPARE(a.nmeaLines, b.nmeaLines);
  QCOMPARE(a.sentencesUsed, b.sentencesUsed);
  QCOMPARE(a.nmeaSkipped(), b.nmeaSkipped());
  QCOMPARE(a.standby, b.standby);
  QCOMPARE(a.repeated, b.repeated);
  QCOMPARE(a.epochs, b.epochs);
  QCOMPARE(a.epochsTimeOnly, b.epochsTimeOnly);
  QCOMPARE(a.timeJumps, b.timeJumps);
  QCOMPARE(a.restartsAfterGap, b.restartsAfterGap);
}

sim::ExportedRun simulated(int seconds) {
  sim::Scenario s = test::builtinScenario("ttkf-matched");
  s.durationUs = seconds * kMicrosPerSecond;
  return sim::exportRun(s, 3, *io::parseIso8601("2026-11-23T10:00:00Z"));
}
}  // namespace

class TestLiveSession : public QObject {
  Q_OBJECT
 private slots:
  void realRecordingsGiveTheReplaysRows() {
    // GIVEN each real recording WHEN fed line by line THEN every row and count equals the file replay's.
    const std::string dir = RECKONER_SHARED_DIR "/data/nmea/";
    for (const char* f : {"gpsd-bundg_zeus_9.log", "openrvdas-NBP1406_seap-2014-08-01.nmea"}) {
      const std::string text = io::readTextFile(dir + f);
      const sim::ReplayOptions o;
      const sim::ReplayResult batch = sim::replay(text, f, nullptr, "", o);
      const LiveRun l = live(text, o);
      qInfo("%s: %zu rows, %ld sentences used, %ld skipped", f, l.rows.size(), l.result.stats.sentencesUsed,
            l.result.stats.nmeaSkipped());
      QVERIFY(!l.rows.empty());
      compareRows(l.rows, batch.own);
      compareCounts(l.result.stats, batch.stats);
      QCOMPARE(l.result.origin.latDeg, batch.origin.latDeg);
      QCOMPARE(l.result.sources.size(), batch.sources.size());
      for (std::size_t i = 0; i < batch.sources.size(); ++i) {
        QCOMPARE(l.result.sources[i].source, batch.sources[i].source);
        QCOMPARE(l.result.sources[i].used, batch.sources[i].used);
        QCOMPARE(l.result.sources[i].standby, batch.sources[i].standby);
      }
    }
  }

  void simulatedRunWithGarbageAndAClockJump() {
    // GIVEN a simulated run's sentences with garbage, a 1 MB line and one sentence stamped an hour
    // ahead WHEN fed live THEN the rows equal the file replay of the same text, the jump dropped by both.
    auto lines = linesOf(simulated(300).nmea);
    lines.insert(lines.begin() + 50, std::string(1 << 20, 'x'));
    lines.insert(lines.begin() + 80, "$GPGGA,garbage*00");
    lines.insert(lines.begin() + 81, std::string("\x01\x02\xff$GPRMC,,,", 10));
    for (std::size_t i = 200; i < lines.size(); ++i)
      if (lines[i].rfind("$GPGGA,", 0) == 0) {
        lines[i] = "$GPGGA,110500.00" + lines[i].substr(lines[i].find(',', 7));
        break;
      }
    const std::string text = joined(lines);
    sim::ReplayOptions o;
    o.settings = test::builtinScenario("ttkf-matched");
    const sim::ReplayResult batch = sim::replay(text, "run.nmea", nullptr, "", o);
    const LiveRun l = live(text, o);
    QVERIFY(batch.stats.malformed + batch.stats.badChecksum >= 2);
    compareRows(l.rows, batch.own);
    compareCounts(l.result.stats, batch.stats);
  }

  void sentencesOutOfOrderWithinTheHorizon() {
    // GIVEN second 100 written after second 104 WHEN fed live with a 5 s reorder horizon THEN the rows
    // equal the replay's (which sorts the file); with no horizon second 100 is late: skipped and
    // counted, and the run goes on.
    auto lines = linesOf(simulated(200).nmea);
    std::vector<std::size_t> starts;
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (lines[i].rfind("$GPRMC,", 0) == 0) starts.push_back(i);
    const std::size_t a = starts[100], b = starts[101], c = starts[105];
    std::vector<std::string> swapped(lines.begin(), lines.begin() + static_cast<std::ptrdiff_t>(a));
    swapped.insert(swapped.end(), lines.begin() + static_cast<std::ptrdiff_t>(b),
                   lines.begin() + static_cast<std::ptrdiff_t>(c));
    swapped.insert(swapped.end(), lines.begin() + static_cast<std::ptrdiff_t>(a),
                   lines.begin() + static_cast<std::ptrdiff_t>(b));
    swapped.insert(swapped.end(), lines.begin() + static_cast<std::ptrdiff_t>(c), lines.end());
    const std::string text = joined(swapped);
    sim::ReplayOptions o;
    o.settings = test::builtinScenario("ttkf-matched");
    const sim::ReplayResult batch = sim::replay(text, "run.nmea", nullptr, "", o);
    QVERIFY(batch.stats.reordered > 0);
    const LiveRun held = live(text, o, 5.0);
    compareRows(held.rows, batch.own);
    const LiveRun now = live(text, o, 0.0);
    qInfo("no horizon: %ld sentences late, %zu rows (the replay: %zu)", now.result.stats.late,
          now.rows.size(), batch.own.size());
    // Second 100's RMC, GGA, GLL, its second GLL and the untimed sentences that followed them: every
    // sentence of the late second counts (fuzz_nmea_epochs: the untimed followers were counted nowhere).
    QCOMPARE(now.result.stats.late, 6L);
    const sim::ReplayStats& st = now.result.stats;
    long sentences = 0;
    for (const sim::SourceStats& src : now.result.sources) sentences += src.sentences;
    QCOMPARE(sentences, st.sentencesUsed + st.notUsed + st.repeated + st.standby + st.unusable + st.notGnss +
                            st.implausible + st.noVariation + st.timeJumps + st.untimed + st.late);
    QVERIFY(now.rows.size() <= batch.own.size());
    for (std::size_t k = 1; k < now.rows.size(); ++k) QVERIFY(now.rows[k].timeUs > now.rows[k - 1].timeUs);
  }

  void radarPlotsInterleavedGiveTheReplaysTracks() {
    // GIVEN a simulated run's NMEA and radar CSV, interleaved by time as two live sources deliver them
    // WHEN fed live THEN the own-ship rows and every track row equal the file replay's, both with the
    // file's target_id association and by nearest neighbour.
    const sim::ExportedRun e = simulated(300);
    const auto nmea = linesOf(e.nmea);
    const auto radar = linesOf(e.radarCsv);
    const UtcUs day = *io::parseIso8601("2026-11-23T00:00:00Z");
    for (const bool known : {true, false}) {
      sim::ReplayOptions o;
      o.settings = test::builtinScenario("ttkf-matched");
      o.assumeAssociation = known;
      const sim::ReplayResult batch = sim::replay(e.nmea, "run.nmea", &e.radarCsv, "run.csv", o);
      sim::LiveOptions lo;
      lo.replay = o;
      lo.radar = true;
      sim::LiveSession session(lo);
      std::size_t r = 0;
      std::vector<sim::TrackRow> tracks;
      for (const std::string& l : nmea) {
        if (l.rfind("$GPRMC,", 0) == 0) {  // the plots stamped before this second go first
          const int hh = std::stoi(l.substr(7, 2)), mm = std::stoi(l.substr(9, 2)),
                    ss = std::stoi(l.substr(11, 2));
          const UtcUs t = day + ((hh * 60 + mm) * 60 + ss) * kMicrosPerSecond;
          for (; r < radar.size(); ++r) {
            const auto u = io::parseIso8601(radar[r].substr(0, radar[r].find(',')));
            if (u && *u >= t) break;
            session.radar(radar[r]);
          }
        }
        session.nmea(l);
        for (auto& tr : session.takeTrackRows()) tracks.push_back(tr);
      }
      for (; r < radar.size(); ++r) session.radar(radar[r]);
      session.finish();
      for (auto& tr : session.takeTrackRows()) tracks.push_back(tr);
      compareRows(session.takeOwnRows(), batch.own);
      qInfo("%s: %zu track rows, %ld plots", known ? "known association" : "nearest neighbour", tracks.size(),
            session.result().stats.radarLines);
      QVERIFY(!tracks.empty());
      QCOMPARE(tracks.size(), batch.tracks.size());
      for (std::size_t k = 0; k < tracks.size(); ++k) {
        QCOMPARE(tracks[k].timeUs, batch.tracks[k].timeUs);
        QCOMPARE(tracks[k].trackId, batch.tracks[k].trackId);
        QCOMPARE(tracks[k].estXM, batch.tracks[k].estXM);
        QCOMPARE(tracks[k].estYM, batch.tracks[k].estYM);
      }
      QCOMPARE(session.result().stats.radarLate, 0L);
      QCOMPARE(session.result().stats.radarTimeJumps, batch.stats.radarTimeJumps);
    }
  }

  void theGnssFailsAndHeadingAndLogGoOn() {
    // GIVEN a simulated run whose GNSS, Loran-C and ZDA stop after 120 s while the gyro and log report on,
    // received at 1 Hz WHEN fed live THEN own-ship rows keep coming each second (dead reckoning on gyro and
    // log), where the untimed sentences would otherwise pile up on the last fix's time; without receive times
    // one time holds at most kMaxGroup of them.
    std::vector<std::string> lines;
    std::vector<UtcUs> received;
    const UtcUs start = *io::parseIso8601("2026-11-23T10:00:00Z");
    int second = -1;
    for (const auto& l : linesOf(simulated(600).nmea)) {
      if (l.rfind("$GPRMC", 0) == 0) ++second;
      const bool fix = l.rfind("$GP", 0) == 0 || l.rfind("$LC", 0) == 0 || l.rfind("$IIZDA", 0) == 0;
      if (fix && second >= 120) continue;
      lines.push_back(l);
      received.push_back(start + second * kMicrosPerSecond + 300'000);
    }
    sim::LiveOptions lo;
    lo.replay.settings = test::builtinScenario("ttkf-matched");
    sim::LiveSession session(lo);
    for (std::size_t i = 0; i < lines.size(); ++i) session.nmea(lines[i], received[i]);
    session.finish();
    const auto rows = session.takeOwnRows();
    qInfo("%zu lines, %zu rows, the last at %.0f s", lines.size(), rows.size(),
          rows.empty() ? 0.0 : toSeconds(rows.back().timeUs));
    // The run's data end at `second`: a row every second to there, 280 of them without a fix.
    QVERIFY(second > 300);
    QVERIFY(rows.size() + 5 >= static_cast<std::size_t>(second));
    QVERIFY(toSeconds(rows.back().timeUs) >= second - 1.0);
    QCOMPARE(rows.back().sensors.find("gps"), std::string::npos);

    sim::LiveSession untimed(lo);
    for (const auto& l : lines) untimed.nmea(l);
    untimed.finish();
    QVERIFY(untimed.result().stats.untimed > 0);
  }

  void aStreamWithoutDatesTakesTheReceiveClocksDay() {
    // GIVEN GGA and HDT only (no date anywhere) received on 2026-12-02 WHEN fed live with receive times
    // THEN the rows are dated that day, as a file replay told the day gives them (without it, a file
    // replay says 1970-01-01 and warns).
    std::vector<std::string> lines;
    for (const auto& l : linesOf(simulated(900).nmea))
      if (l.rfind("$GPGGA", 0) == 0 || l.rfind("$HEHDT", 0) == 0) lines.push_back(l);
    sim::LiveOptions lo;
    lo.replay.settings = test::builtinScenario("ttkf-matched");
    sim::LiveSession session(lo);
    const UtcUs received = *io::parseIso8601("2026-12-02T10:00:30Z");
    for (const auto& l : lines) session.nmea(l, received);
    session.finish();
    const auto rows = session.takeOwnRows();
    // The file replay told the day (--date) gives the same rows.
    sim::ReplayOptions o = lo.replay;
    o.date = std::array<int, 3>{2026, 12, 2};
    const sim::ReplayResult batch = sim::replay(joined(lines), "run.nmea", nullptr, "", o);
    QVERIFY(!rows.empty());
    compareRows(rows, batch.own);
    QCOMPARE(io::formatIso8601(rows.front().utcUs).substr(0, 10), std::string("2026-12-02"));
  }
};

QTEST_APPLESS_MAIN(TestLiveSession)
#include "tst_live_session.moc"
