// reckoner-indep-sim: an independent truth-and-sensor generator for Reckoner's tests.
//
// It shares no code with core/ (nor ui/, charts/, app/): it is written from the NMEA 0183 sentence
// formats and the IMO ARPA error budget so that the project's readers, filters and tracker can be
// tested against data they did not produce. Only the standard library, Eigen and GeographicLib.
//
// Geodesy. Truth lives on the WGS-84 ellipsoid (GeographicLib), not in a tangent plane:
//  * motion at a constant course is a rhumb line (GeographicLib::Rhumb). The manoeuvring own ship
//    of `ownship` is integrated at 10 Hz: each 0.1 s step follows the rhumb line of the mean of the
//    ground velocities at the step's ends (trapezoidal rule). In `arpa`, own ship and targets keep
//    their velocities over ground, so each is one rhumb line in closed form.
//  * sensor errors given in metres east/north (GNSS, Loran-C, the radar target's glint) are applied
//    as a geodesic of that azimuth and length (GeographicLib::Geodesic::Direct).
//  * radar range and bearing are the geodesic distance and the azimuth at own ship
//    (GeographicLib::Geodesic::Inverse).
//  * the targets' geometry at t0 is drawn in own ship's tangent plane (range along the geodesic of
//    the drawn bearing, relative velocity as an east/north vector); over 11 NM this differs from
//    straight-line relative motion by a few metres, which tests comparing CPAs should allow for.
//
// Time. Integer microseconds since the run start, 2026-06-15T10:00:00Z. All 1 Hz epochs fall on
// whole seconds; NMEA time fields are hhmmss.ss.
//
// Randomness. std::mt19937_64 with our own uniform (53 bits) and Box-Muller normal, one stream per
// purpose derived from --seed (SplitMix64), so the output is the same on any standard library and
// switching a sensor on or off leaves the others' errors unchanged.
//
// Usage:
//   reckoner-indep-sim ownship --seed N --out DIR [--loran] [--current-max MPS] [--steady-current]
//       [--duration S] [--outage-start S] [--outage-length S] [--speed-min KN] [--speed-max KN]
//       [--no-log] [--no-gyro] [--gst-understates F]
//   reckoner-indep-sim arpa --seed N --out DIR [--duration S] [--t0 S] [--manoeuvre]
// Bad arguments: one line on stderr, exit status 2. Failure to write: one line, exit status 1.
#include "indep_sim.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

namespace reckoner_indep {
namespace {

struct UsageError {
  std::string message;
};

constexpr const char* kUsage =
    "usage: reckoner-indep-sim ownship --seed N --out DIR [--loran] [--current-max MPS] [--steady-current] "
    "[--duration S] [--outage-start S] [--outage-length S] [--speed-min KN] [--speed-max KN] [--no-log] "
    "[--no-gyro] [--gst-understates F]\n"
    "       reckoner-indep-sim arpa --seed N --out DIR [--duration S] [--t0 S] [--manoeuvre]\n";

class Args {
 public:
  Args(int argc, char** argv) : argc_(argc), argv_(argv) {}
  bool next(std::string& option) {
    if (i_ >= argc_) return false;
    option = argv_[i_++];
    return true;
  }
  std::string value(const std::string& option) {
    if (i_ >= argc_) throw UsageError{option + " needs a value"};
    return argv_[i_++];
  }
  double number(const std::string& option) {
    const std::string text = value(option);
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || errno != 0 || !std::isfinite(v))
      throw UsageError{option + ": '" + text + "' is not a number"};
    return v;
  }
  std::uint64_t seed(const std::string& option) {
    const std::string text = value(option);
    char* end = nullptr;
    errno = 0;
    const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
    if (text.empty() || text[0] == '-' || *end != '\0' || errno != 0)
      throw UsageError{option + ": '" + text + "' is not a non-negative integer"};
    return v;
  }

