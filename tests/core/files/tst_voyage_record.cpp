// GIVEN / WHEN / THEN: the voyage record (files/voyage_recorder.h, files/voyage_record.h,
// docs/recorder.md). A live run's batches recorded and replayed through the same pipeline
// (files/live_run.h) give the same files byte for byte and the recorded estimates bit for bit; the
// commit policy leaves at most a second uncommitted; retention keeps one row a minute; every damaged or
// foreign file is one error naming the file.
#include <QTemporaryDir>
#include <QTest>

#include <sqlite3.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "files/live_run.h"
#include "files/record_playback.h"
#include "files/recorded_actions.h"
#include "files/scenario_json.h"
#include "files/voyage_compare.h"
#include "files/voyage_record.h"
#include "files/voyage_recorder.h"
#include "io/input_error.h"
#include "io/iso8601.h"
#include "io/text_file.h"
#include "sim/nmea_export.h"
#include "support/drkf_fixtures.h"
#include "support/recorded_runs.h"
#include "support/text_lines.h"

using namespace reckoner;

namespace {

const UtcUs kDay = *io::parseIso8601("2026-11-23T00:00:00Z");

files::RecorderSettings recorderSettings(const sim::LiveOptions& lo) {
  files::RecorderSettings s;
  s.program = "tst_voyage_record";
  s.programVersion = "0";
  s.options = lo;
  s.sources = {{0, "nmea1", "nmea", "udp://:10110?name=nmea1"},
               {0, "radar1", "radar", "udp://:2000?role=radar"}};
  return s;
}

/// Runs SQL on a file with SQLite itself (to damage a record as another program would).
void sql(const std::string& path, const std::string& statement) {
  sqlite3* db = nullptr;
  QCOMPARE(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  char* error = nullptr;
  const int rc = sqlite3_exec(db, statement.c_str(), nullptr, nullptr, &error);
  const std::string why = error ? error : "";
  sqlite3_free(error);
  sqlite3_close(db);
  QVERIFY2(rc == SQLITE_OK, why.c_str());
}

/// The error opening (and reading all of) path gives; empty when there is none.
std::string errorOf(const std::string& path) {
  try {
    const files::VoyageRecord rec(path);
    (void)rec.liveOptions();
    rec.forEachBatch([](std::int64_t, std::span<const files::InputLine>) {});
    (void)rec.estimates(INT64_MIN, INT64_MAX);
    (void)rec.tracks(INT64_MIN, INT64_MAX);
    (void)rec.alerts();
    if (rec.inputCount() > 0) {  // played through to its end: no more batches than inputs
      const auto most = static_cast<std::size_t>(rec.inputCount()) + 1;
      files::RecordPlayback play(path);
      if (play.feedTo(
              INT64_MAX, [](std::int64_t, std::span<const files::InputLine>) {}, most) == most)
        return "played on and on";
    }
    return {};
  } catch (const io::InputError& e) {
    return e.what();
  }
}

void copyFile(const std::string& from, const std::string& to) {
  std::filesystem::copy_file(from, to, std::filesystem::copy_options::overwrite_existing);
}

/// A synthetic own-ship row at utc (1 s steps), for the retention test.
sim::ReplayOwnRow ownRowAt(UtcUs utc) {
  sim::ReplayOwnRow r;
  r.utcUs = utc;
  r.timeUs = utc - kDay;
  r.estimate.xM = toSeconds(r.timeUs);
  r.sensors = "gps";
  return r;
}

}  // namespace

class TestVoyageRecord : public QObject {
  Q_OBJECT

  QTemporaryDir dir_;
  std::string good_;  ///< a finished record, made by the first test, damaged by the last
  // what the live run of the first test made and recorded
  std::size_t own_ = 0, tracks_ = 0, alerts_ = 0, batches_ = 0;

 private slots:
  void initTestCase() {
    if (!QFile::exists(RECKONER_SHARED_DIR "/data/ais/gpsd-sample.aivdm"))
      QSKIP("../shared/data/ais is absent");
    QVERIFY(dir_.isValid());
  }

