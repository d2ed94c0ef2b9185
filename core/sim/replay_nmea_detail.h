#pragma once
// Internal to sim/: what the two halves of the NMEA reader share (replay_input.h is the interface).
// replay_nmea.cpp parses the sentences, places them in time and groups them; replay_nmea_epochs.cpp
// turns the groups into epochs with the active source of each quantity.
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
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

/// One line parsed (nullopt: a comment, a blank line, or a line counted into st as skipped, with the
/// reason in whyBad when given). Throws io::InputError naming the file and line for a DTM of a datum
/// other than WGS-84.
std::optional<Parsed> parseLine(std::string_view text, int number, const std::string& name, ReplayStats& st,
                                std::string* whyBad);

/// The sentence's time of day (s), when it has one (RMC, GGA, GNS, GLL, ZDA, GST).
std::optional<double> timeOfDay(const io::nmea::Sentence& s);
/// It carries a date (RMC with its date, ZDA).
bool hasDate(const io::nmea::Sentence& s);

/// The day the times of day are placed around: the first dated sentence's (RMC with its date, ZDA;
/// with --date, that day moved by whole GPS week roll-overs towards --date), else --date's, else (with
/// a warning) 1970-01-01, at the first time of day.
UtcUs firstDayOf(const Parsed* firstDated, std::optional<double> firstTod, const std::string& name,
                 const NmeaOptions& o, std::vector<std::string>& warnings);

/// Places timed sentences on the time line, one after another: a dated sentence by its own date (moved
/// by the first dated sentence's roll-over correction, and by whole roll-overs when it lies that far
/// before the others), the others on the day nearest the median of the last eight times.
class DayPlacer {
 public:
  DayPlacer(UtcUs first, const Parsed* firstDated);
  /// The sentence's UTC; nullopt for an untimed sentence.
  std::optional<UtcUs> place(const io::nmea::Sentence& s);
  /// The roll-over warning, when any date was corrected.
  void warn(const std::string& name, std::vector<std::string>& warnings) const;

 private:
  std::deque<UtcUs> window_;
  std::int64_t rollover_;
  long rolledOver_ = 0;
};

/// Sentences grouped by time: a timed sentence and the untimed ones after it (they share its time).
struct TimedGroups {
  std::vector<UtcUs> utc;
  std::vector<std::vector<std::size_t>> sentences;  ///< indices into the parsed sentences
};

/// Turns the sentences of each epoch (one time) into the epoch with the active source of each quantity,
/// epoch after epoch in time order; counts what each sentence became (used, standby, skipped by reason)
/// into its source's stats and st. The same for a file (assembleEpochs) and a live stream.
class EpochAssembler {
 public:
  EpochAssembler(const NmeaOptions& o, ReplayStats& st, std::map<sources::SourceId, SourceStats>& stats);
  ~EpochAssembler();
  EpochAssembler(const EpochAssembler&) = delete;
  EpochAssembler& operator=(const EpochAssembler&) = delete;
  /// The epoch at t of these sentences (in file order) appended to out, unless it is a time-only epoch
  /// within 0.9 s of the last.
  void addEpoch(UtcUs t, const std::vector<const Parsed*>& sentences, std::vector<Epoch>& out);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The epochs of the groups in replay order (replayOrder: st.reordered counts the groups out of order),
/// each with the value of the active source of each quantity; counts what each sentence became (used,
/// standby, skipped by reason) into its source's stats and the file's st.
std::vector<Epoch> assembleEpochs(const std::vector<Parsed>& ps, const TimedGroups& groups,
                                  const NmeaOptions& o, ReplayStats& st,
                                  std::map<sources::SourceId, SourceStats>& stats);

}  // namespace reckoner::sim::replay_input::detail
