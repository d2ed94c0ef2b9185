#pragma once
// NMEA 0183 sentences for own-ship replay (docs/outputs.md, "Replay inputs"): RMC, GGA, VTG, GLL, HDT,
// VHW, VBW and ZDA, with the checksum required and verified. Parsing never throws: a bad line comes
// back as an error kind with a reason, so that a reader can count it and go on.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace reckoner::io::nmea {

struct Date {
  int year = 0, month = 0, day = 0;
};

struct Rmc {
  double timeOfDayS = 0.0;
  bool valid = false;  ///< status A
  double latDeg = 0.0, lonDeg = 0.0;
  std::optional<double> sogKn, cogTrueDeg;
  std::optional<Date> date;
};
struct Gga {
  double timeOfDayS = 0.0;
  double latDeg = 0.0, lonDeg = 0.0;
  int quality = 0;  ///< 0: no fix
  std::optional<double> hdop;
};
struct Vtg {
  std::optional<double> cogTrueDeg;
  double sogKn = 0.0;
};
struct Gll {
  double latDeg = 0.0, lonDeg = 0.0;
  std::optional<double> timeOfDayS;
  bool valid = true;  ///< status A (absent status in old talkers: valid)
};
struct Hdt {
  double headingDeg = 0.0;
};
struct Vhw {
  std::optional<double> headingTrueDeg;
  double speedKn = 0.0;  ///< through the water
};
struct Vbw {
  std::optional<double> longWaterKn, transWaterKn;    ///< when the water status is A
  std::optional<double> longGroundKn, transGroundKn;  ///< when the ground status is A
};
struct Zda {
  double timeOfDayS = 0.0;
  Date date;
};

using Body = std::variant<Rmc, Gga, Vtg, Gll, Hdt, Vhw, Vbw, Zda>;

struct Sentence {
  std::string talker;  ///< "GP", "LC", "HE", "VW", ...
  Body body;
};

enum class Error : std::uint8_t { None, Empty, BadChecksum, Unknown, Malformed };
const char* errorName(Error e);

struct ParseResult {
  std::optional<Sentence> sentence;
  Error error = Error::None;
  std::string reason;  ///< for Malformed and BadChecksum
};

/// Parses one line (trailing CR/LF allowed).
ParseResult parse(std::string_view line);

/// "$" + body + "*" + two hex digits: a sentence with its checksum (body without '$').
std::string withChecksum(std::string_view body);

/// hhmmss.ss -> seconds of the day; nullopt when malformed.
std::optional<double> parseTimeOfDay(std::string_view f);

}  // namespace reckoner::io::nmea
