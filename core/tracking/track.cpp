#include "tracking/track.h"

#include <algorithm>

namespace reckoner::track {

const char* trackStatusName(TrackStatus s) {
  switch (s) {
    case TrackStatus::Tentative:
      return "tentative";
    case TrackStatus::Confirmed:
      return "confirmed";
    case TrackStatus::Lost:
      return "lost";
  }
  return "?";
}

int Track::tag() const {
  const int n = std::min(tagCount, static_cast<int>(recentTags.size()));
  if (n == 0) return -1;
  int best = -1, bestCount = 0;
  // Walk from the most recent so that ties go to the latest.
  for (int k = 0; k < n; ++k) {
    const int idx = (tagCount - 1 - k) % static_cast<int>(recentTags.size());
    const int cand = recentTags[static_cast<std::size_t>(idx)];
    int count = 0;
    for (int m = 0; m < n; ++m) count += recentTags[static_cast<std::size_t>(m)] == cand ? 1 : 0;
    if (count > bestCount) {
      best = cand;
      bestCount = count;
    }
  }
  return best;
}

}  // namespace reckoner::track
