#pragma once
// NMEA 0183 sentences Reckoner sends (docs/outputs.md, "NMEA 0183 output", field by field with the
// standard's field numbers): own ship (RMC, GGA, VTG, HDT, GST), radar targets (TTM, TLL, OSD), route
// following for an autopilot or a plotter (XTE, RMB, APB) and alerts (ALR; ALF and ALC as IEC 61924-2 bridge
// alert management uses them). Codec only: each encoder takes plain values in the units the sentence carries
// and returns one sentence with its checksum, without CR LF. Absent values (nullopt, NaN) become empty
// fields; text fields are escaped (^hh) so that no reserved character reaches the wire, and cut so that no
// sentence exceeds 82 characters with CR LF.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/time.h"

namespace reckoner::io::nmea {

/// Latitude as the two fields "ddmm.mmmmmm,N" (south: S); longitude "dddmm.mmmmmm,E" (west: W).
/// Degrees in [-90, 90] and [-180, 180]; minuteDecimals (0-9) decimals of minutes, 6 (2 mm) unless
/// a sentence needs the room; the minutes never print as 60. A value not finite or outside those ranges
/// gives both fields empty (","), never "nan".
std::string nmeaLatitude(double latDeg, int minuteDecimals = 6);
std::string nmeaLongitude(double lonDeg, int minuteDecimals = 6);
/// UTC time of day "hhmmss.ss" (truncated to the hundredth) and date "ddmmyy".
std::string nmeaTime(UtcUs t);
std::string nmeaDate(UtcUs t);
/// A text field with the reserved characters ($ * , ! \ ^ ~, CR, LF, and anything outside printable
/// ASCII) written as ^hh (IEC 61162-1 7.1.3), at most maxChars characters of output.
std::string escapeText(std::string_view text, std::size_t maxChars);

/// The longest sentence: 82 characters including '$' and CR LF (so 80 without CR LF).
inline constexpr std::size_t kMaxSentenceChars = 80;

struct RmcOut {
  UtcUs utc = 0;
  double latDeg = 0, lonDeg = 0;
  double sogKn = 0, cogTrueDeg = 0;
  char mode = 'A';  ///< A autonomous, D differential, E estimated (dead reckoning), N not valid
};
/// $--RMC: status A for modes A, D and E, V for N. NMEA 0183 3.01 asks for V with every mode but A
/// and D; receivers with dead reckoning (u-blox among them) send A with E instead, and so does Reckoner,
/// so that plotters keep the dead-reckoned position, flagged estimated by the mode (docs/outputs.md).
std::string rmc(std::string_view talker, const RmcOut& v);

struct GgaOut {
  UtcUs utc = 0;
  double latDeg = 0, lonDeg = 0;
  int quality = 1;  ///< 1 GPS fix, 6 estimated (dead reckoning)
  std::optional<int> satellites;
  std::optional<double> hdop;
  std::optional<double> altitudeM;
};
std::string gga(std::string_view talker, const GgaOut& v);

struct VtgOut {
  double cogTrueDeg = 0, sogKn = 0;
  char mode = 'A';
};
std::string vtg(std::string_view talker, const VtgOut& v);

std::string hdt(std::string_view talker, double headingTrueDeg);

struct GstOut {
  UtcUs utc = 0;
  std::optional<double> rmsM;
  double majorSdM = 0, minorSdM = 0, majorOrientationDeg = 0;  ///< error ellipse, orientation true
  double latSdM = 0, lonSdM = 0;
  std::optional<double> altSdM;
};
std::string gst(std::string_view talker, const GstOut& v);

/// The 1-sigma error ellipse of a 2x2 position covariance in north/east metres: semi-major and
/// semi-minor standard deviations and the major axis's orientation, degrees true in [0, 180).
struct ErrorEllipse {
  double majorSdM = 0, minorSdM = 0, orientationDeg = 0;
};
ErrorEllipse errorEllipse(double varNorthM2, double varEastM2, double covNorthEastM2);

/// Target status of TTM and TLL: L lost, Q query (acquiring, not yet steady), T tracking.
struct TtmOut {
  int number = 0;  ///< 00-99
  double distanceNm = 0, bearingDeg = 0;
  char bearingRef = 'T';  ///< T true, R relative
  double speedKn = 0, courseDeg = 0;
  char courseRef = 'T';
  std::optional<double> cpaNm, tcpaMin;  ///< absent without relative motion; TCPA negative: past
  std::string name;
  char status = 'T';
  bool reference = false;  ///< a reference target (for speed over ground from the radar)
  UtcUs utc = 0;
  char acquisition = 'A';  ///< A automatic, M manual, R reported
};
std::string ttm(std::string_view talker, const TtmOut& v);

struct TllOut {
  int number = 0;
  double latDeg = 0, lonDeg = 0;
  std::string name;
  UtcUs utc = 0;
  char status = 'T';
  bool reference = false;
};
std::string tll(std::string_view talker, const TllOut& v);

struct OsdOut {
  std::optional<double> headingTrueDeg;  ///< status A when present, V when not
  double courseTrueDeg = 0;
  char courseRef = 'P';  ///< B bottom, M manual, W water, R radar, P positioning system
  double speedKn = 0;
  char speedRef = 'P';
  std::optional<double> setTrueDeg, driftKn;  ///< the current
};
std::string osd(std::string_view talker, const OsdOut& v);

/// Route following (XTE, RMB, APB). Status and mode alike in all three: both status fields (the Loran-C
/// blink / general warning flag and the cycle lock flag of the standard) A when `valid` and the mode is
/// A autonomous, D differential or E estimated (dead reckoning: A with E, as RMC), else V; the mode
/// field `mode`, or N (not valid) when not `valid`. Not valid: the fields that depend on own ship's
/// position (cross-track error and direction, range, bearings and heading to steer from own ship,
/// closing velocity) are empty and arrival is V, so that a reader which ignores the status has nothing
/// to steer on; the leg's own data (waypoint ids, destination position, bearing origin to destination)
/// stay. NaN values are empty fields.

/// Waypoint ids in RMB and APB: escaped and cut to 6 characters, the length older plotters and
/// autopilots accept (OpenCPN's default for its autopilot output).
inline constexpr std::size_t kWaypointIdChars = 6;

struct XteOut {
  double crossTrackNm = 0;  ///< magnitude, NM (its sign is ignored; the side is steerRight)
  bool steerRight = false;  ///< direction to steer: R if own ship is left (port) of the track, L if right
  bool valid = false;
  char mode = 'A';  ///< A autonomous, D differential, E estimated (dead reckoning), N not valid
};
/// $--XTE,A,A,x.x,L/R,N,mode: cross-track error, 2 decimals, at most 999.99 NM.
std::string xte(std::string_view talker, const XteOut& v);

struct RmbOut {
  bool valid = false;
  double crossTrackNm = 0;  ///< magnitude, NM; written at most 9.99 (RMB's limit)
  bool steerRight = false;
  std::string originId, destinationId;  ///< escaped, cut to kWaypointIdChars (origin first to fit)
  double destLatDeg = 0, destLonDeg = 0;
  double rangeToDestNm = 0;         ///< written at most 999.9 (RMB's limit)
  double bearingToDestTrueDeg = 0;  ///< from own ship
  double closingVelocityKn = 0;     ///< speed toward the destination; negative: moving away
  bool arrived = false;             ///< arrival circle entered or perpendicular passed
  char mode = 'A';
};
/// $--RMB,A,x.x,L/R,origin,destination,llll.llll,N/S,yyyyy.yyyy,E/W,range,bearing,velocity,A/V,mode.
std::string rmb(std::string_view talker, const RmbOut& v);

struct ApbOut {
  bool valid = false;
  double crossTrackNm = 0;  ///< magnitude, NM
  bool steerRight = false;
  bool arrivalCircleEntered = false;
  bool perpendicularPassed = false;  ///< crossed the line through the destination perpendicular to the leg
  double bearingOriginToDestDeg = 0;
  bool bearingMagnetic = false;  ///< the reference of all three directions: M, or T when false
  std::string destinationId;     ///< escaped, cut to kWaypointIdChars
  double bearingPresentToDestDeg = 0;
  double headingToSteerDeg = 0;
  char mode = 'A';
};
/// $--APB,A,A,x.x,L/R,N,A/V,A/V,x.x,T/M,id,x.x,T/M,x.x,T/M,mode.
std::string apb(std::string_view talker, const ApbOut& v);

struct AlrOut {
  UtcUs utc = 0;       ///< of the condition's last change
  int number = 0;      ///< 000-999
  bool active = true;  ///< A threshold exceeded, V not
  bool acknowledged = false;
  std::string text;
};
std::string alr(std::string_view talker, const AlrOut& v);

/// One alert as ALF reports it (IEC 61162-1 ed. 5, 8.3.6; IEC 61924-2 Annex J).
struct AlfOut {
  int sequence = 0;     ///< sequential message identifier 0-9 (the same in both sentences of one message)
  UtcUs utc = 0;        ///< time of the last change
  char category = 'B';  ///< A, B, C
  char priority = 'W';  ///< E emergency alarm, A alarm, W warning, C caution
  char state = 'V';     ///< V active unacknowledged, S silenced, A acknowledged, O transferred, U rectified
                        ///< unacknowledged, N normal
  std::string manufacturer;  ///< empty for a standard alert identifier
  int identifier = 0;        ///< 1-9999999
  int instance = 1;          ///< 1-999999
  int revision = 1;          ///< 1-99
  int escalation = 0;        ///< 0-9
  std::string title;         ///< first sentence, up to 16 characters
  std::string description;   ///< second sentence when not empty
};
/// One or two sentences: the title in the first, the description (if any) in the second.
std::vector<std::string> alf(std::string_view talker, const AlfOut& v);

struct AlcEntry {
  std::string manufacturer;
  int identifier = 0, instance = 1, revision = 1;
};
/// The cyclic alert list: as many sentences as the entries need (none: one sentence with 0 entries).
std::vector<std::string> alc(std::string_view talker, int sequence, const std::vector<AlcEntry>& entries);

/// The fields of a sentence whose checksum is right: [0] the address ("RATTM"), then fields 1, 2, ...
/// as they are on the wire (not unescaped). nullopt without '$' or '!', without a checksum, or when it
/// is wrong. CR LF at the end allowed.
std::optional<std::vector<std::string>> checkedFields(std::string_view line);

}  // namespace reckoner::io::nmea
