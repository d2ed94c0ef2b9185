#include "io/nmea_out.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "common/angles.h"
#include "common/units.h"
#include "io/iso8601.h"
#include "io/nmea.h"

namespace reckoner::io::nmea {
namespace {

/// "ddmm.mmmm,N" (or with three degree digits, a longitude); "," (both fields empty) for a value not finite
/// or beyond 90 (latitude) or 180 degrees, as a track's position that is unknown (never "nan", nor a
/// cast of NaN to int).
std::string angleField(double deg, int degDigits, int minuteDecimals, char pos, char neg) {
  if (!std::isfinite(deg) || std::abs(deg) > (degDigits == 2 ? 90.0 : 180.0)) return ",";
  const int decimals = std::clamp(minuteDecimals, 0, 9);
  const double a = std::abs(deg);
  int d = static_cast<int>(std::floor(a));
  double m = (a - d) * 60.0;
  if (m >= 60.0 - 0.5 * std::pow(10.0, -decimals)) {  // would print as 60.000000
    m = 0.0;
    ++d;
  }
  char buf[48];
  std::snprintf(buf, sizeof buf, "%0*d%0*.*f,%c", degDigits, d, decimals > 0 ? decimals + 3 : 2, decimals, m,
                deg < 0 ? neg : pos);
  return buf;
}

/// A number with `decimals` decimals; empty when absent or not finite.
std::string num(std::optional<double> v, int decimals) {
  if (!v || !std::isfinite(*v)) return {};
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, *v);
  // "-0.00" says nothing "0.00" does not.
  if (buf[0] == '-' && std::all_of(buf + 1, buf + std::char_traits<char>::length(buf),
                                   [](char c) { return c == '0' || c == '.'; }))
    return buf + 1;
  return buf;
}

/// An angle in [0, 360) with `decimals` decimals (never printed as 360).
std::string degrees(double deg, int decimals) {
  if (!std::isfinite(deg)) return {};
  double d = std::fmod(deg, 360.0);
  if (d < 0) d += 360.0;
  const double scale = std::pow(10.0, decimals);
  if (std::round(d * scale) >= 360.0 * scale) d = 0.0;
  return num(d, decimals);
}

std::string twoDigits(int v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%02d", v);
  return buf;
}

std::string ch(char c) {
  return std::string(1, c);
}

/// The sentence from its address and fields.
std::string sentence(std::string_view talker, std::string_view type, const std::vector<std::string>& fields) {
  std::string body;
  body.append(talker).append(type);
  for (const auto& f : fields) body.append(",").append(f);
  return withChecksum(body);
}

std::string clampInt(int v, int lo, int hi, int width) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%0*d", width, std::clamp(v, lo, hi));
  return buf;
}

/// A magnitude in [0, maxValue] with `decimals` decimals (the sign dropped); empty when not finite.
std::string magnitude(double v, double maxValue, int decimals) {
  if (!std::isfinite(v)) return {};
  return num(std::min(std::abs(v), maxValue), decimals);
}

/// Route following's status (both status fields) and mode (docs/outputs.md, "Route following: XTE, RMB,
/// APB").
bool navStatusValid(bool valid, char mode) {
  return valid && (mode == 'A' || mode == 'D' || mode == 'E');
}
std::string navMode(bool valid, char mode) {
  return ch(valid ? mode : 'N');
}
std::string av(bool a) {
  return a ? "A" : "V";
}

/// Cross-track magnitude and direction to steer as two fields; both empty when not valid or absent.
std::pair<std::string, std::string> crossTrack(bool valid, double nm, double maxNm, bool steerRight) {
  if (!valid || !std::isfinite(nm)) return {};
  return {magnitude(nm, maxNm, 2), steerRight ? "R" : "L"};
}

}  // namespace

std::string nmeaLatitude(double latDeg, int minuteDecimals) {
  return angleField(latDeg, 2, minuteDecimals, 'N', 'S');
}
std::string nmeaLongitude(double lonDeg, int minuteDecimals) {
  return angleField(lonDeg, 3, minuteDecimals, 'E', 'W');
}

std::string nmeaTime(UtcUs t) {
  const std::string iso = formatIso8601(t);  // YYYY-MM-DDThh:mm:ss.ffffffZ
  return iso.substr(11, 2) + iso.substr(14, 2) + iso.substr(17, 2) + "." + iso.substr(20, 2);
}

std::string nmeaDate(UtcUs t) {
  const std::string iso = formatIso8601(t);
  return iso.substr(8, 2) + iso.substr(5, 2) + iso.substr(2, 2);
}

