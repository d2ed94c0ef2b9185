// libFuzzer target: the NMEA 0183 sentence parser (core/io/nmea.h) on every line of arbitrary bytes,
// every sentence type it reads (RMC, GGA, GNS, GLL, VTG, THS, HDT, HDG, HDM, VHW, VBW, ROT, ZDA, GST,
// DTM). Checks what the parser promises beyond not crashing: it never throws; a sentence comes back
// exactly when the error is None, a reason with Malformed and BadChecksum, on one line; each
// value read is finite and inside its field's range (latitude, longitude, headings, times of day,
// dates, GGA quality, mode letters, standard deviations); and the sentence's body, given a fresh
// checksum by withChecksum(), parses the same way (docs/robustness.md, "Fuzzing").
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "io/nmea.h"

namespace {
namespace nm = reckoner::io::nmea;

void check(bool ok) {
  if (!ok) std::abort();
}

void finite(const std::optional<double>& v) {
  if (v) check(std::isfinite(*v));
}
void latLon(double lat, double lon) {
  check(std::isfinite(lat) && std::abs(lat) <= 90.0 && std::isfinite(lon) && std::abs(lon) <= 180.0);
}
void timeOfDay(double s) {
  check(std::isfinite(s) && s >= 0.0 && s < 86461.0);
}
void headingDeg(double h) {
  check(std::isfinite(h) && h >= 0.0 && h <= 360.0);
}
void eastWest(const std::optional<double>& v) {
  if (v) check(std::isfinite(*v) && std::abs(*v) <= 180.0);
}
void nonNegative(const std::optional<double>& v) {
  if (v) check(std::isfinite(*v) && *v >= 0.0);
}
void date(const std::optional<nm::Date>& d) {
  if (d)
    check(d->year >= 1980 && d->year <= 2200 && d->month >= 1 && d->month <= 12 && d->day >= 1 &&
          d->day <= 31);
}
void mode(const std::optional<char>& m) {
  if (m) check(std::string_view("ADEFMNPRS").find(*m) != std::string_view::npos);
}

struct CheckBody {
  void operator()(const nm::Rmc& b) const {
    timeOfDay(b.timeOfDayS);
    latLon(b.latDeg, b.lonDeg);
    finite(b.sogKn);
    finite(b.cogTrueDeg);
    date(b.date);
    eastWest(b.variationDeg);
    mode(b.mode);
  }
  void operator()(const nm::Gga& b) const {
    timeOfDay(b.timeOfDayS);
    latLon(b.latDeg, b.lonDeg);
    check(b.quality >= 0 && b.quality <= 9);
    finite(b.hdop);
  }
  void operator()(const nm::Vtg& b) const {
    finite(b.cogTrueDeg);
    check(std::isfinite(b.sogKn) && b.sogKn >= 0.0);
    mode(b.mode);
  }
  void operator()(const nm::Gll& b) const {
    latLon(b.latDeg, b.lonDeg);
    if (b.timeOfDayS) timeOfDay(*b.timeOfDayS);
    mode(b.mode);
  }
  void operator()(const nm::Hdt& b) const { headingDeg(b.headingDeg); }
  void operator()(const nm::Ths& b) const {
    headingDeg(b.headingDeg);
    check(std::string_view("AEMSV").find(b.mode) != std::string_view::npos);
  }
  void operator()(const nm::Hdg& b) const {
    headingDeg(b.sensorDeg);
    eastWest(b.deviationDeg);
    eastWest(b.variationDeg);
  }
  void operator()(const nm::Hdm& b) const { headingDeg(b.headingDeg); }
  void operator()(const nm::Vhw& b) const {
    if (b.headingTrueDeg) headingDeg(*b.headingTrueDeg);
    if (b.headingMagneticDeg) headingDeg(*b.headingMagneticDeg);
    check(std::isfinite(b.speedKn));
  }
  void operator()(const nm::Vbw& b) const {
    check(b.longWaterKn.has_value() == b.transWaterKn.has_value());
    check(b.longGroundKn.has_value() == b.transGroundKn.has_value());
    for (const auto* v : {&b.longWaterKn, &b.transWaterKn, &b.longGroundKn, &b.transGroundKn}) finite(*v);
  }
  void operator()(const nm::Zda& b) const {
    timeOfDay(b.timeOfDayS);
    date(b.date);
  }
  void operator()(const nm::Rot& b) const {
    check(std::isfinite(b.degPerMin) && std::abs(b.degPerMin) <= 3600.0);
  }
  void operator()(const nm::Gns& b) const {
    timeOfDay(b.timeOfDayS);
    if (b.hasPosition) latLon(b.latDeg, b.lonDeg);
    check(!b.modes.empty() && b.modes.size() <= 8 &&
          b.modes.find_first_not_of("ADEFMNPRS") == std::string::npos);
    check(b.satellites >= 0 && b.satellites <= 999);
    finite(b.hdop);
  }
  void operator()(const nm::Gst& b) const {
    timeOfDay(b.timeOfDayS);
    for (const auto* v : {&b.rmsM, &b.majorSdM, &b.minorSdM, &b.latSdM, &b.lonSdM}) nonNegative(*v);
    finite(b.majorOrientationDeg);
  }
  void operator()(const nm::Dtm& b) const {
    check(!b.localDatum.empty() && b.localDatum.size() <= 8 && b.referenceDatum.size() <= 8);
  }
};

void oneLine(const std::string& s) {
  for (const char c : s) check(c != '\n' && c != '\r');
}

/// The line's body (between the start character and '*') with a checksum of its own, when it has one.
std::optional<std::string> rechecked(std::string_view line) {
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r' || line.back() == ' '))
    line.remove_suffix(1);
  const std::size_t star = line.rfind('*');
  if (line.size() < 2 || (line[0] != '$' && line[0] != '!') || star == std::string_view::npos || star == 0)
    return std::nullopt;
  std::string out = nm::withChecksum(line.substr(1, star - 1));
  out[0] = line[0];
  return out;
}

void checkLine(std::string_view line) {
  nm::ParseResult r;
  try {
    r = nm::parse(line);
  } catch (...) {
    std::abort();  // parsing never throws
  }
  check(r.sentence.has_value() == (r.error == nm::Error::None));
  // The reasons of Malformed and BadChecksum are messages (input quoted); Unknown and Proprietary give
  // the type or maker code as received.
  if (r.error == nm::Error::Malformed || r.error == nm::Error::BadChecksum) {
    check(!r.reason.empty());
    oneLine(r.reason);
  }
  if (r.sentence) {
    check(r.sentence->talker.size() == 2);
    std::visit(CheckBody{}, r.sentence->body);
  }
  // With a checksum of its own the line's body parses as it did: never a bad checksum, and the same
  // outcome (error kind, sentence type) when the original checksum was right.
  if (const auto again = rechecked(line)) {
    const nm::ParseResult r2 = nm::parse(*again);
    check(r2.error != nm::Error::BadChecksum);
    if (r.error != nm::Error::BadChecksum) {
      check(r2.error == r.error);
      if (r.sentence) check(r2.sentence->body.index() == r.sentence->body.index());
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view rest(reinterpret_cast<const char*>(data), size);
  while (!rest.empty()) {
    const auto nl = rest.find('\n');
    checkLine(rest.substr(0, nl));
    rest.remove_prefix(nl == std::string_view::npos ? rest.size() : nl + 1);
  }
  return 0;
}
