#pragma once
// Simulation and filter time: integer microseconds since scenario start.
#include <cmath>
#include <cstdint>

namespace reckoner {

using TimeUs = std::int64_t;
/// UTC as microseconds since 1970-01-01T00:00:00Z.
using UtcUs = std::int64_t;

inline constexpr TimeUs kMicrosPerSecond = 1'000'000;

/// Seconds (double) from microseconds.
constexpr double toSeconds(TimeUs t) {
  return static_cast<double>(t) * 1e-6;
}

/// Microseconds from seconds, rounded to the nearest microsecond. s must be finite and |s| < 9.2e12.
inline TimeUs fromSeconds(double s) {
  return static_cast<TimeUs>(std::llround(s * 1e6));
}

}  // namespace reckoner