std::string escapeText(std::string_view text, std::size_t maxChars) {
  static constexpr std::string_view kReserved = "\r\n$*,!\\^~";
  std::string out;
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    std::string piece;
    if (u < 0x20 || u >= 0x7F || kReserved.find(c) != std::string_view::npos) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "^%02X", static_cast<unsigned>(u));
      piece = buf;
    } else {
      piece = std::string(1, c);
    }
    if (out.size() + piece.size() > maxChars) break;  // never half an escape
    out += piece;
  }
  return out;
}

std::string rmc(std::string_view talker, const RmcOut& v) {
  const bool valid = v.mode == 'A' || v.mode == 'D' || v.mode == 'E';
  const std::string lat = nmeaLatitude(v.latDeg), lon = nmeaLongitude(v.lonDeg);
  return sentence(talker, "RMC",
                  {nmeaTime(v.utc), valid ? "A" : "V", lat.substr(0, lat.find(',')),
                   lat.substr(lat.find(',') + 1), lon.substr(0, lon.find(',')), lon.substr(lon.find(',') + 1),
                   num(v.sogKn, 2), degrees(v.cogTrueDeg, 2), nmeaDate(v.utc), "", "", ch(v.mode)});
}

std::string gga(std::string_view talker, const GgaOut& v) {
  const std::string lat = nmeaLatitude(v.latDeg), lon = nmeaLongitude(v.lonDeg);
  return sentence(talker, "GGA",
                  {nmeaTime(v.utc), lat.substr(0, lat.find(',')), lat.substr(lat.find(',') + 1),
                   lon.substr(0, lon.find(',')), lon.substr(lon.find(',') + 1), std::to_string(v.quality),
                   v.satellites ? clampInt(*v.satellites, 0, 99, 2) : "", num(v.hdop, 1), num(v.altitudeM, 1),
                   "M", "", "M", "", ""});
}

std::string vtg(std::string_view talker, const VtgOut& v) {
  return sentence(talker, "VTG",
                  {degrees(v.cogTrueDeg, 2), "T", "", "M", num(v.sogKn, 2), "N",
                   num(knotsToMps(v.sogKn) * 3.6, 2), "K", ch(v.mode)});
}

std::string hdt(std::string_view talker, double headingTrueDeg) {
  return sentence(talker, "HDT", {degrees(headingTrueDeg, 2), "T"});
}

std::string gst(std::string_view talker, const GstOut& v) {
  return sentence(talker, "GST",
                  {nmeaTime(v.utc), num(v.rmsM, 2), num(v.majorSdM, 2), num(v.minorSdM, 2),
                   degrees(v.majorOrientationDeg, 1), num(v.latSdM, 2), num(v.lonSdM, 2), num(v.altSdM, 2)});
}

ErrorEllipse errorEllipse(double varNorthM2, double varEastM2, double covNorthEastM2) {
  const double mean = 0.5 * (varNorthM2 + varEastM2);
  const double half = 0.5 * (varNorthM2 - varEastM2);
  const double radius = std::hypot(half, covNorthEastM2);
  ErrorEllipse e;
  e.majorSdM = std::sqrt(std::max(0.0, mean + radius));
  e.minorSdM = std::sqrt(std::max(0.0, mean - radius));
  // The major axis at theta from north toward east: tan(2 theta) = 2 c_ne / (c_nn - c_ee).
  double deg = radToDeg(0.5 * std::atan2(2.0 * covNorthEastM2, varNorthM2 - varEastM2));
  if (deg < 0) deg += 180.0;
  if (deg >= 180.0) deg -= 180.0;
  e.orientationDeg = deg;
  return e;
}

std::string ttm(std::string_view talker, const TtmOut& v) {
  // Numbers bounded so that the sentence fits: distance and CPA at most 999.999 NM, speed 999.99 kn,
  // TCPA within +-9999.99 minutes (about a week: farther is no alarm); then the name cut to the room left.
  const auto bounded = [](std::optional<double> x, double lo, double hi, int decimals) {
    return x && std::isfinite(*x) ? num(std::clamp(*x, lo, hi), decimals) : std::string{};
  };
  std::vector<std::string> f{clampInt(v.number, 0, 99, 2),
                             bounded(v.distanceNm, 0.0, 999.999, 3),
                             degrees(v.bearingDeg, 1),
                             ch(v.bearingRef),
                             bounded(v.speedKn, 0.0, 999.99, 2),
                             degrees(v.courseDeg, 1),
                             ch(v.courseRef),
                             bounded(v.cpaNm, 0.0, 999.999, 3),
                             bounded(v.tcpaMin, -9999.99, 9999.99, 2),
                             "N",
                             "",
                             ch(v.status),
                             v.reference ? "R" : "",
                             nmeaTime(v.utc),
                             ch(v.acquisition)};
  const std::size_t used = sentence(talker, "TTM", f).size();
  f[10] =
      escapeText(v.name, std::min<std::size_t>(20, kMaxSentenceChars > used ? kMaxSentenceChars - used : 0));
  return sentence(talker, "TTM", f);
}

