// GIVEN / WHEN / THEN: replay of recordings damaged the way real ones are (gaps, clock jumps, files out
// of order, impossible values, estimated fixes, labels, duplicates, byte-order marks). Each case failed
// before the stream-time policy and the restart after a gap (docs/outputs.md, "Replay: time"); every
// replay here runs under a CPU-time and memory limit, so a hang or an unbounded allocation fails.
#include <QFile>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "files/track_output.h"
#include "io/input_error.h"
#include "io/iso8601.h"
#include "io/json.h"
#include "io/nmea.h"
#include "sim/nmea_export.h"
#include "sim/replay.h"
#include "support/compare_near.h"
#include "support/drkf_fixtures.h"
#include "support/resource_limits.h"
#include "support/text_lines.h"

using namespace reckoner;
namespace nm = reckoner::io::nmea;

namespace {
std::vector<std::string> linesOf(const std::string& text) {
  return test::splitLines(text);
}
std::string joined(const std::vector<std::string>& lines) {
  return test::joinLines(lines);
}

/// The sentence with field k (0: the address) replaced, checksum recomputed.
std::string withField(const std::string& sentence, std::size_t k, const std::string& value) {
  const std::string body = sentence.substr(1, sentence.find('*') - 1);
  std::vector<std::string> f;
  for (std::size_t s = 0;;) {
    const std::size_t c = body.find(',', s);
    f.push_back(body.substr(s, c == std::string::npos ? std::string::npos : c - s));
    if (c == std::string::npos) break;
    s = c + 1;
  }
  f.at(k) = value;
  std::string out;
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (i > 0) out += ',';
    out += f[i];
  }
  return nm::withChecksum(out);
}

bool startsWith(const std::string& s, const char* p) {
  return s.rfind(p, 0) == 0;
}

/// Epoch index of each line of an exported file (each epoch starts with its ZDA).
std::vector<int> epochOfLines(const std::vector<std::string>& lines) {
  std::vector<int> out;
  int k = -1;
  for (const auto& l : lines) {
    if (startsWith(l, "$IIZDA")) ++k;
    out.push_back(k);
  }
  return out;
}

bool finiteRows(const sim::ReplayResult& r) {
  return std::all_of(r.own.begin(), r.own.end(), [](const sim::ReplayOwnRow& o) {
    const auto& e = o.estimate;
    return std::isfinite(e.xM) && std::isfinite(e.yM) && std::isfinite(e.vxMps) && std::isfinite(e.vyMps) &&
           std::isfinite(e.sdXM) && std::isfinite(e.sdYM) && std::isfinite(e.sdVxMps) &&
           std::isfinite(e.sdVyMps);
  });
}
}  // namespace

class TestReplayHostile : public QObject {
  Q_OBJECT
  sim::Scenario scenario_;
  sim::ExportedRun run_;
  UtcUs utc0_ = 0;

  [[nodiscard]] sim::ReplayOptions options() const {
    sim::ReplayOptions o;
    o.settings = scenario_;
    o.settingsName = "ttkf-matched.json";
    o.originFromSettings = true;
    return o;
  }
  /// Largest distance of the replay's estimate from the truth over the rows from `from` on.
  [[nodiscard]] double worstError(const sim::ReplayResult& r, std::size_t from = 0) const {
    double worst = 0.0;
    for (std::size_t k = from; k < r.own.size(); ++k) {
      const TimeUs t = r.own[k].timeUs + (r.utc0 - utc0_);
      const auto it = std::find_if(run_.truth.rows.begin(), run_.truth.rows.end(),
                                   [t](const sim::OwnShipRow& row) { return row.timeUs == t; });
      if (it == run_.truth.rows.end()) continue;
      worst =
          std::max(worst, std::hypot(r.own[k].estimate.xM - it->trueXM, r.own[k].estimate.yM - it->trueYM));
    }
    return worst;
  }

