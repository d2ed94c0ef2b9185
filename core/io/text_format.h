#pragma once
// Human-readable formats for terminals and screens.
#include <optional>
#include <string>
#include <string_view>

namespace reckoner::io {

/// Latitude as degrees and decimal minutes, e.g. "49°17.402'N". NaN gives "--".
std::string formatLatitude(double latDeg);
/// Longitude as degrees and decimal minutes, e.g. "123°06.599'W". NaN gives "--".
std::string formatLongitude(double lonDeg);

/// A field that is one finite number ("12.5", " -3e2 "): spaces around it allowed, nothing else.
std::optional<double> parseFiniteNumber(std::string_view field);

}  // namespace reckoner::io
