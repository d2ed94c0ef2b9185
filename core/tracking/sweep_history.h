#pragma once
// A track's sweep history (Track::history): bit k set when the track was seen in the k-th most recent
// completed sweep. The initiator (M of N) and the deleter (hits in the last sweeps) both count it.
#include <bit>
#include <cstdint>

namespace reckoner::track {

/// The history after one more completed sweep.
[[nodiscard]] inline std::uint32_t recordSweep(std::uint32_t history, bool seen) {
  return (history << 1) | (seen ? 1u : 0u);
}

/// Sweeps with a plot among the last n (n >= 32: all 32 kept).
[[nodiscard]] inline int hitsInLast(std::uint32_t history, int n) {
  const std::uint32_t lowBits = n >= 32 ? 0xFFFFFFFFu : ((1u << n) - 1u);
  return std::popcount(history & lowBits);
}

}  // namespace reckoner::track
