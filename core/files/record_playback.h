#pragma once
// A voyage record played back to a clock (docs/recorder.md, "Playback"): the recorded batches, in the
// order the engine took them, handed out as the playback clock passes their receive times, to be fed
// through a sim::LiveSession and sim::LiveWatch made with the recorded settings, exactly as
// `replay --recording` feeds files::LiveRun (so the window's playback gives the recorded estimates).
// The pipeline cannot go back: a seek back is rewind() (the caller makes a new session and watch) and
// a run at full speed to the time. Inputs are read a page at a time: a 12-hour record is never held.
#include <cstdint>
#include <deque>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "files/voyage_record.h"

namespace reckoner::files {

class RecordPlayback {
 public:
  /// Opens the record (io::InputError naming the file and what is wrong); one without inputs is
  /// refused the same way.
  explicit RecordPlayback(const std::string& path);

  [[nodiscard]] const VoyageRecord& record() const { return rec_; }
  /// The settings the run was made with (for the session and the watch).
  [[nodiscard]] const sim::LiveOptions& options() const { return options_; }
  /// The receive times of the first and last input.
  [[nodiscard]] TimeSpan span() const { return span_; }
  /// The receive time of the last batch handed out (span().first before any).
  [[nodiscard]] UtcUs position() const { return position_; }
  [[nodiscard]] bool atEnd();
  /// Hands every batch not yet handed out whose last line was received at or before utc to `feed` with
  /// its number (OperatorAction::afterBatch's), in order, at most maxBatches of them; returns how many.
  std::size_t feedTo(UtcUs utc,
                     const std::function<void(std::int64_t batch, std::span<const InputLine>)>& feed,
                     std::size_t maxBatches = SIZE_MAX);
  /// Back to before the first batch.
  void rewind();
  /// The record's alert log (raised, acknowledged, cleared ...), read once: the timeline's marks.
  [[nodiscard]] const std::vector<RecordedAlert>& alerts() const { return alerts_; }

 private:
  /// At least one whole batch ahead, unless the record has no more; false at its end.
  bool fillBatch();

  VoyageRecord rec_;
  sim::LiveOptions options_;
  TimeSpan span_;
  std::vector<RecordedAlert> alerts_;
  std::deque<RecordedInput> ahead_;
  std::int64_t lastSeq_ = 0;  ///< of the last input read into ahead_
  bool exhausted_ = false;    ///< the record has no input after lastSeq_
  UtcUs position_ = 0;
};

}  // namespace reckoner::files
