#pragma once
// A replay of a voyage record against the record (docs/recorder.md, "Playback"): does playback give the
// estimates the original run had? Own-ship rows are matched by UTC and compared field by field exactly
// (every double bit-equal but for the sign of zero; NaN equals NaN), track rows by UTC and track
// number, alert log entries in order. Rows pruned from the record (--record-max-hours) are counted as
// not recorded, not as different.
#include <cstdint>
#include <deque>
#include <span>
#include <string>
#include <vector>

#include "files/live_output.h"
#include "files/voyage_record.h"

namespace reckoner::files {

struct RecordComparison {
  long ownEqual = 0, ownDifferent = 0;
  long ownNotRecorded = 0;  ///< computed, with no recorded row of its UTC (pruned, or after a kill)
  long ownNotReplayed = 0;  ///< recorded, never computed
  long tracksEqual = 0, tracksDifferent = 0, tracksNotRecorded = 0, tracksNotReplayed = 0;
  long alertsEqual = 0, alertsDifferent = 0, alertsNotRecorded = 0, alertsNotReplayed = 0;
  std::string firstDifference;  ///< empty when none: what differed first, with its time and field
  /// No row differs and none was recorded that the replay did not compute.
  [[nodiscard]] bool equal() const {
    return ownDifferent + ownNotReplayed + tracksDifferent + tracksNotReplayed + alertsDifferent +
               alertsNotReplayed ==
           0;
  }
};

class RecordComparer {
 public:
  /// record must outlive the comparer.
  explicit RecordComparer(const VoyageRecord& record);
  /// What the replay wrote of one batch (LiveRun::batch, LiveRun::finish), in order.
  void add(const LiveBatch& b, std::span<const std::string> targetLabels);
  /// The recorded rows never matched counted; the result.
  RecordComparison finish();

 private:
  void own(const sim::ReplayOwnRow& r);
  void track(const RecordedTrack& t);
  void alert(const RecordedAlert& a);
  void fetchOwn(UtcUs upTo);
  void fetchTracks(UtcUs upTo);
  void differ(const std::string& what);

  const VoyageRecord& rec_;
  RecordComparison c_;
  std::deque<sim::ReplayOwnRow> own_;
  std::deque<RecordedTrack> tracks_;
  std::vector<RecordedAlert> alerts_;
  std::size_t nextAlert_ = 0;
  UtcUs ownFetched_ = INT64_MIN, tracksFetched_ = INT64_MIN;  ///< rows up to here are in the deques
};

}  // namespace reckoner::files