std::string tll(std::string_view talker, const TllOut& v) {
  const std::string lat = nmeaLatitude(v.latDeg), lon = nmeaLongitude(v.lonDeg);
  return sentence(talker, "TLL",
                  {clampInt(v.number, 0, 99, 2), lat.substr(0, lat.find(',')), lat.substr(lat.find(',') + 1),
                   lon.substr(0, lon.find(',')), lon.substr(lon.find(',') + 1), escapeText(v.name, 20),
                   nmeaTime(v.utc), ch(v.status), v.reference ? "R" : ""});
}

std::string osd(std::string_view talker, const OsdOut& v) {
  return sentence(talker, "OSD",
                  {v.headingTrueDeg ? degrees(*v.headingTrueDeg, 1) : "", v.headingTrueDeg ? "A" : "V",
                   degrees(v.courseTrueDeg, 1), ch(v.courseRef), num(v.speedKn, 2), ch(v.speedRef),
                   v.setTrueDeg ? degrees(*v.setTrueDeg, 1) : "", num(v.driftKn, 2), "N"});
}

std::string xte(std::string_view talker, const XteOut& v) {
  const std::string status = av(navStatusValid(v.valid, v.mode));
  const auto [xteNm, steer] = crossTrack(v.valid, v.crossTrackNm, 999.99, v.steerRight);
  return sentence(talker, "XTE", {status, status, xteNm, steer, "N", navMode(v.valid, v.mode)});
}

std::string rmb(std::string_view talker, const RmbOut& v) {
  const auto [xteNm, steer] = crossTrack(v.valid, v.crossTrackNm, 9.99, v.steerRight);
  // 4 decimals of minutes (0.2 m): with 6 the ids would have no room in 80 characters.
  const std::string lat = nmeaLatitude(v.destLatDeg, 4), lon = nmeaLongitude(v.destLonDeg, 4);
  std::vector<std::string> f{av(navStatusValid(v.valid, v.mode)),
                             xteNm,
                             steer,
                             escapeText(v.originId, kWaypointIdChars),
                             escapeText(v.destinationId, kWaypointIdChars),
                             lat.substr(0, lat.find(',')),
                             lat.substr(lat.find(',') + 1),
                             lon.substr(0, lon.find(',')),
                             lon.substr(lon.find(',') + 1),
                             v.valid ? magnitude(v.rangeToDestNm, 999.9, 2) : "",
                             v.valid ? degrees(v.bearingToDestTrueDeg, 1) : "",
                             v.valid ? num(std::clamp(v.closingVelocityKn, -999.9, 999.9), 1) : "",
                             av(v.valid && v.arrived),
                             navMode(v.valid, v.mode)};
  // Too long (only with the longest ids and numbers): cut the origin's id, then the destination's.
  for (const std::size_t i : {std::size_t(3), std::size_t(4)}) {
    const std::size_t length = sentence(talker, "RMB", f).size();
    if (length <= kMaxSentenceChars) break;
    const std::size_t over = length - kMaxSentenceChars;
    f[i] = escapeText(i == 3 ? v.originId : v.destinationId, f[i].size() > over ? f[i].size() - over : 0);
  }
  return sentence(talker, "RMB", f);
}

std::string apb(std::string_view talker, const ApbOut& v) {
  const std::string status = av(navStatusValid(v.valid, v.mode));
  const auto [xteNm, steer] = crossTrack(v.valid, v.crossTrackNm, 999.99, v.steerRight);
  const std::string ref = v.bearingMagnetic ? "M" : "T";
  return sentence(
      talker, "APB",
      {status, status, xteNm, steer, "N", av(v.valid && v.arrivalCircleEntered),
       av(v.valid && v.perpendicularPassed), degrees(v.bearingOriginToDestDeg, 1), ref,
       escapeText(v.destinationId, kWaypointIdChars), v.valid ? degrees(v.bearingPresentToDestDeg, 1) : "",
       ref, v.valid ? degrees(v.headingToSteerDeg, 1) : "", ref, navMode(v.valid, v.mode)});
}

