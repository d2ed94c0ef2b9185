#pragma once
// The deleter: an established track is lost when it was seen in fewer than keepHits of its last
// keepSweeps sweeps (IMO MSC.192(79) 5.25: 5 of 10); a lost track is still shown, at its last position,
// for lostHoldS, then removed. docs/ttkf.md has the rules and their reasons.
#include <cstdint>

#include "common/time.h"

namespace reckoner::track {

class HitsInWindowDeleter {
 public:
  /// 1 <= keepHits <= keepSweeps <= 32, lostHoldS >= 0 (TrackManagerConfig::check).
  HitsInWindowDeleter(int keepHits, int keepSweeps, double lostHoldS);
  /// history: bit k set when seen k sweeps ago; sweeps: completed sweeps since initiation (>= 1). True
  /// when more than keepSweeps - keepHits of the last min(sweeps, keepSweeps) sweeps were misses.
  [[nodiscard]] bool lost(std::uint32_t history, int sweeps) const;
  /// True when a track lost at lostUs has been shown long enough at nowUs.
  [[nodiscard]] bool expired(TimeUs lostUs, TimeUs nowUs) const { return nowUs - lostUs >= holdUs_; }

 private:
  int keepSweeps_;
  int allowedMisses_;  ///< keepSweeps - keepHits
  TimeUs holdUs_;
};

}  // namespace reckoner::track
