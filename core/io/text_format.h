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

/// A graticule label: whole degrees, then minutes and seconds only where they are not zero (rounded
/// to the second), e.g. "47°N", "47°30'N", "47°07'30\"S"; the equator is "0°".
std::string formatLatitudeLabel(double latDeg);
/// The same for a longitude, wrapped into (-180, 180] first: "122°30'W", "0°", "180°".
std::string formatLongitudeLabel(double lonDeg);

/// A field that is one finite number ("12.5", " -3e2 "): spaces around it allowed, nothing else.
std::optional<double> parseFiniteNumber(std::string_view field);

}  // namespace reckoner::io
