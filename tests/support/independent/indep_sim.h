// Independent truth-and-sensor generator for tests (reckoner-indep-sim).
//
// Written from the NMEA 0183 sentence formats and the IMO ARPA performance standard's error
// budget, sharing no code with core/: it is an oracle the project's readers and filters are
// tested against, so nothing here may come from, or be "fixed" to agree with, the code under test.
// See indep_main.cpp for the geodesy, the time base and the command line.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <initializer_list>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace reckoner_indep {

// ---- Units (edges only: knots, nautical miles and degrees appear in files and options) ----
inline constexpr double kMetresPerNm = 1852.0;
inline constexpr double kMpsPerKnot = 1852.0 / 3600.0;
inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDegPerRad = 180.0 / kPi;

double wrapDeg360(double deg);  // [0, 360)
double wrapDeg180(double deg);  // (-180, 180]

// ENU vector (east, north) in metres or metres per second.
using Enu = Eigen::Vector2d;
Enu enuFromPolar(double magnitude, double azimuthDeg);  // azimuth clockwise from true north
double azimuthDegOf(const Enu& v);                      // [0, 360); 0 for a zero vector

// ---- Randomness: std::mt19937_64 and our own transforms, so results do not depend on the
// standard library's distributions (their algorithms are implementation-defined). ----
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  double uniform01();                    // [0, 1), 53 bits
  double uniform(double lo, double hi);  // [lo, hi)
  double normal(double sd = 1.0);        // Box-Muller (both values of a pair are used)
  double sign();                         // -1 or +1 with equal probability
 private:
  std::mt19937_64 engine_;
  bool haveSpare_ = false;
  double spare_ = 0.0;
};

// One independent stream per purpose: enabling a sensor never changes another sensor's errors.
// (Append only: a stream's seed depends on its value, so inserting one would change the others.)
enum class Stream : std::uint64_t {
  Params = 1,
  Plan,
  Gnss,
  Gyro,
  Log,
  Loran,
  Radar,
  Targets,
  RadarSweep,
  Manoeuvre
};
Rng makeRng(std::uint64_t seed, Stream stream);

// First-order Gauss-Markov process x' = -x/tau + w, sampled exactly: x(k+1) = phi x(k) +
// sd sqrt(1 - phi^2) n, phi = exp(-dt/tau). Starts from its stationary distribution N(0, sd^2).
class GaussMarkov {
 public:
  GaussMarkov(double sd, double tauS, Rng& rng) : sd_(sd), tauS_(tauS), x_(rng.normal(sd)) {}
  double value() const { return x_; }
  void step(double dtS, Rng& rng);

 private:
  double sd_, tauS_, x_;
};

// ---- Time: integer microseconds since the run start; the start is a UTC instant. ----
struct UtcClock {
  std::int64_t startUnixS = 0;                                  // seconds since 1970-01-01T00:00:00Z
  std::string iso(std::int64_t tUs, int fractionDigits) const;  // 2026-06-15T10:00:00.000Z
  std::string nmeaTime(std::int64_t tUs) const;                 // hhmmss.ss
  std::string nmeaDateDdmmyy(std::int64_t tUs) const;           // RMC date
  std::string zdaDate(std::int64_t tUs) const;                  // "dd,mm,yyyy"
};
std::int64_t unixSecondsFromCivil(int year, int month, int day, int hour, int minute, int second);

// ---- Geodesy on the WGS-84 ellipsoid (GeographicLib) ----
struct LatLon {
  double latDeg = 0.0;
  double lonDeg = 0.0;
};
LatLon rhumbDirect(const LatLon& from, double azimuthDeg, double distanceM);  // constant course
LatLon offsetEnu(const LatLon& from, const Enu& offsetM);  // geodesic of that azimuth and length
struct RangeBearing {
  double rangeM = 0.0;
  double bearingDeg = 0.0;  // geodesic azimuth at `from`, [0, 360)
};
RangeBearing rangeBearing(const LatLon& from, const LatLon& to);

// ---- NMEA 0183 ----
std::string nmeaSentence(std::string_view body);  // "$" body "*hh\r\n", hh = XOR of body
std::string nmeaLat(double latDeg);               // "ddmm.mmmmmm,N"
std::string nmeaLon(double lonDeg);               // "dddmm.mmmmmm,W"
std::string fmt(const char* format, double value);
/// The fields joined with commas: the body of an NMEA sentence.
std::string joinFields(std::initializer_list<std::string> fields);

// ---- Own-ship truth, 1 Hz, as written to truth.csv ----
struct TruthRow {
  std::int64_t tUs = 0;
  LatLon pos;
  double sogMps = 0.0, cogDeg = 0.0, headingDeg = 0.0, stwMps = 0.0;
  Enu currentMps = Enu::Zero();
  bool gpsOn = true;
};
void writeTruthCsv(const std::string& path, const UtcClock& clock, const std::vector<TruthRow>& rows);

// ---- Own-ship sensor error models (all drawn per run before writing) ----
struct SensorModel {
  // GNSS: white per axis sd gnssWhiteSdM, plus a Gauss-Markov part per axis.
  double gnssWhiteSdM = 4.0, gnssCorrelatedSdM = 1.0, gnssCorrelationS = 60.0;
  double gstUnderstates = 1.0;    ///< the receiver's GST reports its white sd divided by this
  double gnssVelocitySdKn = 0.1;  // per axis (east, north) of the velocity over ground
  double outageStartS = 0.0, outageLengthS = 0.0;
  bool gyro = true;
  double gyroBiasDeg = 0.0, gyroNoiseSdDeg = 0.3;
  bool log = true;
  double logScale = 0.0;  // fraction: measured = (1 + scale) stw + offset + noise
  double logOffsetKn = 0.0, logNoiseSdKn = 0.1;
  bool loran = false;
  double loranCorrelatedSdM = 150.0, loranCorrelationS = 600.0, loranWhiteSdM = 20.0;
};
// Writes DIR/ownship.nmea from the truth rows (one epoch per row).
void writeOwnShipNmea(const std::string& path, const UtcClock& clock, const std::vector<TruthRow>& truth,
                      const SensorModel& model, std::uint64_t seed);
std::string sensorModelJson(const SensorModel& model);  // JSON object body for params.json

// ---- Subcommands (return the process exit code) ----
struct OwnShipOptions {
  std::uint64_t seed = 1;
  std::string outDir;
  bool loran = false, log = true, gyro = true, steadyCurrent = false;
  double currentMaxMps = 1.0, durationS = 3600.0, outageStartS = 2400.0, outageLengthS = 600.0;
  double speedMinKn = 6.0, speedMaxKn = 14.0;
  double gstUnderstates = 1.0;  // --gst-understates F: the GST reports the GNSS noise divided by F
};
int runOwnShip(const OwnShipOptions& options);

struct ArpaOptions {
  std::uint64_t seed = 1;
  std::string outDir;
  double durationS = 1200.0;
  double t0S = 300.0;  // instant at which each target's drawn geometry holds
  // Every target turns once, at constant speed, after the 3-minute scoring time (t0 + 240 to 540 s):
  // by 45-90 deg either way at 0.5-1 deg/s (params.json "manoeuvre").
  bool manoeuvre = false;
};
int runArpa(const ArpaOptions& options);

// Output helpers: create DIR, open files, fail with one line.
void ensureDirectory(const std::string& dir);
void writeTextFile(const std::string& path, const std::string& text);

}  // namespace reckoner_indep
