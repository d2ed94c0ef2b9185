#pragma once
// Human-readable formats for terminals and screens.
#include <string>

namespace reckoner::io {

/// Latitude as degrees and decimal minutes, e.g. "49°17.402'N". NaN gives "--".
std::string formatLatitude(double latDeg);
/// Longitude as degrees and decimal minutes, e.g. "123°06.599'W". NaN gives "--".
std::string formatLongitude(double lonDeg);

}  // namespace reckoner::io