 private:
  int argc_;
  char** argv_;
  int i_ = 2;  // after the program name and the subcommand
};

void require(bool condition, const std::string& message) {
  if (!condition) throw UsageError{message};
}

OwnShipOptions parseOwnShip(Args& args) {
  OwnShipOptions o;
  for (std::string opt; args.next(opt);) {
    if (opt == "--seed")
      o.seed = args.seed(opt);
    else if (opt == "--out")
      o.outDir = args.value(opt);
    else if (opt == "--loran")
      o.loran = true;
    else if (opt == "--no-log")
      o.log = false;
    else if (opt == "--no-gyro")
      o.gyro = false;
    else if (opt == "--steady-current")
      o.steadyCurrent = true;
    else if (opt == "--current-max")
      o.currentMaxMps = args.number(opt);
    else if (opt == "--duration")
      o.durationS = args.number(opt);
    else if (opt == "--outage-start")
      o.outageStartS = args.number(opt);
    else if (opt == "--outage-length")
      o.outageLengthS = args.number(opt);
    else if (opt == "--speed-min")
      o.speedMinKn = args.number(opt);
    else if (opt == "--speed-max")
      o.speedMaxKn = args.number(opt);
    else if (opt == "--gst-understates")
      o.gstUnderstates = args.number(opt);
    else
      throw UsageError{"ownship: unknown option '" + opt + "'"};
  }
  require(!o.outDir.empty(), "ownship: --out DIR is required");
  require(o.durationS >= 1.0 && o.durationS <= 7.0 * 86400.0, "ownship: --duration must be in [1, 604800] s");
  require(o.currentMaxMps >= 0.0 && o.currentMaxMps <= 5.0, "ownship: --current-max must be in [0, 5] m/s");
  require(o.gstUnderstates >= 1.0 && o.gstUnderstates <= 100.0,
          "ownship: --gst-understates must be in [1, 100]");
  require(o.outageStartS >= 0.0 && o.outageLengthS >= 0.0, "ownship: outage start and length must be >= 0 s");
  require(o.speedMinKn >= 0.0 && o.speedMaxKn <= 40.0 && o.speedMinKn <= o.speedMaxKn,
          "ownship: speeds must satisfy 0 <= --speed-min <= --speed-max <= 40 kn");
  return o;
}

ArpaOptions parseArpa(Args& args) {
  ArpaOptions o;
  for (std::string opt; args.next(opt);) {
    if (opt == "--seed")
      o.seed = args.seed(opt);
    else if (opt == "--out")
      o.outDir = args.value(opt);
    else if (opt == "--duration")
      o.durationS = args.number(opt);
    else if (opt == "--t0")
      o.t0S = args.number(opt);
    else if (opt == "--manoeuvre")
      o.manoeuvre = true;
    else
      throw UsageError{"arpa: unknown option '" + opt + "'"};
  }
  require(!o.outDir.empty(), "arpa: --out DIR is required");
  require(o.durationS >= 1.0 && o.durationS <= 86400.0, "arpa: --duration must be in [1, 86400] s");
  require(o.t0S >= 0.0 && o.t0S < o.durationS, "arpa: --t0 must be in [0, duration) s");
  return o;
}

}  // namespace
}  // namespace reckoner_indep

int main(int argc, char** argv) {
  using namespace reckoner_indep;
  try {
    if (argc < 2) throw UsageError{"a subcommand is required (ownship or arpa)"};
    const std::string command = argv[1];
    Args args(argc, argv);
    if (command == "ownship") return runOwnShip(parseOwnShip(args));
    if (command == "arpa") return runArpa(parseArpa(args));
    if (command == "--help" || command == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    throw UsageError{"unknown subcommand '" + command + "'"};
  } catch (const UsageError& e) {
    std::fprintf(stderr, "reckoner-indep-sim: error: %s\n", e.message.c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "reckoner-indep-sim: error: %s\n", e.what());
    return 1;
  }
}
