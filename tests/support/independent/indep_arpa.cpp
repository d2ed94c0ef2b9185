// `arpa`: a straight-running own ship, eight constant-velocity targets and the radar plots of them,
// with the own-ship sensor errors of the IMO ARPA test budget (A.823(19) annex, MSC.192(79)).
//
// Own ship: heading uniform [0, 360) deg and speed through the water uniform [5, 25) kn, both constant;
// current 0.3 m/s towards a uniform direction; sensors: GNSS as in `ownship` (no outage), gyro with a
// calibration error of 0.5 deg (random sign) + N(0, 0.1 deg), log through the water (VHW) with a
// calibration error of 0.5 kn (random sign) + N(0, 0.05 kn), no scale error, no Loran-C.
//
// Geometry: every target's range, bearing, relative speed and CPA are drawn to hold at t0 (default
// 300 s into the run, so a tracker has settled before scoring starts) for the instantaneous relative
// motion in the tangent plane at own ship's position at t0; CPA and TCPA in params.json are those of
// straight-line relative motion from there. Every ship then keeps its course and speed over ground
// (a rhumb line), which curves slightly in that plane (meridian convergence), so the closest range
// in the truth can differ from the t0 CPA by metres to a few tens of metres.
// With --manoeuvre every target then turns once, after the 3-minute scoring time: starting at
// t0 + U(240, 540) s, by U(45, 90) deg to a random side at U(0.5, 1) deg/s, keeping its speed (a rhumb
// line per 0.1 s of the arc at the step's mid course), and runs straight again; params.json gives each
// turn's start, end, angle, rate and final course. The draws come from a stream of their own, so the
// plots before the first turn are the same as without --manoeuvre.
//
// Radar model (all numbers are the constants below; params.json repeats them):
//  * antenna: one rotation per 2.5 s, clockwise, at the ship's heading marker at t = 0, 2.5, 5, ...
//    A target is seen when the antenna points at it: the plot time solves
//    t = 2.5 s * (n + relative bearing(t) / 360 deg) for rotation n, with the relative bearing
//    unwrapped along the run, so one plot per rotation, about 2.5 s apart, even for a target that
//    crosses the heading line. truth_targets.csv holds every target at each rotation start.
//  * plot errors: the IMO A.823(19) radar error budget (Annex 3), each term drawn independently:
//      - range: geodesic distance to the target's reference point (glint, below) + N(0, 20 m)
//        (pulse shape), then quantised: rounded to the nearest multiple of 0.02 NM (37.04 m).
//      - bearing (true): geodesic azimuth at own ship
//          + the gyro's calibration error (the picture is gyro-stabilised, so the gyro's constant
//            +-0.5 deg, the same value as in $HEHDT, is in the plots too),
//          + gyro scatter N(0, 0.12 deg): one draw per antenna rotation (the rotation that starts at
//            the heading marker at 2.5 s * floor(t / 2.5 s)), common to every plot of that rotation
//            and independent of the N(0, 0.1 deg) noise of $HEHDT,
//          + N(0, 0.05 deg) (beam shape) + N(0, 0.03 deg) (bearing encoder): A.823's "0.05 + 0.03 deg"
//            read as two independent random sources, each drawn per plot; their sum is
//            N(0, sqrt(0.05^2 + 0.03^2) = 0.0583 deg),
//          + antenna backlash, uniform [-0.05, +0.05) deg per plot,
//        then wrapped to [0, 360) and quantised: rounded to the nearest multiple of 0.2 deg
//        (359.9 deg and above become 0.0).
//        Zero-mean bearing terms together, about the calibration error, without glint:
//        sqrt(0.12^2 + 0.05^2 + 0.03^2 + 0.05^2/3 + 0.2^2/12) = 0.148 deg.
//  * glint: the reference point lies uniform +-30 m along the target's course from its centre,
//    drawn anew for every plot.
//  * detection probability 0.95 per target per rotation; no plot beyond 12 NM (true range) or when
//    the reported (noisy, quantised) range is under 50 m (the radar's minimum range). No clutter.
//  Every draw is made for every rotation, detected or not, so rotation n's errors are fixed by the seed.
#include "indep_sim.h"

#include <GeographicLib/LocalCartesian.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace reckoner_indep {