  void aRecordedRunReplaysToTheSameFilesAndEstimates() {
    // GIVEN a simulated run with radar plots and real AIS sentences, taken in 300 batches by a live
    // run that records them
    const std::string d = dir_.path().toStdString();
    good_ = d + "/run.sqlite";
    const sim::LiveOptions lo = test::radarLiveOptions();
    const auto batches = test::simulatedBatches(300, kDay, RECKONER_SHARED_DIR "/data/ais/gpsd-sample.aivdm");
    std::filesystem::create_directories(d + "/live");
    std::filesystem::create_directories(d + "/replay");
    std::vector<sim::ReplayOwnRow> own;
    std::size_t lines = 0, tracks = 0, alerts = 0;
    {
      files::VoyageRecorder recorder(good_, recorderSettings(lo), kDay);
      files::LiveRun run(lo, d + "/live", &recorder);
      for (const auto& b : batches) {
        const files::LiveBatch out = run.batch(b, b.front().receivedUtc);
        own.insert(own.end(), out.own.begin(), out.own.end());
        tracks += out.tracks.size();
        alerts += out.alerts.size();
        lines += b.size();
      }
      // an operator's action, as the window makes and records it (replays apply it again)
      const files::OperatorAction ack{0, kDay + 5, kDay + 6, "cpa_limits", "", "cpa_m=500;tcpa_s=300"};
      QVERIFY(files::applyOperatorAction(ack, run.watch()));
      recorder.operatorAction(ack);
      recorder.chart(
          {kDay + 7, std::nullopt, "loaded", "US5WA22M", "12", "3", "20250101", "/charts/US5WA22M.000"});
      const files::LiveBatch last = run.finish("live", batches.back().front().receivedUtc + 1);
      own.insert(own.end(), last.own.begin(), last.own.end());
      tracks += last.tracks.size();
      alerts += last.alerts.size();
      QCOMPARE(recorder.batches(), static_cast<std::int64_t>(batches.size()));
      qInfo("%zu lines in %zu batches, %zu own-ship rows, %zu track rows, %zu alert entries; %lld commits",
            lines, batches.size(), own.size(), tracks, alerts, static_cast<long long>(recorder.commits()));
    }
    QVERIFY(own.size() > 250 && tracks > 100 && alerts > 0);
    // WHEN the record is read
    const files::VoyageRecord rec(good_);
    // THEN it holds the inputs in order, the settings, the estimates bit for bit, the alerts
    QCOMPARE(rec.meta().at("schema_version"), std::string("1"));
    QVERIFY(rec.endUtc().has_value());
    QCOMPARE(rec.inputCount(), static_cast<std::int64_t>(lines));
    QCOMPARE(rec.sources().size(), std::size_t{2});
    QCOMPARE(rec.sources()[1].spec, std::string("udp://:2000?role=radar"));
    const sim::LiveOptions back = rec.liveOptions();
    QCOMPARE(files::writeScenario(back.replay.settings), files::writeScenario(lo.replay.settings));
    QCOMPARE(back.radar, true);
    QCOMPARE(back.reorderHorizonS, 1.0);
    const std::vector<sim::ReplayOwnRow> recorded = rec.estimates(INT64_MIN, INT64_MAX);
    QCOMPARE(recorded.size(), own.size());
    for (std::size_t k = 0; k < own.size(); ++k) {
      QCOMPARE(recorded[k].utcUs, own[k].utcUs);
      QCOMPARE(recorded[k].estimate.xM, own[k].estimate.xM);
      QCOMPARE(recorded[k].estimate.sdVyMps, own[k].estimate.sdVyMps);
      QCOMPARE(recorded[k].calibration.sdLogOffsetMps, own[k].calibration.sdLogOffsetMps);
      QCOMPARE(recorded[k].sensors, own[k].sensors);
    }
    QCOMPARE(rec.tracks(INT64_MIN, INT64_MAX).size(), tracks);
    QCOMPARE(rec.alerts().size(), alerts);
    QCOMPARE(rec.operatorActions().size(), std::size_t{1});
    QCOMPARE(rec.operatorActions()[0].afterBatch, static_cast<std::int64_t>(batches.size()));
    QCOMPARE(rec.charts().at(0).name, std::string("US5WA22M"));
    // AND a playback timeline can seek: the estimate nearest a time, the input at a time, pages of inputs
    const sim::ReplayOwnRow mid = own[own.size() / 2];
    QCOMPARE(rec.estimateNear(mid.utcUs + 400'000)->utcUs, mid.utcUs);
    const std::int64_t seq = rec.inputSeqAt(batches[100].front().receivedUtc);
    const std::vector<files::RecordedInput> page = rec.inputs(seq - 1, 3);
    QCOMPARE(page.size(), std::size_t{3});
    QCOMPARE(page[0].line, batches[100].front().line);
    QCOMPARE(page[0].batch, std::int64_t{101});
    QCOMPARE(rec.inputSeqAt(kDay + 86400 * kMicrosPerSecond), std::int64_t{0});

    own_ = own.size();
    tracks_ = tracks;
    alerts_ = alerts;
    batches_ = batches.size();
  }

  void aRecordReplaysThroughTheSamePipelineToTheSameFiles() {
    if (good_.empty()) QSKIP("needs the record of aRecordedRunReplaysToTheSameFilesAndEstimates");
    const std::string d = dir_.path().toStdString();
    const files::VoyageRecord rec(good_);
    // WHEN it is replayed through the same pipeline with the recorded settings, batch by batch
    files::LiveRun replay(rec.liveOptions(), d + "/replay");
    files::RecordComparer compare(rec);
    std::size_t replayedBatches = 0;
    files::ActionReplayer actions(rec.operatorActions());
    rec.forEachBatch([&](std::int64_t batch, std::span<const files::InputLine> b) {
      compare.add(replay.batch(b, 0), replay.session().result().targetLabels);
      actions.afterBatch(batch, replay.watch());
      ++replayedBatches;
    });
    QCOMPARE(actions.applied(), 1L);
    compare.add(replay.finish(rec.inputName(), 0), replay.session().result().targetLabels);
    const files::RecordComparison c = compare.finish();
    // THEN every recorded estimate, track row and alert entry is computed again, exactly
    QVERIFY2(c.equal(), c.firstDifference.c_str());
    QCOMPARE(replayedBatches, batches_);
    QCOMPARE(c.ownEqual, static_cast<long>(own_));
    QCOMPARE(c.tracksEqual, static_cast<long>(tracks_));
    QCOMPARE(c.alertsEqual, static_cast<long>(alerts_));
    QCOMPARE(c.ownNotRecorded + c.tracksNotRecorded + c.alertsNotRecorded, 0L);
    // AND the files are the live run's, byte for byte
    for (const char* f : {"ownship.csv", "targets.csv", "ais.csv", "alerts.csv", "summary.json"})
      QVERIFY2(io::readTextFile(d + "/live/" + f) == io::readTextFile(d + "/replay/" + f), f);
  }

  void aPlaybackToAClockGivesTheRecordedRun() {
    // GIVEN the record of the first test, played back to a clock that moves in uneven steps (a tenth
    // of a second to a minute, at most 7 batches a call: the window's timeline at any speed), rewound
    // two thirds of the way through and played again from the start, as a seek back does
    if (good_.empty()) QSKIP("needs the record of aRecordedRunReplaysToTheSameFilesAndEstimates");
    const std::string d = dir_.path().toStdString();
    files::RecordPlayback playback(good_);
    QCOMPARE(playback.alerts().size(), files::VoyageRecord(good_).alerts().size());
    const files::TimeSpan span = playback.span();
    QVERIFY(span.last > span.first);
    for (const int pass : {0, 1}) {
      const std::string out = d + "/playback" + std::to_string(pass);
      std::filesystem::create_directories(out);
      files::LiveRun run(playback.options(), out);
      files::RecordComparer compare(playback.record());
      files::ActionReplayer actions(playback.record().operatorActions());
      const auto feed = [&](std::int64_t batch, std::span<const files::InputLine> b) {
        compare.add(run.batch(b, 0), run.session().result().targetLabels);
        actions.afterBatch(batch, run.watch());
      };
      const UtcUs stop = pass == 0 ? span.first + (span.last - span.first) * 2 / 3 : span.last;
      UtcUs clock = span.first - 1;
      std::size_t calls = 0;
      // (a call that fed its 7 batches may have more due: the clock waits for them, as the window's does)
      for (std::int64_t step = 100'000; !playback.atEnd() && clock < stop; ++calls) {
        clock = std::min(stop, clock + step);
        while (playback.feedTo(clock, feed, 7) == 7) ++calls;
        QVERIFY(playback.position() <= clock);
        step = step >= 60 * kMicrosPerSecond ? 100'000 : step * 3;
      }
      if (pass == 0) {
        // THEN the position is where the clock stopped (within a batch's second) AND after the rewind
        QVERIFY2(
            playback.position() <= stop && playback.position() > stop - 2 * kMicrosPerSecond,
            qPrintable(QString("position %1 s before the stop").arg(toSeconds(stop - playback.position()))));
        playback.rewind();
        QCOMPARE(playback.position(), span.first);
        continue;
      }
      QVERIFY(playback.atEnd());
      compare.add(run.finish(playback.record().inputName(), 0), run.session().result().targetLabels);
      const files::RecordComparison c = compare.finish();
      // THEN the run played again from the start is the recorded run, estimate for estimate
      QVERIFY2(c.equal(), c.firstDifference.c_str());
      QCOMPARE(c.ownNotReplayed + c.tracksNotReplayed + c.alertsNotReplayed, 0L);
      qInfo("played back in %zu calls: %ld own-ship rows, %ld track rows, %ld alert entries equal", calls,
            c.ownEqual, c.tracksEqual, c.alertsEqual);
      QVERIFY(c.ownEqual > 250);
    }
    // AND a record with no input cannot be played back
    const std::string empty = d + "/empty.sqlite";
    { files::VoyageRecorder rec(empty, recorderSettings(sim::LiveOptions{}), kDay); }
    try {
      files::RecordPlayback none(empty);
      QFAIL("a record without inputs was accepted");
    } catch (const io::InputError& e) {
      QVERIFY2(std::string(e.what()).find("empty.sqlite") != std::string::npos, e.what());
    }
  }

  void operatorActionsAreAppliedAgainOrCounted() {
    sim::LiveWatch w;
    const auto act = [](std::int64_t after, const char* action, const char* subject, const char* value) {
      return files::OperatorAction{after, 0, std::nullopt, action, subject, value};
    };
    QVERIFY(files::applyOperatorAction(act(0, "cpa_limits", "", "cpa_m=500;tcpa_s=300"), w));
    QCOMPARE(w.settings().alerts.cpa.cpaM, 500.0);
    QCOMPARE(w.settings().ais.tcpaLimitS, 300.0);
    QVERIFY(files::applyOperatorAction(act(0, "dr_limit", "", "m=250"), w));
    QCOMPARE(w.settings().alerts.drLimitM, 250.0);
    QVERIFY(files::applyOperatorAction(act(0, "acknowledge", "alert:CPA/TCPA:3", ""), w));
    QVERIFY(files::applyOperatorAction(act(0, "silence_all", "", ""), w));
    QVERIFY(files::applyOperatorAction(act(0, "ais_select", "mmsi:244660000", ""), w));
    // what cannot be read or is refused is counted, never applied halfway
    for (const auto& bad :
         {act(0, "cpa_limits", "", "cpa_m=x;tcpa_s=300"), act(0, "cpa_limits", "", "cpa_m=500"),
          act(0, "dr_limit", "", "m=-5"), act(0, "acknowledge", "alert:NO SUCH ALERT:1", ""),
          act(0, "acknowledge", "alert:CPA/TCPA:x", ""), act(0, "ais_sleep", "mmsi:abc", ""),
          act(0, "teleport", "", "")})
      QVERIFY2(!files::applyOperatorAction(bad, w),
               (bad.action + " " + bad.subject + " " + bad.value).c_str());
    QCOMPARE(w.settings().alerts.cpa.cpaM, 500.0);
    QCOMPARE(w.settings().alerts.drLimitM, 250.0);
    // in batch order, each once, after its batch
    files::ActionReplayer r(
        {act(3, "dr_limit", "", "m=300"), act(1, "dr_limit", "", "m=200"), act(3, "teleport", "", "")});
    r.afterBatch(1, w);
    QCOMPARE(w.settings().alerts.drLimitM, 200.0);
    r.afterBatch(2, w);
    QCOMPARE(r.applied(), 1L);
    r.afterBatch(5, w);
    QCOMPARE(w.settings().alerts.drLimitM, 300.0);
    QCOMPARE(r.applied(), 2L);
    QCOMPARE(r.skipped(), 1L);
    r.rewind();
    r.afterBatch(1, w);
    QCOMPARE(w.settings().alerts.drLimitM, 200.0);
  }

  void commitsKeepAtMostTheLastSecondPending() {
    // GIVEN a recorder on a made-up wall clock and a reader of the same file beside it
    const std::string path = dir_.path().toStdString() + "/commits.sqlite";
    files::VoyageRecorder rec(path, recorderSettings(sim::LiveOptions{}), kDay);
    const auto committed = [&path] { return files::VoyageRecord(path).inputCount(); };
    const auto line = [](UtcUs rx) { return std::vector<files::InputLine>{{"nmea1", "$GPZDA", rx, false}}; };
    const UtcUs ms = 1000;
    // WHEN lines come at real time, one each 200 ms of wall and stream time
    rec.batch(line(kDay), {}, {}, kDay, kDay);
    rec.batch(line(kDay + 200 * ms), {}, {}, kDay + 200 * ms, kDay + 200 * ms);
    // THEN nothing is committed before the first pending line is 0.5 s old on the wall clock ...
    QCOMPARE(committed(), std::int64_t{0});
    rec.tick(kDay + 400 * ms);
    QCOMPARE(committed(), std::int64_t{0});
    // ... and then the timer's tick commits both, with no new line needed
    rec.tick(kDay + 500 * ms);
    QCOMPARE(committed(), std::int64_t{2});
    // WHEN a recording is played 100 times faster than real time (10 s of stream per 0.1 s of wall)
    for (int k = 1; k <= 100; ++k) {
      const UtcUs stream = kDay + 500 * ms + UtcUs{k} * 100 * ms, wall = kDay + 500 * ms + k * ms;
      rec.batch(line(wall), {}, {}, stream, wall);
      // THEN at most a second of stream time is ever pending
      QVERIFY(rec.lines() - committed() <= 10);
    }
    // AND the log was made durable at most once per wall second (here: the creation's, one more)
    QVERIFY(rec.syncs() <= 1);
    rec.tick(kDay + 2000 * ms);
    QCOMPARE(committed(), rec.lines());
    QCOMPARE(rec.syncs(), std::int64_t{1});
  }

  void retentionKeepsOneRowAMinuteBeyondMaxHours() {
    // GIVEN a recorder keeping full-rate estimates for 0.1 h (6 min)
    const std::string path = dir_.path().toStdString() + "/retention.sqlite";
    files::RecorderSettings s = recorderSettings(sim::LiveOptions{});
    s.maxHours = 0.1;
    files::VoyageRecorder rec(path, s, kDay);
    // WHEN 30 minutes of own-ship rows at 1 s arrive, a batch a second
    UtcUs t = kDay;
    // (played fast: 1 ms of wall time a batch, so the log is synced only every thousand commits)
    for (int k = 0; k < 1800; ++k, t += kMicrosPerSecond) {
      files::LiveBatch b;
      b.own.push_back(ownRowAt(t));
      rec.batch(std::vector<files::InputLine>{{"nmea1", "$GPRMC", t, false}}, b, {}, t,
                kDay + UtcUs{k} * 1000);
    }
    rec.finish({}, {}, kDay + UtcUs{1800} * 1000);
    // THEN the last 6 minutes are at full rate (pruning runs once a stream minute, so up to a minute more)
    const files::VoyageRecord r(path);
    const UtcUs newest = t - kMicrosPerSecond, cut = newest - 360 * kMicrosPerSecond;
    const auto recent = r.estimates(cut, newest);
    QCOMPARE(recent.size(), std::size_t{361});
    // AND before that one row a minute: the first of each minute (on the minute here)
    const auto old = r.estimates(INT64_MIN, cut - 60 * kMicrosPerSecond);
    QVERIFY(old.size() >= 20 && old.size() <= 25);
    for (const auto& o : old) QCOMPARE((o.utcUs - kDay) % (60 * kMicrosPerSecond), std::int64_t{0});
    QVERIFY(rec.prunedRows() > 1300);
    // AND the inputs are all kept
    QCOMPARE(r.inputCount(), std::int64_t{1800});
    qInfo("%lld rows pruned; %zu minute rows before the last 7 minutes",
          static_cast<long long>(rec.prunedRows()), old.size());
  }

  void theRecorderForgetsTracksGoneAMinute() {
    // GIVEN a recorder WHEN 30 minutes bring a new track every second (clutter starts thousands an hour),
    // each with a row a second for 10 s
    const std::string path = dir_.path().toStdString() + "/many-tracks.sqlite";
    files::VoyageRecorder rec(path, recorderSettings(sim::LiveOptions{}), kDay);
    UtcUs t = kDay;
    std::size_t mostRemembered = 0;
    for (int k = 0; k < 1800; ++k, t += kMicrosPerSecond) {
      files::LiveBatch b;
      b.own.push_back(ownRowAt(t));
      for (int id = std::max(0, k - 9); id <= k; ++id) {
        sim::TrackRow row;
        row.trackId = id + 1;
        b.tracks.push_back(row);
        b.trackUtc.push_back(t);
      }
      rec.batch(std::vector<files::InputLine>{{"nmea1", "$GPRMC", t, false}}, b, {}, t,
                kDay + std::int64_t{k} * 1000);
      mostRemembered = std::max(mostRemembered, rec.rememberedTracks());
    }
    rec.finish({}, {}, kDay + std::int64_t{1800} * 1000);
    // THEN it remembers the tracks of the last two or three minutes, not all 1800 (the soak's memory)
    QVERIFY2(mostRemembered <= 190, qPrintable(QString::number(mostRemembered)));
    QCOMPARE(rec.lines(), std::int64_t{1800});
  }
  void seeksAtTheEndsOfTimeAreExact() {
    // Found by fuzz_voyage_record: a record of another making with an own-ship row at utc_us =
    // INT64_MIN made estimateNear compute utc - INT64_MIN (signed overflow: UBSan's report; in a release
    // build the wrapped difference chose the far row). By reading: max(seq) = INT64_MAX overflowed the
    // input seek's bound.
    if (good_.empty()) QSKIP("needs the record of the first test");
    const std::string path = dir_.path().toStdString() + "/ends-of-time.sqlite";
    copyFile(good_, path);
    // GIVEN two own-ship rows, one at the start of int64 time and one a microsecond after `at`; and the
    // last input at seq INT64_MAX
    const UtcUs at = kDay + 600 * kMicrosPerSecond;
    sql(path,
        "DELETE FROM ownship WHERE seq NOT IN (SELECT min(seq) FROM ownship UNION SELECT max(seq) FROM "
        "ownship); UPDATE ownship SET utc_us = -9223372036854775808 WHERE seq = (SELECT min(seq) FROM "
        "ownship); UPDATE ownship SET utc_us = " +
            std::to_string(at + 1) +
            " WHERE seq = (SELECT max(seq) FROM ownship); UPDATE inputs SET seq = 9223372036854775807 "
            "WHERE seq = (SELECT max(seq) FROM inputs)");
    const files::VoyageRecord rec(path);
    // WHEN the estimate nearest `at` is asked THEN it is the row a microsecond away
    const auto near = rec.estimateNear(at);
    QVERIFY(near);
    QCOMPARE(near->utcUs, at + 1);
    QCOMPARE(rec.estimateNear(INT64_MIN)->utcUs, INT64_MIN);
    QCOMPARE(rec.estimateNear(INT64_MAX)->utcUs, at + 1);
    // AND the input seek finds the first input, the last (at INT64_MAX) or none, without overflow
    const std::int64_t firstSeq = rec.inputs(INT64_MIN, 1).at(0).seq;
    const std::vector<files::RecordedInput> last = rec.inputs(INT64_MAX - 1, 1);
    QCOMPARE(last.size(), std::size_t{1});
    QCOMPARE(last[0].seq, INT64_MAX);
    const UtcUs lastRx = last[0].receivedUtc;
    QCOMPARE(rec.inputSeqAt(INT64_MIN), firstSeq);
    // (a seek is a seq bound: the pages from it start at the first input received at lastRx)
    const std::int64_t lastBatch = rec.inputSeqAt(lastRx);
    QVERIFY(lastBatch > firstSeq);
    QCOMPARE(rec.inputs(lastBatch - 1, 1).front().receivedUtc, lastRx);
    QCOMPARE(rec.inputSeqAt(lastRx + 1), std::int64_t{0});
    QCOMPARE(rec.inputSeqAt(INT64_MAX), std::int64_t{0});
  }

  void badFilesAreOneErrorNamingTheFile_data() {
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("expected");
    QTest::newRow("missing") << "missing"
                             << "cannot open: no such file";
    QTest::newRow("folder") << "folder"
                            << "a folder, not a file";
    QTest::newRow("text") << "text"
                          << "not a SQLite database";
    QTest::newRow("empty") << "empty"
                           << "not a Reckoner voyage record: no table 'meta'";
    QTest::newRow("other database") << "other"
                                    << "not a Reckoner voyage record: no table 'meta'";
    QTest::newRow("newer schema") << "version"
                                  << "meta.schema_version: schema version '2', this program reads version 1";
    QTest::newRow("no version") << "no-version"
                                << "meta: no 'schema_version'";
    QTest::newRow("missing table") << "table"
                                   << "missing table 'tracks'";
    QTest::newRow("missing column") << "column"
                                    << "ownship: missing column 'sd_x_m'";
    QTest::newRow("bad setting") << "setting"
                                 << "meta.settings.max_gap_s: not a number: 'soon'";
    // Found by reading for fuzz_voyage_record: these were cast to integers unchecked (undefined
    // behaviour) or let through as NaN, infinity or a window of 1e300 timestamps.
    QTest::newRow("huge window") << "meta:settings.time_window=1e300"
                                 << "meta.settings.time_window: '1e300' is outside [1, 1000]";
    QTest::newRow("fractional window") << "meta:settings.time_window=2.5"
                                       << "meta.settings.time_window: not a whole number: '2.5'";
    QTest::newRow("negative jump") << "meta:settings.isolated_jump_us=-1e19"
                                   << "meta.settings.isolated_jump_us: '-1e19' is outside [0, 1000000000000]";
    QTest::newRow("nan gap") << "meta:settings.max_gap_s=nan"
                             << "meta.settings.max_gap_s: not a number: 'nan'";
    QTest::newRow("infinite horizon") << "meta:live.reorder_horizon_s=inf"
                                      << "meta.live.reorder_horizon_s: not a number: 'inf'";
    // Found by reading for fuzz_voyage_record: a playback pages on seq, and a seq that does not rise
    // gave the same page for ever.
    QTest::newRow("text seq") << "text-seq"
                              << "inputs.seq: not a rising whole number: 'x1'";
    QTest::newRow("bad scenario") << "scenario"
                                  << "meta.settings.scenario: scenario:";
    QTest::newRow("truncated") << "truncated"
                               << "";
    QTest::newRow("overwritten") << "overwritten"
                                 << "";
  }
  void badFilesAreOneErrorNamingTheFile() {
    QFETCH(QString, kind);
    QFETCH(QString, expected);
    if (good_.empty()) QSKIP("needs the record of the first test");
    const std::string d = dir_.path().toStdString(),
                      path = d + "/bad-" + QString(QTest::currentDataTag()).replace(' ', '-').toStdString() +
                             ".sqlite";
    const std::string k = kind.toStdString();
    if (k == "folder") std::filesystem::create_directory(path);
    if (k == "text") io::writeTextFile(path, "$GPRMC,not,a,database\n");
    if (k == "empty") io::writeTextFile(path, "");
    if (k == "other") sql(path, "CREATE TABLE t(x); INSERT INTO t VALUES(1)");
    const bool copy = k == "version" || k == "no-version" || k == "table" || k == "column" ||
                      k == "setting" || k.starts_with("meta:") || k == "text-seq" || k == "scenario" ||
                      k == "truncated" || k == "overwritten";
    if (copy) copyFile(good_, path);
    if (k == "version") sql(path, "UPDATE meta SET value = '2' WHERE key = 'schema_version'");
    if (k == "no-version") sql(path, "DELETE FROM meta WHERE key = 'schema_version'");
    if (k == "table") sql(path, "DROP TABLE tracks");
    if (k == "column") sql(path, "ALTER TABLE ownship DROP COLUMN sd_x_m");
    if (k == "setting") sql(path, "UPDATE meta SET value = 'soon' WHERE key = 'settings.max_gap_s'");
    if (k == "text-seq")
      sql(path,
          "ALTER TABLE inputs RENAME TO old_inputs; CREATE TABLE inputs(seq TEXT, batch INTEGER, rx_utc_us "
          "INTEGER, source INTEGER, line TEXT); INSERT INTO inputs SELECT 'x' || seq, batch, rx_utc_us, "
          "source, line FROM old_inputs; DROP TABLE old_inputs");
    if (k.starts_with("meta:")) {  // meta:KEY=VALUE
      const std::size_t eq = k.find('=');
      sql(path,
          "UPDATE meta SET value = '" + k.substr(eq + 1) + "' WHERE key = '" + k.substr(5, eq - 5) + "'");
    }
    if (k == "scenario")
      sql(path, "UPDATE meta SET value = '{\"format\": 1}' WHERE key = 'settings.scenario'");
    if (k == "truncated") std::filesystem::resize_file(path, std::filesystem::file_size(path) / 3);
    if (k == "overwritten") {
      std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
      f.seekp(static_cast<std::streamoff>(std::filesystem::file_size(path) / 2));
      const std::string junk(20000, '\x5a');
      f.write(junk.data(), static_cast<std::streamsize>(junk.size()));
    }
    // WHEN it is opened and read through THEN one error naming the file, never a crash
    const std::string error = errorOf(path);
    qInfo("%s: %s", qPrintable(kind), error.c_str());
    QVERIFY2(!error.empty(), "no error");
    QVERIFY2(error.starts_with(path + ": "), error.c_str());
    QVERIFY2(error.find(expected.toStdString()) != std::string::npos, error.c_str());
    QVERIFY(error.find('\n') == std::string::npos);
  }

  void aRecordIsNeverWrittenOver() {
    if (good_.empty()) QSKIP("needs the record of the first test");
    try {
      files::VoyageRecorder again(good_, recorderSettings(sim::LiveOptions{}), kDay);
      QFAIL("an existing record was opened for writing");
    } catch (const io::InputError& e) {
      QVERIFY2(std::string(e.what()).find("exists already") != std::string::npos, e.what());
    }
  }
};

QTEST_GUILESS_MAIN(TestVoyageRecord)
#include "tst_voyage_record.moc"
