// The ARPA tracker on data it did not make: MSC.192(79)'s accuracy cells, scored against an
// independent truth (support/independent, written apart from core/), beside a plain constant-velocity
// Kalman filter written here.
//
// Pipeline. For seeds 1..24, `reckoner-indep-sim arpa` writes own-ship NMEA (GNSS, a gyro with a
// +-0.5 deg calibration error, a log with +-0.5 kn), radar plots of 8 constant-velocity targets under
// the IMO A.823(19) radar error budget (indep_arpa.cpp) and the truth. `reckoner-cli replay --nmea
// --radar` replays them with its default settings (no --config, no --assume-association: the tracker
// associates plots itself; radar.csv's target_id labels only reach targets.csv, as the label of the
// target whose plots each track mostly used). Nothing of core/ is linked into the scoring.
//
// Acquisition. For target k: the time of k's first plot in radar.csv stamped at or after t0 (params.json
// "t0_s", the instant at which the generator drew k's geometry; 300 s into a 1200 s run). The tracker
// has seen plots since the start of the run; "acquisition" is only the origin of the scoring times
// T1 = acquisition + 60 s and T3 = acquisition + 180 s. (Every target is within 11 NM at t0, so it has
// plots then; the test fails if one has none.)
//
// Reckoner's sample at T. The radar sweep (a distinct `utc` of targets.csv; sweeps end every 2 s by
// default) nearest to T, ties to the later one, and in it the confirmed track whose target_id is k
// (of several, the lowest track_id: the oldest). No such track, or no sweep within 2.5 s of T: k is not
// held, a miss, which counts as an infinite error in every cell at that T. Truth is taken at that
// sweep's time.
//
// Truth at time t (truth.csv for own ship at 1 Hz, truth_targets.csv at every 2.5 s rotation start,
// lat/lon interpolated linearly in time: both ships run straight, so the interpolation error is far
// under a millimetre). Everything is referred to one plane: GeographicLib::LocalCartesian at own ship's
// true position at t (x east, y north). Positions map by LocalCartesian::Forward; a velocity (speed over
// ground along a true course at a point) is the plane image of one second's travel along the geodesic
// of that course from that point, so the meridian convergence between own ship and a target (up to
// ~0.2 deg at 11 NM) does not enter the relative velocity. Truth relative motion = target ground
// velocity - own ground velocity; CPA and TCPA of straight-line relative motion from there; the true
// course and speed are the target's cog_deg and sog_mps. Before scoring, this truth is checked against
// the generator's own CPA and TCPA at t0 in params.json (within 1 m and 0.5 s).
//
// Reckoner's estimate. Target: course_deg / speed_kn of the row (true course, over ground) at the row's
// est_lat_deg / est_lon_deg; own ship: ownship.csv's est_vx_mps / est_vy_mps (ground velocity along the
// replay's grid axes), interpolated to the sweep's time. The grid is the UTM zone of the first fix, whose
// north differs from true north by the meridian convergence, ~0.45 deg off Seattle (the generator's
// area) and up to ~2.2 deg elsewhere at this latitude; taking grid as east/north would put a bias of
// that angle times own ship's speed (up to 0.2 kn here) into the relative velocity. The convergence and
// the grid's point scale are therefore measured from the replay's own output: the azimuth and length of
// the geodesic between two ownship.csv rows (est_lat/lon, +-60 s around t) against the grid displacement
// of the same rows (est_x/y). Estimated relative velocity = target minus own ship; CPA and TCPA are the
// row's cpa_nm / tcpa_min (empty: no relative motion, an infinite error).
//
// Errors: relative course (deg, wrapped to +-180), relative speed (kn), CPA (NM), TCPA (min), true
// course (deg, wrapped), true speed (kn), all absolute. Each cell pools all 24 x 8 targets and takes the
// 95th percentile (nearest rank) of |error|. MSC.192(79) limits (95%): 1 min: relative course 11 deg,
// relative speed max(1.5 kn, 10%), CPA 1.0 NM; 3 min: relative course 3 deg, relative speed max(0.8 kn,
// 1%), CPA 0.3 NM, TCPA 0.5 min, true course 5 deg, true speed max(0.5 kn, 1%). A percentage is of the
// pooled mean true value at 3 minutes, as core/metrics/imo_accuracy.cpp applies it, with one
// difference: the project averages over the runs that held the target, this test over every target (its
// truth is known whether held or not), so the limit does not depend on the tracker's misses.
//
// The baseline: a plain 4-state constant-velocity Kalman filter per target (see CvKalman below), given
// perfect association (each plot goes to the filter of its target_id label, which Reckoner's tracker is
// not told), fed every plot of its target from the start of the run (the data Reckoner has), scored at
// exactly T1 and T3 with the same cells; its own-ship velocity is the last RMC's SOG/COG at or before T.
//
// What must hold (the requirement): all nine cells met by Reckoner, and each 3-minute cell of
// Reckoner at or below the baseline's p95. The table (cell, Reckoner p95, baseline p95, limit, pass) is
// printed whatever the outcome.
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <Eigen/Dense>
#include <GeographicLib/Geodesic.hpp>
#include <GeographicLib/LocalCartesian.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/campaign_tools.h"
#include "support/compare_near.h"
#include "support/resource_limits.h"

