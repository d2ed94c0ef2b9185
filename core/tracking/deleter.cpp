#include "tracking/deleter.h"

#include <algorithm>

#include "tracking/sweep_history.h"

namespace reckoner::track {

HitsInWindowDeleter::HitsInWindowDeleter(int keepHits, int keepSweeps, double lostHoldS)
    : keepSweeps_(keepSweeps), allowedMisses_(keepSweeps - keepHits), holdUs_(fromSeconds(lostHoldS)) {}

bool HitsInWindowDeleter::lost(std::uint32_t history, int sweeps) const {
  const int window = std::min(sweeps, keepSweeps_);
  const int misses = window - hitsInLast(history, window);
  return misses > allowedMisses_;
}

}  // namespace reckoner::track
