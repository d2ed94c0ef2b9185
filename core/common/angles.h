#pragma once
// Angles: radians inside the program, clockwise from (grid or true) north for bearings and headings.
#include <cmath>
#include <numbers>

namespace reckoner {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;

constexpr double degToRad(double deg) {
  return deg * (kPi / 180.0);
}
constexpr double radToDeg(double rad) {
  return rad * (180.0 / kPi);
}

/// Wraps an angle to (-pi, pi]. Exact for any finite input (std::remainder is exact); NaN stays NaN.
inline double wrapPi(double a) {
  const double r = std::remainder(a, kTwoPi);  // in [-pi, pi]
  return r <= -kPi ? r + kTwoPi : r;
}

/// Wraps an angle to [0, 2 pi).
inline double wrapTwoPi(double a) {
  const double r = std::remainder(a, kTwoPi);  // in [-pi, pi]
  return r < 0.0 ? r + kTwoPi : r;
}

/// Signed smallest difference a - b, in (-pi, pi]. angleDiff(1 deg, 359 deg) = +2 deg.
inline double angleDiff(double a, double b) {
  return wrapPi(a - b);
}

/// Bearing of the vector (east, north), clockwise from north, in [0, 2 pi). Zero vector gives 0.
inline double bearingOf(double east, double north) {
  return wrapTwoPi(std::atan2(east, north));
}

}  // namespace reckoner