namespace {

using reckoner::test::Csv;
using reckoner::test::percentile95;
using reckoner::test::readCsv;
using reckoner::test::runTool;
using reckoner::test::splitFields;
using reckoner::test::toolPath;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;
constexpr double kDegPerRad = 180.0 / kPi;
constexpr double kMetresPerNm = 1852.0;
constexpr double kMpsPerKnot = 1852.0 / 3600.0;
constexpr int kRuns = 24;

// ---- The baseline's fixed settings (chosen a priori for ships, not tuned on these files) ----
/// White-acceleration intensity per axis, m^2/s^3: without plots a velocity may wander by sqrt(q t),
/// 1.1 m/s (2.1 kn) in a minute, a generic allowance for a ship's unmodelled manoeuvres. With plots every
/// 2.5 s its steady-state velocity sd per axis is about 0.6 m/s for 20 m of measurement noise and 1 m/s
/// for the 100 m across the line of sight at 6 NM. The 3-minute comparison depends on q: a smaller q
/// suits these exactly straight-running targets better and makes the baseline harder to beat.
constexpr double kBaselineQ = 0.02;
constexpr double kBaselineRangeSdM = 20.0;
constexpr double kBaselineBearingNoiseSdDeg = 0.1;
constexpr double kBaselineGyroCalibrationDeg = 0.5;     // added as white noise: the filter cannot see a bias
constexpr double kBaselineInitialVelocitySdMps = 20.0;  // about 40 kn: any ship, unknown at the first plot

using Vec2 = Eigen::Vector2d;
using Vec4 = Eigen::Vector4d;
using Mat2 = Eigen::Matrix2d;
using Mat4 = Eigen::Matrix4d;

double wrap180(double deg) {
  double w = std::fmod(deg + 180.0, 360.0);
  if (w < 0.0) w += 360.0;
  return w - 180.0;
}

/// Azimuth of a plane vector, clockwise from the plane's north, [0, 360).
double azimuthDeg(const Vec2& v) {
  const double a = std::atan2(v.x(), v.y()) * kDegPerRad;
  return a < 0.0 ? a + 360.0 : a;
}

Vec2 polar(double magnitude, double azimuthDegrees) {
  const double a = azimuthDegrees / kDegPerRad;
  return Vec2(magnitude * std::sin(a), magnitude * std::cos(a));
}

// ---- Time: microseconds since 1970-01-01T00:00:00Z; the tests work in seconds since the run start ----
std::int64_t daysFromCivil(int year, int month, int day) {  // H. Hinnant's algorithm
  const std::int64_t y = year - (month <= 2 ? 1 : 0);
  const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
  const std::int64_t yoe = y - era * 400;
  const std::int64_t doy = (153 * ((month + 9) % 12) + 2) / 5 + day - 1;
  return era * 146097 + yoe * 365 + yoe / 4 - yoe / 100 + doy - 719468;
}

/// Seconds of a day, "hhmmss[.ss...]" (NMEA) or "hh:mm:ss[.ffffff]" (ISO 8601), to microseconds.
std::int64_t timeOfDayUs(int h, int m, const std::string& seconds) {
  const std::size_t dot = seconds.find('.');
  std::int64_t us = std::stoll(seconds.substr(0, dot)) * 1000000;
  if (dot != std::string::npos) {
    std::string frac = seconds.substr(dot + 1, 6);
    frac.resize(6, '0');
    us += std::stoll(frac);
  }
  return (static_cast<std::int64_t>(h) * 3600 + static_cast<std::int64_t>(m) * 60) * 1000000 + us;
}

/// "2026-06-15T10:00:02.050673Z" (any number of fraction digits, up to 6 used).
std::int64_t isoToUs(const std::string& s) {
  if (s.size() < 20 || s[4] != '-' || s[10] != 'T' || s.back() != 'Z')
    throw std::runtime_error("bad utc " + s);
  const std::int64_t days =
      daysFromCivil(std::stoi(s.substr(0, 4)), std::stoi(s.substr(5, 2)), std::stoi(s.substr(8, 2)));
  return days * 86400 * 1000000 +
         timeOfDayUs(std::stoi(s.substr(11, 2)), std::stoi(s.substr(14, 2)), s.substr(17, s.size() - 18));
}

// ---- Geodesy (WGS-84, GeographicLib) ----
struct LatLon {
  double lat = 0.0, lon = 0.0;
};

LatLon lerp(const LatLon& a, const LatLon& b, double f) {
  return LatLon{a.lat + f * (b.lat - a.lat), a.lon + f * (b.lon - a.lon)};
}

LatLon direct(const LatLon& from, double azimuthDegrees, double distanceM) {
  LatLon to;
  GeographicLib::Geodesic::WGS84().Direct(from.lat, from.lon, azimuthDegrees, distanceM, to.lat, to.lon);
  return to;
}

/// Geodesic length (m) and azimuth at `from` (deg) to `to`.
std::pair<double, double> inverse(const LatLon& from, const LatLon& to) {
  double s12 = 0.0, azi1 = 0.0, azi2 = 0.0;
  GeographicLib::Geodesic::WGS84().Inverse(from.lat, from.lon, to.lat, to.lon, s12, azi1, azi2);
  return {s12, azi1};
}

Vec2 forward(const GeographicLib::LocalCartesian& plane, const LatLon& p) {
  double x = 0.0, y = 0.0, z = 0.0;
  plane.Forward(p.lat, p.lon, 0.0, x, y, z);
  return Vec2(x, y);
}

LatLon reverse(const GeographicLib::LocalCartesian& plane, const Vec2& p) {
  LatLon q;
  double h = 0.0;
  plane.Reverse(p.x(), p.y(), 0.0, q.lat, q.lon, h);
  return q;
}

/// A velocity over ground (speed along a true course at `at`) as a vector of `plane`: the plane image
/// of one second's travel along the geodesic of that course.
Vec2 planeVelocity(const GeographicLib::LocalCartesian& plane, const LatLon& at, double speedMps,
                   double courseDeg) {
  return forward(plane, direct(at, courseDeg, speedMps)) - forward(plane, at);
}

// ---- The quantities scored ----
/// One target's motion, referred to the plane at own ship's true position at the scoring time.
struct Kinematics {
  Vec2 relVelMps = Vec2::Zero();          ///< target minus own ship, over ground, in the plane
  std::optional<double> cpaNm, tcpaMin;   ///< empty: no relative motion
  double courseDeg = 0.0, speedKn = 0.0;  ///< the target's true course and speed over ground
};

/// Relative course, relative speed, CPA, TCPA, true course, true speed.
constexpr int kQuantities = 6;
using Errors = std::array<double, kQuantities>;
const Errors kMissed{kInf, kInf, kInf, kInf, kInf, kInf};
constexpr std::array<const char*, kQuantities> kQuantityName{
    "relative course (deg)", "relative speed (kn)", "CPA (NM)", "TCPA (min)",
    "true course (deg)",     "true speed (kn)"};

/// CPA and TCPA of straight-line relative motion from relative position r with relative velocity v.
void closestApproach(const Vec2& r, const Vec2& v, Kinematics& k) {
  const double vv = v.squaredNorm();
  if (vv <= 0.0) return;
  const double tcpaS = -r.dot(v) / vv;
  k.cpaNm = (r + v * tcpaS).norm() / kMetresPerNm;
  k.tcpaMin = tcpaS / 60.0;
}

Errors errorsOf(const Kinematics& est, const Kinematics& truth) {
  Errors e{};
  e[0] = std::abs(wrap180(azimuthDeg(est.relVelMps) - azimuthDeg(truth.relVelMps)));
  e[1] = std::abs(est.relVelMps.norm() - truth.relVelMps.norm()) / kMpsPerKnot;
  e[2] = est.cpaNm && truth.cpaNm ? std::abs(*est.cpaNm - *truth.cpaNm) : kInf;
  e[3] = est.tcpaMin && truth.tcpaMin ? std::abs(*est.tcpaMin - *truth.tcpaMin) : kInf;
  e[4] = std::abs(wrap180(est.courseDeg - truth.courseDeg));
  e[5] = std::abs(est.speedKn - truth.speedKn);
  return e;
}

// ---- Truth ----
/// A ship's truth: positions at increasing times (s since the run start), constant course and speed.
struct Path {
  std::vector<double> t;
  std::vector<LatLon> p;
  double sogMps = 0.0, cogDeg = 0.0;
  LatLon at(double tS) const {
    const auto hi = std::upper_bound(t.begin(), t.end(), tS);
    if (hi == t.begin()) return p.front();
    if (hi == t.end()) return p.back();
    const auto i = static_cast<std::size_t>(hi - t.begin());
    return lerp(p[i - 1], p[i], (tS - t[i - 1]) / (t[i] - t[i - 1]));
  }
};

struct Truth {
  Path own;
  std::map<std::string, Path> targets;
  /// The plane at own ship's true position at tS.
  GeographicLib::LocalCartesian planeAt(double tS) const {
    const LatLon o = own.at(tS);
    return GeographicLib::LocalCartesian(o.lat, o.lon, 0.0);
  }
  Kinematics at(const std::string& id, double tS) const {
    const Path& tg = targets.at(id);
    const GeographicLib::LocalCartesian plane = planeAt(tS);
    const LatLon o = own.at(tS), p = tg.at(tS);
    Kinematics k;
    k.relVelMps =
        planeVelocity(plane, p, tg.sogMps, tg.cogDeg) - planeVelocity(plane, o, own.sogMps, own.cogDeg);
    closestApproach(forward(plane, p) - forward(plane, o), k.relVelMps, k);
    k.courseDeg = tg.cogDeg;
    k.speedKn = tg.sogMps / kMpsPerKnot;
    return k;
  }
};

Truth readTruth(const QString& dir, std::int64_t startUs) {
  Truth truth;
  const Csv own = readCsv(dir + "/truth.csv");
  for (const auto& r : own.rows) {
    truth.own.t.push_back(own.number(r, "t_s"));
    truth.own.p.push_back(LatLon{own.number(r, "lat_deg"), own.number(r, "lon_deg")});
    truth.own.sogMps = own.number(r, "sog_mps");  // constant in `arpa`
    truth.own.cogDeg = own.number(r, "cog_deg");
  }
  const Csv tg = readCsv(dir + "/truth_targets.csv");
  for (const auto& r : tg.rows) {
    Path& p = truth.targets[tg.get(r, "target_id")];
    p.t.push_back(static_cast<double>(isoToUs(tg.get(r, "utc")) - startUs) * 1e-6);
    p.p.push_back(LatLon{tg.number(r, "lat_deg"), tg.number(r, "lon_deg")});
    p.sogMps = tg.number(r, "sog_mps");
    p.cogDeg = tg.number(r, "cog_deg");
  }
  if (truth.own.t.size() < 2 || truth.targets.empty())
    throw std::runtime_error("empty truth in " + dir.toStdString());
  return truth;
}

// ---- Reckoner's replay output ----
struct TrackRow {
  int trackId = 0;
  std::string targetId;
  bool confirmed = false;
  LatLon p;
  double courseDeg = 0.0, speedKn = 0.0;
  std::optional<double> cpaNm, tcpaMin;
};

struct OwnRow {
  double tS = 0.0;
  Vec2 gridPosM, gridVelMps;
  LatLon p;
};

struct Replay {
  std::map<std::int64_t, std::vector<TrackRow>> sweeps;  ///< by the sweep's time, us since the run start
  std::vector<OwnRow> own;                               ///< time-ordered