 private slots:
  void initTestCase() {
    test::limitThisProcess(300, std::size_t{4} << 30);
    scenario_ = test::builtinScenario("ttkf-matched");
    scenario_.durationUs = 600 * kMicrosPerSecond;
    utc0_ = *io::parseIso8601("2026-11-23T10:00:00Z");
    run_ = sim::exportRun(scenario_, 5, utc0_);
  }

  void gapOfMinutesRestartsTheFilterAtTheNextFix() {
    // GIVEN a recording with nothing for 200 s WHEN replayed THEN the DRKF restarts at the first fix
    // after the gap (counted), every row is finite and the estimate after the gap is on the truth.
    const auto lines = linesOf(run_.nmea);
    const auto epoch = epochOfLines(lines);
    std::vector<std::string> cut;
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (epoch[i] < 150 || epoch[i] >= 350) cut.push_back(lines[i]);
    const auto r = sim::replay(joined(cut), "gap.nmea", nullptr, "", options());
    QCOMPARE(r.stats.restartsAfterGap, 1L);
    QVERIFY(finiteRows(r));
    QCOMPARE(r.updates[nav::kGpsPosition].failed, 0L);
    const double worst = worstError(r, 160);
    qInfo("after a 200 s gap: worst error %.1f m, final sd %.1f m", worst, r.own.back().estimate.sdXM);
    QVERIFY(worst < 60.0);
    QVERIFY(r.own.back().estimate.sdXM < 10.0);
  }
  void gapWithoutRestartIsPredictedAcross() {
    // GIVEN the same gap and a max gap longer than it WHEN replayed THEN the DRKF predicts across the
    // 200 s (its covariance stays positive definite: it used to turn to NaN there) and takes GPS again.
    const auto lines = linesOf(run_.nmea);
    const auto epoch = epochOfLines(lines);
    std::vector<std::string> cut;
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (epoch[i] < 150 || epoch[i] >= 350) cut.push_back(lines[i]);
    sim::ReplayOptions o = options();
    o.maxGapS = 1e6;
    const auto r = sim::replay(joined(cut), "gap.nmea", nullptr, "", o);
    QCOMPARE(r.stats.restartsAfterGap, 0L);
    QVERIFY(finiteRows(r));
    QCOMPARE(r.updates[nav::kGpsPosition].failed, 0L);
    QVERIFY(r.updates[nav::kGpsPosition].accepted > 300);
    QVERIFY(r.own.back().estimate.sdXM < 10.0);
  }
  void oneSentenceStampedAheadIsDroppedAlone() {
    // GIVEN one RMC stamped 20 minutes ahead with a valid checksum WHEN replayed THEN it alone is
    // dropped as a clock error: every other sentence is used and the last row is finite and on track.
    auto lines = linesOf(run_.nmea);
    std::size_t seen = 0;
    for (auto& l : lines) {
      if (!startsWith(l, "$GPRMC") || ++seen != 100) continue;
      const std::string t = l.substr(7, 10);  // hhmmss.sss
      char stamp[16];
      std::snprintf(stamp, sizeof stamp, "%s%02d%s", t.substr(0, 2).c_str(), std::stoi(t.substr(2, 2)) + 20,
                    t.substr(4).c_str());
      l = withField(l, 1, stamp);
    }
    const auto r = sim::replay(joined(lines), "jump.nmea", nullptr, "", options());
    QCOMPARE(r.stats.timeJumps, 1L);
    QCOMPARE(r.stats.nmeaSkipped(), 1L);
    QCOMPARE(r.own.size(), run_.truth.rows.size());
    QVERIFY(finiteRows(r));
    QVERIFY(worstError(r, 30) < 30.0);
  }
  void reversedFileIsReplayedInTimeOrder() {
    // GIVEN the first 600 lines of a recording in reverse order WHEN replayed THEN all timed sentences
    // are used in time order (counted as reordered, with a warning), not dropped as out of order.
    auto lines = linesOf(run_.nmea);
    lines.resize(600);
    std::reverse(lines.begin(), lines.end());
    const auto r = sim::replay(joined(lines), "reversed.nmea", nullptr, "", options());
    QVERIFY2(r.stats.sentencesUsed >= 590, qPrintable(QString::number(r.stats.sentencesUsed)));
    QVERIFY(r.stats.reordered > 0);
    QVERIFY(!r.warnings.empty());
    for (std::size_t k = 1; k < r.own.size(); ++k) QVERIFY(r.own[k].timeUs > r.own[k - 1].timeUs);
    QVERIFY(worstError(r, 10) < 30.0);
  }
  void impossibleSpeedIsNotTaken() {
    // GIVEN a first RMC of 1,000,000 kn WHEN replayed THEN it is counted implausible and the filter
    // starts at a ship's speed (it started at 514 km/s).
    auto lines = linesOf(run_.nmea);
    for (auto& l : lines)
      if (startsWith(l, "$GPRMC")) {
        l = withField(l, 7, "1000000.0");
        break;
      }
    const auto r = sim::replay(joined(lines), "fast.nmea", nullptr, "", options());
    QCOMPARE(r.stats.implausible, 1L);
    QVERIFY(std::hypot(r.own.front().estimate.vxMps, r.own.front().estimate.vyMps) < 30.0);
    QVERIFY(finiteRows(r));
  }
  void estimatedManualAndSimulatorFixesAreNotGnss() {
    // GIVEN every GGA with quality 6 (estimated) and every RMC with mode E WHEN replayed THEN none is
    // taken as a GPS fix (they are counted), and the replay runs on the Loran-C fixes it has.
    auto lines = linesOf(run_.nmea);
    long changed = 0;
    for (auto& l : lines) {
      if (startsWith(l, "$GPGGA")) l = withField(l, 6, "6"), ++changed;
      if (startsWith(l, "$GPRMC")) l = withField(l, 12, "E"), ++changed;
    }
    const auto r = sim::replay(joined(lines), "estimated.nmea", nullptr, "", options());
    QCOMPARE(r.stats.notGnss, changed);
    QCOMPARE(r.updates[nav::kGpsPosition].accepted + r.updates[nav::kGpsPosition].gated, 0L);
    qInfo("Loran-C fixes accepted %ld", r.updates[nav::kLoranPosition].accepted);
    QVERIFY(r.updates[nav::kLoranPosition].accepted > 300);  // Loran-C is off from 200 to 400 s
  }
  void proprietaryAndByteOrderMark() {
    // GIVEN a file saved with a UTF-8 byte-order mark and proprietary $P sentences WHEN replayed THEN
    // the first line is read and the proprietary sentences are counted as such, not as malformed.
    auto lines = linesOf(run_.nmea);
    lines.insert(lines.begin() + 3, nm::withChecksum("PGRME,15.0,M,45.0,M,25.0,M"));
    lines.insert(lines.begin(), "# recorded by a logger that writes comments");
    const auto r = sim::replay("\xEF\xBB\xBF" + joined(lines), "bom.nmea", nullptr, "", options());
    QCOMPARE(r.stats.proprietary, 1L);
    QCOMPARE(r.stats.comments, 1L);
    QCOMPARE(r.stats.malformed, 0L);
    QCOMPARE(r.stats.untimed, 0L);
    QCOMPARE(r.own.size(), run_.truth.rows.size());
  }
  void summaryCountsUpdatesPerSensorAndRestarts() {
    // GIVEN any replay WHEN its summary.json is written THEN it gives, per DRKF sensor block, updates
    // accepted, gated out and failed, and the restarts; the counts add up to the epochs' blocks.
    const auto r = sim::replay(run_.nmea, "run.nmea", &run_.radarCsv, "run.csv", options());
    const io::JsonValue j = io::parseJson(files::replaySummaryJson(r, "run.nmea"));
    const io::JsonValue* updates = j.find("own_ship_filter")->find("updates");
    QVERIFY(updates);
    for (const char* block : {"gps_position", "gps_velocity", "loran_c", "speedlog", "gyro"}) {
      const io::JsonValue* b = updates->find(block);
      QVERIFY2(b && b->find("accepted") && b->find("gated") && b->find("failed"), block);
    }
    QCOMPARE(j.find("own_ship_filter")->find("restarts")->find("after_gap")->number, 0.0);
    const long gpsEpochs = static_cast<long>(std::count_if(r.own.begin(), r.own.end(), [](const auto& o) {
      return o.sensors.find("gps") != std::string::npos;
    }));
    const auto& g = r.updates[nav::kGpsPosition];
    QCOMPARE(g.accepted + g.gated + g.failed, gpsEpochs);
  }
  void farOriginFallsBackToTheFirstFixWithAWarning() {
    // GIVEN settings whose origin is 5,000 km from the data WHEN replayed THEN the grid frame starts
    // at the first fix and a warning names the settings and their origin (it failed with an error
    // that named no file).
    sim::ReplayOptions o = options();
    o.settings.origin = {10.0, -30.0};
    const auto r = sim::replay(run_.nmea, "run.nmea", nullptr, "", o);
    QCOMPARE(r.warnings.size(), std::size_t(1));
    QVERIFY2(r.warnings[0].rfind("ttkf-matched.json: origin: ", 0) == 0, r.warnings[0].c_str());
    RK_COMPARE_NEAR(r.origin.latDeg, scenario_.origin.latDeg, 1.0);
    QVERIFY(finiteRows(r));
  }

