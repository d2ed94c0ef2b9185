// Scenario files: the writer (format: docs/scenarios.md); parseScenario() reads back what it writes.
#include "files/scenario_fields.h"
#include "files/scenario_json.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>

#include "common/angles.h"
#include "common/units.h"
#include "io/json.h"
#include "io/text_file.h"
#include "sim/scenario_limits.h"

// The file formats are written with the codecs of io/: their names unqualified here.
using namespace reckoner::io;

namespace reckoner::files {
namespace {

using sensors::SpeedlogMode;

constexpr int kExact = 17;  // significant digits that round-trip a double

void writeTime(JsonWriter& w, std::string_view key, TimeUs t) {
  w.key(key).value(toSeconds(t), kExact);
}

void writeGaussMarkov(JsonWriter& w, const est::GaussMarkov& gm, std::string_view sigmaKey) {
  w.beginObject()
      .key(sigmaKey)
      .value(gm.sigma, kExact)
      .key("beta_per_s")
      .value(gm.betaPerS, kExact)
      .endObject();
}

/// Merges a power schedule (and for the speedlog its mode schedule) into "schedule" entries.
void writeSchedule(JsonWriter& w, const StepSchedule<bool>& power, const StepSchedule<SpeedlogMode>* mode) {
  struct Entry {
    TimeUs t;
    std::optional<bool> on;
    std::optional<SpeedlogMode> mode;
  };
  std::vector<Entry> entries;
  const auto entryAt = [&entries](TimeUs t) -> Entry& {
    auto it =
        std::lower_bound(entries.begin(), entries.end(), t, [](const Entry& e, TimeUs v) { return e.t < v; });
    if (it == entries.end() || it->t != t) it = entries.insert(it, Entry{t, {}, {}});
    return *it;
  };
  if (!power.initial()) entryAt(0).on = false;
  for (const auto& [t, on] : power.changes()) entryAt(t).on = on;
  if (mode)
    for (const auto& [t, m] : mode->changes()) entryAt(t).mode = m;
  if (entries.empty()) return;
  w.key("schedule").beginArray();
  for (const Entry& e : entries) {
    w.beginObject();
    writeTime(w, "t_s", e.t);
    if (e.on) w.key("on").value(*e.on);
    if (e.mode) w.key("mode").value(scenario_detail::nameOf(scenario_detail::kSpeedlogModes, *e.mode));
    w.endObject();
  }
  w.endArray();
}

double degrees360(double rad) {
  const double d = radToDeg(wrapTwoPi(rad));
  return d >= 360.0 ? 0.0 : d;
}

void writeMotion(JsonWriter& w, const sim::VesselMotionSpec& m) {
  w.key("position_m").numberArray({m.initialPosition.xM, m.initialPosition.yM}, kExact);
  w.key("velocity_mps").numberArray({m.initialVelocityMps[0], m.initialVelocityMps[1]}, kExact);
  if (m.initialHeadingRad) w.key("heading_deg").value(radToDeg(*m.initialHeadingRad), kExact);
  if (m.maxAccelerationMps2 > 0.0) w.key("max_acceleration_mps2").value(m.maxAccelerationMps2, kExact);
  if (m.maxTurnRateRadPerS > 0.0) w.key("max_turn_rate_dps").value(radToDeg(m.maxTurnRateRadPerS), kExact);
  if (m.randomAcceleration) {
    w.key("random_acceleration");
    writeGaussMarkov(w, *m.randomAcceleration, "sigma_mps2");
  }
  if (m.schedule.empty()) return;
  w.key("schedule").beginArray();
  for (const auto& e : m.schedule) {
    w.beginObject();
    writeTime(w, "t_s", e.timeUs);
    if (e.setVelocityMps)
      w.key("velocity_mps").numberArray({(*e.setVelocityMps)[0], (*e.setVelocityMps)[1]}, kExact);
    if (e.turnRateRadPerS) w.key("turn_rate_dps").value(radToDeg(*e.turnRateRadPerS), kExact);
    if (e.order) {
      w.key("order").beginObject();
      w.key("heading_deg").value(degrees360(e.order->headingRad), kExact);
      w.key("speed_mps").value(e.order->speedMps, kExact);
      if (e.order->turnRateRadPerS > 0.0)
        w.key("turn_rate_dps").value(radToDeg(e.order->turnRateRadPerS), kExact);
      if (e.order->accelerationMps2 > 0.0)
        w.key("acceleration_mps2").value(e.order->accelerationMps2, kExact);
      w.endObject();
    }
    w.endObject();
  }
  w.endArray();
}

// One writer per sensor: the sensor's object, key included, in the order parseScenario() reads them.

void writeGps(JsonWriter& w, const sensors::GpsSpec& g) {
  w.key("gps").beginObject();
  w.key("rate_hz").value(g.rateHz, kExact);
  w.key("position_variance_m2").value(g.positionVarM2, kExact);
  w.key("velocity_variance_m2_s2").value(g.velocityVarM2PerS2, kExact);
  writeSchedule(w, g.power, nullptr);
  w.endObject();
}

void writeLoran(JsonWriter& w, const sensors::LoranSpec& l) {
  w.key("loran_c").beginObject();
  w.key("rate_hz").value(l.rateHz, kExact);
  w.key("markov_variance_m2").value(l.error.sigma * l.error.sigma, kExact);
  w.key("markov_beta_per_s").value(l.error.betaPerS, kExact);
  w.key("white_variance_m2").value(l.whiteVarM2, kExact);
  writeSchedule(w, l.power, nullptr);
  w.endObject();
}

void writeSpeedlog(JsonWriter& w, const sensors::SpeedlogSpec& l) {
  w.key("speedlog").beginObject();
  w.key("rate_hz").value(l.rateHz, kExact);
  w.key("markov_variance_m2_s2").value(l.error.sigma * l.error.sigma, kExact);
  w.key("markov_beta_per_s").value(l.error.betaPerS, kExact);
  w.key("white_variance_m2_s2").value(l.whiteVarM2PerS2, kExact);
  if (l.scaleError.sigma > 0.0) {
    w.key("scale_error").beginObject();
    w.key("sigma").value(l.scaleError.sigma, kExact);
    w.key("beta_per_s").value(l.scaleError.betaPerS, kExact);
    w.endObject();
  }
  w.key("mode").value(scenario_detail::nameOf(scenario_detail::kSpeedlogModes, l.mode.initial()));
  writeSchedule(w, l.power, &l.mode);
  w.endObject();
}

void writeGyro(JsonWriter& w, const sensors::GyroSpec& g) {
  w.key("gyro").beginObject();
  w.key("rate_hz").value(g.rateHz, kExact);
  w.key("sd_deg").value(radToDeg(g.sdRad), kExact);
  if (g.bias.sigma > 0.0) {
    w.key("bias").beginObject();
    w.key("sigma_deg").value(radToDeg(g.bias.sigma), kExact);
    w.key("beta_per_s").value(g.bias.betaPerS, kExact);
    w.endObject();
  }
  writeSchedule(w, g.power, nullptr);
  w.endObject();
}

void writeRadar(JsonWriter& w, const sensors::RadarSpec& r) {
  w.key("radar").beginObject();
  w.key("sweep_period_s").value(r.sweepPeriodS, kExact);
  w.key("range_sd_m").value(r.rangeSdM, kExact);
  w.key("bearing_sd_deg").value(radToDeg(r.bearingSdRad), kExact);
  w.key("bearing_backlash_deg").value(radToDeg(r.bearingBacklashRad), kExact);
  w.key("range_quantum_m").value(r.rangeQuantumM, kExact);
  w.key("bearing_quantum_deg").value(radToDeg(r.bearingQuantumRad), kExact);
  w.key("gyro_calibration_deg").value(radToDeg(r.gyroCalibrationRad), kExact);
  w.key("gyro_scatter_sd_deg").value(radToDeg(r.gyroScatterSdRad), kExact);
  w.key("max_range_nm").value(metresToNm(r.maxRangeM), kExact);
  w.key("min_range_m").value(r.minRangeM, kExact);
  w.key("detection_probability").value(r.detectionProbability, kExact);
  w.key("clutter_per_km2").value(r.clutterPerKm2, kExact);
  w.key("clutter_max_range_nm").value(metresToNm(r.clutterMaxRangeM), kExact);
  writeSchedule(w, r.power, nullptr);
  w.endObject();
}

/// "sensors": the fitted ones.
void writeSensors(JsonWriter& w, const sim::Scenario& s) {
  w.key("sensors").beginObject();
  if (s.gps.fitted) writeGps(w, s.gps);
  if (s.loran.fitted) writeLoran(w, s.loran);
  if (s.speedlog.fitted) writeSpeedlog(w, s.speedlog);
  if (s.gyro.fitted) writeGyro(w, s.gyro);
  if (s.radar.fitted) writeRadar(w, s.radar);
  w.endObject();
}

/// "targets", when there are any.
void writeTargets(JsonWriter& w, const std::vector<sim::TargetSpec>& targets) {
  if (targets.empty()) return;
  w.key("targets").beginArray();
  for (const auto& t : targets) {
    w.beginObject();
    w.key("id").value(t.id);
    w.key("name").value(t.name);
    if (t.appearUs > 0) writeTime(w, "appear_s", t.appearUs);
    if (t.leaveUs) writeTime(w, "leave_s", *t.leaveUs);
    writeMotion(w, t.motion);
    if (t.ais) scenario_detail::writeTargetAis(w, *t.ais);
    w.endObject();
  }
  w.endArray();
}

/// "filter": own ship's DRKF.
void writeFilter(JsonWriter& w, const sim::FilterSpec& f) {
  w.key("filter").beginObject();
  w.key("acceleration");
  writeGaussMarkov(w, f.acceleration, "sigma_mps2");
  if (f.current) {
    w.key("current");
    writeGaussMarkov(w, *f.current, "sigma_mps");
  }
  w.key("initial_position_sd_m").value(f.initialPositionSdM, kExact);
  w.key("initial_velocity_sd_mps").value(f.initialVelocitySdMps, kExact);
  w.key("gate_probability").value(f.gateProbability, kExact);
  w.key("gate_reopen_s").value(f.gateReopenS, kExact);
  w.key("min_speed_mps").value(f.minSpeedMps, kExact);
  if (f.adaptiveGnssNoise) w.key("adaptive_gnss_noise").value(true);
  if (f.shipMotion.enabled) {
    const auto& m = f.shipMotion;
    w.key("ship_motion").beginObject();
    w.key("along_sigma_mps2").value(m.alongAcceleration.sigma, kExact);
    w.key("along_beta_per_s").value(m.alongAcceleration.betaPerS, kExact);
    w.key("turn_sigma_dps").value(radToDeg(m.turnRate.sigma), kExact);
    w.key("turn_beta_per_s").value(m.turnRate.betaPerS, kExact);
    w.key("white_acceleration_m2_s3").value(m.whiteAccelerationQ, kExact);
    w.key("min_speed_mps").value(m.minSpeedMps, kExact);
    w.endObject();
  }
  w.endObject();
}

/// "radar_matching", when it is on at some time.
void writeRadarMatching(JsonWriter& w, const sim::RadarMatchingSpec& m) {
  if (!m.active.initial() && m.active.changes().empty()) return;
  w.key("radar_matching").beginObject();
  w.key("enabled").value(m.active.initial());
  if (!m.active.changes().empty()) writeSchedule(w, m.active, nullptr);
  w.key("azimuths").value(m.azimuths);
  w.key("range_bins").value(m.rangeBins);
  w.key("every_sweeps").value(m.everySweeps);
  w.key("max_range_nm").value(metresToNm(m.maxRangeM), kExact);
  w.key("reject_distance_m").value(m.rejectDistanceM, kExact);
  w.key("beam_width_deg").value(m.beamWidthDeg, kExact);
  w.key("max_fix_sd_m").value(m.maxFixSdM, kExact);
  w.key("max_fix_heading_sd_deg").value(m.maxFixHeadingSdDeg, kExact);
  w.key("error_correlation").value(m.errorCorrelation, kExact);
  w.endObject();
}

/// {"hits": M, "of_sweeps": N} under key.
void writeMOfN(JsonWriter& w, std::string_view key, int hits, int sweeps) {
  w.key(key).beginObject().key("hits").value(hits).key("of_sweeps").value(sweeps).endObject();
}

/// Ring sectors as the reader takes them.
void writeZones(JsonWriter& w, const std::vector<track::AcquisitionZone>& zones) {
  w.beginArray();
  for (const auto& z : zones) {
    w.beginObject();
    w.key("min_range_nm").value(metresToNm(z.minRangeM), kExact);
    w.key("max_range_nm").value(metresToNm(z.maxRangeM), kExact);
    w.key("from_bearing_deg").value(radToDeg(z.fromBearingRad), kExact);
    w.key("to_bearing_deg").value(radToDeg(z.toBearingRad), kExact);
    w.endObject();
  }
  w.endArray();
}

/// The tracker's track management: models, association, M of N, zones and the danger limits.
void writeTrackManagement(JsonWriter& w, const sim::TrackerSpec& t) {
  w.key("own_acceleration");
  writeGaussMarkov(w, t.ownAcceleration, "sigma_mps2");
  w.key("target_acceleration");
  writeGaussMarkov(w, t.targetAcceleration, "sigma_mps2");
  w.key("own_ship_feed").value(scenario_detail::nameOf(scenario_detail::kOwnShipFeeds, t.feed));
  w.key("gate_probability").value(t.gateProbability, kExact);
  w.key("initial_speed_sd_mps").value(t.initialSpeedSdMps, kExact);
  w.key("capacity").value(static_cast<std::uint64_t>(t.capacity));
  w.key("association").value(scenario_detail::nameOf(scenario_detail::kAssociations, t.association));
  writeMOfN(w, "confirm", t.confirmHits, t.confirmSweeps);
  writeMOfN(w, "keep", t.keepHits, t.keepSweeps);
  w.key("lost_hold_s").value(t.lostHoldS, kExact);
  w.key("auto_acquire").value(t.autoAcquire);
  if (!t.zones.empty()) writeZones(w.key("acquisition_zones"), t.zones);
  if (!t.zoneChanges.empty()) {
    w.key("acquisition_zone_changes").beginArray();
    for (const auto& [when, zones] : t.zoneChanges) {
      w.beginObject().key("t_s").value(toSeconds(when), kExact);
      writeZones(w.key("zones"), zones);
      w.endObject();
    }
    w.endArray();
  }
  w.key("danger_cpa_nm").value(metresToNm(t.dangerCpaM), kExact);
  w.key("danger_tcpa_min").value(t.dangerTcpaS / 60.0, kExact);
}

/// The tracker's filters: the kind, its changes and each kind's parameters.
void writeTrackFilters(JsonWriter& w, const sim::TrackerSpec& t) {
  w.key("filter").value(track::trackerKindName(t.kind));
  if (!t.kindChanges.empty()) {
    w.key("filter_changes").beginArray();
    for (const auto& [when, kind] : t.kindChanges)
      w.beginObject()
          .key("t_s")
          .value(toSeconds(when), kExact)
          .key("filter")
          .value(track::trackerKindName(kind))
          .endObject();
    w.endArray();
  }
  w.key("input_estimation").beginObject();
  w.key("window").value(t.inputEstimationWindow);
  w.key("false_alarm_probability").value(t.inputEstimationPfa, kExact);
  w.endObject();
  w.key("alpha_beta_gamma").beginObject();
  w.key("alpha").value(t.abg.alpha, kExact);
  w.key("expanding_start").value(t.abg.expandingStart);
  w.endObject();
  w.key("imm").beginObject();
  w.key("cv_accel_q").value(t.imm.cvAccelQ, kExact);
  w.key("ct_accel_q").value(t.imm.ctAccelQ, kExact);
  w.key("ct_turn_q_deg2").value(radToDeg(radToDeg(t.imm.ctTurnQ)), kExact);
  w.key("cv_sojourn_s").value(t.imm.cvSojournS, kExact);
  w.key("ct_sojourn_s").value(t.imm.ctSojournS, kExact);
  w.key("initial_turn_sd_dps").value(radToDeg(t.imm.initialTurnSdRadPerS), kExact);
  w.key("manoeuvre_probability").value(t.imm.manoeuvreProbability, kExact);
  w.endObject();
}

}  // namespace

std::string writeScenario(const sim::Scenario& s) {
  JsonWriter w;
  w.beginObject();
  w.key("format").value(kScenarioFormat);
  w.key("name").value(s.name);
  if (!s.description.empty()) w.key("description").value(s.description);
  w.key("origin").beginObject();
  w.key("lat_deg").value(s.origin.latDeg, kExact).key("lon_deg").value(s.origin.lonDeg, kExact);
  w.endObject();
  writeTime(w, "duration_s", s.durationUs);
  writeTime(w, "step_s", s.stepUs);
  w.key("seed").value(s.seed);
  w.key("current");
  writeGaussMarkov(w, s.current, "sigma_mps");

  w.key("own_ship").beginObject();
  writeMotion(w, s.ownShip);
  w.endObject();
  writeSensors(w, s);
  writeTargets(w, s.targets);
  writeFilter(w, s.filter);
  writeRadarMatching(w, s.radarMatching);
  scenario_detail::writeVoyage(w, s.voyage);
  w.key("tracker").beginObject();
  writeTrackManagement(w, s.tracker);
  writeTrackFilters(w, s.tracker);
  scenario_detail::writeAisAssociation(w, s.tracker.aisAssociation);
  w.endObject();
  w.endObject();
  return w.str() + "\n";
}

void saveScenarioFile(const sim::Scenario& s, const std::string& path) {
  const std::string text = writeScenario(s);
  const std::string tmp = path + ".part";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(path, 0, "", std::string("cannot write: ") + errnoText(errno));
    out << text;
    out.flush();
    if (!out) throw InputError(path, 0, "", std::string("write error: ") + errnoText(errno));
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = errnoText(errno);
    std::remove(tmp.c_str());
    throw InputError(path, 0, "", "cannot replace the file: " + why);
  }
}

}  // namespace reckoner::files
