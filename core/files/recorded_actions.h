#pragma once
// The operator's recorded actions applied again (docs/recorder.md, "Operator actions"): a replay or a
// playback of a record puts each action to the watch after the batch it followed, so the alert log's
// acknowledgements, the silences and the limits come out as they did in the run.
#include <cstdint>
#include <vector>

#include "files/voyage_record.h"
#include "sim/live_watch.h"

namespace reckoner::files {

/// One action on the watch: acknowledge ("alert:KIND:SOURCE"), silence_all, cpa_limits
/// ("cpa_m=..;tcpa_s=.."), dr_limit ("m=.."), ais_activate, ais_sleep, ais_select ("mmsi:N"). False
/// for an action this program does not know or cannot read (the caller counts it).
bool applyOperatorAction(const OperatorAction& a, sim::LiveWatch& watch);

/// A record's actions in batch order, applied after their batches.
class ActionReplayer {
 public:
  explicit ActionReplayer(std::vector<OperatorAction> actions);
  /// Applies every action made after batch `batch` or before it and not yet applied.
  void afterBatch(std::int64_t batch, sim::LiveWatch& watch);
  /// Back to the first action (a playback's seek back).
  void rewind() { next_ = 0; }
  [[nodiscard]] long applied() const { return applied_; }
  [[nodiscard]] long skipped() const { return skipped_; }

 private:
  std::vector<OperatorAction> actions_;
  std::size_t next_ = 0;
  long applied_ = 0, skipped_ = 0;
};

}  // namespace reckoner::files
