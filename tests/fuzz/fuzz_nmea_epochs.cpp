// libFuzzer target: NMEA 0183 text grouped into own-ship epochs (core/sim/replay_input.h), read as a
// file (replay_input::readNmea: day placement, clock correction, the stream-time policy, the active
// source of each quantity) and line by line as a live stream (replay_input::NmeaStream) on the same
// lines. A first byte below 0x20 chooses the options (a --date, a --variation, receive times for the
// stream, a short or long reorder horizon). Checks what the readers promise beyond not crashing: only
// io::InputError is thrown (by the file reader alone, naming the file); epochs come out in time order
// with finite values in range (positions, GST variance, HDOP, velocity and log speed under
// kMaxPlausibleSpeedKn, headings in [0, 2 pi)); and every line is counted once: the lines read are the
// skipped ones plus the sentences, and each sentence ends in exactly one outcome (used, not used,
// repeated, standby, unusable, not GNSS, implausible, no variation, time jump, untimed, late), the
// sources' counts adding up to the same (docs/robustness.md, "Fuzzing"; docs/outputs.md).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "common/units.h"
#include "fuzz/options_byte.h"
#include "io/input_error.h"
#include "sim/replay_input.h"
#include "sim/replay_stream.h"

namespace {
namespace ri = reckoner::sim::replay_input;
using reckoner::sim::ReplayStats;
using reckoner::sim::SourceStats;

void check(bool ok) {
  if (!ok) std::abort();
}

constexpr double kTwoPi = 6.283185307179586;
const double kMaxMps = reckoner::knotsToMps(reckoner::sim::kMaxPlausibleSpeedKn) * 1.000001;

void checkPoint(const reckoner::geo::GeoPoint& p) {
  check(std::isfinite(p.latDeg) && std::abs(p.latDeg) <= 90.0);
  check(std::isfinite(p.lonDeg) && std::abs(p.lonDeg) <= 180.0);
}

void checkEpochs(const std::vector<ri::Epoch>& epochs) {
  for (std::size_t i = 0; i < epochs.size(); ++i) {
    const ri::Epoch& e = epochs[i];
    if (i > 0) check(e.utc >= epochs[i - 1].utc);
    if (e.gps) checkPoint(*e.gps);
    if (e.loran) checkPoint(*e.loran);
    if (e.gpsVarM2) check(std::isfinite(*e.gpsVarM2) && *e.gpsVarM2 >= 0.0);
    check(std::isfinite(e.gpsHdop));
    if (e.gpsVelocity) {
      check(std::isfinite(e.gpsVelocity->first) && e.gpsVelocity->first >= 0.0 &&
            e.gpsVelocity->first <= kMaxMps);
      check(std::isfinite(e.gpsVelocity->second));
    }
    if (e.headingRad) check(*e.headingRad >= 0.0 && *e.headingRad < kTwoPi);
    if (e.log) check(std::isfinite(e.log->first) && std::abs(e.log->first) <= kMaxMps);
  }
}

/// Every sentence read ends in one outcome; the sources' counts say the same.
void checkCounts(const ReplayStats& st, const std::vector<SourceStats>& sources) {
  long sentences = 0;
  for (const SourceStats& s : sources) {
    check(s.used + s.standby + s.repeated + s.unusable + s.notMeasured + s.implausible + s.timeJumps <=
          s.sentences);
    check(std::isfinite(s.activeS) && s.activeS >= 0.0);
    sentences += s.sentences;
  }
  check(st.nmeaLines ==
        st.comments + st.badChecksum + st.unknownSentences + st.proprietary + st.malformed + sentences);
  check(sentences == st.sentencesUsed + st.notUsed + st.repeated + st.standby + st.unusable + st.notGnss +
                         st.implausible + st.noVariation + st.timeJumps + st.untimed + st.late);
}

void oneLine(const std::string& s) {
  for (const char c : s) check(c != '\n' && c != '\r');
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto input = reckoner::fuzz::splitOptionsByte(data, size);
  const std::uint8_t flags = input.flags;
  const std::string& text = input.text;
  ri::NmeaOptions o;
  if (flags & 1) o.date = std::array<int, 3>{2024, 3, 1};
  if (flags & 2) o.variationDeg = -14.5;
  if (flags & 4) o.time.window = 2;

  // As a file.
  {
    ReplayStats st;
    std::vector<SourceStats> sources;
    std::vector<std::string> warnings;
    try {
      const auto epochs = ri::readNmea(text, "fuzz.nmea", o, st, sources, warnings);
      checkEpochs(epochs);
      checkCounts(st, sources);
      for (const std::string& w : warnings) oneLine(w);
    } catch (const reckoner::io::InputError& e) {
      check(std::string_view(e.what()).starts_with("fuzz.nmea"));
      oneLine(e.what());
    }
  }
  // As a live stream, line by line (never throws: a bad datum is counted malformed).
  {
    ReplayStats st;
    const std::int64_t horizonUs = (flags & 8) ? 0 : 5'000'000;
    ri::NmeaStream stream(o, "live", horizonUs, st);
    std::vector<ri::Epoch> epochs;
    const bool received = (flags & 16) != 0;
    std::int64_t rx = 1'709'251'200'000'000;  // 2024-03-01T00:00:00Z
    try {
      for (const ri::Line& l : ri::linesOf(text)) {
        rx += 50'000 + 10'000 * static_cast<std::int64_t>(l.text.size() % 64);
        stream.push(l.text, received ? std::optional<std::int64_t>(rx) : std::nullopt);
        for (auto& e : stream.takeEpochs()) epochs.push_back(e);
      }
      stream.finish();
    } catch (...) {
      std::abort();
    }
    for (auto& e : stream.takeEpochs()) epochs.push_back(e);
    checkEpochs(epochs);
    checkCounts(st, stream.sources());
    for (const std::string& w : stream.warnings()) oneLine(w);
  }
  return 0;
}
