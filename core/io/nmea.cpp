#include "io/nmea.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <vector>

#include "io/error_line.h"

namespace reckoner::io::nmea {
namespace {

struct Bad {
  std::string reason;
};

/// A sentence's comma-separated fields.
using Fields = std::vector<std::string_view>;

Fields split(std::string_view s) {
  Fields out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = s.find(',', start);
    out.push_back(s.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return out;
}

std::optional<double> number(std::string_view f) {
  if (f.empty()) return std::nullopt;
  double v = 0.0;
  const auto [p, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
  if (ec != std::errc() || p != f.data() + f.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

double required(const Fields& f, std::size_t i, const char* what) {
  if (i >= f.size()) throw Bad{std::string(what) + ": field missing"};
  const auto v = number(f[i]);
  if (!v) throw Bad{std::string(what) + ": not a number " + quoted(f[i], 40)};
  return *v;
}

/// An integer field in [lo, hi] (checked before any conversion: a cast of 1e300 to int is undefined).
int integer(const Fields& f, std::size_t i, const char* what, int lo, int hi) {
  const double v = required(f, i, what);
  if (v < lo || v > hi || v != std::floor(v))
    throw Bad{std::string(what) + ": must be an integer in [" + std::to_string(lo) + ", " +
              std::to_string(hi) + "], got " + quoted(f[i], 40)};
  return static_cast<int>(v);
}

/// The FAA mode indicator of NMEA 2.3 and later (RMC, GLL, VTG, GNS): one letter, absent in older
/// talkers.
std::optional<char> modeIndicator(const Fields& f, std::size_t i, const char* what) {
  if (i >= f.size() || f[i].empty()) return std::nullopt;
  const std::string_view m = f[i];
  if (m.size() != 1 || std::string_view("ADEFMNPRS").find(m[0]) == std::string_view::npos)
    throw Bad{std::string(what) + ": unknown mode indicator " + quoted(m, 8)};
  return m[0];
}

std::optional<double> optionalNumber(const Fields& f, std::size_t i, const char* what) {
  if (i >= f.size() || f[i].empty()) return std::nullopt;
  const auto v = number(f[i]);
  if (!v) throw Bad{std::string(what) + ": not a number " + quoted(f[i], 40)};
  return v;
}

/// ddmm.mmmm / dddmm.mmmm with hemisphere.
double angle(const Fields& f, std::size_t i, int degreeDigits, char pos, char neg, const char* what) {
  if (i + 1 >= f.size() || f[i].size() < static_cast<std::size_t>(degreeDigits) + 2)
    throw Bad{std::string(what) + ": missing or too short"};
  const auto deg = number(f[i].substr(0, static_cast<std::size_t>(degreeDigits)));
  const auto min = number(f[i].substr(static_cast<std::size_t>(degreeDigits)));
  if (!deg || !min || *min < 0.0 || *min >= 60.0 || *deg < 0.0)
    throw Bad{std::string(what) + ": malformed " + quoted(f[i], 40)};
  const double v = *deg + *min / 60.0;
  if (v > (degreeDigits == 2 ? 90.0 : 180.0)) throw Bad{std::string(what) + ": out of range"};
  if (f[i + 1] == std::string_view(&pos, 1)) return v;
  if (f[i + 1] == std::string_view(&neg, 1)) return -v;
  throw Bad{std::string(what) + ": hemisphere must be " + pos + " or " + neg};
}

double time(const Fields& f, std::size_t i) {
  if (i >= f.size()) throw Bad{"time: field missing"};
  const auto t = parseTimeOfDay(f[i]);
  if (!t) throw Bad{"time: malformed " + quoted(f[i], 40)};
  return *t;
}

Date checkedDate(int y, int m, int d) {
  static constexpr int kDays[] = {31, 29, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (m < 1 || m > 12 || d < 1 || d > kDays[m - 1] || y < 1980 || y > 2200) throw Bad{"date: out of range"};
  return {y, m, d};
}

/// An optional heading field in [0, 360].
std::optional<double> heading(const Fields& f, std::size_t i, const char* what) {
  const auto h = optionalNumber(f, i, what);
  if (h && (*h < 0.0 || *h > 360.0)) throw Bad{std::string(what) + ": out of range " + quoted(f[i], 40)};
  return h;
}

/// An optional signed angle with its E/W letter in the next field (east positive).
std::optional<double> eastWest(const Fields& f, std::size_t i, const char* what) {
  const auto v = optionalNumber(f, i, what);
  if (!v) return std::nullopt;
  if (*v < 0.0 || *v > 180.0) throw Bad{std::string(what) + ": out of range " + quoted(f[i], 40)};
  const std::string_view side = i + 1 < f.size() ? f[i + 1] : std::string_view();
  if (side == "E") return *v;
  if (side == "W") return -*v;
  throw Bad{std::string(what) + ": needs E or W, got " + quoted(side, 8)};
}

// One parser per sentence type. Each takes the fields with f[0] the address field (data fields start
// at f[1]) and throws Bad with the field it could not read.

/// RMC's ddmmyy date field.
Date rmcDate(std::string_view ddmmyy) {
  if (ddmmyy.size() != 6) throw Bad{"RMC date: must be ddmmyy"};
  int dmy[3] = {0, 0, 0};
  for (std::size_t k = 0; k < 3; ++k) {
    const char a = ddmmyy[2 * k], b = ddmmyy[2 * k + 1];
    if (a < '0' || a > '9' || b < '0' || b > '9') throw Bad{"RMC date: malformed " + quoted(ddmmyy, 40)};
    dmy[k] = (a - '0') * 10 + (b - '0');
  }
  return checkedDate(dmy[2] < 80 ? 2000 + dmy[2] : 1900 + dmy[2], dmy[1], dmy[0]);
}

Body parseRmc(const Fields& f) {
  Rmc r;
  r.timeOfDayS = time(f, 1);
  if (f.size() < 10) throw Bad{"RMC: needs at least 9 fields"};
  r.valid = f[2] == "A";
  if (!r.valid && f[2] != "V") throw Bad{"RMC status: must be A or V"};
  if (r.valid) {
    r.latDeg = angle(f, 3, 2, 'N', 'S', "RMC latitude");
    r.lonDeg = angle(f, 5, 3, 'E', 'W', "RMC longitude");
  }
  r.sogKn = optionalNumber(f, 7, "RMC speed");
  if (r.sogKn && *r.sogKn < 0.0) throw Bad{"RMC speed: negative"};
  r.cogTrueDeg = heading(f, 8, "RMC course");
  if (!f[9].empty()) r.date = rmcDate(f[9]);
  if (f.size() > 11) r.variationDeg = eastWest(f, 10, "RMC magnetic variation");
  r.mode = modeIndicator(f, 12, "RMC mode");
  return r;
}

Body parseGga(const Fields& f) {
  Gga g;
  g.timeOfDayS = time(f, 1);
  if (f.size() < 9) throw Bad{"GGA: needs at least 8 fields"};
  g.quality = integer(f, 6, "GGA quality", 0, 9);
  if (g.quality > 0) {
    g.latDeg = angle(f, 2, 2, 'N', 'S', "GGA latitude");
    g.lonDeg = angle(f, 4, 3, 'E', 'W', "GGA longitude");
  }
  g.hdop = optionalNumber(f, 8, "GGA hdop");
  return g;
}

Body parseVtg(const Fields& f) {
  Vtg v;
  if (f.size() < 8) throw Bad{"VTG: needs at least 7 fields"};
  v.cogTrueDeg = heading(f, 1, "VTG course");
  v.sogKn = required(f, 5, "VTG speed");
  if (v.sogKn < 0.0) throw Bad{"VTG speed: negative"};
  v.mode = modeIndicator(f, 9, "VTG mode");
  return v;
}

Body parseGll(const Fields& f) {
  Gll g;
  g.latDeg = angle(f, 1, 2, 'N', 'S', "GLL latitude");
  g.lonDeg = angle(f, 3, 3, 'E', 'W', "GLL longitude");
  if (f.size() > 5 && !f[5].empty()) g.timeOfDayS = time(f, 5);
  if (f.size() > 6) g.valid = f[6] == "A";
  g.mode = modeIndicator(f, 7, "GLL mode");
  return g;
}

Body parseHdt(const Fields& f) {
  const double h = required(f, 1, "HDT heading");
  if (h < 0.0 || h > 360.0) throw Bad{"HDT heading: out of range"};
  return Hdt{h};
}

Body parseVhw(const Fields& f) {
  Vhw v;
  v.headingTrueDeg = heading(f, 1, "VHW true heading");
  v.headingMagneticDeg = heading(f, 3, "VHW magnetic heading");
  if (f.size() < 6) throw Bad{"VHW: needs at least 5 fields"};
  v.speedKn = required(f, 5, "VHW speed");
  return v;
}

Body parseVbw(const Fields& f) {
  Vbw v;
  if (f.size() < 7) throw Bad{"VBW: needs at least 6 fields"};
  if (f[3] == "A") {
    v.longWaterKn = required(f, 1, "VBW water speed");
    v.transWaterKn = required(f, 2, "VBW water speed");
  }
  if (f[6] == "A") {
    v.longGroundKn = required(f, 4, "VBW ground speed");
    v.transGroundKn = required(f, 5, "VBW ground speed");
  }
  return v;
}

Body parseZda(const Fields& f) {
  Zda z;
  z.timeOfDayS = time(f, 1);
  const bool undated = f.size() < 5 || (f[2].empty() && f[3].empty() && f[4].empty());
  if (!undated)
    z.date = checkedDate(integer(f, 4, "ZDA year", 1980, 2200), integer(f, 3, "ZDA month", 1, 12),
                         integer(f, 2, "ZDA day", 1, 31));
  return z;
}

Body parseThs(const Fields& f) {
  Ths t;
  t.headingDeg = required(f, 1, "THS heading");
  if (t.headingDeg < 0.0 || t.headingDeg > 360.0) throw Bad{"THS heading: out of range"};
  if (f.size() < 3 || f[2].size() != 1 || std::string_view("AEMSV").find(f[2][0]) == std::string_view::npos)
    throw Bad{"THS mode: must be A, E, M, S or V"};
  t.mode = f[2][0];
  return t;
}

Body parseHdg(const Fields& f) {
  Hdg h;
  h.sensorDeg = required(f, 1, "HDG heading");
  if (h.sensorDeg < 0.0 || h.sensorDeg > 360.0) throw Bad{"HDG heading: out of range"};
  h.deviationDeg = eastWest(f, 2, "HDG deviation");
  h.variationDeg = eastWest(f, 4, "HDG variation");
  return h;
}

Body parseHdm(const Fields& f) {
  const double h = required(f, 1, "HDM heading");
  if (h < 0.0 || h > 360.0) throw Bad{"HDM heading: out of range"};
  return Hdm{h};
}

Body parseRot(const Fields& f) {
  Rot r;
  r.degPerMin = required(f, 1, "ROT rate");
  if (std::abs(r.degPerMin) > 3600.0) throw Bad{"ROT rate: beyond 3600 deg/min"};
  r.valid = f.size() > 2 && f[2] == "A";
  return r;
}

Body parseGns(const Fields& f) {
  Gns g;
  g.timeOfDayS = time(f, 1);
  if (f.size() < 9) throw Bad{"GNS: needs at least 8 fields"};
  g.modes = std::string(f[6]);
  if (g.modes.empty() || g.modes.size() > 8 || g.modes.find_first_not_of("ADEFMNPRS") != std::string::npos)
    throw Bad{"GNS mode: letters of ADEFMNPRS, got " + quoted(f[6], 16)};
  g.hasPosition = !f[2].empty();
  if (g.hasPosition) {
    g.latDeg = angle(f, 2, 2, 'N', 'S', "GNS latitude");
    g.lonDeg = angle(f, 4, 3, 'E', 'W', "GNS longitude");
  }
  if (!f[7].empty()) g.satellites = integer(f, 7, "GNS satellites", 0, 999);
  g.hdop = optionalNumber(f, 8, "GNS hdop");
  return g;
}

/// An optional standard deviation field, in metres: not negative, and below 1e7 m (beyond the size of
/// the Earth it says nothing, and its square, the variance a filter is given, must stay finite).
std::optional<double> sdField(const Fields& f, std::size_t i, const char* what) {
  const auto v = optionalNumber(f, i, what);
  if (v && *v < 0.0) throw Bad{std::string(what) + ": negative"};
  if (v && *v > 1e7) throw Bad{std::string(what) + ": out of range " + quoted(f[i], 40)};
  return v;
}

Body parseGst(const Fields& f) {
  Gst g;
  g.timeOfDayS = time(f, 1);
  if (f.size() < 8) throw Bad{"GST: needs at least 7 fields"};
  g.rmsM = sdField(f, 2, "GST rms");
  g.majorSdM = sdField(f, 3, "GST semi-major sd");
  g.minorSdM = sdField(f, 4, "GST semi-minor sd");
  g.majorOrientationDeg = optionalNumber(f, 5, "GST orientation");
  g.latSdM = sdField(f, 6, "GST latitude sd");
  g.lonSdM = sdField(f, 7, "GST longitude sd");
  return g;
}

Body parseDtm(const Fields& f) {
  Dtm d;
  if (f.size() < 2 || f[1].empty()) throw Bad{"DTM: no local datum"};
  d.localDatum = std::string(f[1].substr(0, std::min<std::size_t>(f[1].size(), 8)));
  if (f.size() > 8) d.referenceDatum = std::string(f[8].substr(0, std::min<std::size_t>(f[8].size(), 8)));
  return d;
}

/// The sentence types Reckoner reads, each with its parser.
struct SentenceParser {
  std::string_view type;
  Body (*parse)(const Fields&);
};
constexpr SentenceParser kParsers[] = {
    {"RMC", parseRmc}, {"GGA", parseGga}, {"VTG", parseVtg}, {"GLL", parseGll}, {"HDT", parseHdt},
    {"VHW", parseVhw}, {"VBW", parseVbw}, {"ZDA", parseZda}, {"THS", parseThs}, {"HDG", parseHdg},
    {"HDM", parseHdm}, {"ROT", parseRot}, {"GNS", parseGns}, {"GST", parseGst}, {"DTM", parseDtm},
};

/// The parser of a sentence type, or nullptr for a type Reckoner does not read.
const SentenceParser* parserOf(std::string_view type) {
  for (const SentenceParser& p : kParsers)
    if (p.type == type) return &p;
  return nullptr;
}

int hexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}
}  // namespace

const char* errorName(Error e) {
  switch (e) {
    case Error::None:
      return "none";
    case Error::Empty:
      return "empty";
    case Error::BadChecksum:
      return "bad_checksum";
    case Error::Unknown:
      return "unknown";
    case Error::Proprietary:
      return "proprietary";
    case Error::Malformed:
      return "malformed";
  }
  return "?";
}

bool gnssFix(std::optional<char> mode) {
  return !mode || *mode == 'A' || *mode == 'D' || *mode == 'F' || *mode == 'R' || *mode == 'P';
}

bool gnssFix(int q) {
  return (q >= 1 && q <= 5) || q == 9;
}

bool gnssFix(std::string_view modes) {
  bool fix = false;
  for (const char m : modes) {
    if (m == 'E' || m == 'M' || m == 'S') return false;
    fix = fix || (m != 'N' && gnssFix(std::optional<char>(m)));
  }
  return fix;
}

std::optional<double> parseTimeOfDay(std::string_view f) {
  if (f.size() < 6) return std::nullopt;
  const auto h = number(f.substr(0, 2)), m = number(f.substr(2, 2)), s = number(f.substr(4));
  if (!h || !m || !s || *h < 0 || *h > 23 || *m < 0 || *m > 59 || *s < 0.0 || *s >= 61.0) return std::nullopt;
  if (f[0] == '-' || f[2] == '-' || f[4] == '-') return std::nullopt;
  return *h * 3600.0 + *m * 60.0 + *s;
}

std::string withChecksum(std::string_view body) {
  unsigned char sum = 0;
  for (char c : body) sum = static_cast<unsigned char>(sum ^ static_cast<unsigned char>(c));
  char tail[4];
  std::snprintf(tail, sizeof tail, "*%02X", sum);
  std::string out = "$";
  out.append(body);
  out.append(tail);
  return out;
}

ParseResult parse(std::string_view line) {
  ParseResult r;
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r' || line.back() == ' '))
    line.remove_suffix(1);
  if (line.empty()) {
    r.error = Error::Empty;
    return r;
  }
  if (line[0] != '$' && line[0] != '!') {
    r.error = Error::Malformed;
    r.reason = "does not start with '$'";
    return r;
  }
  const std::size_t star = line.rfind('*');
  if (star == std::string_view::npos || star + 3 != line.size()) {
    r.error = Error::BadChecksum;
    r.reason = "no checksum";
    return r;
  }
  const int hi = hexValue(line[star + 1]), lo = hexValue(line[star + 2]);
  unsigned char sum = 0;
  for (std::size_t i = 1; i < star; ++i)
    sum = static_cast<unsigned char>(sum ^ static_cast<unsigned char>(line[i]));
  if (hi < 0 || lo < 0 || sum != hi * 16 + lo) {
    r.error = Error::BadChecksum;
    // The two characters after '*' are input: quoted, so that a reason stays one line whatever they are.
    char buf[40];
    std::snprintf(buf, sizeof buf, "checksum %02X, sentence says ", sum);
    r.reason = buf + quoted(line.substr(star + 1, 2), 8);
    return r;
  }
  const std::string_view body = line.substr(1, star - 1);
  const auto fields = split(body);
  const std::string_view address = fields[0];
  if (!address.empty() && address[0] == 'P') {  // $P + manufacturer code: proprietary, not ours to read
    r.error = Error::Proprietary;
    r.reason = std::string(address.substr(0, std::min<std::size_t>(address.size(), 4)));
    return r;
  }
  if (address.size() != 5) {
    r.error = Error::Malformed;
    r.reason = "address " + quoted(address, 20);
    return r;
  }
  const std::string_view type = address.substr(2);
  const SentenceParser* parser = parserOf(type);
  if (!parser) {
    r.error = Error::Unknown;
    r.reason = std::string(type);
    return r;
  }
  try {
    r.sentence = Sentence{std::string(address.substr(0, 2)), parser->parse(fields)};
  } catch (const Bad& b) {
    r.error = Error::Malformed;
    r.reason = b.reason;
  }
  return r;
}

}  // namespace reckoner::io::nmea
