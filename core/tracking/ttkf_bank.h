#pragma once
// One DRKF feeds a bank of TTKFs (seed 000 figure 3). This bank assumes each plot's target is known
// (the paper's assumption); track management with unknown association builds on it.
#include <cstddef>
#include <unordered_map>
#include <vector>

#include "tracking/ttkf.h"

namespace reckoner::track {

struct TrackState {
  int trackId = 0;
  int targetId = -1;  ///< the true target this track follows (known under perfect association)
  Ttkf filter;
  int radarUpdates = 0;
  est::UpdateReport<2> lastRadar;
};

class TtkfBank {
 public:
  /// capacity: most tracks held (at least 1000 by design); throws std::invalid_argument for a bad
  /// configuration.
  explicit TtkfBank(const TtkfConfig& config, std::size_t capacity = 1000);

  /// Feeds the DRKF's own-ship output to every track.
  void feedOwnShip(const OwnShipInput& own);
  /// A plot whose source target is known: updates that target's track, or initiates one from the plot
  /// (own ship from `lastOwn`). Returns the track, or nullptr when the bank is full.
  const TrackState* processAssociated(int targetId, const GridPlot& plot, const OwnShipInput& lastOwn);
  /// Predicts every track to t (for a snapshot at a common time).
  void predictAllTo(TimeUs t);

  [[nodiscard]] const std::vector<TrackState>& tracks() const { return tracks_; }
  [[nodiscard]] std::size_t capacity() const { return capacity_; }
  [[nodiscard]] long plotsRefusedForCapacity() const { return refused_; }
  [[nodiscard]] const std::shared_ptr<const TtkfContext>& context() const { return ctx_; }

 private:
  std::shared_ptr<const TtkfContext> ctx_;
  std::size_t capacity_;
  std::vector<TrackState> tracks_;
  std::unordered_map<int, std::size_t> byTarget_;
  int nextTrackId_ = 1;
  long refused_ = 0;
};

}  // namespace reckoner::track
