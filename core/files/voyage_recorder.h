#pragma once
// Writes the voyage record (files/voyage_record.h, docs/recorder.md) of a live run as it goes:
// append-only, crash-safe. The database is in WAL mode with synchronous=NORMAL; the inserts of the
// batches go into one open transaction that is committed once a second of stream time has passed since
// the last commit, or commitWallS of wall time since its first insert (tick() from the run's timer
// covers a silent input), so a process killed outright loses at most the last second; the write-ahead
// log is made durable (fdatasync) at most once per syncWallS of wall time, so a power cut loses at most
// about that much more. Plain C++ (no Qt); the wall clock is the caller's, for tests.
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "files/live_output.h"
#include "files/voyage_record.h"

namespace reckoner::files {

namespace sqlite {
class Db;
class Statement;
}  // namespace sqlite

struct RecorderSettings {
  std::string program = "reckoner-cli live";  ///< what made the record (meta.program)
  std::string programVersion;                 ///< meta.program_version
  std::string inputName = "live";             ///< the input's name in summary.json
  sim::LiveOptions options;                   ///< the run's settings, recorded for its replay
  /// The charts of the anti-grounding look-ahead (a cell or a folder; meta.voyage.enc): the record names
  /// them, it does not hold them (a replay loads them again from there).
  std::optional<std::string> charts;
  /// The connections known at the start (name, role "nmea"/"radar", spec); a line from a source not
  /// listed adds it with an empty spec.
  std::vector<RecordedSource> sources;
  /// Own-ship and track rows older than this (hours behind the newest) are pruned but for one per
  /// minute (per track); nullopt: everything kept. Inputs and alerts are never pruned.
  std::optional<double> maxHours;
  double commitStreamS = 1.0;  ///< commit once the stream clock has moved this far since the last
  double commitWallS = 0.5;    ///< commit once a pending insert is this old on the wall clock
  double syncWallS = 1.0;      ///< make the log durable at most this often
};
/// Throws std::invalid_argument naming the field.
void validate(const RecorderSettings& s);

class VoyageRecorder {
 public:
  /// Creates the file (it must not exist), its schema and its meta rows, committed and synced.
  /// Throws io::InputError naming the file.
  VoyageRecorder(const std::string& path, const RecorderSettings& settings, UtcUs wallUtc);
  /// Commits what is pending (errors are swallowed: use finish() to see them).
  ~VoyageRecorder();
  VoyageRecorder(const VoyageRecorder&) = delete;
  VoyageRecorder& operator=(const VoyageRecorder&) = delete;

  /// One engine batch: its lines in the order the engine took them, then what it produced (own-ship
  /// and track rows, alert log entries; targetLabels: ReplayResult::targetLabels), and the stream's
  /// clock after it. Commits when due. An empty batch is not one (nothing is recorded). Throws
  /// io::InputError naming the file (disk full, I/O error).
  void batch(std::span<const InputLine> lines, const LiveBatch& out,
             std::span<const std::string> targetLabels, std::optional<UtcUs> streamUtc, UtcUs wallUtc);
  /// An operator action after the latest batch; a chart loaded or unloaded.
  void operatorAction(OperatorAction a);
  void chart(const ChartEvent& c);
  /// The run's timer (a few times a second): commits what has waited commitWallS, syncs.
  void tick(UtcUs wallUtc);
  /// The end of the run: its last rows (as batch() without lines), meta end_utc_us, the last commit,
  /// the log checkpointed into the database.
  void finish(const LiveBatch& last, std::span<const std::string> targetLabels, UtcUs wallUtc);

  [[nodiscard]] const std::string& path() const;
  [[nodiscard]] std::int64_t batches() const { return batch_; }
  [[nodiscard]] std::int64_t lines() const { return lines_; }
  [[nodiscard]] std::int64_t committedLines() const { return committedLines_; }
  [[nodiscard]] std::int64_t commits() const { return commits_; }
  [[nodiscard]] std::int64_t syncs() const { return syncs_; }
  [[nodiscard]] std::int64_t prunedRows() const { return pruned_; }
  /// Tracks whose latest row's minute is remembered (those of the last minutes; bounded by the tracks
  /// alive then, not by every track the run has seen).
  [[nodiscard]] std::size_t rememberedTracks() const { return trackMinute_.size(); }

 private:
  struct Statements;
  void begin(UtcUs wallUtc);
  void rows(const LiveBatch& out, std::span<const std::string> targetLabels);
  void forgetTracksBefore(std::int64_t minute);
  void maybeCommit(std::optional<UtcUs> streamUtc, UtcUs wallUtc);
  void commit(std::optional<UtcUs> streamUtc, UtcUs wallUtc);
  void prune();
  std::int64_t sourceId(const InputLine& l);

  RecorderSettings s_;
  std::unique_ptr<sqlite::Db> db_;
  std::unique_ptr<Statements> st_;
  std::map<std::string, std::int64_t> sources_;
  bool inTransaction_ = false;
  UtcUs pendingSinceWall_ = 0;
  std::optional<UtcUs> lastCommitStream_, lastStream_;
  UtcUs lastSyncWall_ = 0;
  bool unsynced_ = false;
  std::int64_t batch_ = 0, lines_ = 0, committedLines_ = 0, commits_ = 0, syncs_ = 0, pruned_ = 0;
  std::optional<std::int64_t> ownMinute_;
  std::map<int, std::int64_t> trackMinute_;  ///< each recent track's last row's minute
  std::int64_t forgottenBefore_ = 0;
  std::optional<UtcUs> newestUtc_, lastPruneUtc_;
};

}  // namespace reckoner::files
