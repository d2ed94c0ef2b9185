#include "sim/scenario.h"

#include <cmath>
#include <cstdio>
#include <string_view>

#include "common/angles.h"
#include "common/units.h"
#include "sim/scenario_limits.h"

namespace reckoner::sim {
namespace {
using limits::Range;

std::string formatValue(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

constexpr Range squared(const Range& r, const char* unit) {
  return {r.lo * r.lo, r.hi * r.hi, r.loOpen, unit};
}

/// The first problem of a scenario, with the JSON path of the field: every value against its range of
/// scenario_limits.h, every time against the run's duration.
class ScenarioCheck {
 public:
  ScenarioCheck() = default;
  [[nodiscard]] bool ok() const { return problem_.empty(); }
  [[nodiscard]] const std::string& problem() const { return problem_; }

  void fail(const std::string& path, const std::string& message) {
    if (ok()) problem_ = path + ": " + message;
  }
  /// v in the file's units.
  void number(const std::string& path, double v, const Range& r) {
    if (!ok()) return;
    const bool inside = std::isfinite(v) && (r.loOpen ? v > r.lo : v >= r.lo) && v <= r.hi;
    if (inside) return;
    std::string msg = "must lie in ";
    msg.append(r.loOpen ? "(" : "[")
        .append(formatValue(r.lo))
        .append(", ")
        .append(formatValue(r.hi))
        .append("]");
    if (*r.unit) msg.append(" ").append(r.unit);
    msg.append(", got ").append(formatValue(v));
    fail(path, msg);
  }
  void gaussMarkov(const std::string& path, const std::string& sigmaKey, const est::GaussMarkov& gm,
                   const Range& sigma) {
    number(path + "." + sigmaKey, gm.sigma, sigma);
    number(path + ".beta_per_s", gm.betaPerS, limits::kBetaPerS);
  }
  /// A time of the run: not negative, and within the longest run (a scenario cut short may keep
  /// later changes; files are held to their duration_s by the reader).
  void time(const std::string& path, TimeUs t) {
    if (ok() && (t < 0 || toSeconds(t) > limits::kMaxDurationS))
      fail(path, "time " + formatValue(toSeconds(t)) + " s must lie in [0, " +
                     formatValue(limits::kMaxDurationS) + "] s");
  }
  /// Times of a schedule: each within the run, strictly increasing.
  template <class T>
  void schedule(const std::string& path, const StepSchedule<T>& sched) {
    TimeUs last = -1;
    for (std::size_t i = 0; i < sched.changes().size(); ++i) {
      const TimeUs t = sched.changes()[i].first;
      time(path + "[" + std::to_string(i) + "].t_s", t);
      if (t <= last) fail(path + "[" + std::to_string(i) + "].t_s", "schedule times must increase");
      last = t;
    }
  }

 private:
  std::string problem_;
};

void checkRun(ScenarioCheck& c, const Scenario& s) {
  c.number("duration_s", toSeconds(s.durationUs), {0.0, limits::kMaxDurationS, true, "s"});
  c.number("step_s", toSeconds(s.stepUs), limits::kStepS);
  if (s.stepUs > s.durationUs) c.fail("step_s", "must not exceed duration_s");
  c.number("origin.lat_deg", s.origin.latDeg, {-80.0, 84.0, false, "deg (the UTM band)"});
  c.number("origin.lon_deg", s.origin.lonDeg, {-180.0, 180.0, false, "deg"});
  c.gaussMarkov("current", "sigma_mps", s.current, limits::kCurrentSdMps);
}

void checkMotion(ScenarioCheck& c, const std::string& path, const VesselMotionSpec& m) {
  c.number(path + ".position_m[0]", m.initialPosition.xM, limits::kPositionM);
  c.number(path + ".position_m[1]", m.initialPosition.yM, limits::kPositionM);
  c.number(path + ".velocity_mps", std::hypot(m.initialVelocityMps[0], m.initialVelocityMps[1]),
           limits::kSpeedMps);
  if (m.initialHeadingRad)
    c.number(path + ".heading_deg", radToDeg(*m.initialHeadingRad), limits::kHeadingDeg);
  c.number(path + ".max_acceleration_mps2", m.maxAccelerationMps2, limits::kAccelerationMps2);
  c.number(path + ".max_turn_rate_dps", radToDeg(m.maxTurnRateRadPerS), {0.0, 30.0, false, "deg/s"});
  if (m.randomAcceleration)
    c.gaussMarkov(path + ".random_acceleration", "sigma_mps2", *m.randomAcceleration, limits::kAccelSdMps2);
  TimeUs last = -1;
  for (std::size_t i = 0; i < m.schedule.size(); ++i) {
    const KinematicEvent& e = m.schedule[i];
    const std::string at = path + ".schedule[" + std::to_string(i) + "]";
    c.time(at + ".t_s", e.timeUs);
    if (e.timeUs <= last) c.fail(at + ".t_s", "event times must increase");
    last = e.timeUs;
    if (e.order && (e.setVelocityMps || e.turnRateRadPerS))
      c.fail(at + ".order", "an order cannot be combined with velocity_mps or turn_rate_dps");
    if (e.setVelocityMps)
      c.number(at + ".velocity_mps", std::hypot((*e.setVelocityMps)[0], (*e.setVelocityMps)[1]),
               limits::kSpeedMps);
    if (e.turnRateRadPerS)
      c.number(at + ".turn_rate_dps", radToDeg(*e.turnRateRadPerS), limits::kTurnRateDps);
    if (e.order) {
      c.number(at + ".order.heading_deg", radToDeg(e.order->headingRad), limits::kHeadingDeg);
      c.number(at + ".order.speed_mps", e.order->speedMps, limits::kSpeedMps);
      c.number(at + ".order.turn_rate_dps", radToDeg(e.order->turnRateRadPerS), {0.0, 30.0, false, "deg/s"});
      c.number(at + ".order.acceleration_mps2", e.order->accelerationMps2, limits::kAccelerationMps2);
    }
  }
}

void checkRadar(ScenarioCheck& c, const sensors::RadarSpec& r) {
  const std::string p = "sensors.radar";
  c.number(p + ".sweep_period_s", r.sweepPeriodS, limits::kSweepPeriodS);
  c.number(p + ".range_sd_m", r.rangeSdM, limits::kRangeSdM);
  c.number(p + ".bearing_sd_deg", radToDeg(r.bearingSdRad), limits::kAngleSdDeg);
  c.number(p + ".bearing_backlash_deg", radToDeg(r.bearingBacklashRad), limits::kAngleErrorDeg);
  c.number(p + ".range_quantum_m", r.rangeQuantumM, limits::kRangeQuantumM);
  c.number(p + ".bearing_quantum_deg", radToDeg(r.bearingQuantumRad), limits::kAngleErrorDeg);
  c.number(p + ".gyro_calibration_deg", radToDeg(r.gyroCalibrationRad), limits::kSignedAngleErrorDeg);
  c.number(p + ".gyro_scatter_sd_deg", radToDeg(r.gyroScatterSdRad), limits::kAngleErrorDeg);
  c.number(p + ".max_range_nm", metresToNm(r.maxRangeM), limits::kRadarRangeNm);
  c.number(p + ".min_range_m", r.minRangeM, {0.0, r.maxRangeM, false, "m (below max_range_nm)"});
  if (c.ok() && r.minRangeM >= r.maxRangeM) c.fail(p + ".min_range_m", "must be below max_range_nm");
  c.number(p + ".detection_probability", r.detectionProbability, limits::kProbability);
  c.number(p + ".clutter_per_km2", r.clutterPerKm2, limits::kClutterPerKm2);
  c.number(p + ".clutter_max_range_nm", metresToNm(r.clutterMaxRangeM), {0.0, 200.0, false, "NM"});
  c.schedule(p + ".schedule", r.power);
}

void checkSensors(ScenarioCheck& c, const Scenario& s) {
  const Range posVar = squared(limits::kPositionSdM, "m^2");
  const Range velVar = squared(limits::kVelocitySdMps, "m^2/s^2");
  if (s.gps.fitted) {
    c.number("sensors.gps.rate_hz", s.gps.rateHz, limits::kRateHz);
    c.number("sensors.gps.position_variance_m2", s.gps.positionVarM2, posVar);
    c.number("sensors.gps.velocity_variance_m2_s2", s.gps.velocityVarM2PerS2, velVar);
    c.schedule("sensors.gps.schedule", s.gps.power);
  }
  if (s.loran.fitted) {
    c.number("sensors.loran_c.rate_hz", s.loran.rateHz, limits::kRateHz);
    c.number("sensors.loran_c.markov_variance_m2", s.loran.error.sigma * s.loran.error.sigma,
             squared(limits::kMarkovPositionSdM, "m^2"));
    c.number("sensors.loran_c.markov_beta_per_s", s.loran.error.betaPerS, limits::kBetaPerS);
    c.number("sensors.loran_c.white_variance_m2", s.loran.whiteVarM2, posVar);
    c.schedule("sensors.loran_c.schedule", s.loran.power);
  }
  if (s.speedlog.fitted) {
    c.number("sensors.speedlog.rate_hz", s.speedlog.rateHz, limits::kRateHz);
    c.number("sensors.speedlog.markov_variance_m2_s2", s.speedlog.error.sigma * s.speedlog.error.sigma,
             squared(limits::kMarkovVelocitySdMps, "m^2/s^2"));
    c.number("sensors.speedlog.markov_beta_per_s", s.speedlog.error.betaPerS, limits::kBetaPerS);
    c.number("sensors.speedlog.white_variance_m2_s2", s.speedlog.whiteVarM2PerS2, velVar);
    c.number("sensors.speedlog.scale_error.sigma", s.speedlog.scaleError.sigma, limits::kLogScaleSd);
    c.number("sensors.speedlog.scale_error.beta_per_s", s.speedlog.scaleError.betaPerS, limits::kBetaPerS);
    c.schedule("sensors.speedlog.schedule", s.speedlog.power);
    c.schedule("sensors.speedlog.schedule", s.speedlog.mode);
  }
  if (s.gyro.fitted) {
    c.number("sensors.gyro.rate_hz", s.gyro.rateHz, limits::kRateHz);
    c.number("sensors.gyro.sd_deg", radToDeg(s.gyro.sdRad), limits::kAngleSdDeg);
    c.number("sensors.gyro.bias.sigma_deg", radToDeg(s.gyro.bias.sigma), limits::kHeadingBiasSdDeg);
    c.number("sensors.gyro.bias.beta_per_s", s.gyro.bias.betaPerS, limits::kBetaPerS);
    c.schedule("sensors.gyro.schedule", s.gyro.power);
  }
  // The DRKF models the Loran-C and speedlog errors whether or not the sensors are fitted.
  c.gaussMarkov("sensors.loran_c", "markov_sigma_m", s.loran.error, limits::kMarkovPositionSdM);
  c.gaussMarkov("sensors.speedlog", "markov_sigma_mps", s.speedlog.error, limits::kMarkovVelocitySdMps);
  if (s.radar.fitted) checkRadar(c, s.radar);
}

void checkTarget(ScenarioCheck& c, const Scenario& s, std::size_t i) {
  const TargetSpec& t = s.targets[i];
  const std::string path = "targets[" + std::to_string(i) + "]";
  if (t.id < 0 || t.id > 1000000000) c.fail(path + ".id", "must be an integer in [0, 1e9]");
  for (std::size_t j = 0; j < i; ++j)
    if (s.targets[j].id == t.id) c.fail(path + ".id", "id " + std::to_string(t.id) + " used twice");
  c.time(path + ".appear_s", t.appearUs);
  if (t.leaveUs) {
    c.time(path + ".leave_s", *t.leaveUs);
    if (*t.leaveUs <= t.appearUs) c.fail(path + ".leave_s", "must be after appear_s");
  }
  checkMotion(c, path, t.motion);
  if (t.ais) {
    if (const std::string e = t.ais->check(); !e.empty()) c.fail(path + ".ais", e);
    for (std::size_t j = 0; j < i; ++j)
      if (s.targets[j].ais && s.targets[j].ais->mmsi == t.ais->mmsi)
        c.fail(path + ".ais.mmsi", "MMSI " + std::to_string(t.ais->mmsi) + " used twice");
  }
}

void checkFilter(ScenarioCheck& c, const FilterSpec& f) {
  c.gaussMarkov("filter.acceleration", "sigma_mps2", f.acceleration, limits::kAccelSdMps2);
  if (f.current) c.gaussMarkov("filter.current", "sigma_mps", *f.current, limits::kCurrentSdMps);
  c.number("filter.initial_position_sd_m", f.initialPositionSdM, limits::kInitialPositionSdM);
  c.number("filter.initial_velocity_sd_mps", f.initialVelocitySdMps, limits::kInitialSpeedSdMps);
  if (!(f.gateProbability >= 0.0 && f.gateProbability < 1.0))
    c.fail("filter.gate_probability",
           "must be in [0, 1) (0 disables gating), got " + formatValue(f.gateProbability));
  c.number("filter.gate_reopen_s", f.gateReopenS, limits::kHoldS);
  c.number("filter.min_speed_mps", f.minSpeedMps, limits::kSpeedThresholdMps);
}

void checkZones(ScenarioCheck& c, const std::string& path, const std::vector<track::AcquisitionZone>& zones) {
  for (std::size_t i = 0; i < zones.size(); ++i) {
    const std::string z = path + "[" + std::to_string(i) + "]";
    c.number(z + ".min_range_nm", metresToNm(zones[i].minRangeM), limits::kDistanceNm);
    c.number(z + ".max_range_nm", metresToNm(zones[i].maxRangeM), limits::kRadarRangeNm);
    c.number(z + ".from_bearing_deg", radToDeg(zones[i].fromBearingRad), limits::kBearingDeg);
    c.number(z + ".to_bearing_deg", radToDeg(zones[i].toBearingRad), limits::kBearingDeg);
    if (!(zones[i].maxRangeM > zones[i].minRangeM)) c.fail(z + ".max_range_nm", "must exceed min_range_nm");
  }
}

void checkTracker(ScenarioCheck& c, const Scenario& s) {
  const TrackerSpec& tr = s.tracker;
  if (const std::string e = tr.aisAssociation.check(); !e.empty()) c.fail("tracker.ais_association", e);
  c.gaussMarkov("tracker.own_acceleration", "sigma_mps2", tr.ownAcceleration, limits::kAccelSdMps2);
  c.gaussMarkov("tracker.target_acceleration", "sigma_mps2", tr.targetAcceleration, limits::kAccelSdMps2);
  if (!(tr.gateProbability >= 0.0 && tr.gateProbability < 1.0))
    c.fail("tracker.gate_probability",
           "must be in [0, 1) (0 disables gating), got " + formatValue(tr.gateProbability));
  c.number("tracker.initial_speed_sd_mps", tr.initialSpeedSdMps, limits::kInitialSpeedSdMps);
  c.number("tracker.capacity", static_cast<double>(tr.capacity),
           {1.0, limits::kMaxTrackCapacity, false, "tracks"});
  c.number("tracker.lost_hold_s", tr.lostHoldS, limits::kHoldS);
  checkZones(c, "tracker.acquisition_zones", tr.zones);
  TimeUs lastZones = -1;
  for (std::size_t i = 0; i < tr.zoneChanges.size(); ++i) {
    const std::string at = "tracker.acquisition_zone_changes[" + std::to_string(i) + "]";
    c.time(at + ".t_s", tr.zoneChanges[i].first);
    if (tr.zoneChanges[i].first <= lastZones) c.fail(at + ".t_s", "must increase from change to change");
    lastZones = tr.zoneChanges[i].first;
    checkZones(c, at + ".zones", tr.zoneChanges[i].second);
  }
  c.number("tracker.danger_cpa_nm", metresToNm(tr.dangerCpaM), limits::kDistanceNm);
  c.number("tracker.danger_tcpa_min", tr.dangerTcpaS / 60.0, limits::kTcpaMin);
  TimeUs last = -1;
  for (std::size_t i = 0; i < tr.kindChanges.size(); ++i) {
    const std::string at = "tracker.filter_changes[" + std::to_string(i) + "].t_s";
    c.time(at, tr.kindChanges[i].first);
    if (tr.kindChanges[i].first <= last) c.fail(at, "must increase from change to change");
    last = tr.kindChanges[i].first;
  }
  const track::ImmConfig& m = tr.imm;
  c.number("tracker.imm.cv_accel_q", m.cvAccelQ, limits::kImmAccelQ);
  c.number("tracker.imm.ct_accel_q", m.ctAccelQ, limits::kImmAccelQ);
  c.number("tracker.imm.ct_turn_q_deg2", radToDeg(radToDeg(m.ctTurnQ)), limits::kImmTurnQDeg2);
  c.number("tracker.imm.cv_sojourn_s", m.cvSojournS, limits::kSojournS);
  c.number("tracker.imm.ct_sojourn_s", m.ctSojournS, limits::kSojournS);
  c.number("tracker.imm.initial_turn_sd_dps", radToDeg(m.initialTurnSdRadPerS), limits::kTurnSdDps);
  if (c.ok())
    if (const std::string p = trackManagerConfigFor(tr, s.radar.sweepPeriodS).check(); !p.empty())
      c.fail("tracker", p);
}

void checkRadarMatching(ScenarioCheck& c, const RadarMatchingSpec& m) {
  const std::string p = "radar_matching";
  c.schedule(p + ".schedule", m.active);
  c.number(p + ".azimuths", m.azimuths, {64.0, 16384.0, false, ""});
  c.number(p + ".range_bins", m.rangeBins, {32.0, 8192.0, false, ""});
  c.number(p + ".every_sweeps", m.everySweeps, {1.0, 1000.0, false, ""});
  c.number(p + ".max_range_nm", metresToNm(m.maxRangeM), {0.0, 50.0, true, "NM"});
  c.number(p + ".reject_distance_m", m.rejectDistanceM, limits::kMatchingDistanceM);
  c.number(p + ".beam_width_deg", m.beamWidthDeg, {0.0, 10.0, true, "deg"});
  c.number(p + ".max_fix_sd_m", m.maxFixSdM, limits::kMatchingDistanceM);
  c.number(p + ".max_fix_heading_sd_deg", m.maxFixHeadingSdDeg, {0.0, 45.0, true, "deg"});
  c.number(p + ".error_correlation", m.errorCorrelation, {0.0, 0.95, false, ""});
}

/// What the run will hold: a row per step, a row per track per sweep (targets, and the tracks clutter
/// may start), and each sweep's clutter plots; every one bounded so that no file asks for more than
/// the machine has.
void checkBudget(ScenarioCheck& c, const Scenario& s) {
  const double steps = static_cast<double>(s.durationUs) / static_cast<double>(s.stepUs);
  double sweeps = 0.0, clutter = 0.0;
  if (s.radar.fitted) {
    sweeps = toSeconds(s.durationUs) / s.radar.sweepPeriodS;
    const double rMax = s.radar.clutterMaxRangeM > 0.0 ? std::min(s.radar.clutterMaxRangeM, s.radar.maxRangeM)
                                                       : s.radar.maxRangeM;
    const double r0 = std::min(s.radar.minRangeM, rMax);
    clutter = s.radar.clutterPerKm2 * kPi * (rMax * rMax - r0 * r0) * 1e-6;
    if (clutter > limits::kMaxClutterPerSweep)
      c.fail("sensors.radar.clutter_per_km2",
             formatValue(s.radar.clutterPerKm2) + " per km^2 over the clutter range gives " +
                 formatValue(clutter) + " false plots per sweep; the limit is " +
                 formatValue(limits::kMaxClutterPerSweep));
  }
  // A target counts for the share of the run it is present (appear_s to leave_s).
  double targets = 0.0;
  for (const TargetSpec& t : s.targets)
    targets += static_cast<double>(t.leaveUs.value_or(s.durationUs) - std::min(t.appearUs, s.durationUs)) /
               static_cast<double>(s.durationUs);
  const double tracks = targets + std::min(clutter, static_cast<double>(s.tracker.capacity));
  const double rows = steps + sweeps * tracks;
  if (rows > limits::kMaxOutputRows)
    c.fail("duration_s", formatValue(toSeconds(s.durationUs)) + " s gives " + formatValue(steps) +
                             " steps and " + formatValue(sweeps) + " sweeps, about " + formatValue(rows) +
                             " output rows; the limit is " + formatValue(limits::kMaxOutputRows) +
                             " (shorten duration_s or lengthen step_s)");
}

}  // namespace

SensorStates sensorStatesAt(const Scenario& s, TimeUs t) {
  using sensors::SensorId;
  SensorStates st;
  st.on[static_cast<std::size_t>(SensorId::Gps)] = s.gps.fitted && s.gps.power.at(t);
  st.on[static_cast<std::size_t>(SensorId::LoranC)] = s.loran.fitted && s.loran.power.at(t);
  st.on[static_cast<std::size_t>(SensorId::Speedlog)] = s.speedlog.fitted && s.speedlog.power.at(t);
  st.on[static_cast<std::size_t>(SensorId::Gyro)] = s.gyro.fitted && s.gyro.power.at(t);
  st.speedlogMode = s.speedlog.mode.at(t);
  return st;
}

std::string sensorLabel(const SensorStates& s) {
  using sensors::SensorId;
  std::string label;
  auto add = [&label](std::string_view part) {
    if (!label.empty()) label += '+';
    label += part;
  };
  if (s.isOn(SensorId::Gps)) add("gps");
  if (s.isOn(SensorId::LoranC)) add("loran_c");
  if (s.isOn(SensorId::Speedlog))
    add(s.speedlogMode == sensors::SpeedlogMode::GroundLock ? "speedlog_gl" : "speedlog_bl");
  if (s.isOn(SensorId::Gyro)) add("gyro");
  return label.empty() ? "none" : label;
}

track::TrackerKind trackerKindAt(const TrackerSpec& t, TimeUs time) {
  track::TrackerKind k = t.kind;
  for (const auto& [when, kind] : t.kindChanges) {
    if (when > time) break;
    k = kind;
  }
  return k;
}

std::pair<const std::vector<track::AcquisitionZone>*, int> zonesAt(const TrackerSpec& t, TimeUs time) {
  std::pair<const std::vector<track::AcquisitionZone>*, int> in{&t.zones, -1};
  for (std::size_t i = 0; i < t.zoneChanges.size() && t.zoneChanges[i].first <= time; ++i)
    in = {&t.zoneChanges[i].second, static_cast<int>(i)};
  return in;
}

track::TrackManagerConfig trackManagerConfigFor(const TrackerSpec& t, double sweepPeriodS) {
  track::TrackManagerConfig c;
  c.filter.process = {t.ownAcceleration, t.targetAcceleration};
  c.filter.gateProbability = t.gateProbability;
  c.filter.feed = t.feed;
  c.filter.initialSpeedSdMps = t.initialSpeedSdMps;
  c.association = t.association;
  c.capacity = t.capacity;
  c.confirmHits = t.confirmHits;
  c.confirmSweeps = t.confirmSweeps;
  c.keepHits = t.keepHits;
  c.keepSweeps = t.keepSweeps;
  c.lostHoldS = t.lostHoldS;
  c.autoAcquire = t.autoAcquire;
  c.zones = t.zones;
  c.sweepPeriodS = sweepPeriodS;
  c.dangerCpaM = t.dangerCpaM;
  c.dangerTcpaS = t.dangerTcpaS;
  c.kind = t.kind;
  c.inputEstimationWindow = t.inputEstimationWindow;
  c.inputEstimationPfa = t.inputEstimationPfa;
  c.abg = t.abg;
  c.imm = t.imm;
  return c;
}

std::string checkScenario(const Scenario& s) {
  ScenarioCheck c;
  checkRun(c, s);
  checkMotion(c, "own_ship", s.ownShip);
  checkSensors(c, s);
  for (std::size_t i = 0; i < s.targets.size(); ++i) checkTarget(c, s, i);
  checkFilter(c, s.filter);
  checkTracker(c, s);
  checkRadarMatching(c, s.radarMatching);
  if (c.ok()) {
    const std::vector<std::string> voyage = s.voyage.problems();
    if (!voyage.empty()) return voyage.front();
  }
  return c.problem();
}

std::string checkScenarioForRows(const Scenario& s) {
  if (std::string problem = checkScenario(s); !problem.empty()) return problem;
  ScenarioCheck c;
  checkBudget(c, s);
  return c.problem();
}

}  // namespace reckoner::sim
