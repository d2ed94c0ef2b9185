#pragma once
// The stream-time policy of replay (docs/outputs.md, "Replay: time"). Recorded streams carry clock
// errors a filter must not follow: a lone sentence stamped minutes or years away (a bit flip, a
// receiver's glitch) and stretches written out of order (files concatenated or reversed, talkers that
// stamp their sentences a little apart). The policy, the same for NMEA sentences and radar plots:
//  1. an isolated time jump, a timestamp farther than isolatedJumpUs plus the neighbourhood's own spread
//     (four median absolute deviations) from the median of the `window` timestamps before it and from
//     the median of the `window` after it, is a clock error: counted and dropped (at the ends of the
//     stream, one side of a full window). The spread makes the test scale with the stream's rate (60 s
//     is far for 1 Hz sentences, not for sonar pings every 80 s), and medians keep a minority of wrong
//     times in a window from hiding each other;
//  2. what remains is replayed in time order (a stable sort: items of one time keep their order); an
//     item older than one before it in the file counts as reordered, never as lost;
//  3. a gap longer than the replay's max gap restarts the own-ship filter at the next fix (replay.h).
// Cost: O(n window log window) time, O(n) memory.
#include <cstdint>
#include <span>
#include <vector>

#include "common/time.h"

namespace reckoner::sim {

struct StreamTimePolicy {
  std::int64_t isolatedJumpUs = 60'000'000;  ///< this much beyond both neighbourhoods: a jump
  int window = 8;                            ///< timestamps on each side
};

/// For times in arrival order: 1 where the time is an isolated jump (rule 1 above), else 0.
std::vector<char> isolatedTimeJumps(std::span<const UtcUs> times, const StreamTimePolicy& policy);

/// Rule 1 for the time at i alone. It reads times[i - window, i + window] only, so a stream can decide
/// each time once the window after it has arrived (or the stream has ended) and get the same answer
/// (scratch: working memory, reused between calls).
bool isolatedTimeJumpAt(std::span<const UtcUs> times, std::size_t i, const StreamTimePolicy& policy,
                        std::vector<UtcUs>& scratch);

/// The order (indices into times) in which items are replayed: the stable time order of the items
/// not flagged in `drop`. `reordered` counts the kept items older than a kept item before them.
std::vector<std::size_t> replayOrder(std::span<const UtcUs> times, std::span<const char> drop,
                                     long& reordered);

}  // namespace reckoner::sim