  /// Own ship's estimated position and ground velocity (in `plane`) at tS.
  std::pair<LatLon, Vec2> ownAt(double tS, const GeographicLib::LocalCartesian& plane) const {
    auto idx = [&](double t) {
      const auto it =
          std::lower_bound(own.begin(), own.end(), t, [](const OwnRow& r, double v) { return r.tS < v; });
      return std::min(static_cast<std::size_t>(it - own.begin()), own.size() - 1);
    };
    const std::size_t hi = std::max<std::size_t>(idx(tS), 1);
    const OwnRow &a = own[hi - 1], &b = own[hi];
    const double f = std::clamp((tS - a.tS) / (b.tS - a.tS), 0.0, 1.0);
    const LatLon p = lerp(a.p, b.p, f);
    const Vec2 gridVel = a.gridVelMps + f * (b.gridVelMps - a.gridVelMps);
    // Grid north against true north (the meridian convergence) and grid scale, from the replay's own
    // rows: the geodesic between two estimated positions against their grid displacement.
    const OwnRow &r0 = own[idx(tS - 60.0)], &r1 = own[idx(tS + 60.0)];
    const Vec2 grid = r1.gridPosM - r0.gridPosM;
    const auto [lengthM, trueAzimuthDeg] = inverse(r0.p, r1.p);
    double convergenceDeg = 0.0, scale = 1.0;
    if (lengthM > 50.0) {  // own ship moves at 4 kn or more in `arpa`: 250 m in the 120 s window
      convergenceDeg = wrap180(trueAzimuthDeg - azimuthDeg(grid));
      scale = grid.norm() / lengthM;
    }
    return {p, planeVelocity(plane, p, gridVel.norm() / scale, azimuthDeg(gridVel) + convergenceDeg)};
  }
};

std::optional<double> optionalNumber(const std::string& s) {
  if (s.empty()) return std::nullopt;
  return std::stod(s);
}

Replay readReplay(const QString& dir, std::int64_t startUs) {
  Replay replay;
  const Csv tg = readCsv(dir + "/targets.csv");
  for (const auto& r : tg.rows) {
    TrackRow row;
    row.trackId = std::stoi(tg.get(r, "track_id"));
    row.targetId = tg.get(r, "target_id");
    row.confirmed = tg.get(r, "status") == "confirmed";
    row.p = LatLon{tg.number(r, "est_lat_deg"), tg.number(r, "est_lon_deg")};
    row.courseDeg = tg.number(r, "course_deg");
    row.speedKn = tg.number(r, "speed_kn");
    row.cpaNm = optionalNumber(tg.get(r, "cpa_nm"));
    row.tcpaMin = optionalNumber(tg.get(r, "tcpa_min"));
    replay.sweeps[isoToUs(tg.get(r, "utc")) - startUs].push_back(row);
  }
  const Csv own = readCsv(dir + "/ownship.csv");
  for (const auto& r : own.rows) {
    OwnRow row;
    row.tS = static_cast<double>(isoToUs(own.get(r, "utc")) - startUs) * 1e-6;
    row.gridPosM = Vec2(own.number(r, "est_x_m"), own.number(r, "est_y_m"));
    row.gridVelMps = Vec2(own.number(r, "est_vx_mps"), own.number(r, "est_vy_mps"));
    row.p = LatLon{own.number(r, "est_lat_deg"), own.number(r, "est_lon_deg")};
    replay.own.push_back(row);
  }
  std::sort(replay.own.begin(), replay.own.end(),
            [](const OwnRow& a, const OwnRow& b) { return a.tS < b.tS; });
  if (replay.sweeps.empty() || replay.own.size() < 2)
    throw std::runtime_error("empty replay output in " + dir.toStdString());
  return replay;
}

/// Reckoner's sample of target `id` at scoring time tS: errors against truth at the nearest sweep.
Errors reckonerErrors(const Replay& replay, const Truth& truth, const std::string& id, double tS) {
  const auto tUs = static_cast<std::int64_t>(std::llround(tS * 1e6));
  auto it = replay.sweeps.lower_bound(tUs);  // first sweep at or after tS
  if (it == replay.sweeps.end() ||
      (it != replay.sweeps.begin() && tUs - std::prev(it)->first < it->first - tUs))
    it = std::prev(it);
  if (std::abs(it->first - tUs) > 2500000) return kMissed;
  const TrackRow* held = nullptr;
  for (const TrackRow& r : it->second)
    if (r.confirmed && r.targetId == id && (!held || r.trackId < held->trackId)) held = &r;
  if (!held) return kMissed;

  const double sweepS = static_cast<double>(it->first) * 1e-6;
  const GeographicLib::LocalCartesian plane = truth.planeAt(sweepS);
  Kinematics est;
  const Vec2 ownVel = replay.ownAt(sweepS, plane).second;
  est.relVelMps = planeVelocity(plane, held->p, held->speedKn * kMpsPerKnot, held->courseDeg) - ownVel;
  est.cpaNm = held->cpaNm;
  est.tcpaMin = held->tcpaMin;
  est.courseDeg = held->courseDeg;
  est.speedKn = held->speedKn;
  return errorsOf(est, truth.at(id, sweepS));
}

// ---- The baseline's inputs: own ship's GNSS from the NMEA, the plots ----
struct OwnFixes {
  std::vector<double> ggaT, rmcT;  ///< s since the run start
  std::vector<LatLon> gga;
  std::vector<double> sogKn, cogDeg;  ///< RMC

