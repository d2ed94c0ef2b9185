// voyage_seeds DIR: writes the seed corpus of fuzz_voyage_record (tests/fuzz/corpus/voyage_record/):
// small voyage records of this project's own making, through files::VoyageRecorder as a live run
// writes them (invented sentences and plots, three batches, own-ship and track rows, an alert, an
// operator action, a chart event), then compacted with SQLite itself (512-byte pages, rollback journal,
// VACUUM) so that a fuzzer mutates a few kilobytes rather than a WAL-sized file:
//   small.db     the record as described;
//   empty.db     a record with its schema and meta rows and nothing else (no input: playback refuses);
//   unfinished.db  the record of a run killed before its end (no end_utc_us).
#include <sqlite3.h>

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "files/live_output.h"
#include "files/voyage_record.h"
#include "files/voyage_recorder.h"

namespace {
using namespace reckoner;
namespace fs = std::filesystem;

constexpr UtcUs kStart = 1'795'392'000'000'000;  // 2026-11-22T00:00:00Z

files::RecorderSettings settings() {
  files::RecorderSettings s;
  s.program = "voyage_seeds";
  s.programVersion = "0";
  s.options = sim::LiveOptions{};
  s.sources = {{0, "nmea1", "nmea", "udp://:10110?name=nmea1"},
               {0, "radar1", "radar", "udp://:2000?role=radar"}};
  return s;
}

files::LiveBatch rows(UtcUs utc, int k) {
  files::LiveBatch b;
  sim::ReplayOwnRow own;
  own.utcUs = utc;
  own.timeUs = utc - kStart;
  own.estimate.xM = 10.0 * k;
  own.sensors = "gps+gyro";
  own.rowsApplied = 2;
  b.own.push_back(own);
  sim::TrackRow t;
  t.timeUs = own.timeUs;
  t.trackId = 1;
  t.estXM = 900.0 + k;
  t.estYM = 400.0;
  t.estLatDeg = 49.52;
  t.estLonDeg = -29.48;
  b.tracks.push_back(t);
  b.trackUtc.push_back(utc);
  return b;
}

void record(const std::string& path, bool finish, bool inputs) {
  files::VoyageRecorder rec(path, settings(), kStart);
  if (inputs) {
    const char* nmea[] = {"$GPRMC,000001.00,A,4931.20,N,02928.80,W,5.0,90.0,221126,,,A*71",
                          "$HEHDT,90.0,T*16", "$GPZDA,000002.00,22,11,2026,00,00*62"};
    for (int k = 0; k < 3; ++k) {
      const UtcUs utc = kStart + UtcUs{1'000'000} * (k + 1);
      std::vector<files::InputLine> lines{
          {"nmea1", nmea[k], utc, false},
          {"radar1", "2026-11-22T00:00:01.000Z,1852.0,45.0,a", utc + 1000, true}};
      rec.batch(lines, rows(utc, k), std::vector<std::string>{"a"}, utc, utc + 2000);
    }
    files::OperatorAction a;
    a.afterBatch = 2;
    a.wallUtc = kStart + 2'500'000;
    a.action = "cpa_limits";
    a.value = "cpa_m=1852;tcpa_s=720";
    rec.operatorAction(a);
    files::ChartEvent c;
    c.wallUtc = kStart + 2'600'000;
    c.event = "loaded";
    c.name = "RK5SOUND";
    c.edition = "1";
    c.updateNumber = "0";
    c.issueDate = "20261123";
    c.path = "builtin:default";
    rec.chart(c);
  }
  if (finish) rec.finish(files::LiveBatch{}, {}, kStart + 5'000'000);
}

void compact(const std::string& path) {
  sqlite3* db = nullptr;
  if (sqlite3_open(path.c_str(), &db) != SQLITE_OK) throw std::runtime_error("cannot open " + path);
  char* error = nullptr;
  const int rc =
      sqlite3_exec(db, "PRAGMA journal_mode=DELETE; PRAGMA page_size=512; VACUUM;", nullptr, nullptr, &error);
  const std::string why = error ? error : "";
  sqlite3_free(error);
  sqlite3_close(db);
  if (rc != SQLITE_OK) throw std::runtime_error(path + ": " + why);
  for (const char* s : {"-wal", "-shm"}) fs::remove(path + s);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: voyage_seeds DIR\n");
    return 2;
  }
  try {
    const fs::path dir(argv[1]);
    fs::create_directories(dir);
    for (const auto& [name, finish, inputs] :
         {std::tuple{"small.db", true, true}, {"empty.db", true, false}, {"unfinished.db", false, true}}) {
      const std::string path = (dir / name).string();
      fs::remove(path);
      record(path, finish, inputs);
      compact(path);
      (void)files::VoyageRecord(path).inputCount();  // it still opens
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "voyage_seeds: %s\n", e.what());
    return 1;
  }
  return 0;
}
