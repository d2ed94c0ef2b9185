#include "sim/stream_time.h"

#include <algorithm>
#include <numeric>

namespace reckoner::sim {
namespace {
/// How far a time lies beyond the neighbourhood times[from, to): its distance from their median (the
/// upper one of an even count) less four median absolute deviations, the neighbourhood's own spread
/// (for evenly spaced times about its span, whatever a minority of wrong times among them says).
std::int64_t beyond(std::span<const UtcUs> times, std::size_t from, std::size_t to, UtcUs t,
                    std::vector<UtcUs>& scratch) {
  scratch.assign(times.begin() + static_cast<std::ptrdiff_t>(from),
                 times.begin() + static_cast<std::ptrdiff_t>(to));
  const auto mid = scratch.begin() + static_cast<std::ptrdiff_t>(scratch.size() / 2);
  std::nth_element(scratch.begin(), mid, scratch.end());
  const UtcUs median = *mid;
  for (UtcUs& v : scratch) v = v > median ? v - median : median - v;
  std::nth_element(scratch.begin(), mid, scratch.end());
  const std::int64_t d = t > median ? t - median : median - t;
  return d - 4 * *mid;
}

}  // namespace

bool isolatedTimeJumpAt(std::span<const UtcUs> times, std::size_t i, const StreamTimePolicy& p,
                        std::vector<UtcUs>& scratch) {
  const std::size_t n = times.size(), w = static_cast<std::size_t>(std::max(1, p.window));
  const bool hasBefore = i > 0, hasAfter = i + 1 < n;
  // At the ends of the stream one side must be a full window to judge by.
  if (!hasBefore && n - 1 < w) return false;
  if (!hasAfter && i < w) return false;
  const bool farBefore =
      !hasBefore || beyond(times, i > w ? i - w : 0, i, times[i], scratch) > p.isolatedJumpUs;
  const bool farAfter =
      !hasAfter || beyond(times, i + 1, std::min(n, i + 1 + w), times[i], scratch) > p.isolatedJumpUs;
  return farBefore && farAfter;
}

std::vector<char> isolatedTimeJumps(std::span<const UtcUs> times, const StreamTimePolicy& p) {
  std::vector<char> out(times.size(), 0);
  std::vector<UtcUs> scratch;
  scratch.reserve(static_cast<std::size_t>(std::max(1, p.window)));
  for (std::size_t i = 0; i < times.size(); ++i) out[i] = isolatedTimeJumpAt(times, i, p, scratch) ? 1 : 0;
  return out;
}

std::vector<std::size_t> replayOrder(std::span<const UtcUs> times, std::span<const char> drop,
                                     long& reordered) {
  std::vector<std::size_t> order;
  order.reserve(times.size());
  bool any = false;
  UtcUs latest = 0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (i < drop.size() && drop[i]) continue;
    if (any && times[i] < latest) ++reordered;
    latest = any ? std::max(latest, times[i]) : times[i];
    any = true;
    order.push_back(i);
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return times[a] < times[b]; });
  return order;
}

}  // namespace reckoner::sim
