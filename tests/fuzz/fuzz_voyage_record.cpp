// libFuzzer target: the voyage record reader (core/files/voyage_record.h, record_playback.h) on an
// arbitrary file: the input is written to a scratch file (in /dev/shm when there is one) and opened
// through files::VoyageRecord and files::RecordPlayback as `replay --recording` and the window's
// playback open a record. Checks what the reader promises beyond not crashing (files/voyage_record.h,
// docs/recorder.md): anything wrong with the file is one io::InputError naming it, on one line, and
// never another exception; every accessor is called (meta, settings, sources, inputs in pages, the
// seek, batches, estimates, tracks, alerts, operator actions, charts); the settings read from a record
// pass sim::checkScenario; pages of inputs come in seq order, none longer than asked, together no
// more than the count; batches are never empty (docs/robustness.md, "Fuzzing").
#include <unistd.h>

#include <climits>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "files/record_playback.h"
#include "files/voyage_record.h"
#include "io/input_error.h"
#include "sim/scenario.h"

namespace {
namespace fs = std::filesystem;
using reckoner::files::InputLine;

void check(bool ok) {
  if (!ok) std::abort();
}

/// A scratch folder of this process, removed at exit. The path is never destroyed: the exit handler
/// runs after static destructors registered before it (a static std::string here was read after its
/// destruction: heap-use-after-free at exit, found by the first fuzz_smoke.sh run).
const std::string& scratchFile() {
  static const std::string* const path = [] {
    const fs::path base = fs::is_directory("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
    const fs::path dir = base / ("reckoner-fuzz-record-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    auto* p = new std::string((dir / "voyage.db").string());
    std::atexit([] { fs::remove_all(fs::path(scratchFile()).parent_path()); });
    return p;
  }();
  return *path;
}

void clear(const std::string& path) {
  for (const char* suffix : {"", "-wal", "-shm", "-journal"}) std::remove((path + suffix).c_str());
}

void checkError(const reckoner::io::InputError& e, const std::string& path) {
  const std::string_view what = e.what();
  check(what.starts_with(path));
  check(what.find_first_of("\r\n") == std::string_view::npos);
}

void readRecord(const std::string& path) {
  const reckoner::files::VoyageRecord rec(path);
  (void)rec.meta();
  (void)rec.programVersion();
  (void)rec.startUtc();
  (void)rec.endUtc();
  (void)rec.inputName();
  (void)rec.chartsPath();
  try {
    const auto o = rec.liveOptions();
    check(reckoner::sim::checkScenario(o.replay.settings).empty());
  } catch (const reckoner::io::InputError& e) {
    checkError(e, path);
  }
  (void)rec.sources();
  const std::int64_t count = rec.inputCount();
  check(count >= 0);
  // Pages of 7 after the last seq of the page before: increasing seq, never more than the count.
  std::int64_t after = INT64_MIN, read = 0;
  for (int page = 0; page < 64; ++page) {
    const auto in = rec.inputs(after, 7);
    check(in.size() <= 7);
    for (const auto& i : in) {
      check(i.seq > after);
      after = i.seq;
    }
    read += static_cast<std::int64_t>(in.size());
    if (in.size() < 7) break;
  }
  check(read <= count);
  const auto span = rec.inputSpan();
  for (const std::int64_t utc :
       {INT64_MIN, std::int64_t{0}, INT64_MAX, span ? span->first : 1, span ? span->last : 2})
    (void)rec.inputSeqAt(utc);
  std::int64_t batches = 0;
  rec.forEachBatch([&](std::int64_t, std::span<const InputLine> lines) {
    check(!lines.empty());
    ++batches;
  });
  (void)rec.estimateSpan();
  (void)rec.estimates(INT64_MIN, INT64_MAX, 64);
  (void)rec.estimateNear(0);
  (void)rec.estimateNear(INT64_MAX);
  (void)rec.estimateNear(INT64_MIN);
  (void)rec.tracks(INT64_MIN, INT64_MAX, 64);
  (void)rec.alerts();
  (void)rec.operatorActions();
  (void)rec.charts();
}

void playBack(const std::string& path) {
  reckoner::files::RecordPlayback playback(path);
  check(reckoner::sim::checkScenario(playback.options().replay.settings).empty());
  (void)playback.alerts();
  for (int round = 0; round < 2; ++round) {
    std::size_t lines = 0, fed = 0;
    for (int k = 0; k < 4096 && !playback.atEnd(); ++k) {
      const std::size_t n = playback.feedTo(
          INT64_MAX,
          [&](std::int64_t, std::span<const InputLine> batch) {
            check(!batch.empty());
            lines += batch.size();
          },
          16);
      fed += n;
      if (n == 0) break;  // a batch received after INT64_MAX: impossible, but never loop on it
    }
    check(fed <= lines);
    check(playback.position() >= playback.span().first);
    playback.rewind();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = scratchFile();
  clear(path);
  {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    readRecord(path);
  } catch (const reckoner::io::InputError& e) {
    checkError(e, path);
  } catch (...) {
    std::abort();
  }
  try {
    playBack(path);
  } catch (const reckoner::io::InputError& e) {
    checkError(e, path);
  } catch (...) {
    std::abort();
  }
  clear(path);
  return 0;
}
