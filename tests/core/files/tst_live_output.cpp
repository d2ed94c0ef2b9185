// GIVEN / WHEN / THEN: a live run's files (files/live_output.h) written a batch at a time equal the
// replay's files of the same sentences (ownship.csv byte for byte), with AIS interleaved going to
// ais.csv, and an output that cannot be written is one error naming the file.
#include <QTemporaryDir>
#include <QTest>

#include <string>
#include <vector>

#include "files/ais_output.h"
#include "files/live_output.h"
#include "files/track_output.h"
#include "io/ais.h"
#include "io/input_error.h"
#include "io/json.h"
#include "io/text_file.h"
#include "sim/live_session.h"
#include "sim/live_watch.h"
#include "sim/replay.h"
#include "support/text_lines.h"

using namespace reckoner;

class TestLiveOutput : public QObject {
  Q_OBJECT
 private slots:
  void aRecordingWithAisInterleavedGivesTheReplaysFiles() {
    // GIVEN a real recording and real AIS sentences interleaved, one AIS line after every 7 NMEA lines
    const std::string nmea = io::readTextFile(RECKONER_SHARED_DIR "/data/nmea/gpsd-bundg_zeus_9.log");
    std::vector<std::string> ais;  // the sentences of the sample (its comments give gpsd's decodes)
    for (auto& l : test::splitLines(io::readTextFile(RECKONER_SHARED_DIR "/data/ais/gpsd-sample.aivdm")))
      if (l.starts_with('!')) ais.push_back(l);
    const auto own = test::splitLines(nmea);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string out = dir.path().toStdString();
    // WHEN fed line by line to a live session whose rows are written every 50 lines
    sim::LiveOptions lo;
    lo.frames = true;
    sim::LiveSession session(lo);
    sim::LiveWatch watch;
    files::LiveOutputWriter writer(out, false);
    const auto write = [&] {
      const sim::LiveWatch::Taken taken = watch.absorb(session, std::nullopt);
      writer.append(session, taken.ais, watch);
    };
    std::size_t a = 0, n = 0;
    io::AisDecoder reference;
    std::size_t aisDecoded = 0;
    for (const std::string& l : own) {
      session.nmea(l, std::nullopt, "bus");
      if (++n % 7 == 0 && a < ais.size()) {
        if (reference.feed(ais[a])) ++aisDecoded;
        session.nmea(ais[a++], std::nullopt, "bus");
      }
      if (n % 50 == 0) write();
    }
    session.finish();
    const sim::LiveWatch::Taken last = watch.absorb(session, std::nullopt);
    writer.finish(session, last.ais, watch, "bus");
    // THEN ownship.csv is the replay's, byte for byte
    const sim::ReplayResult batch = sim::replay(nmea, "bus", nullptr, "", sim::ReplayOptions{});
    files::writeReplayOwnShipCsv(out + "/replay_ownship.csv", batch);
    QVERIFY(batch.own.size() > 100);
    QCOMPARE(io::readTextFile(out + "/ownship.csv"), io::readTextFile(out + "/replay_ownship.csv"));
    QCOMPARE(writer.ownRows(), static_cast<long>(batch.own.size()));
    // AND every AIS message an independent decoder run gives is one ais.csv row, after the header
    const auto rows = test::splitLines(io::readTextFile(out + "/ais.csv"));
    QVERIFY(aisDecoded > 10);
    QCOMPARE(rows.size(), aisDecoded + 1);
    QCOMPARE(rows.front(), files::aisCsvHeader());
    QVERIFY(rows[1].find(",bus,") != std::string::npos);
    QCOMPARE(session.aisCounters().decoded, static_cast<std::uint64_t>(aisDecoded));
    // AND summary.json carries the AIS counts and the replay's own-ship counts
    const io::JsonValue summary = io::parseJson(io::readTextFile(out + "/summary.json"));
    const io::JsonValue* aisCounts = summary.find("ais");
    QVERIFY(aisCounts && aisCounts->find("lines") && aisCounts->find("decoded"));
    QCOMPARE(aisCounts->find("lines")->number, static_cast<double>(a));
    QCOMPARE(aisCounts->find("decoded")->number, static_cast<double>(aisDecoded));
    const io::JsonValue* counts = summary.find("nmea");
    QVERIFY(counts && counts->find("epochs"));
    QCOMPARE(counts->find("epochs")->number, static_cast<double>(batch.stats.epochs));
    // AND the AIS table's and the alerts' objects are there, the table holding the sample's stations
    const io::JsonValue* targets = summary.find("ais_targets");
    QVERIFY(targets && targets->find("targets") && targets->find("messages"));
    QVERIFY(targets->find("targets")->number >= 5);
    QVERIFY(summary.find("alerts") != nullptr);
    const auto alertRows = test::splitLines(io::readTextFile(out + "/alerts.csv"));
    QCOMPARE(alertRows.front(), std::string("utc,t_s,event,priority,kind,source,text"));
    QCOMPARE(static_cast<long>(alertRows.size()) - 1, writer.alertRows());
  }

  void aDirectoryThatCannotBeWrittenIsOneErrorNamingTheFile() {
    // GIVEN an output directory that does not exist WHEN the writer opens THEN InputError names the file
    try {
      files::LiveOutputWriter writer("/nonexistent-reckoner-dir/x", true);
      QFAIL("expected an error");
    } catch (const io::InputError& e) {
      QVERIFY2(std::string(e.what()).find("/nonexistent-reckoner-dir/x/ownship.csv") != std::string::npos,
               e.what());
    }
  }
};

QTEST_GUILESS_MAIN(TestLiveOutput)
#include "tst_live_output.moc"
