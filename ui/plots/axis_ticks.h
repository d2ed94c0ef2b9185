#pragma once
// Round axis ticks for the error plots (plain C++, no Qt): value axes on steps of 1, 2, 2.5 or 5 x 10^k
// whose ends are ticks, the time axis on steps of seconds, minutes and hours labelled mm:ss (h:mm:ss
// from an hour on). The plots ask for as many intervals as their pixel size holds.
#include <limits>
#include <string>
#include <vector>

namespace reckoner::ui {

/// Ticks at min, min + step, ..., max: `intervals` steps, min and max multiples of step.
struct AxisTicks {
  double min = 0.0, max = 1.0, step = 0.25;
  int intervals = 4;
  /// Digits after the point that write every tick exactly (0 for steps of 1 and above but 2.5).
  int decimals = 2;

  [[nodiscard]] double at(int i) const { return min + step * i; }
  bool operator==(const AxisTicks&) const = default;
};

/// The range of the finite values given to add() (NaN and infinities are ignored).
struct DataRange {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();

  void add(double v);
  [[nodiscard]] bool empty() const { return !(lo <= hi); }
};

/// The nice-stepped axis covering [lo, hi] widened by `margin` (a fraction of the span on each side;
/// a margin never takes a non-negative range below 0 nor a non-positive one above 0) in at most
/// maxIntervals intervals (at least 1). A single value v gets v +- 10% (+-1 for 0); a range that is not
/// finite or empty (lo > hi) gets [0, 1].
[[nodiscard]] AxisTicks niceTicks(double lo, double hi, int maxIntervals, double margin = 0.03);

/// The time axis covering [t0S, t1S] (when shorter than a minute, the whole minute it starts in, or
/// the 60 s from the start of that minute) in at most maxIntervals intervals of 10 s,
/// 15 s, 30 s, 1, 2, 5, 10, 15 or 30 min, 1, 2, 3, 6 or 12 h or whole days; a range that is not finite
/// or empty gets [0, 60] s.
[[nodiscard]] AxisTicks timeTicks(double t0S, double t1S, int maxIntervals);

/// v with `decimals` digits after the point, never "-0".
[[nodiscard]] std::string tickLabel(double v, int decimals);
/// "mm:ss" (minutes may pass 59 only when withHours is false), "h:mm:ss" when withHours; whole
/// seconds, rounded; a minus sign before negative times.
[[nodiscard]] std::string clockLabel(double tS, bool withHours);
/// Whether a time axis ending at maxS writes hours (from an hour on).
[[nodiscard]] inline bool clockNeedsHours(double maxS) {
  return maxS >= 3600.0 - 0.5;
}

/// The labels of the ticks: tickLabel of each, or clockLabel for a time axis.
[[nodiscard]] std::vector<std::string> tickLabels(const AxisTicks& ticks);
[[nodiscard]] std::vector<std::string> clockLabels(const AxisTicks& ticks);

}  // namespace reckoner::ui
