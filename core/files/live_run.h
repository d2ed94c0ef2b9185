#pragma once
// The pipeline of a live run, one batch of received lines at a time: sim::LiveSession (the replay's
// reader and engine), sim::LiveWatch (alerts, AIS target table), the files (files/live_output.h) and,
// when recording, the voyage record (files/voyage_recorder.h). `reckoner-cli live` feeds it the lines
// its connections deliver; `replay --recording` feeds it the recorded batches in their order with their
// receive times, so both give the same rows, files and alerts (docs/recorder.md).
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "files/live_output.h"
#include "files/voyage_record.h"
#include "sim/live_session.h"
#include "sim/live_watch.h"

namespace reckoner::files {

class VoyageRecorder;

/// The watch's settings of a run's options: its tracker's CPA/TCPA limits for radar tracks and AIS
/// targets alike, the settings' DR limit and conditions.
sim::LiveWatchSettings liveWatchSettings(const sim::LiveOptions& o);

class LiveRun {
 public:
  /// Creates the files in outDir (LiveOutputWriter); recorder may be null. Throws io::InputError.
  LiveRun(const sim::LiveOptions& options, const std::string& outDir, VoyageRecorder* recorder = nullptr);
  ~LiveRun();
  LiveRun(const LiveRun&) = delete;
  LiveRun& operator=(const LiveRun&) = delete;

  /// One batch: every line into the session in order (radar rows to its radar input), then the watch
  /// absorbs what came of them (at the stream clock of the last line's receive time), the rows are
  /// written and recorded. An empty batch does nothing. wallUtc: the system clock (the recorder's).
  /// Returns the rows and alert entries written.
  LiveBatch batch(std::span<const InputLine> lines, UtcUs wallUtc);
  /// The recorder's timer (commits due on the wall clock); nothing without a recorder.
  void tick(UtcUs wallUtc);
  /// The end of the input: the session finishes, the watch absorbs, the last rows, summary.json (with
  /// inputName), the record's end. Returns the last rows.
  LiveBatch finish(const std::string& inputName, UtcUs wallUtc);

  [[nodiscard]] const sim::LiveSession& session() const { return session_; }
  sim::LiveSession& session() { return session_; }
  [[nodiscard]] const sim::LiveWatch& watch() const { return watch_; }
  sim::LiveWatch& watch() { return watch_; }
  [[nodiscard]] const LiveOutputWriter& writer() const { return writer_; }
  [[nodiscard]] long lines() const { return lines_; }
  [[nodiscard]] long radarLines() const { return radarLines_; }

 private:
  void addRoute(const std::vector<sim::SimFrame>& frames, LiveBatch& out) const;
  sim::LiveSession session_;
  sim::LiveWatch watch_;
  LiveOutputWriter writer_;
  VoyageRecorder* recorder_;
  long lines_ = 0, radarLines_ = 0;
};

}  // namespace reckoner::files
