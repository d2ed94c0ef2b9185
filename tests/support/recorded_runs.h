#pragma once
// A live run's input for the recorder and playback tests: a simulated run (the builtin ttkf-matched
// scenario exported as NMEA 0183 and radar plots) with real AIS sentences, as the batches a live run
// takes, and the settings that go with it.
#include <string>
#include <vector>

#include "common/time.h"
#include "files/voyage_record.h"
#include "io/iso8601.h"
#include "io/text_file.h"
#include "sim/live_session.h"
#include "sim/nmea_export.h"
#include "support/drkf_fixtures.h"
#include "support/text_lines.h"

namespace reckoner::test {

/// `seconds` of the run starting at 10:00 UTC of `day` (midnight UTC), with the AIS sentences of
/// aisPath: each second's sentences (from its RMC on) in one batch, the plots stamped before that
/// second and one AIS sentence ahead of them; receive times 0.3 s into each second.
inline std::vector<std::vector<files::InputLine>> simulatedBatches(int seconds, UtcUs day,
                                                                   const std::string& aisPath) {
  sim::Scenario s = builtinScenario("ttkf-matched");
  s.durationUs = seconds * kMicrosPerSecond;
  const sim::ExportedRun e = sim::exportRun(s, 3, day + UtcUs{10} * 3600 * kMicrosPerSecond);
  const auto radar = splitLines(e.radarCsv, EmptyLines::Drop);
  std::vector<std::string> ais;
  for (auto& l : splitLines(io::readTextFile(aisPath)))
    if (l.starts_with('!')) ais.push_back(l);
  std::vector<std::vector<files::InputLine>> batches;
  std::size_t r = 0, a = 0;
  UtcUs rx = 0;
  for (const std::string& l : splitLines(e.nmea, EmptyLines::Drop)) {
    if (l.starts_with("$GPRMC,")) {
      const int hh = std::stoi(l.substr(7, 2)), mm = std::stoi(l.substr(9, 2)),
                ss = std::stoi(l.substr(11, 2));
      const UtcUs t = day + ((hh * 60 + mm) * 60 + ss) * kMicrosPerSecond;
      rx = t + 300'000;
      batches.emplace_back();
      if (a < ais.size()) batches.back().push_back({"nmea1", ais[a++], rx, false});
      for (; r < radar.size(); ++r) {
        const auto u = io::parseIso8601(radar[r].substr(0, radar[r].find(',')));
        if (u && *u >= t) break;
        batches.back().push_back({"radar1", radar[r], rx, true});
      }
    }
    if (batches.empty()) batches.emplace_back();
    batches.back().push_back({"nmea1", l, rx, false});
  }
  return batches;
}

/// The live run's settings for those batches: the scenario's, its origin, radar, frames.
inline sim::LiveOptions radarLiveOptions() {
  sim::LiveOptions lo;
  lo.replay.settings = builtinScenario("ttkf-matched");
  lo.replay.settingsName = "builtin:ttkf-matched";
  lo.replay.originFromSettings = true;
  lo.reorderHorizonS = 1.0;
  lo.radar = true;
  lo.frames = true;
  return lo;
}

}  // namespace reckoner::test