  LatLon positionAt(double tS) const {  // linear between the GGA fixes around tS
    const auto hi = std::upper_bound(ggaT.begin(), ggaT.end(), tS);
    if (hi == ggaT.begin()) return gga.front();
    if (hi == ggaT.end()) return gga.back();
    const auto i = static_cast<std::size_t>(hi - ggaT.begin());
    return lerp(gga[i - 1], gga[i], (tS - ggaT[i - 1]) / (ggaT[i] - ggaT[i - 1]));
  }
  /// The last RMC at or before tS (index), or the first.
  std::size_t rmcAt(double tS) const {
    const auto hi = std::upper_bound(rmcT.begin(), rmcT.end(), tS);
    return hi == rmcT.begin() ? 0 : static_cast<std::size_t>(hi - rmcT.begin()) - 1;
  }
};

/// "ddmm.mmmm" / "dddmm.mmmm" with its hemisphere letter, to signed degrees.
double nmeaDegrees(const std::string& value, const std::string& hemisphere, int degreeDigits) {
  const auto d = static_cast<std::size_t>(degreeDigits);
  const double deg = std::stod(value.substr(0, d)) + std::stod(value.substr(d)) / 60.0;
  return hemisphere == "S" || hemisphere == "W" ? -deg : deg;
}

/// Reads GGA fixes (quality > 0) and RMC velocities (status A), dated by the ZDA before them.
OwnFixes readOwnFixes(const QString& path, std::int64_t startUs) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) throw std::runtime_error("cannot read " + path.toStdString());
  OwnFixes fixes;
  std::int64_t dayUs = -1;  // midnight of the ZDA's date
  while (!f.atEnd()) {
    const std::string line = f.readLine().trimmed().toStdString();
    const std::size_t star = line.find('*');
    if (line.size() < 4 || line[0] != '$' || star == std::string::npos || star + 3 > line.size()) continue;
    unsigned sum = 0;
    for (std::size_t i = 1; i < star; ++i) sum ^= static_cast<unsigned char>(line[i]);
    if (sum != std::stoul(line.substr(star + 1, 2), nullptr, 16)) continue;
    const std::vector<std::string> v = splitFields(line.substr(1, star - 1), ',');
    const std::string type = v[0].size() >= 5 ? v[0].substr(2) : "";
    auto timeS = [&](const std::string& hhmmss) {  // of the day of the last ZDA
      const std::int64_t ofDayUs =
          timeOfDayUs(std::stoi(hhmmss.substr(0, 2)), std::stoi(hhmmss.substr(2, 2)), hhmmss.substr(4));
      return static_cast<double>(dayUs + ofDayUs - startUs) * 1e-6;
    };
    if (type == "ZDA" && v.size() >= 5) {
      dayUs = daysFromCivil(std::stoi(v[4]), std::stoi(v[3]), std::stoi(v[2])) * 86400 * 1000000;
    } else if (type == "GGA" && v.size() >= 7 && dayUs >= 0 && !v[6].empty() && v[6] != "0") {
      fixes.ggaT.push_back(timeS(v[1]));
      fixes.gga.push_back(LatLon{nmeaDegrees(v[2], v[3], 2), nmeaDegrees(v[4], v[5], 3)});
    } else if (type == "RMC" && v.size() >= 9 && dayUs >= 0 && v[2] == "A") {
      fixes.rmcT.push_back(timeS(v[1]));
      fixes.sogKn.push_back(std::stod(v[7]));
      fixes.cogDeg.push_back(std::stod(v[8]));
    }
  }
  if (fixes.gga.size() < 2 || fixes.rmcT.empty())
    throw std::runtime_error("no GNSS in " + path.toStdString());
  return fixes;
}

