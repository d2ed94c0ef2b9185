// reckoner-bench: the live session's throughput (sim/live_session.h) against the file replay of the same
// recording (../shared/data/nmea, read in place; skipped when absent). Items are NMEA lines.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "io/text_file.h"
#include "sim/live_session.h"
#include "sim/replay.h"
#include "support/text_lines.h"

namespace {
using namespace reckoner;

const std::string& recording() {
  static const std::string text = [] {
    try {
      return io::readTextFile(RECKONER_SHARED_DIR "/data/nmea/openrvdas-NBP1406_seap-2014-08-01.nmea");
    } catch (const std::exception&) {
      return std::string();
    }
  }();
  return text;
}

void BM_LiveSessionRecording(benchmark::State& state) {
  const std::vector<std::string> lines = test::splitLines(recording());
  if (lines.empty()) {
    state.SkipWithError("../shared/data/nmea recording not found");
    return;
  }
  std::size_t rows = 0;
  for (auto _ : state) {
    const sim::LiveOptions options;
    sim::LiveSession session(options);
    for (const std::string& l : lines) session.nmea(l);
    session.finish();
    rows = session.takeOwnRows().size();
    benchmark::DoNotOptimize(rows);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(lines.size()));
  state.counters["rows"] = static_cast<double>(rows);
}
BENCHMARK(BM_LiveSessionRecording)->Unit(benchmark::kMillisecond);

void BM_ReplayRecording(benchmark::State& state) {
  const std::string& text = recording();
  if (text.empty()) {
    state.SkipWithError("../shared/data/nmea recording not found");
    return;
  }
  const auto lines = static_cast<std::int64_t>(test::splitLines(text).size());
  for (auto _ : state) {
    const sim::ReplayResult r = sim::replay(text, "recording", nullptr, "", sim::ReplayOptions{});
    benchmark::DoNotOptimize(r.own.size());
  }
  state.SetItemsProcessed(state.iterations() * lines);
}
BENCHMARK(BM_ReplayRecording)->Unit(benchmark::kMillisecond);

}  // namespace
