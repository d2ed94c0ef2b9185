#pragma once
// NMEA 0183 sentences for own-ship replay (docs/outputs.md, "Replay inputs"): positions (RMC, GGA, GNS,
// GLL), their accuracy (GST) and datum (DTM), velocity over ground (VTG), headings (THS, HDT, HDG, HDM,
// VHW), rate of turn (ROT), speed through the water or over ground (VHW, VBW) and time (ZDA), from any
// talker, with the checksum required and verified. Parsing never throws: a bad line comes back as an
// error kind with a reason, so that a reader can count it and go on.
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
  std::optional<double> variationDeg;  ///< magnetic variation, east positive
  std::optional<char> mode;            ///< NMEA 2.3 mode indicator (gnssFix() says which are fixes)
};
struct Gga {
  double timeOfDayS = 0.0;
  double latDeg = 0.0, lonDeg = 0.0;
  int quality =
      0;  ///< 0 no fix, 1 GPS, 2 DGPS, 3 PPS, 4 RTK, 5 float RTK, 6 estimated, 7 manual, 8 simulator
  std::optional<double> hdop;
};
struct Vtg {
  std::optional<double> cogTrueDeg;
  double sogKn = 0.0;
  std::optional<char> mode;
};
struct Gll {
  double latDeg = 0.0, lonDeg = 0.0;
  std::optional<double> timeOfDayS;
  bool valid = true;  ///< status A (absent status in old talkers: valid)
  std::optional<char> mode;
};
struct Hdt {
  double headingDeg = 0.0;
};
/// Heading, true, with its mode: A autonomous, E estimated (dead reckoning), M manual, S simulator,
/// V not valid (IEC 61162-1).
struct Ths {
  double headingDeg = 0.0;
  char mode = 'A';
};
/// Heading of a magnetic sensor with its deviation and the magnetic variation (east positive):
/// magnetic heading = sensor + deviation, true heading = magnetic + variation.
struct Hdg {
  double sensorDeg = 0.0;
  std::optional<double> deviationDeg;
  std::optional<double> variationDeg;
};
/// Heading, magnetic (variation from elsewhere: HDG, RMC or the configuration).
struct Hdm {
  double headingDeg = 0.0;
};
struct Vhw {
  std::optional<double> headingTrueDeg;
  std::optional<double> headingMagneticDeg;
  double speedKn = 0.0;  ///< through the water
};
/// Rate of turn, degrees per minute (negative: to port), valid when its status is A.
struct Rot {
  double degPerMin = 0.0;
  bool valid = false;
};
/// GNSS fix: position with one mode letter per constellation (GPS, GLONASS, Galileo, BeiDou, ...).
struct Gns {
  double timeOfDayS = 0.0;
  double latDeg = 0.0, lonDeg = 0.0;
  bool hasPosition = false;
  std::string modes;  ///< "AA", "DN", ...: N for a constellation not used
  int satellites = 0;
  std::optional<double> hdop;
};
/// GNSS pseudorange error statistics: standard deviations of the position error, metres.
struct Gst {
  double timeOfDayS = 0.0;
  std::optional<double> rmsM;
  std::optional<double> majorSdM, minorSdM, majorOrientationDeg;  ///< error ellipse, true bearing
  std::optional<double> latSdM, lonSdM;
};
/// Datum reference: the local datum code (W84 for WGS-84, the only one Reckoner takes).
struct Dtm {
  std::string localDatum;
  std::string referenceDatum;
};
struct Vbw {
  std::optional<double> longWaterKn, transWaterKn;    ///< when the water status is A
  std::optional<double> longGroundKn, transGroundKn;  ///< when the ground status is A
};
struct Zda {
  double timeOfDayS = 0.0;
  std::optional<Date> date;  ///< absent in some receivers' ZDA (day, month and year left empty)
};

using Body = std::variant<Rmc, Gga, Vtg, Gll, Hdt, Vhw, Vbw, Zda, Ths, Hdg, Hdm, Rot, Gns, Gst, Dtm>;

struct Sentence {
  std::string talker;  ///< "GP", "LC", "HE", "VW", ...
  Body body;
};

/// Proprietary: a $P sentence (manufacturer-specific; counted apart from unknown ones).
enum class Error : std::uint8_t { None, Empty, BadChecksum, Unknown, Proprietary, Malformed };
const char* errorName(Error e);

struct ParseResult {
  std::optional<Sentence> sentence;
  Error error = Error::None;
  std::string reason;  ///< for Malformed and BadChecksum
};

/// Whether a mode indicator (absent: an older talker, taken as a fix) marks a GNSS fix: A autonomous,
/// D differential, F float RTK, R RTK, P precise. E (estimated, dead reckoning), M (manual input),
/// S (simulator) and N (not valid) are not.
bool gnssFix(std::optional<char> mode);
/// Whether a GGA quality is a GNSS fix: 1 GPS, 2 DGPS, 3 PPS, 4 RTK, 5 float RTK, and 9 (SBAS, as some
/// receivers send it). 0 invalid, 6 estimated, 7 manual and 8 simulator are not.
bool gnssFix(int ggaQuality);
/// Whether a GNS mode string marks a GNSS fix: some constellation in a fix mode (gnssFix of its letter)
/// and none estimated, manual or simulated.
bool gnssFix(std::string_view gnsModes);

/// Parses one line (trailing CR/LF allowed).
ParseResult parse(std::string_view line);

/// "$" + body + "*" + two hex digits: a sentence with its checksum (body without '$').
std::string withChecksum(std::string_view body);

/// hhmmss.ss -> seconds of the day; nullopt when malformed.
std::optional<double> parseTimeOfDay(std::string_view f);

}  // namespace reckoner::io::nmea