  void realRecordingsReadWhole() {
    // GIVEN the two real recordings (../shared/data/nmea) WHEN replayed THEN no line is malformed (the
    // Seapath's $PSXN attitude sentences were 2,142 malformed lines; gpsd's '#' comments 10), every
    // epoch with a fix has its fix accepted, and every row is finite.
    const std::string dir = RECKONER_SHARED_DIR "/data/nmea/";
    if (!QFile::exists(QString::fromStdString(dir))) QSKIP("../shared/data/nmea is absent");
    for (const char* name : {"openrvdas-NBP1406_seap-2014-08-01.nmea", "gpsd-bundg_zeus_9.log"}) {
      QFile f(QString::fromStdString(dir + name));
      QVERIFY(f.open(QIODevice::ReadOnly));
      const std::string text = f.readAll().toStdString();
      const auto r = sim::replay(text, name, nullptr, "", sim::ReplayOptions{});
      qInfo("%s: %ld lines, %ld used, %ld proprietary, %ld unknown, %ld comments, GPS %ld/%ld/%ld", name,
            r.stats.nmeaLines, r.stats.sentencesUsed, r.stats.proprietary, r.stats.unknownSentences,
            r.stats.comments, r.updates[nav::kGpsPosition].accepted, r.updates[nav::kGpsPosition].gated,
            r.updates[nav::kGpsPosition].failed);
      QCOMPARE(r.stats.malformed, 0L);
      QCOMPARE(r.stats.badChecksum, 0L);
      QCOMPARE(r.updates[nav::kGpsPosition].gated + r.updates[nav::kGpsPosition].failed, 0L);
      QVERIFY(finiteRows(r));
    }
  }