namespace {
constexpr int kTargets = 8;
constexpr double kRotationS = 2.5;
constexpr double kDetectionProbability = 0.95;
constexpr double kGlintHalfLengthM = 30.0, kMaxRangeNm = 12.0, kMinRangeM = 50.0;
// A.823(19) Annex 3 radar error budget (see the top of this file).
constexpr double kRangeSdM = 20.0;                         // pulse shape
constexpr double kBeamSdDeg = 0.05, kEncoderSdDeg = 0.03;  // random bearing terms, per plot
constexpr double kBacklashHalfDeg = 0.05;                  // antenna backlash, uniform +-
constexpr double kGyroScatterSdDeg = 0.12;                 // per rotation, common to its plots
constexpr double kRangeQuantumM = 0.02 * kMetresPerNm;     // 37.04 m
constexpr double kBearingQuantumDeg = 0.2;
constexpr double kTargetSpeedMaxKn = 40.0, kCurrentMps = 0.3;

struct Target {
  std::string id;
  LatLon atT0;
  double sogMps = 0.0, cogDeg = 0.0;
  // drawn geometry at t0
  double rangeNm = 0.0, bearingDeg = 0.0, relSpeedKn = 0.0, relCourseDeg = 0.0, cpaNm = 0.0, tcpaS = 0.0;
  int resamples = 0;
  // A turn (--manoeuvre): from turnStartS at turnRateDegS (signed) by turnDeg, at constant speed. The
  // arc is tabulated every kTurnStepS (each step a rhumb line of the step's mid course), then straight.
  double turnStartS = -1.0, turnDeg = 0.0, turnRateDegS = 0.0;
  std::vector<LatLon> arc;  ///< positions at turnStartS + k kTurnStepS, k = 0..n
  [[nodiscard]] bool turns() const { return turnStartS >= 0.0; }
  [[nodiscard]] double turnEndS() const { return turnStartS + std::abs(turnDeg / turnRateDegS); }
  [[nodiscard]] double courseAt(double tS) const {
    if (!turns() || tS <= turnStartS) return cogDeg;
    return wrapDeg360(cogDeg + turnRateDegS * (std::min(tS, turnEndS()) - turnStartS));
  }
  LatLon at(double t0S, double tS) const {
    if (!turns() || tS <= turnStartS) return rhumbDirect(atT0, cogDeg, sogMps * (tS - t0S));
    if (tS >= turnEndS()) return rhumbDirect(arc.back(), courseAt(tS), sogMps * (tS - turnEndS()));
    const double k = (tS - turnStartS) / kTurnStepS;
    const auto i = std::min(static_cast<std::size_t>(k), arc.size() - 2);
    const double f = k - static_cast<double>(i);  // linear between tabulated points (sagitta < 1 mm)
    return {arc[i].latDeg + f * (arc[i + 1].latDeg - arc[i].latDeg),
            arc[i].lonDeg + f * (arc[i + 1].lonDeg - arc[i].lonDeg)};
  }
  void tabulateTurn(double t0S) {
    const double lengthS = turnEndS() - turnStartS;
    const auto n = static_cast<std::size_t>(std::ceil(lengthS / kTurnStepS));
    arc.assign(1, at(t0S, turnStartS));
    for (std::size_t k = 0; k < n; ++k) {
      const double a = turnStartS + static_cast<double>(k) * kTurnStepS;
      const double b = std::min(a + kTurnStepS, turnEndS());
      arc.push_back(rhumbDirect(arc.back(), courseAt(0.5 * (a + b)), sogMps * (b - a)));
    }
    if (arc.size() < 2) arc.push_back(arc.back());
  }
  static constexpr double kTurnStepS = 0.1;
};

struct Plot {
  std::int64_t tUs;
  double rangeM, bearingDeg;
  std::string id;
};

/// Own ship: constant heading and speed through the water in a constant current.
struct OwnShip {
  LatLon start;
  double headingDeg = 0.0, stwMps = 0.0;
  Enu currentMps = Enu::Zero(), velocityMps = Enu::Zero();
  double sogMps = 0.0, cogDeg = 0.0;
  [[nodiscard]] LatLon at(double tS) const { return rhumbDirect(start, cogDeg, sogMps * tS); }
};

OwnShip drawOwnShip(Rng& params) {
  OwnShip own;
  own.start = LatLon{47.6 + params.uniform(-0.1, 0.1), -122.4 + params.uniform(-0.1, 0.1)};
  own.headingDeg = params.uniform(0.0, 360.0);
  own.stwMps = params.uniform(5.0, 25.0) * kMpsPerKnot;
  own.currentMps = enuFromPolar(kCurrentMps, params.uniform(0.0, 360.0));
  own.velocityMps = enuFromPolar(own.stwMps, own.headingDeg) + own.currentMps;
  own.sogMps = own.velocityMps.norm();
  own.cogDeg = azimuthDegOf(own.velocityMps);
  return own;
}

/// Own ship's sensors at the A.823 calibration errors (the draws after own ship's, same stream).
SensorModel drawSensorModel(Rng& params) {
  SensorModel model;
  model.gnssWhiteSdM = params.uniform(3.0, 5.0);
  model.gyroBiasDeg = 0.5 * params.sign();  // A.823: gyro calibration error 0.5 deg
  model.gyroNoiseSdDeg = 0.1;
  model.logScale = 0.0;
  model.logOffsetKn = 0.5 * params.sign();  // A.823: log calibration error 0.5 kn
  model.logNoiseSdKn = 0.05;
  return model;
}

/// Targets: geometry drawn at t0 in the tangent plane at own ship's position then
/// (GeographicLib::LocalCartesian, x east, y north), resampled while implausible. Own ship is at the
/// plane's origin, where its local velocity is its plane velocity. A target's local course is the
/// azimuth, at its own position, of its plane velocity (meridians converge: at 11 NM east or west local
/// north is ~0.2 deg off the plane's, which would move a CPA by hundreds of metres).
std::vector<Target> drawTargets(const ArpaOptions& o, const OwnShip& own, Rng& targetRng, Rng& manoeuvreRng) {
  const LatLon ownT0 = own.at(o.t0S);
  const GeographicLib::LocalCartesian plane(ownT0.latDeg, ownT0.lonDeg, 0.0);
  auto fromPlane = [&](const Enu& p) {
    LatLon q;
    double hM = 0.0;
    plane.Reverse(p.x(), p.y(), 0.0, q.latDeg, q.lonDeg, hM);  // foot of the ellipsoid normal
    return q;
  };
  std::vector<Target> targets;
  for (int i = 0; i < kTargets; ++i) {
    Target t;
    t.id =
        std::string("T").append(std::to_string(i + 1));  // (not "T" + ...: GCC 12 -Wrestrict false positive)
    Enu positionM, velocityMps;
    for (;; ++t.resamples) {
      if (t.resamples > 100000) throw std::runtime_error("cannot place target " + t.id);
      t.rangeNm = targetRng.uniform(3.0, 11.0);
      t.bearingDeg = targetRng.uniform(0.0, 360.0);
      t.relSpeedKn = targetRng.uniform(8.0, 30.0);
      t.cpaNm = targetRng.uniform(0.0, 2.0);
      const double side = targetRng.sign();
      // Relative motion at angle alpha off the line of sight towards own ship: miss distance
      // R sin(alpha) = CPA, closing component R cos(alpha) > 0 (CPA <= 2 < 3 <= R).
      const double alphaDeg = std::asin(t.cpaNm / t.rangeNm) * kDegPerRad;
      t.relCourseDeg = wrapDeg360(t.bearingDeg + 180.0 + side * alphaDeg);
      t.tcpaS = t.rangeNm * kMetresPerNm * std::cos(alphaDeg / kDegPerRad) / (t.relSpeedKn * kMpsPerKnot);
      positionM = enuFromPolar(t.rangeNm * kMetresPerNm, t.bearingDeg);
      velocityMps = own.velocityMps + enuFromPolar(t.relSpeedKn * kMpsPerKnot, t.relCourseDeg);
      if (velocityMps.norm() <= kTargetSpeedMaxKn * kMpsPerKnot) break;
    }
    t.atT0 = fromPlane(positionM);
    const double dtS = 1.0;  // local velocity from the plane step of 1 s (curvature terms ~1e-9 m)
    const RangeBearing step = rangeBearing(t.atT0, fromPlane(positionM + velocityMps * dtS));
    t.sogMps = step.rangeM / dtS;
    t.cogDeg = step.bearingDeg;
    if (o.manoeuvre) {
      t.turnStartS = o.t0S + manoeuvreRng.uniform(240.0, 540.0);
      t.turnDeg = manoeuvreRng.sign() * manoeuvreRng.uniform(45.0, 90.0);
      t.turnRateDegS = std::copysign(manoeuvreRng.uniform(0.5, 1.0), t.turnDeg);
      t.tabulateTurn(o.t0S);
    }
    targets.push_back(t);
  }
  return targets;
}

double quantise(double value, double quantum) {
  return std::round(value / quantum) * quantum;
}

/// One target's radar plots: a plot each rotation the antenna passes it (bearing-proportional from the
/// heading marker), with the A.823 errors, the rotation's gyro scatter and the detection probability.
void addTargetPlots(const ArpaOptions& o, const OwnShip& own, const Target& tg, std::size_t index,
                    double gyroBiasDeg, const std::vector<double>& sweepScatterDeg, double endS,
                    std::vector<Plot>& plots) {
  Rng radarRng = makeRng(o.seed + 0x100000001B3ULL * (index + 1), Stream::Radar);  // one stream per target
  auto relativeBearing = [&](double tS) {
    return rangeBearing(own.at(tS), tg.at(o.t0S, tS)).bearingDeg - own.headingDeg;
  };
  double unwrappedDeg = wrapDeg360(relativeBearing(0.0));  // continuous along the run
  for (int n = 0;; ++n) {
    double tS = kRotationS * (n + unwrappedDeg / 360.0);
    for (int it = 0; it < 6; ++it) {  // fixed point: contraction for any range over ~20 m
      const double b = unwrappedDeg + wrapDeg180(relativeBearing(tS) - unwrappedDeg);
      tS = kRotationS * (n + b / 360.0);
    }
    unwrappedDeg += wrapDeg180(relativeBearing(tS) - unwrappedDeg);
    // Every draw is made for every rotation, detected or not, so the errors of rotation n are fixed.
    const double detect = radarRng.uniform01();
    const double glintM = radarRng.uniform(-kGlintHalfLengthM, kGlintHalfLengthM);
    const double rangeNoiseM = radarRng.normal(kRangeSdM);
    const double beamNoiseDeg = radarRng.normal(kBeamSdDeg);
    const double encoderNoiseDeg = radarRng.normal(kEncoderSdDeg);
    const double backlashDeg = radarRng.uniform(-kBacklashHalfDeg, kBacklashHalfDeg);
    if (tS > endS) break;
    if (tS < 0.0) continue;
    const std::int64_t tUs = std::llround(tS * 1e6);
    const double exactS = static_cast<double>(tUs) * 1e-6;  // truth at the written time
    const LatLon reference = offsetEnu(tg.at(o.t0S, exactS), enuFromPolar(glintM, tg.courseAt(exactS)));
    const RangeBearing rb = rangeBearing(own.at(exactS), reference);
    const double rangeM = quantise(rb.rangeM + rangeNoiseM, kRangeQuantumM);
    if (detect >= kDetectionProbability || rb.rangeM > kMaxRangeNm * kMetresPerNm || rangeM < kMinRangeM)
      continue;
    const auto rotation =
        std::min(static_cast<std::size_t>(std::floor(exactS / kRotationS)), sweepScatterDeg.size() - 1);
    double bearingDeg = quantise(wrapDeg360(rb.bearingDeg + gyroBiasDeg + sweepScatterDeg[rotation] +
                                            beamNoiseDeg + encoderNoiseDeg + backlashDeg),
                                 kBearingQuantumDeg);
    if (bearingDeg >= 360.0 - 0.5 * kBearingQuantumDeg) bearingDeg = 0.0;  // 360.0 is north
    plots.push_back(Plot{tUs, rangeM, bearingDeg, tg.id});
  }
}

/// The radar plots of every target, in time order.
std::vector<Plot> radarPlots(const ArpaOptions& o, const OwnShip& own, const std::vector<Target>& targets,
                             double gyroBiasDeg, double endS) {
  // Gyro scatter of every rotation k (from 2.5 k s), drawn up front from its own stream, so it is the
  // same for every target's plots in that rotation and independent of the targets' draws.
  std::vector<double> sweepScatterDeg(static_cast<std::size_t>(std::floor(endS / kRotationS)) + 1);
  {
    Rng sweepRng = makeRng(o.seed, Stream::RadarSweep);
    for (double& scatterDeg : sweepScatterDeg) scatterDeg = sweepRng.normal(kGyroScatterSdDeg);
  }
  std::vector<Plot> plots;
  for (std::size_t i = 0; i < targets.size(); ++i)
    addTargetPlots(o, own, targets[i], i, gyroBiasDeg, sweepScatterDeg, endS, plots);
  std::stable_sort(plots.begin(), plots.end(), [](const Plot& a, const Plot& b) { return a.tUs < b.tUs; });
  return plots;
}

std::string radarCsv(const UtcClock& clock, const std::vector<Plot>& plots) {
  std::string radar = "utc,range_m,bearing_deg,target_id\n";
  for (const Plot& p : plots)
    radar += clock.iso(p.tUs, 6) + fmt(",%.2f", p.rangeM) + fmt(",%.4f", p.bearingDeg) + "," + p.id + "\n";
  return radar;
}

/// The targets' truth at every rotation start.
std::string truthTargetsCsv(const UtcClock& clock, const std::vector<Target>& targets, double t0S,
                            std::int64_t endUs) {
  std::string truthTargets = "utc,t_s,target_id,lat_deg,lon_deg,sog_mps,cog_deg\n";
  for (std::int64_t tUs = 0; tUs <= endUs; tUs += static_cast<std::int64_t>(kRotationS * 1e6)) {
    const double tS = static_cast<double>(tUs) * 1e-6;
    for (const Target& tg : targets) {
      const LatLon p = tg.at(t0S, tS);
      char buf[160];
      std::snprintf(buf, sizeof buf, ",%.3f,%s,%.9f,%.9f,%.4f,%.4f\n", tS, tg.id.c_str(), p.latDeg, p.lonDeg,
                    tg.sogMps, tg.courseAt(tS));
      truthTargets += clock.iso(tUs, 3) + buf;
    }
  }
  return truthTargets;
}

/// params.json's "targets": each target's drawn geometry, and its turn when it has one.
std::string targetsJson(const std::vector<Target>& targets) {
  std::string targetText;
  for (const Target& t : targets) {
    char buf[512];
    std::snprintf(
        buf, sizeof buf,
        "%s\n    {\"id\": \"%s\", \"range_nm\": %.6f, \"bearing_deg\": %.6f, \"rel_speed_kn\": %.6f, "
        "\"rel_course_deg\": %.6f, \"cpa_nm\": %.6f, \"tcpa_s\": %.3f, \"sog_kn\": %.6f, "
        "\"cog_deg\": %.6f, \"lat_deg_at_t0\": %.9f, \"lon_deg_at_t0\": %.9f, \"resamples\": %d",
        targetText.empty() ? "" : ",", t.id.c_str(), t.rangeNm, t.bearingDeg, t.relSpeedKn, t.relCourseDeg,
        t.cpaNm, t.tcpaS, t.sogMps / kMpsPerKnot, t.cogDeg, t.atT0.latDeg, t.atT0.lonDeg, t.resamples);
    targetText += buf;
    if (t.turns()) {
      std::snprintf(buf, sizeof buf,
                    ", \"manoeuvre\": {\"start_s\": %.3f, \"end_s\": %.3f, \"turn_deg\": %.4f, "
                    "\"rate_deg_s\": %.4f, \"cog_after_deg\": %.6f}",
                    t.turnStartS, t.turnEndS(), t.turnDeg, t.turnRateDegS, t.courseAt(t.turnEndS()));
      targetText += buf;
    }
    targetText += "}";
  }
  return targetText;
}

/// params.json: the run's own ship, current, radar error budget, sensors and targets.
void writeArpaParams(const ArpaOptions& o, const UtcClock& clock, const OwnShip& own,
                     const SensorModel& model, const std::vector<Target>& targets, std::size_t plotCount) {
  const LatLon ownT0 = own.at(o.t0S);
  char head[4096];
  std::snprintf(
      head, sizeof head,
      "{\n  \"generator\": \"reckoner-indep-sim arpa\",\n  \"seed\": %llu,\n"
      "  \"start_utc\": \"%s\",\n  \"duration_s\": %.3f,\n  \"t0_s\": %.3f,\n  \"t0_utc\": \"%s\",\n"
      "  \"own\": {\"start_lat_deg\": %.9f, \"start_lon_deg\": %.9f, \"heading_deg\": %.6f, "
      "\"stw_kn\": %.6f, \"sog_kn\": %.6f, \"cog_deg\": %.6f, \"lat_deg_at_t0\": %.9f, "
      "\"lon_deg_at_t0\": %.9f},\n"
      "  \"current\": {\"speed_mps\": %.3f, \"set_deg\": %.6f},\n"
      "  \"radar\": {\"rotation_s\": %.2f, \"plot_time\": \"antenna passes the target (bearing-proportional "
      "from the heading marker)\", \"error_budget\": \"A.823(19) Annex 3\", \"range_sd_m\": %.1f, "
      "\"range_quantum_m\": %.2f, \"bearing_beam_sd_deg\": %.3f, \"bearing_encoder_sd_deg\": %.3f, "
      "\"bearing_random_sd_deg\": %.4f, \"bearing_backlash_half_width_deg\": %.3f, "
      "\"bearing_quantum_deg\": %.2f, \"gyro_calibration_deg\": %.3f, \"gyro_scatter_sd_deg\": %.3f, "
      "\"detection_probability\": %.2f, \"glint_uniform_half_length_m\": "
      "%.1f, \"max_range_nm\": %.1f, \"min_range_m\": %.1f, \"plots\": %zu},\n",
      static_cast<unsigned long long>(o.seed), clock.iso(0, 3).c_str(), o.durationS, o.t0S,
      clock.iso(std::llround(o.t0S * 1e6), 3).c_str(), own.start.latDeg, own.start.lonDeg, own.headingDeg,
      own.stwMps / kMpsPerKnot, own.sogMps / kMpsPerKnot, own.cogDeg, ownT0.latDeg, ownT0.lonDeg, kCurrentMps,
      azimuthDegOf(own.currentMps), kRotationS, kRangeSdM, kRangeQuantumM, kBeamSdDeg, kEncoderSdDeg,
      std::hypot(kBeamSdDeg, kEncoderSdDeg), kBacklashHalfDeg, kBearingQuantumDeg, model.gyroBiasDeg,
      kGyroScatterSdDeg, kDetectionProbability, kGlintHalfLengthM, kMaxRangeNm, kMinRangeM, plotCount);
  writeTextFile(o.outDir + "/params.json", std::string(head) + "  \"sensors\": " + sensorModelJson(model) +
                                               ",\n  \"targets\": [" + targetsJson(targets) + "\n  ]\n}\n");
}
}  // namespace