struct Plot {
  std::int64_t tUs = 0;  ///< us since the run start, as written
  double tS = 0.0, rangeM = 0.0, bearingDeg = 0.0;
};

/// Plots by target label, time-ordered (radar.csv is).
std::map<std::string, std::vector<Plot>> readPlots(const QString& path, std::int64_t startUs) {
  std::map<std::string, std::vector<Plot>> plots;
  const Csv csv = readCsv(path);
  for (const auto& r : csv.rows) {
    const std::int64_t tUs = isoToUs(csv.get(r, "utc")) - startUs;
    plots[csv.get(r, "target_id")].push_back(
        Plot{tUs, static_cast<double>(tUs) * 1e-6, csv.number(r, "range_m"), csv.number(r, "bearing_deg")});
  }
  return plots;
}

// ---- The baseline filter ----
/// A plain constant-velocity Kalman filter in a local east/north plane (GeographicLib::LocalCartesian at
/// the first GGA fix): state (x, y, vx, vy), white acceleration of intensity kBaselineQ per axis,
/// position measurements (a plot converted to an absolute position: the geodesic of its range and true
/// bearing from own ship's GGA fix interpolated to the plot's time) with the range/bearing covariance
/// rotated into the plane (plotCovariance), Joseph-form update. Started at the target's first plot with
/// zero velocity of sd kBaselineInitialVelocitySdMps. No gating, no track management: the plots are the
/// target's own (perfect association). Glint, quantisation and the GNSS fix noise (~4 m) are left out
/// of the measurement covariance, as a plain filter told "20 m, 0.1 deg + 0.5 deg gyro" would.
class CvKalman {
 public:
  [[nodiscard]] bool started() const { return started_; }

  void start(double tS, const Vec2& z, const Mat2& r) {
    x_ << z, 0.0, 0.0;
    p_.setZero();
    p_.topLeftCorner<2, 2>() = r;
    p_.bottomRightCorner<2, 2>() =
        Mat2::Identity() * kBaselineInitialVelocitySdMps * kBaselineInitialVelocitySdMps;
    tS_ = tS;
    started_ = true;
  }

  void predict(double tS) {
    const double dt = tS - tS_;
    if (dt <= 0.0) return;
    Mat4 f = Mat4::Identity();
    f(0, 2) = f(1, 3) = dt;
    Mat4 q = Mat4::Zero();
    const double dt2 = dt * dt, dt3 = dt2 * dt;
    for (int i = 0; i < 2; ++i) {
      q(i, i) = kBaselineQ * dt3 / 3.0;
      q(i, i + 2) = q(i + 2, i) = kBaselineQ * dt2 / 2.0;
      q(i + 2, i + 2) = kBaselineQ * dt;
    }
    x_ = f * x_;
    p_ = f * p_ * f.transpose() + q;
    tS_ = tS;
  }

  void update(const Vec2& z, const Mat2& r) {
    Eigen::Matrix<double, 2, 4> h = Eigen::Matrix<double, 2, 4>::Zero();
    h(0, 0) = h(1, 1) = 1.0;
    const Mat2 s = h * p_ * h.transpose() + r;
    const Eigen::Matrix<double, 4, 2> k = p_ * h.transpose() * s.inverse();
    x_ += k * (z - h * x_);
    const Mat4 a = Mat4::Identity() - k * h;
    p_ = a * p_ * a.transpose() + k * r * k.transpose();  // Joseph form
  }

  [[nodiscard]] const Vec4& state() const { return x_; }

 private:
  Vec4 x_ = Vec4::Zero();
  Mat4 p_ = Mat4::Identity();
  double tS_ = 0.0;
  bool started_ = false;
};

/// Covariance, in the plane, of a plot at range r and true bearing b: range sd along the line of sight,
/// r times the bearing sd across it.
Mat2 plotCovariance(double rangeM, double bearingDeg) {
  static const double bearingSdRad =
      std::hypot(kBaselineBearingNoiseSdDeg, kBaselineGyroCalibrationDeg) / kDegPerRad;
  const Vec2 along = polar(1.0, bearingDeg), across = polar(1.0, bearingDeg + 90.0);
  const double crossSdM = rangeM * bearingSdRad;
  return kBaselineRangeSdM * kBaselineRangeSdM * along * along.transpose() +
         crossSdM * crossSdM * across * across.transpose();
}