std::string alr(std::string_view talker, const AlrOut& v) {
  std::vector<std::string> f{nmeaTime(v.utc), clampInt(v.number, 0, 999, 3), v.active ? "A" : "V",
                             v.acknowledged ? "A" : "V", ""};
  const std::size_t used = sentence(talker, "ALR", f).size();
  f.back() = escapeText(v.text, kMaxSentenceChars - used);
  return sentence(talker, "ALR", f);
}

std::vector<std::string> alf(std::string_view talker, const AlfOut& v) {
  const bool two = !v.description.empty();
  const std::string total = two ? "2" : "1", seq = std::to_string(std::clamp(v.sequence, 0, 9));
  const std::string id = std::to_string(std::clamp(v.identifier, 1, 9999999));
  const std::string inst = std::to_string(std::clamp(v.instance, 1, 999999));
  const std::string rev = std::to_string(std::clamp(v.revision, 1, 99));
  const std::string esc = std::to_string(std::clamp(v.escalation, 0, 9));
  const std::string man = escapeText(v.manufacturer, 3);
  std::vector<std::string> out;
  out.push_back(sentence(talker, "ALF",
                         {total, "1", seq, nmeaTime(v.utc), ch(v.category), ch(v.priority), ch(v.state), man,
                          id, inst, rev, esc, escapeText(v.title, 16)}));
  if (two) {
    // The second sentence: the additional text, with time, category, priority and state null.
    std::vector<std::string> f{total, "2", seq, "", "", "", "", man, id, inst, rev, esc, ""};
    const std::size_t used = sentence(talker, "ALF", f).size();
    f.back() = escapeText(v.description, kMaxSentenceChars - used);
    out.push_back(sentence(talker, "ALF", f));
  }
  return out;
}

std::vector<std::string> alc(std::string_view talker, int sequence, const std::vector<AlcEntry>& entries) {
  const std::string seq = std::to_string(std::clamp(sequence, 0, 9));
  // Entries per sentence: as many as fit in 80 characters ("$xxALC,tt,nn,s,ee" + ",*hh" for the tail).
  std::vector<std::vector<std::string>> groups(1);
  std::size_t length = 1 + talker.size() + 3 + 3 + 3 + 2 + 3 + 3;
  for (const auto& e : entries) {
    std::vector<std::string> f{
        escapeText(e.manufacturer, 3), std::to_string(std::clamp(e.identifier, 1, 9999999)),
        std::to_string(std::clamp(e.instance, 1, 999999)), std::to_string(std::clamp(e.revision, 1, 99))};
    std::size_t add = 0;
    for (const auto& x : f) add += 1 + x.size();
    if (!groups.back().empty() && length + add > kMaxSentenceChars) {
      groups.emplace_back();
      length = 1 + talker.size() + 3 + 3 + 3 + 2 + 3 + 3;
    }
    length += add;
    groups.back().insert(groups.back().end(), f.begin(), f.end());
  }
  std::vector<std::string> out;
  const std::string total = twoDigits(static_cast<int>(groups.size()));
  for (std::size_t i = 0; i < groups.size(); ++i) {
    std::vector<std::string> f{total, twoDigits(static_cast<int>(i + 1)), seq,
                               twoDigits(static_cast<int>(groups[i].size() / 4))};
    f.insert(f.end(), groups[i].begin(), groups[i].end());
    out.push_back(sentence(talker, "ALC", f));
  }
  return out;
}

std::optional<std::vector<std::string>> checkedFields(std::string_view line) {
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.remove_suffix(1);
  if (line.size() < 4 || (line[0] != '$' && line[0] != '!')) return std::nullopt;
  const std::size_t star = line.rfind('*');
  if (star == std::string_view::npos || star + 3 != line.size()) return std::nullopt;
  unsigned sum = 0;
  for (std::size_t i = 1; i < star; ++i) sum ^= static_cast<unsigned char>(line[i]);
  unsigned given = 0;
  for (std::size_t i = star + 1; i < line.size(); ++i) {
    const char c = line[i];
    unsigned d = 0;
    if (c >= '0' && c <= '9')
      d = static_cast<unsigned>(c - '0');
    else if (c >= 'A' && c <= 'F')
      d = static_cast<unsigned>(c - 'A' + 10);
    else if (c >= 'a' && c <= 'f')
      d = static_cast<unsigned>(c - 'a' + 10);
    else
      return std::nullopt;
    given = given * 16 + d;
  }
  if (given != sum) return std::nullopt;
  std::vector<std::string> fields;
  const std::string_view body = line.substr(1, star - 1);
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = body.find(',', start);
    fields.emplace_back(
        body.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return fields;
}

}  // namespace reckoner::io::nmea
