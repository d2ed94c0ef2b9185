// libFuzzer target: radar plot CSV (`utc,range_m,bearing_deg[,target_id]`, docs/outputs.md) read as a
// file (sim/replay_input.h: readRadar, then the stream-time policy's replay order) and line by line as
// a live stream (sim/replay_stream.h: PlotStream). A first byte below 0x20 chooses the policy's window
// and whether the stream has receive times. Checks what the readers promise beyond not crashing: only
// io::InputError is thrown (by the file reader alone, naming the file, on one line); every plot has a
// range in [0, kMaxPlausiblePlotRangeM], a bearing in [0, 2 pi] and a tag that names one of the labels
// (at most 64 printable bytes each, no two alike); no plot twice; the replay order sorted; and the rows
// add up: read = bad + plots + repeats (+ time jumps) (docs/robustness.md, "Fuzzing").
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz/options_byte.h"
#include "io/input_error.h"
#include "sim/replay_input.h"
#include "sim/replay_stream.h"

namespace {
namespace ri = reckoner::sim::replay_input;
using reckoner::sim::ReplayStats;

void check(bool ok) {
  if (!ok) std::abort();
}

constexpr double kTwoPi = 6.283185307179586;

void checkLabels(const std::vector<std::string>& labels) {
  check(std::set<std::string>(labels.begin(), labels.end()).size() == labels.size());
  for (const std::string& l : labels) {
    check(!l.empty() && l.size() <= 64);
    for (const char c : l) check(static_cast<unsigned char>(c) >= 0x20 && c != 0x7f && c != '"');
  }
}

void checkPlot(const ri::Plot& p, const std::vector<std::string>& labels) {
  check(std::isfinite(p.rangeM) && p.rangeM >= 0.0 && p.rangeM <= reckoner::sim::kMaxPlausiblePlotRangeM);
  check(std::isfinite(p.bearingRad) && p.bearingRad >= 0.0 && p.bearingRad <= kTwoPi);
  check(p.tag >= -1 && p.tag < static_cast<int>(labels.size()));
}

void oneLine(std::string_view s) {
  check(s.find_first_of("\r\n") == std::string_view::npos);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto input = reckoner::fuzz::splitOptionsByte(data, size);
  const std::uint8_t flags = input.flags;
  const std::string& text = input.text;
  reckoner::sim::StreamTimePolicy policy;
  policy.window = 1 + (flags & 7);

  // As a file.
  try {
    ReplayStats st;
    std::vector<std::string> labels;
    const std::vector<ri::Plot> plots = ri::readRadar(text, "fuzz.csv", st, labels);
    checkLabels(labels);
    for (const ri::Plot& p : plots) checkPlot(p, labels);
    check(st.radarLines == st.radarBad + static_cast<long>(plots.size()) + st.radarDuplicates);
    for (std::size_t i = 0; i < plots.size(); ++i)
      for (std::size_t j = i + 1; j < plots.size() && j < i + 16; ++j) check(!(plots[i] == plots[j]));
    long jumps = 0, reordered = 0;
    const auto ordered = ri::inReplayOrder(
        plots, [](const ri::Plot& p) { return p.utc; }, policy, jumps, reordered);
    check(ordered.size() + static_cast<std::size_t>(jumps) == plots.size());
    check(std::is_sorted(ordered.begin(), ordered.end(),
                         [](const ri::Plot& a, const ri::Plot& b) { return a.utc < b.utc; }));
    (void)ri::rotationPeriodS(ordered);
  } catch (const reckoner::io::InputError& e) {
    check(std::string_view(e.what()).starts_with("fuzz.csv:"));
    oneLine(e.what());
  }

  // As a live stream (never throws).
  try {
    ReplayStats st;
    std::vector<std::string> labels;
    ri::PlotStream stream(policy, st, labels);
    const bool received = (flags & 8) != 0;
    std::int64_t rx = 1'709'251'200'000'000;  // 2024-03-01T00:00:00Z
    long taken = 0;
    const auto take = [&](std::optional<std::int64_t> before) {
      const auto plots = stream.take(before);
      for (std::size_t i = 0; i < plots.size(); ++i) {
        checkPlot(plots[i], labels);
        if (before) check(plots[i].utc < *before);
        if (i > 0) check(plots[i].utc >= plots[i - 1].utc);
      }
      taken += static_cast<long>(plots.size());
    };
    for (const ri::Line& l : ri::linesOf(text)) {
      rx += 100'000 + 1'000'000 * static_cast<std::int64_t>(l.text.size() % 4);
      stream.push(l.text, received ? std::optional<std::int64_t>(rx) : std::nullopt);
      if (l.number % 7 == 0) stream.expire(rx);
      if (const auto from = stream.undecidedFrom(); from && l.number % 3 == 0) take(*from);
    }
    stream.finish();
    check(!stream.undecidedFrom());
    take(std::nullopt);
    checkLabels(labels);
    check(st.radarLines == st.radarBad + st.radarDuplicates + st.radarTimeJumps + taken);
  } catch (...) {
    std::abort();
  }
  return 0;
}