/// The baseline's sample of one target at scoring time tS: the filter over the target's plots up to
/// tS, predicted to tS. No plot by then: a miss.
Errors baselineErrors(const std::vector<Plot>& plots, const OwnFixes& own,
                      const GeographicLib::LocalCartesian& base, const Truth& truth, const std::string& id,
                      double tS) {
  CvKalman kf;
  for (const Plot& p : plots) {
    if (p.tS > tS) break;
    // The plot as an absolute position: the geodesic of its range and bearing from own ship's fix.
    const Vec2 z = forward(base, direct(own.positionAt(p.tS), p.bearingDeg, p.rangeM));
    const Mat2 r = plotCovariance(p.rangeM, p.bearingDeg);
    if (!kf.started()) {
      kf.start(p.tS, z, r);
    } else {
      kf.predict(p.tS);
      kf.update(z, r);
    }
  }
  if (!kf.started()) return kMissed;
  kf.predict(tS);
  const Vec2 pos = kf.state().head<2>(), vel = kf.state().tail<2>();

  // The target's course and speed at its position (the plane's north is not the target's north).
  const LatLon target = reverse(base, pos);
  const auto [speedMps, courseDeg] = inverse(target, reverse(base, pos + vel));
  const LatLon ownPos = own.positionAt(tS);
  const std::size_t rmc = own.rmcAt(tS);

  const GeographicLib::LocalCartesian plane = truth.planeAt(tS);
  Kinematics est;
  est.relVelMps = planeVelocity(plane, target, speedMps, courseDeg) -
                  planeVelocity(plane, ownPos, own.sogKn[rmc] * kMpsPerKnot, own.cogDeg[rmc]);
  closestApproach(forward(plane, target) - forward(plane, ownPos), est.relVelMps, est);
  est.courseDeg = courseDeg;
  est.speedKn = speedMps / kMpsPerKnot;
  return errorsOf(est, truth.at(id, tS));
}

/// `reckoner-indep-sim arpa --seed N` (with `extra`) into out, replayed with default settings into
/// out/replay; params is the generator's params.json. False with err set when a step fails.
bool generateAndReplay(const QString& out, int seed, const QStringList& extra, QJsonObject& params,
                       QString& err) {
  if (!runTool(toolPath(RECKONER_INDEP_SIM, "RECKONER_INDEP_SIM"),
               QStringList{"arpa", "--seed", QString::number(seed), "--out", out} + extra, err))
    return false;
  if (!runTool(toolPath(RECKONER_CLI, "RECKONER_CLI_UNDER_TEST"),
               {"replay", "--nmea", out + "/ownship.nmea", "--radar", out + "/radar.csv", "--out",
                out + "/replay", "--quiet"},
               err))
    return false;
  QFile f(out + "/params.json");
  if (!f.open(QIODevice::ReadOnly)) {
    err = out + "/params.json: cannot read";
    return false;
  }
  params = QJsonDocument::fromJson(f.readAll()).object();
  return true;
}

/// One target of one run: the errors of Reckoner and of the baseline at 1 and 3 minutes.
struct Sample {
  int seed = 0;
  std::string target;
  Errors reckoner1{}, reckoner3{}, baseline1{}, baseline3{};
  double trueRelSpeedKn3 = 0.0, trueSpeedKn3 = 0.0;  ///< truth at acquisition + 3 min
};

/// Generates run `seed`, replays it and appends its targets' samples.
void scoreRun(const QTemporaryDir& dir, int seed, std::vector<Sample>& samples) {
  const QString out = dir.filePath(QString("arpa-%1").arg(seed));
  QString err;
  QJsonObject params;
  QVERIFY2(generateAndReplay(out, seed, {}, params, err), qPrintable(err));
  try {
    const std::int64_t startUs = isoToUs(params["start_utc"].toString().toStdString());
    const auto t0Us = static_cast<std::int64_t>(std::llround(params["t0_s"].toDouble() * 1e6));
    const double durationS = params["duration_s"].toDouble();
    const Truth truth = readTruth(out, startUs);
    const Replay replay = readReplay(out + "/replay", startUs);
    const OwnFixes own = readOwnFixes(out + "/ownship.nmea", startUs);
    const auto plots = readPlots(out + "/radar.csv", startUs);
    const GeographicLib::LocalCartesian base(own.gga.front().lat, own.gga.front().lon, 0.0);

    const QJsonArray targets = params["targets"].toArray();
    QVERIFY2(!targets.isEmpty(), qPrintable(out + "/params.json: no targets"));
    for (const auto& t : targets) {
      Sample s;
      s.seed = seed;
      s.target = t.toObject()["id"].toString().toStdString();
      // The scoring's truth against the generator's own geometry at t0 (its CPA and TCPA are of
      // straight-line relative motion in the plane at own ship then, as here): checks the time base,
      // the interpolation and the plane velocities before anything is scored with them.
      const Kinematics atT0 = truth.at(s.target, static_cast<double>(t0Us) * 1e-6);
      const double cpaM = atT0.cpaNm.value_or(kInf) * kMetresPerNm;
      const double tcpaS = atT0.tcpaMin.value_or(kInf) * 60.0;
      const reckoner::test::NearContext at(
          QString("%1 %2: truth at t0 against params.json").arg(out, QString::fromStdString(s.target)));
      RK_COMPARE_NEAR(cpaM, t.toObject()["cpa_nm"].toDouble() * kMetresPerNm, 1.0);
      RK_COMPARE_NEAR(tcpaS, t.toObject()["tcpa_s"].toDouble(), 0.5);
      const auto p = plots.find(s.target);
      QVERIFY2(p != plots.end(), qPrintable(out + ": no plots of " + QString::fromStdString(s.target)));
      // Acquisition: the target's first plot at or after t0 (compared in whole microseconds).
      const auto first =
          std::find_if(p->second.begin(), p->second.end(), [&](const Plot& q) { return q.tUs >= t0Us; });
      QVERIFY2(first != p->second.end(),
               qPrintable(out + ": no plot of " + QString::fromStdString(s.target) + " at or after t0"));
      const double acquiredS = first->tS, t1 = acquiredS + 60.0, t3 = acquiredS + 180.0;
      QVERIFY2(t3 <= durationS,
               qPrintable(out + ": " + QString::fromStdString(s.target) + " acquired too late"));
      s.reckoner1 = reckonerErrors(replay, truth, s.target, t1);
      s.reckoner3 = reckonerErrors(replay, truth, s.target, t3);
      s.baseline1 = baselineErrors(p->second, own, base, truth, s.target, t1);
      s.baseline3 = baselineErrors(p->second, own, base, truth, s.target, t3);
      const Kinematics k3 = truth.at(s.target, t3);
      s.trueRelSpeedKn3 = k3.relVelMps.norm() / kMpsPerKnot;
      s.trueSpeedKn3 = k3.speedKn;
      samples.push_back(s);
    }
  } catch (const std::exception& e) {
    QFAIL(qPrintable(out + ": " + QString::fromStdString(e.what())));
  }
}

