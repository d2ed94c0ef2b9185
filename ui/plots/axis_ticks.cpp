#include "ui/plots/axis_ticks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace reckoner::ui {
namespace {

/// mult x 10^k, divided rather than multiplied by a negative power so that 3 x 10^-1 is 0.3.
double scaled(double mult, int k) {
  return k >= 0 ? mult * std::pow(10.0, k) : mult / std::pow(10.0, -k);
}

/// The intervals of `step` from the multiple at or below a to the multiple at or above b (a tolerance of
/// 1e-9 step keeps an end that is a multiple up to rounding from taking one interval more).
struct Cover {
  double first, last;  ///< a / step rounded down, b / step rounded up
};
Cover cover(double a, double b, double step) {
  const double first = std::floor(a / step + 1e-9);
  return {first, std::max(first + 1.0, std::ceil(b / step - 1e-9))};
}

}  // namespace

void DataRange::add(double v) {
  if (!std::isfinite(v)) return;
  lo = std::min(lo, v);
  hi = std::max(hi, v);
}

AxisTicks niceTicks(double lo, double hi, int maxIntervals, double margin) {
  maxIntervals = std::max(1, maxIntervals);
  margin = std::max(0.0, margin);
  if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi) {
    lo = 0.0;
    hi = 1.0;
    margin = 0.0;
  } else if (lo == hi) {
    const double half = lo == 0.0 ? 1.0 : std::abs(lo) * 0.1;
    lo -= half;
    hi += half;
    margin = 0.0;
  }
  const double pad = (hi - lo) * margin;
  double a = lo - pad, b = hi + pad;
  if (lo >= 0.0 && a < 0.0) a = 0.0;
  if (hi <= 0.0 && b > 0.0) b = 0.0;
  // From a decade below the step that divides the span exactly, the first nice step that fits.
  constexpr std::array<double, 4> kMantissas{1.0, 2.0, 2.5, 5.0};
  for (int k = static_cast<int>(std::floor(std::log10((b - a) / maxIntervals))) - 1;; ++k)
    for (const double m : kMantissas) {
      const double step = scaled(m, k);
      const Cover c = cover(a, b, step);
      if (c.last - c.first > maxIntervals) continue;
      AxisTicks t;
      t.step = step;
      t.min = scaled(c.first * m, k);
      t.max = scaled(c.last * m, k);
      t.intervals = static_cast<int>(c.last - c.first);
      t.decimals = std::max(0, -k + (m == 2.5 ? 1 : 0));
      return t;
    }
}

AxisTicks timeTicks(double t0S, double t1S, int maxIntervals) {
  maxIntervals = std::max(1, maxIntervals);
  if (!std::isfinite(t0S) || !std::isfinite(t1S) || t0S > t1S) {
    t0S = 0.0;
    t1S = 60.0;
  }
  if (t1S - t0S < 60.0) {  // at least the minute the data starts in
    t0S = std::floor(t0S / 60.0) * 60.0;
    t1S = std::max(t1S, t0S + 60.0);
  }
  constexpr std::array<double, 15> kSteps{10.0,   15.0,   30.0,   60.0,    120.0,   300.0,   600.0,  900.0,
                                          1800.0, 3600.0, 7200.0, 10800.0, 21600.0, 43200.0, 86400.0};
  for (int i = 0;; ++i) {
    // Past a day: 1, 2, 5, 10, 20, ... days.
    const double step = i < static_cast<int>(kSteps.size())
                            ? kSteps[static_cast<std::size_t>(i)]
                            : 86400.0 * scaled(std::array{2.0, 5.0, 10.0}[(i - 15) % 3], (i - 15) / 3);
    const Cover c = cover(t0S, t1S, step);
    if (c.last - c.first > maxIntervals) continue;
    AxisTicks t;
    t.step = step;
    t.min = c.first * step;
    t.max = c.last * step;
    t.intervals = static_cast<int>(c.last - c.first);
    t.decimals = 0;
    return t;
  }
}

std::string tickLabel(double v, int decimals) {
  decimals = std::clamp(decimals, 0, 17);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  std::string s(buf);
  // "-0", "-0.00": a value that rounds to zero is written without its sign.
  if (s.front() == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

std::string clockLabel(double tS, bool withHours) {
  long long s = std::llround(tS);
  const bool negative = s < 0;
  if (negative) s = -s;
  char buf[64];
  if (withHours)
    std::snprintf(buf, sizeof buf, "%s%lld:%02lld:%02lld", negative ? "-" : "", s / 3600, s % 3600 / 60,
                  s % 60);
  else
    std::snprintf(buf, sizeof buf, "%s%02lld:%02lld", negative ? "-" : "", s / 60, s % 60);
  return buf;
}

std::vector<std::string> tickLabels(const AxisTicks& ticks) {
  std::vector<std::string> out;
  for (int i = 0; i <= ticks.intervals; ++i) out.push_back(tickLabel(ticks.at(i), ticks.decimals));
  return out;
}

std::vector<std::string> clockLabels(const AxisTicks& ticks) {
  std::vector<std::string> out;
  const bool hours = clockNeedsHours(ticks.max);
  for (int i = 0; i <= ticks.intervals; ++i) out.push_back(clockLabel(ticks.at(i), hours));
  return out;
}

}  // namespace reckoner::ui
