#pragma once
// The voyage record (docs/recorder.md): an SQLite database of everything that entered a live run's
// engine (every line with its receive time and connection, in order and in the batches the engine took
// them), what it estimated (own-ship rows, track rows), its alerts, operator actions and charts, and
// the settings it ran with. files/voyage_recorder.h writes it; this is the reader, for `reckoner-cli
// replay --recording` and a playback timeline (seek to a time, step through the alerts).
//
// Opening checks the file: a missing file, one that is not an SQLite database, a database that is not a
// voyage record, another schema version, a missing table or column are each one io::InputError naming
// the file and what is wrong. A database damaged further in shows when it is read: the same error,
// never a crash.
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "alerts/alert.h"
#include "common/time.h"
#include "sim/live_session.h"
#include "sim/replay.h"
#include "sim/run_rows.h"

namespace reckoner::files {

namespace sqlite {
class Db;
}

/// One line as it entered a live run: the connection it came on, its text, when it was read.
struct InputLine {
  std::string source;     ///< the connection's name
  std::string line;       ///< without its terminator
  UtcUs receivedUtc = 0;  ///< the system clock when its bytes were read, UTC microseconds
  bool radar = false;     ///< a radar plot row (CSV), else an NMEA 0183 or AIS sentence
};

/// A recorded input: the line, its place in the record and the engine batch it was taken in.
struct RecordedInput : InputLine {
  std::int64_t seq = 0;    ///< 1, 2, ... in the order the engine took the lines
  std::int64_t batch = 0;  ///< lines of one batch went to the engine together (then the watch ran)
};

struct RecordedSource {
  std::int64_t id = 0;
  std::string name;
  std::string role;  ///< "nmea" or "radar"
  std::string spec;  ///< the connection spec (docs/connections.md), when known
};

/// A track row as recorded: its UTC, the plots' target label (empty: none) and the estimate columns
/// (TrackRow without truth; targetId -1, the label is `target`).
struct RecordedTrack {
  UtcUs utc = 0;
  std::string target;
  sim::TrackRow row;
};

/// One alert log entry with the columns of alerts.csv (names as text, docs/alerts.md).
struct RecordedAlert {
  UtcUs utc = 0;      ///< the alert manager's clock as UTC
  TimeUs timeUs = 0;  ///< the alert manager's clock (microseconds since the watch's zero)
  std::string event, priority, kind;
  int source = 0;  ///< track number, MMSI, DRKF block, zone
  std::string text;
  friend bool operator==(const RecordedAlert&, const RecordedAlert&) = default;
};
/// The entry as recorded (zeroUtc: the watch's zero when the entry was taken).
RecordedAlert recordedAlert(const alerts::AlertLogEntry& e, UtcUs zeroUtc);

/// An operator action (the window's: acknowledge, silence, CPA limits ...; reckoner-cli live has
/// none), made after the engine batch afterBatch.
struct OperatorAction {
  std::int64_t afterBatch = 0;
  UtcUs wallUtc = 0;
  std::optional<UtcUs> streamUtc;
  std::string action;   ///< e.g. "acknowledge", "silence_all", "cpa_limits"
  std::string subject;  ///< what it acted on ("alert:KIND:SOURCE", "mmsi:244660000"), may be empty
  std::string value;    ///< its value ("cpa_m=1852;tcpa_s=720"), may be empty
};

/// A chart loaded or unloaded during the run (the window's; reckoner-cli live has none).
struct ChartEvent {
  UtcUs wallUtc = 0;
  std::optional<UtcUs> streamUtc;
  std::string event;  ///< "loaded" or "unloaded"
  std::string name, edition, updateNumber, issueDate, path;
};

struct TimeSpan {
  UtcUs first = 0, last = 0;
};

class VoyageRecord {
 public:
  /// Opens the file read-only (a record whose writer was killed is read with its write-ahead log).
  explicit VoyageRecord(const std::string& path);
  ~VoyageRecord();
  VoyageRecord(VoyageRecord&&) noexcept;
  VoyageRecord& operator=(VoyageRecord&&) noexcept;

  [[nodiscard]] const std::string& path() const;
  /// Every meta row: schema_version, program, program_version, start_utc, settings.*, end_utc ...
  [[nodiscard]] const std::map<std::string, std::string>& meta() const { return meta_; }
  [[nodiscard]] std::string programVersion() const;
  [[nodiscard]] UtcUs startUtc() const;  ///< wall clock when recording began
  /// When the run ended and wrote its end (nullopt: killed, or still running).
  [[nodiscard]] std::optional<UtcUs> endUtc() const;
  /// The settings the run was made with (its scenario, options), ready for sim::LiveSession.
  [[nodiscard]] sim::LiveOptions liveOptions() const;
  /// The charts the run's anti-grounding look-ahead used (RecorderSettings::charts; nullopt: none).
  [[nodiscard]] std::optional<std::string> chartsPath() const {
    const auto it = meta_.find("voyage.enc");
    return it == meta_.end() ? std::nullopt : std::optional<std::string>(it->second);
  }
  /// The name the run gave its input in summary.json ("live").
  [[nodiscard]] std::string inputName() const;

  [[nodiscard]] std::vector<RecordedSource> sources() const;
  [[nodiscard]] std::int64_t inputCount() const;
  /// Receive times of the first and last input whose receive time is known (not 0; nullopt: none).
  [[nodiscard]] std::optional<TimeSpan> inputSpan() const;
  /// UTC of the first and last own-ship estimate (nullopt: none).
  [[nodiscard]] std::optional<TimeSpan> estimateSpan() const;

  /// Up to max inputs after seq afterSeq, in order (page through a long voyage from 0).
  [[nodiscard]] std::vector<RecordedInput> inputs(std::int64_t afterSeq, std::size_t max) const;
  /// The seq of the first input received at or after utc (for a seek; 0 when there is none): a binary
  /// search on seq, so where the system clock was stepped back it is one of the places utc is passed.
  [[nodiscard]] std::int64_t inputSeqAt(UtcUs utc) const;
  /// Every input in order, one engine batch per call (what replay --recording feeds the engine).
  void forEachBatch(const std::function<void(std::int64_t batch, std::span<const InputLine>)>& f) const;

  /// Own-ship rows with UTC in [from, to], in time order, at most max.
  [[nodiscard]] std::vector<sim::ReplayOwnRow> estimates(UtcUs from, UtcUs to,
                                                         std::size_t max = SIZE_MAX) const;
  /// The own-ship row nearest to utc in time (nullopt: none).
  [[nodiscard]] std::optional<sim::ReplayOwnRow> estimateNear(UtcUs utc) const;
  /// Track rows with UTC in [from, to], in the order recorded, at most max.
  [[nodiscard]] std::vector<RecordedTrack> tracks(UtcUs from, UtcUs to, std::size_t max = SIZE_MAX) const;
  /// Every alert log entry, in order (the jumps of a timeline).
  [[nodiscard]] std::vector<RecordedAlert> alerts() const;
  [[nodiscard]] std::vector<OperatorAction> operatorActions() const;
  [[nodiscard]] std::vector<ChartEvent> charts() const;

 private:
  std::unique_ptr<sqlite::Db> db_;
  std::map<std::string, std::string> meta_;
};

}  // namespace reckoner::files