/// One turning target of one `--manoeuvre` run, as Reckoner's replay followed it.
struct TurnOutcome {
  int seed = 0;
  std::string target;
  std::optional<double> flagLatencyS;         ///< first flagged sweep at or after the turn's start, minus it
  int straightSweeps = 0, straightFlags = 0;  ///< sweeps of the held track from t0 to the turn's start
  bool inRangeAfter = false;                  ///< true range under 11.5 NM two minutes after the turn
  std::optional<double> courseErrorAfterDeg;  ///< |course - true final course| then, when held
};

/// Generates `--manoeuvre` run `seed`, replays it with default settings and appends each target's
/// outcome. The held track at a sweep: the confirmed track labelled with the target, lowest track_id.
void scoreTurns(const QTemporaryDir& dir, int seed, std::vector<TurnOutcome>& outcomes) {
  const QString out = dir.filePath(QString("turns-%1").arg(seed));
  QString err;
  QJsonObject params;
  QVERIFY2(generateAndReplay(out, seed, {"--manoeuvre"}, params, err), qPrintable(err));
  try {
    const std::int64_t startUs = isoToUs(params["start_utc"].toString().toStdString());
    const double t0S = params["t0_s"].toDouble();
    const Truth truth = readTruth(out, startUs);  // positions only: its course is the last row's
    struct Row {
      double tS;
      int trackId;
      double courseDeg;
      bool flagged;
    };
    std::map<std::string, std::vector<Row>> byTarget;
    const Csv tg = readCsv(out + "/replay/targets.csv");
    for (const auto& r : tg.rows) {
      if (tg.get(r, "status") != "confirmed") continue;
      byTarget[tg.get(r, "target_id")].push_back(
          Row{static_cast<double>(isoToUs(tg.get(r, "utc")) - startUs) * 1e-6,
              std::stoi(tg.get(r, "track_id")), tg.number(r, "course_deg"), tg.get(r, "manoeuvring") == "1"});
    }
    for (const auto& t : params["targets"].toArray()) {
      const QJsonObject target = t.toObject(), m = target["manoeuvre"].toObject();
      QVERIFY2(!m.isEmpty(), qPrintable(out + "/params.json: a target without a manoeuvre"));
      TurnOutcome o;
      o.seed = seed;
      o.target = target["id"].toString().toStdString();
      const double startS = m["start_s"].toDouble(), afterS = m["end_s"].toDouble() + 120.0;
      // The held track per sweep: the lowest confirmed track_id labelled with the target.
      std::map<double, Row> held;
      for (const Row& r : byTarget[o.target]) {
        auto [it, fresh] = held.emplace(r.tS, r);
        if (!fresh && r.trackId < it->second.trackId) it->second = r;
      }
      for (const auto& [tS, r] : held) {
        if (tS >= t0S && tS < startS) {
          ++o.straightSweeps;
          o.straightFlags += r.flagged ? 1 : 0;
        }
        if (tS >= startS && r.flagged && !o.flagLatencyS) o.flagLatencyS = tS - startS;
        if (std::abs(tS - afterS) <= 1.25 && !o.courseErrorAfterDeg)
          o.courseErrorAfterDeg = std::abs(wrap180(r.courseDeg - m["cog_after_deg"].toDouble()));
      }
      o.inRangeAfter =
          inverse(truth.own.at(afterS), truth.targets.at(o.target).at(afterS)).first < 11.5 * kMetresPerNm;
      outcomes.push_back(o);
    }
  } catch (const std::exception& e) {
    QFAIL(qPrintable(out + ": " + QString::fromStdString(e.what())));
  }
}

/// The five worst of Reckoner's samples in a failed cell, where to start looking.
void logWorst(const std::vector<Sample>& samples, const std::vector<double>& e) {
  std::vector<std::size_t> order(samples.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return e[a] > e[b]; });
  QStringList worst;
  for (std::size_t i = 0; i < std::min<std::size_t>(5, order.size()); ++i)
    worst << QString("seed %1 %2: %3")
                 .arg(samples[order[i]].seed)
                 .arg(QString::fromStdString(samples[order[i]].target))
                 .arg(e[order[i]], 0, 'g', 4);
  qInfo("    worst: %s", qPrintable(worst.join("; ")));
}

}  // namespace

class TstIndependentArpa : public QObject {
  Q_OBJECT