int runArpa(const ArpaOptions& o) {
  ensureDirectory(o.outDir);
  Rng params = makeRng(o.seed, Stream::Params);
  Rng targetRng = makeRng(o.seed, Stream::Targets);
  Rng manoeuvreRng = makeRng(o.seed, Stream::Manoeuvre);
  const OwnShip own = drawOwnShip(params);
  const SensorModel model = drawSensorModel(params);

  const UtcClock clock{unixSecondsFromCivil(2026, 6, 15, 10, 0, 0)};
  const std::int64_t endUs = static_cast<std::int64_t>(std::floor(o.durationS)) * 1000000;
  std::vector<TruthRow> rows;
  for (std::int64_t tUs = 0; tUs <= endUs; tUs += 1000000)
    rows.push_back(TruthRow{tUs, own.at(static_cast<double>(tUs) * 1e-6), own.sogMps, own.cogDeg,
                            own.headingDeg, own.stwMps, own.currentMps, true});
  const std::vector<Target> targets = drawTargets(o, own, targetRng, manoeuvreRng);
  const std::vector<Plot> plots =
      radarPlots(o, own, targets, model.gyroBiasDeg, static_cast<double>(endUs) * 1e-6);

  // ---- Files ----
  writeTruthCsv(o.outDir + "/truth.csv", clock, rows);
  writeOwnShipNmea(o.outDir + "/ownship.nmea", clock, rows, model, o.seed);
  writeTextFile(o.outDir + "/radar.csv", radarCsv(clock, plots));
  writeTextFile(o.outDir + "/truth_targets.csv", truthTargetsCsv(clock, targets, o.t0S, endUs));
  writeArpaParams(o, clock, own, model, targets, plots.size());
  return 0;
}

}  // namespace reckoner_indep
