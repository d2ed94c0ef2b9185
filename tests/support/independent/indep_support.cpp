// Shared pieces of the independent generator: randomness, UTC text, geodesy, NMEA text, files.
#include "indep_sim.h"

#include <GeographicLib/Geodesic.hpp>
#include <GeographicLib/Rhumb.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace reckoner_indep {

double wrapDeg360(double deg) {
  double w = std::fmod(deg, 360.0);
  if (w < 0.0) w += 360.0;
  return w >= 360.0 ? 0.0 : w;
}

double wrapDeg180(double deg) {
  double w = wrapDeg360(deg);
  return w > 180.0 ? w - 360.0 : w;
}

Enu enuFromPolar(double magnitude, double azimuthDeg) {
  const double a = azimuthDeg / kDegPerRad;
  return Enu(magnitude * std::sin(a), magnitude * std::cos(a));
}

double azimuthDegOf(const Enu& v) {
  if (v.x() == 0.0 && v.y() == 0.0) return 0.0;
  return wrapDeg360(std::atan2(v.x(), v.y()) * kDegPerRad);
}

// ---- Randomness ----
double Rng::uniform01() {
  return static_cast<double>(engine_() >> 11) * 0x1.0p-53;  // 53 random bits -> [0, 1)
}

double Rng::uniform(double lo, double hi) {
  return lo + (hi - lo) * uniform01();
}

double Rng::normal(double sd) {
  if (haveSpare_) {
    haveSpare_ = false;
    return sd * spare_;
  }
  // Box-Muller: u1 in (0, 1] keeps the logarithm finite.
  const double u1 = 1.0 - uniform01();
  const double u2 = uniform01();
  const double radius = std::sqrt(-2.0 * std::log(u1));
  const double angle = 2.0 * kPi * u2;
  spare_ = radius * std::sin(angle);
  haveSpare_ = true;
  return sd * radius * std::cos(angle);
}

double Rng::sign() {
  return uniform01() < 0.5 ? -1.0 : 1.0;
}

Rng makeRng(std::uint64_t seed, Stream stream) {
  // SplitMix64 finaliser of (seed, stream): well-separated seeds for the streams of one run.
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (static_cast<std::uint64_t>(stream) + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return Rng(z ^ (z >> 31));
}

void GaussMarkov::step(double dtS, Rng& rng) {
  const double phi = std::exp(-dtS / tauS_);
  x_ = phi * x_ + rng.normal(sd_ * std::sqrt(1.0 - phi * phi));
}

// ---- Time (proleptic Gregorian calendar, H. Hinnant's day-count algorithms) ----
std::int64_t unixSecondsFromCivil(int year, int month, int day, int hour, int minute, int second) {
  const std::int64_t y = year - (month <= 2 ? 1 : 0);
  const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
  const std::int64_t yoe = y - era * 400;
  const std::int64_t mp = (month + 9) % 12;  // March = 0
  const std::int64_t doy = (153 * mp + 2) / 5 + day - 1;
  const std::int64_t doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  const std::int64_t days = era * 146097 + doe - 719468;
  return days * 86400 + std::int64_t{hour} * 3600 + std::int64_t{minute} * 60 + second;
}

namespace {
struct Civil {
  int year, month, day, hour, minute, second;
  std::int64_t microsecond;
};

Civil civilFromUnixUs(std::int64_t unixUs) {
  std::int64_t secs = unixUs / 1000000, us = unixUs % 1000000;
  if (us < 0) {
    us += 1000000;
    --secs;
  }
  std::int64_t days = secs / 86400, sod = secs % 86400;
  if (sod < 0) {
    sod += 86400;
    --days;
  }
  const std::int64_t z = days + 719468;
  const std::int64_t era = (z >= 0 ? z : z - 146096) / 146097;
  const std::int64_t doe = z - era * 146097;
  const std::int64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const std::int64_t doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const std::int64_t mp = (5 * doy + 2) / 153;
  const std::int64_t d = doy - (153 * mp + 2) / 5 + 1;
  const std::int64_t m = mp < 10 ? mp + 3 : mp - 9;
  const std::int64_t y = yoe + era * 400 + (m <= 2 ? 1 : 0);
  return Civil{static_cast<int>(y),
               static_cast<int>(m),
               static_cast<int>(d),
               static_cast<int>(sod / 3600),
               static_cast<int>(sod / 60 % 60),
               static_cast<int>(sod % 60),
               us};
}
}  // namespace

std::string UtcClock::iso(std::int64_t tUs, int fractionDigits) const {
  const Civil c = civilFromUnixUs(startUnixS * 1000000 + tUs);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02d", c.year, c.month, c.day, c.hour, c.minute,
                c.second);
  std::string s = buf;
  if (fractionDigits > 0) {
    char frac[8];
    std::snprintf(frac, sizeof frac, "%06lld", static_cast<long long>(c.microsecond));
    s += '.';
    s.append(frac, static_cast<std::size_t>(std::min(fractionDigits, 6)));
  }
  return s + 'Z';
}

