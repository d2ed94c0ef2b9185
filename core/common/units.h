#pragma once
// Units used only at the edges (files, screens): knots and nautical miles.

namespace reckoner {

inline constexpr double kMetresPerNauticalMile = 1852.0;
inline constexpr double kMpsPerKnot = 1852.0 / 3600.0;

constexpr double knotsToMps(double kn) {
  return kn * kMpsPerKnot;
}
constexpr double mpsToKnots(double mps) {
  return mps / kMpsPerKnot;
}
constexpr double nmToMetres(double nm) {
  return nm * kMetresPerNauticalMile;
}
constexpr double metresToNm(double m) {
  return m / kMetresPerNauticalMile;
}

}  // namespace reckoner