  void radarLabelsAreAnyText() {
    // GIVEN target_id labels that are not integers ("T5") WHEN replayed with association by target_id
    // THEN every line is used and the tracks carry the labels (every line was bad before).
    auto rows = linesOf(run_.radarCsv);
    for (std::size_t i = 1; i < rows.size(); ++i) {
      const std::size_t comma = rows[i].rfind(',');
      if (comma != std::string::npos && comma + 1 < rows[i].size())
        rows[i] = rows[i].substr(0, comma + 1).append("T").append(rows[i].substr(comma + 1));
    }
    const std::string csv = joined(rows);
    sim::ReplayOptions o = options();
    o.assumeAssociation = true;
    const auto r = sim::replay(run_.nmea, "run.nmea", &csv, "labels.csv", o);
    QCOMPARE(r.stats.radarBad, 0L);
    QVERIFY(!r.targetLabels.empty());
    QVERIFY(std::all_of(r.targetLabels.begin(), r.targetLabels.end(),
                        [](const std::string& l) { return l[0] == 'T'; }));
    QVERIFY(std::any_of(r.tracks.begin(), r.tracks.end(),
                        [](const sim::TrackRow& t) { return t.targetId >= 0; }));
  }
  void radarFileWithoutAUsableLineIsAnError() {
    // GIVEN a radar file whose every line is bad WHEN replayed THEN one error names the file, the first
    // bad line and its reason (replay used to finish with no tracks and exit 0).
    const std::string csv = "utc,range_m,bearing_deg\n2026-11-23T10:00:01Z,abc,10\nnot,a,line\n";
    try {
      sim::replay(run_.nmea, "run.nmea", &csv, "bad.csv", options());
      QFAIL("accepted a radar file without a usable plot");
    } catch (const io::InputError& e) {
      QVERIFY2(QString(e.what()).startsWith("bad.csv:2: range_m: no usable plot"), e.what());
    }
  }
  void radarYearBitFlipAndLongGapCostNothing() {
    // GIVEN one plot whose year reads 6026 WHEN replayed THEN it is dropped as a clock error; GIVEN the
    // second half of the plots 4000 years later (not a lone row) WHEN replayed THEN the replay skips the
    // gap instead of closing every sweep of it (it ran for hours) and its rows stay bounded.
    auto rows = linesOf(run_.radarCsv);
    auto flipped = rows;
    flipped[rows.size() / 2][0] = '6';
    const std::string one = joined(flipped);
    const auto r1 = sim::replay(run_.nmea, "run.nmea", &one, "year.csv", options());
    QCOMPARE(r1.stats.radarTimeJumps, 1L);
    auto later = rows;
    for (std::size_t i = rows.size() / 2; i < rows.size(); ++i)
      if (!later[i].empty()) later[i][0] = '6';
    const std::string half = joined(later);
    const auto r2 = sim::replay(run_.nmea, "run.nmea", &half, "years.csv", options());
    QCOMPARE(r2.stats.radarTimeJumps, 0L);
    const auto plain = sim::replay(run_.nmea, "run.nmea", &run_.radarCsv, "run.csv", options());
    QVERIFY2(r2.tracks.size() < 2 * plain.tracks.size(),
             qPrintable(QString("%1 rows against %2").arg(r2.tracks.size()).arg(plain.tracks.size())));
  }
  void duplicatePlotsCountOnce() {
    // GIVEN 5,000 copies of one plot WHEN replayed THEN they count as duplicates and the tracks are
    // those of the file without them (the copies took minutes in one association cluster).
    auto rows = linesOf(run_.radarCsv);
    rows.insert(rows.begin() + 200, 5000, rows[200]);
    const std::string csv = joined(rows);
    const auto r = sim::replay(run_.nmea, "run.nmea", &csv, "dup.csv", options());
    QCOMPARE(r.stats.radarDuplicates, 5000L);
    const auto plain = sim::replay(run_.nmea, "run.nmea", &run_.radarCsv, "run.csv", options());
    QCOMPARE(r.tracks.size(), plain.tracks.size());
    QCOMPARE(r.tracking.tracksConfirmed, plain.tracking.tracksConfirmed);
  }
  void radarByteOrderMark() {
    const std::string csv = "\xEF\xBB\xBF" + run_.radarCsv;
    const auto r = sim::replay(run_.nmea, "run.nmea", &csv, "bom.csv", options());
    QCOMPARE(r.stats.radarBad, 0L);
    QCOMPARE(r.stats.radarPlots, static_cast<long>(linesOf(run_.radarCsv).size()) - 1);  // less the header
  }
};

QTEST_APPLESS_MAIN(TestReplayHostile)
#include "tst_replay_hostile.moc"