std::string UtcClock::nmeaTime(std::int64_t tUs) const {
  const Civil c = civilFromUnixUs(startUnixS * 1000000 + tUs);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%02d%02d%02d.%02d", c.hour, c.minute, c.second,
                static_cast<int>(c.microsecond / 10000));
  return buf;
}

std::string UtcClock::nmeaDateDdmmyy(std::int64_t tUs) const {
  const Civil c = civilFromUnixUs(startUnixS * 1000000 + tUs);
  char buf[16];
  std::snprintf(buf, sizeof buf, "%02d%02d%02d", c.day, c.month, c.year % 100);
  return buf;
}

std::string UtcClock::zdaDate(std::int64_t tUs) const {
  const Civil c = civilFromUnixUs(startUnixS * 1000000 + tUs);
  char buf[24];
  std::snprintf(buf, sizeof buf, "%02d,%02d,%04d", c.day, c.month, c.year);
  return buf;
}

// ---- Geodesy ----
LatLon rhumbDirect(const LatLon& from, double azimuthDeg, double distanceM) {
  if (distanceM < 0.0) {  // the same rhumb line travelled backwards
    distanceM = -distanceM;
    azimuthDeg += 180.0;
  }
  LatLon to;
  GeographicLib::Rhumb::WGS84().Direct(from.latDeg, from.lonDeg, wrapDeg360(azimuthDeg), distanceM, to.latDeg,
                                       to.lonDeg);
  to.lonDeg = wrapDeg180(to.lonDeg);
  return to;
}

LatLon offsetEnu(const LatLon& from, const Enu& offsetM) {
  const double distanceM = offsetM.norm();
  if (distanceM == 0.0) return from;
  LatLon to;
  GeographicLib::Geodesic::WGS84().Direct(from.latDeg, from.lonDeg, azimuthDegOf(offsetM), distanceM,
                                          to.latDeg, to.lonDeg);
  to.lonDeg = wrapDeg180(to.lonDeg);
  return to;
}

RangeBearing rangeBearing(const LatLon& from, const LatLon& to) {
  double s12 = 0.0, azi1 = 0.0, azi2 = 0.0;
  GeographicLib::Geodesic::WGS84().Inverse(from.latDeg, from.lonDeg, to.latDeg, to.lonDeg, s12, azi1, azi2);
  return RangeBearing{s12, wrapDeg360(azi1)};
}

// ---- NMEA 0183 text ----
std::string nmeaSentence(std::string_view body) {
  unsigned checksum = 0;
  for (const char ch : body) checksum ^= static_cast<unsigned char>(ch);
  char tail[8];
  std::snprintf(tail, sizeof tail, "*%02X\r\n", checksum);
  std::string sentence;
  sentence.reserve(body.size() + 6);
  sentence.append(1, '$').append(body).append(tail);
  return sentence;
}

namespace {
// Degrees and minutes with 6 decimals of a minute; rounding is done on integer micro-minutes so
// 59.9999996' carries into the degrees instead of printing 60.000000.
std::string degreesMinutes(double absDeg, int degreeDigits) {
  const long long microMinutes = std::llround(absDeg * 60.0e6);
  const long long degrees = microMinutes / 60000000LL;
  const long long rest = microMinutes % 60000000LL;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%0*lld%02lld.%06lld", degreeDigits, degrees, rest / 1000000LL,
                rest % 1000000LL);
  return buf;
}
}  // namespace

std::string nmeaLat(double latDeg) {
  return degreesMinutes(std::fabs(latDeg), 2) + (latDeg < 0 ? ",S" : ",N");
}
std::string nmeaLon(double lonDeg) {
  return degreesMinutes(std::fabs(lonDeg), 3) + (lonDeg < 0 ? ",W" : ",E");
}

std::string fmt(const char* format, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, value);
  return buf;
}

std::string joinFields(std::initializer_list<std::string> fields) {
  std::string out;
  for (const std::string& f : fields) {
    if (&f != fields.begin()) out += ',';
    out += f;
  }
  return out;
}

// ---- Files ----
void ensureDirectory(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw std::runtime_error("cannot create output directory '" + dir + "'");
}

void writeTextFile(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);  // binary: the NMEA's CR LF is written as is
  out << text;
  if (!out) throw std::runtime_error("cannot write '" + path + "'");
}

void writeTruthCsv(const std::string& path, const UtcClock& clock, const std::vector<TruthRow>& rows) {
  std::string text =
      "utc,t_s,lat_deg,lon_deg,sog_mps,cog_deg,heading_deg,stw_mps,current_east_mps,current_north_mps,gps_"
      "on\n";
  for (const TruthRow& r : rows) {
    char buf[256];
    std::snprintf(buf, sizeof buf, ",%.3f,%.9f,%.9f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%d\n",
                  static_cast<double>(r.tUs) * 1e-6, r.pos.latDeg, r.pos.lonDeg, r.sogMps, r.cogDeg,
                  r.headingDeg, r.stwMps, r.currentMps.x(), r.currentMps.y(), r.gpsOn ? 1 : 0);
    text += clock.iso(r.tUs, 3) + buf;
  }
  writeTextFile(path, text);
}

}  // namespace reckoner_indep
