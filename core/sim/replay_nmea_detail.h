#pragma once
// Internal to sim/: what the two halves of the NMEA reader share (replay_input.h is the interface).
// replay_nmea.cpp parses the sentences, places them in time and groups them; replay_nmea_epochs.cpp
// turns the groups into epochs with the active source of each quantity.
#include <map>
#include <vector>

#include "io/nmea.h"
#include "sim/replay_input.h"
#include "sim/replay_sources.h"

namespace reckoner::sim::replay_input::detail {

/// One sentence read from the file.
struct Parsed {
  int line;
  io::nmea::Sentence sentence;
  sources::SourceId source;  ///< "GP:GGA"
  sources::Kind kind;
};

/// Sentences grouped by time: a timed sentence and the untimed ones after it (they share its time).
struct TimedGroups {
  std::vector<UtcUs> utc;
  std::vector<std::vector<std::size_t>> sentences;  ///< indices into the parsed sentences
};

/// The epochs of the groups in replay order (replayOrder: st.reordered counts the groups out of order),
/// each with the value of the active source of each quantity; counts what each sentence became (used,
/// standby, skipped by reason) into its source's stats and the file's st.
std::vector<Epoch> assembleEpochs(const std::vector<Parsed>& ps, const TimedGroups& groups,
                                  const NmeaOptions& o, ReplayStats& st,
                                  std::map<sources::SourceId, SourceStats>& stats);

}  // namespace reckoner::sim::replay_input::detail