 private slots:
  void msc192AccuracyCells() {
    reckoner::test::limitThisProcess(1200, std::size_t{4} << 30);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    std::vector<Sample> samples;
    for (int seed = 1; seed <= kRuns; ++seed) {
      scoreRun(dir, seed, samples);
      if (QTest::currentTestFailed()) return;
    }
    QVERIFY(!samples.empty());

    // Percent limits of the pooled mean true values at 3 minutes (every target, held or not).
    double relSpeedKn = 0.0, speedKn = 0.0;
    for (const Sample& s : samples) {
      relSpeedKn += s.trueRelSpeedKn3;
      speedKn += s.trueSpeedKn3;
    }
    relSpeedKn /= static_cast<double>(samples.size());
    speedKn /= static_cast<double>(samples.size());

    struct Cell {
      int minutes, quantity;
      double limit;
    };
    const std::array<Cell, 9> cells{{{1, 0, 11.0},
                                     {1, 1, std::max(1.5, 0.10 * relSpeedKn)},
                                     {1, 2, 1.0},
                                     {3, 0, 3.0},
                                     {3, 1, std::max(0.8, 0.01 * relSpeedKn)},
                                     {3, 2, 0.3},
                                     {3, 3, 0.5},
                                     {3, 4, 5.0},
                                     {3, 5, std::max(0.5, 0.01 * speedKn)}}};

    auto errors = [&](const Cell& c, bool reckoner) {
      std::vector<double> e;
      for (const Sample& s : samples) {
        const Errors& x =
            c.minutes == 1 ? (reckoner ? s.reckoner1 : s.baseline1) : (reckoner ? s.reckoner3 : s.baseline3);
        e.push_back(x[static_cast<std::size_t>(c.quantity)]);
      }
      return e;
    };
    auto held = [&](int minutes, bool reckoner) {
      return std::count_if(samples.begin(), samples.end(), [&](const Sample& s) {
        return std::isfinite(minutes == 1 ? (reckoner ? s.reckoner1 : s.baseline1)[1]
                                          : (reckoner ? s.reckoner3 : s.baseline3)[1]);
      });
    };

    qInfo("%d runs x %zu targets = %zu samples; mean true relative speed %.2f kn, mean true speed %.2f kn",
          kRuns, samples.size() / kRuns, samples.size(), relSpeedKn, speedKn);
    qInfo(
        "targets held by a confirmed track labelled with them: Reckoner %lld at 1 min, %lld at 3 min "
        "(baseline, with plots: %lld, %lld)",
        static_cast<long long>(held(1, true)), static_cast<long long>(held(3, true)),
        static_cast<long long>(held(1, false)), static_cast<long long>(held(3, false)));
    qInfo("%-31s %12s %12s %8s  %-4s  %s", "cell (95th percentile of |error|)", "Reckoner", "CV baseline",
          "limit", "pass", "<= baseline");
    QStringList failures;
    for (const Cell& c : cells) {
      const double rk = percentile95(errors(c, true)), bl = percentile95(errors(c, false));
      const bool pass = rk <= c.limit, beats = rk <= bl;
      const QString name =
          QString("%1 min %2").arg(c.minutes).arg(kQuantityName[static_cast<std::size_t>(c.quantity)]);
      qInfo("%-31s %12.3f %12.3f %8.3f  %-4s  %s", qPrintable(name), rk, bl, c.limit, pass ? "yes" : "NO",
            c.minutes == 3 ? (beats ? "yes" : "NO") : "-");
      if (!pass)
        failures
            << QString("%1: Reckoner p95 %2 > limit %3").arg(name).arg(rk, 0, 'g', 4).arg(c.limit, 0, 'g', 4);
      if (c.minutes == 3 && !beats)
        failures << QString("%1: Reckoner p95 %2 > baseline p95 %3")
                        .arg(name)
                        .arg(rk, 0, 'g', 4)
                        .arg(bl, 0, 'g', 4);
      if (!pass || (c.minutes == 3 && !beats)) logWorst(samples, errors(c, true));
    }
    QVERIFY2(failures.isEmpty(), qPrintable(failures.join("\n")));
  }
  /// Every target turns once (45-90 deg at 0.5-1 deg/s) after the scoring times: the default tracker,
  /// tuned for ARPA-grade accuracy on straight runs, must still flag the manoeuvre promptly, keep the
  /// track and settle on the new course, and not flag straight runs.
  void manoeuvresFlaggedAndFollowed() {
    reckoner::test::limitThisProcess(1200, std::size_t{4} << 30);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    std::vector<TurnOutcome> outcomes;
    for (int seed = 1; seed <= kRuns; ++seed) {
      scoreTurns(dir, seed, outcomes);
      if (QTest::currentTestFailed()) return;
    }
    std::vector<double> latency, courseError;
    long straight = 0, falseFlags = 0, inRange = 0, heldAfter = 0;
    for (const TurnOutcome& o : outcomes) {
      if (o.flagLatencyS) latency.push_back(*o.flagLatencyS);
      straight += o.straightSweeps;
      falseFlags += o.straightFlags;
      if (!o.inRangeAfter) continue;
      ++inRange;
      if (o.courseErrorAfterDeg) {
        ++heldAfter;
        courseError.push_back(*o.courseErrorAfterDeg);
      }
    }
    const auto within120 = std::count_if(latency.begin(), latency.end(), [](double s) { return s <= 120.0; });
    std::sort(latency.begin(), latency.end());
    double medianLatency = kInf;
    if (!latency.empty()) medianLatency = latency[latency.size() / 2];
    const double p95Course = courseError.empty() ? kInf : percentile95(courseError);
    qInfo(
        "%zu turning targets: %lld flagged within 120 s of the turn's start (median latency %.1f s), %zu "
        "flagged at all; straight runs flagged in %ld of %ld sweeps; 2 min after the turn %ld of %ld targets "
        "in range held, course error p95 %.2f deg",
        outcomes.size(), static_cast<long long>(within120), medianLatency, latency.size(), falseFlags,
        straight, heldAfter, inRange, p95Course);
    QVERIFY2(static_cast<double>(within120) >= 0.9 * static_cast<double>(outcomes.size()),
             "fewer than 90% of the turns flagged within 120 s");
    QVERIFY2(static_cast<double>(falseFlags) <= 0.01 * static_cast<double>(straight),
             "straight runs flagged in more than 1% of their sweeps");
    QVERIFY2(static_cast<double>(heldAfter) >= 0.95 * static_cast<double>(inRange),
             "fewer than 95% of the targets in range held 2 min after their turn");
    QVERIFY2(p95Course <= 10.0,
             qPrintable(QString("course error 2 min after the turn: p95 %1 deg").arg(p95Course)));
  }
};

QTEST_GUILESS_MAIN(TstIndependentArpa)
#include "tst_independent_arpa.moc"
