#include "io/text_format.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>
#include <system_error>

namespace reckoner::io {
namespace {
std::string degMin(double v, int degWidth, char pos, char neg) {
  if (!std::isfinite(v)) return "--";
  const char hemi = v < 0 ? neg : pos;
  // Round to the printed 0.001' first so that 59.9995' carries into the degrees.
  const long thousandths = std::lround(std::abs(v) * 60000.0);
  const long deg = thousandths / 60000;
  const double min = static_cast<double>(thousandths % 60000) / 1000.0;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%0*ld\u00b0%06.3f'%c", degWidth, deg, min, hemi);
  return buf;
}
std::string degMinSec(double v, char pos, char neg) {
  if (!std::isfinite(v)) return "--";
  const long seconds = std::lround(std::abs(v) * 3600.0);
  std::string s = std::to_string(seconds / 3600) + "\u00b0";
  char buf[24];
  if (seconds % 3600 != 0) {
    std::snprintf(buf, sizeof buf, "%02ld'", seconds / 60 % 60);
    s += buf;
  }
  if (seconds % 60 != 0) {
    std::snprintf(buf, sizeof buf, "%02ld\"", seconds % 60);
    s += buf;
  }
  if (seconds != 0 && seconds != 180L * 3600) s.push_back(v < 0 ? neg : pos);
  return s;
}
}  // namespace

std::string formatLatitudeLabel(double latDeg) {
  return degMinSec(latDeg, 'N', 'S');
}
std::string formatLongitudeLabel(double lonDeg) {
  if (!std::isfinite(lonDeg)) return "--";
  double lon = std::fmod(lonDeg, 360.0);
  if (lon > 180.0) lon -= 360.0;
  if (lon <= -180.0) lon += 360.0;
  return degMinSec(lon, 'E', 'W');
}

std::string formatLatitude(double latDeg) {
  return degMin(latDeg, 2, 'N', 'S');
}
std::string formatLongitude(double lonDeg) {
  return degMin(lonDeg, 3, 'E', 'W');
}

std::optional<double> parseFiniteNumber(std::string_view f) {
  while (!f.empty() && f.front() == ' ') f.remove_prefix(1);
  while (!f.empty() && f.back() == ' ') f.remove_suffix(1);
  if (f.empty()) return std::nullopt;
  double v = 0.0;
  const auto [p, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
  if (ec != std::errc() || p != f.data() + f.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace reckoner::io
