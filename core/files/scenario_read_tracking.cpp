// Scenario files: the radar-matching, tracker and filter sections of the reader (scenario_read.cpp).
#include "files/scenario_fields.h"

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

namespace reckoner::files::scenario_detail {

void readRadarMatching(Fields& top, sim::Scenario& s) {
  const JsonValue* v = top.get("radar_matching");
  if (!v) return;
  Fields f(top.file(), *v, "radar_matching");
  auto& m = s.radarMatching;
  bool enabled = true;
  if (const JsonValue* e = f.get("enabled")) enabled = f.boolean(*e, f.pathOf("enabled"));
  m.active = StepSchedule<bool>(enabled);
  readPowerSchedule(f, m.active, s.durationUs);
  m.azimuths = f.integerOr("azimuths", 64, 16384, m.azimuths);
  m.rangeBins = f.integerOr("range_bins", 32, 8192, m.rangeBins);
  m.everySweeps = f.integerOr("every_sweeps", 1, 1000, m.everySweeps);
  m.maxRangeM = nmToMetres(f.numberOr("max_range_nm", metresToNm(m.maxRangeM), Fields::Check::Positive));
  m.rejectDistanceM = f.numberOr("reject_distance_m", m.rejectDistanceM, Fields::Check::Positive);
  m.beamWidthDeg = f.numberOr("beam_width_deg", m.beamWidthDeg, Fields::Check::Positive);
  m.maxFixSdM = f.numberOr("max_fix_sd_m", m.maxFixSdM, Fields::Check::Positive);
  m.maxFixHeadingSdDeg = f.numberOr("max_fix_heading_sd_deg", m.maxFixHeadingSdDeg, Fields::Check::Positive);
  m.errorCorrelation = f.numberOr("error_correlation", m.errorCorrelation);
  if (!(m.errorCorrelation >= 0.0 && m.errorCorrelation <= 0.95))
    f.fail(*f.get("error_correlation"), f.pathOf("error_correlation"), "must be in [0, 0.95]");
  if (m.beamWidthDeg > 10.0)
    f.fail(*f.get("beam_width_deg"), f.pathOf("beam_width_deg"), "must be at most 10");
  f.finish();
}

namespace {

// The groups of the "tracker" section, in the order they are read (f is the section; the caller
// finishes it).

/// The accelerations the track filters model, and how own ship's estimate feeds them.
void readTrackerModels(Fields& f, sim::TrackerSpec& tr) {
  if (const JsonValue* a = f.get("own_acceleration")) {
    Fields g(f.file(), *a, f.pathOf("own_acceleration"));
    tr.ownAcceleration = gaussMarkov(g, "variance_m2_s4", "sigma_mps2");
    g.finish();
  }
  if (const JsonValue* a = f.get("target_acceleration")) {
    Fields g(f.file(), *a, f.pathOf("target_acceleration"));
    tr.targetAcceleration = gaussMarkov(g, "variance_m2_s4", "sigma_mps2");
    g.finish();
  }
  if (const JsonValue* feed = f.get("own_ship_feed"))
    tr.feed = valueOf(kOwnShipFeeds, f, *feed, f.pathOf("own_ship_feed"));
}

/// The gate, a new track's speed sd, the bank's capacity and how plots are associated.
void readTrackerAssociation(Fields& f, sim::TrackerSpec& tr) {
  if (const JsonValue* g = f.get("gate_probability")) {
    tr.gateProbability = f.checkedNumber(*g, f.pathOf("gate_probability"), Fields::Check::NonNegative);
    if (!(tr.gateProbability < 1.0))
      f.fail(*g, f.pathOf("gate_probability"), "must be in [0, 1) (0 disables gating)");
  }
  tr.initialSpeedSdMps = f.numberOr("initial_speed_sd_mps", tr.initialSpeedSdMps, Fields::Check::Positive);
  tr.capacity = static_cast<std::size_t>(f.integerOr("capacity", 1, 1000000, static_cast<int>(tr.capacity)));
  if (const JsonValue* a = f.get("association"))
    tr.association = valueOf(kAssociations, f, *a, f.pathOf("association"));
}

struct MOfN {
  int hits = 0, sweeps = 0;
};

/// {"hits": M, "of_sweeps": N} with integers 1 <= M <= N <= 32, when the key is given.
std::optional<MOfN> readMOfN(Fields& f, std::string_view key) {
  const JsonValue* c = f.get(key);
  if (!c) return std::nullopt;
  Fields g(f.file(), *c, f.pathOf(key));
  const double m = g.number("hits", Fields::Check::Positive);
  const double n = g.number("of_sweeps", Fields::Check::Positive);
  if (m != std::floor(m) || n != std::floor(n) || m > n || n > 32)
    g.fail(*c, f.pathOf(key), "needs integers 1 <= hits <= of_sweeps <= 32");
  g.finish();
  return MOfN{static_cast<int>(m), static_cast<int>(n)};
}

/// A track's life: confirmation and keeping (M of N), the hold when lost, automatic acquisition.
void readTrackLife(Fields& f, sim::TrackerSpec& tr) {
  if (const auto confirm = readMOfN(f, "confirm")) {
    tr.confirmHits = confirm->hits;
    tr.confirmSweeps = confirm->sweeps;
  }
  if (const auto keep = readMOfN(f, "keep")) {
    tr.keepHits = keep->hits;
    tr.keepSweeps = keep->sweeps;
  }
  tr.lostHoldS = f.numberOr("lost_hold_s", tr.lostHoldS, Fields::Check::NonNegative);
  if (const JsonValue* a = f.get("auto_acquire")) tr.autoAcquire = f.boolean(*a, f.pathOf("auto_acquire"));
}

/// An array of ring sectors under `key` of f.
std::vector<track::AcquisitionZone> readZones(Fields& f, const char* key) {
  std::vector<track::AcquisitionZone> zones;
  const JsonValue* z = f.get(key);
  if (!z) return zones;
  if (!z->isArray()) f.fail(*z, f.pathOf(key), "must be an array of zones");
  for (std::size_t i = 0; i < z->array.size(); ++i) {
    Fields g(f.file(), z->array[i], f.pathOf(key) + "[" + std::to_string(i) + "]");
    track::AcquisitionZone zone;
    zone.minRangeM = nmToMetres(g.numberOr("min_range_nm", 0.0, Fields::Check::NonNegative));
    zone.maxRangeM = nmToMetres(g.number("max_range_nm", Fields::Check::Positive));
    if (zone.maxRangeM <= zone.minRangeM)
      g.fail(*g.get("max_range_nm"), g.pathOf("max_range_nm"), "must exceed min_range_nm");
    zone.fromBearingRad = degToRad(g.numberOr("from_bearing_deg", 0.0));
    zone.toBearingRad = degToRad(g.numberOr("to_bearing_deg", 0.0));
    g.finish();
    zones.push_back(zone);
  }
  return zones;
}

/// The zones ("acquisition_zones") and their later changes ("acquisition_zone_changes").
void readAcquisitionZones(Fields& f, sim::TrackerSpec& tr, TimeUs durationUs) {
  tr.zones = readZones(f, "acquisition_zones");
  const JsonValue* ch = f.get("acquisition_zone_changes");
  if (!ch) return;
  if (!ch->isArray())
    f.fail(*ch, f.pathOf("acquisition_zone_changes"), "must be an array of {\"t_s\", \"zones\"}");
  for (std::size_t i = 0; i < ch->array.size(); ++i) {
    Fields g(f.file(), ch->array[i], f.pathOf("acquisition_zone_changes") + "[" + std::to_string(i) + "]");
    const TimeUs t = timeField(g, "t_s", durationUs);
    if (!tr.zoneChanges.empty() && t <= tr.zoneChanges.back().first)
      g.fail(*g.get("t_s"), g.pathOf("t_s"), "must increase from change to change");
    g.require("zones");
    auto zones = readZones(g, "zones");
    g.finish();
    tr.zoneChanges.emplace_back(t, std::move(zones));
  }
}

/// seed 001's input estimation: its window and false-alarm probability; it makes the filter ekf-ie.
void readInputEstimation(Fields& f, sim::TrackerSpec& tr) {
  const JsonValue* ie = f.get("input_estimation");
  if (!ie) return;
  Fields g(f.file(), *ie, f.pathOf("input_estimation"));
  const JsonValue& w = g.require("window");
  if (!w.isNumber() || w.number < 1 || w.number > 100 || std::floor(w.number) != w.number)
    g.fail(w, g.pathOf("window"), "must be an integer in [1, 100] (radar updates)");
  tr.inputEstimationWindow = static_cast<int>(w.number);
  if (const JsonValue* p = g.get("false_alarm_probability")) {
    tr.inputEstimationPfa = g.checkedNumber(*p, g.pathOf("false_alarm_probability"), Fields::Check::Positive);
    if (!(tr.inputEstimationPfa < 1.0)) g.fail(*p, g.pathOf("false_alarm_probability"), "must lie in (0, 1)");
  }
  g.finish();
  tr.kind = track::TrackerKind::EkfInputEstimation;  // unless "filter" says otherwise
}

/// The track filter ("filter") and its later changes ("filter_changes").
void readFilterKind(Fields& f, sim::TrackerSpec& tr, TimeUs durationUs) {
  if (const JsonValue* k = f.get("filter")) {
    const auto kind = k->isString() ? track::trackerKindFromName(k->string) : std::nullopt;
    if (!kind)
      f.fail(*k, f.pathOf("filter"),
             "must be \"ekf\", \"ekf-ie\" (with input estimation), \"abg\" (alpha-beta-gamma) or \"imm\"");
    tr.kind = *kind;
  }
  const JsonValue* ch = f.get("filter_changes");
  if (!ch) return;
  if (!ch->isArray()) f.fail(*ch, f.pathOf("filter_changes"), "must be an array of {\"t_s\", \"filter\"}");
  for (std::size_t i = 0; i < ch->array.size(); ++i) {
    Fields g(f.file(), ch->array[i], f.pathOf("filter_changes") + "[" + std::to_string(i) + "]");
    const TimeUs t = timeField(g, "t_s", durationUs);
    if (!tr.kindChanges.empty() && t <= tr.kindChanges.back().first)
      g.fail(*g.get("t_s"), g.pathOf("t_s"), "must increase from change to change");
    const JsonValue& k = g.require("filter");
    const auto kind = k.isString() ? track::trackerKindFromName(k.string) : std::nullopt;
    if (!kind) g.fail(k, g.pathOf("filter"), "must be \"ekf\", \"ekf-ie\", \"abg\" or \"imm\"");
    g.finish();
    tr.kindChanges.emplace_back(t, *kind);
  }
}

/// seed 003's alpha-beta-gamma filter.
void readAlphaBetaGamma(Fields& f, track::AbgConfig& abg) {
  const JsonValue* a = f.get("alpha_beta_gamma");
  if (!a) return;
  Fields g(f.file(), *a, f.pathOf("alpha_beta_gamma"));
  if (const JsonValue* al = g.get("alpha")) {
    abg.alpha = g.checkedNumber(*al, g.pathOf("alpha"), Fields::Check::Positive);
    if (!(abg.alpha <= 0.6)) g.fail(*al, g.pathOf("alpha"), "must lie in (0, 0.6] (seed 003's bound)");
  }
  if (const JsonValue* es = g.get("expanding_start"))
    abg.expandingStart = g.boolean(*es, g.pathOf("expanding_start"));
  g.finish();
}

/// The IMM's two models (constant velocity, coordinated turn) and their switching.
void readImm(Fields& f, track::ImmConfig& c) {
  const JsonValue* m = f.get("imm");
  if (!m) return;
  Fields g(f.file(), *m, f.pathOf("imm"));
  c.cvAccelQ = g.numberOr("cv_accel_q", c.cvAccelQ, Fields::Check::Positive);
  c.ctAccelQ = g.numberOr("ct_accel_q", c.ctAccelQ, Fields::Check::Positive);
  c.ctTurnQ = degToRad(
      degToRad(g.numberOr("ct_turn_q_deg2", radToDeg(radToDeg(c.ctTurnQ)), Fields::Check::NonNegative)));
  c.cvSojournS = g.numberOr("cv_sojourn_s", c.cvSojournS, Fields::Check::Positive);
  c.ctSojournS = g.numberOr("ct_sojourn_s", c.ctSojournS, Fields::Check::Positive);
  c.initialTurnSdRadPerS =
      degToRad(g.numberOr("initial_turn_sd_dps", radToDeg(c.initialTurnSdRadPerS), Fields::Check::Positive));
  if (const JsonValue* mp = g.get("manoeuvre_probability")) {
    c.manoeuvreProbability = g.checkedNumber(*mp, g.pathOf("manoeuvre_probability"), Fields::Check::Positive);
    if (!(c.manoeuvreProbability < 1.0)) g.fail(*mp, g.pathOf("manoeuvre_probability"), "must lie in (0, 1)");
  }
  g.finish();
}

}  // namespace

void readTracker(Fields& top, sim::Scenario& s) {
  const JsonValue* v = top.get("tracker");
  if (!v) return;
  Fields f(top.file(), *v, "tracker");
  auto& tr = s.tracker;
  readTrackerModels(f, tr);
  readTrackerAssociation(f, tr);
  readTrackLife(f, tr);
  readAcquisitionZones(f, tr, s.durationUs);
  tr.dangerCpaM =
      nmToMetres(f.numberOr("danger_cpa_nm", metresToNm(tr.dangerCpaM), Fields::Check::NonNegative));
  tr.dangerTcpaS = 60.0 * f.numberOr("danger_tcpa_min", tr.dangerTcpaS / 60.0, Fields::Check::NonNegative);
  readInputEstimation(f, tr);
  readFilterKind(f, tr, s.durationUs);
  readAlphaBetaGamma(f, tr.abg);
  readImm(f, tr.imm);
  readAisAssociation(f, tr);
  f.finish();
}

void readFilter(Fields& top, sim::Scenario& s) {
  const JsonValue* v = top.get("filter");
  if (!v) return;
  Fields f(top.file(), *v, "filter");
  auto& fs = s.filter;
  if (const JsonValue* a = f.get("acceleration")) {
    Fields g(top.file(), *a, "filter.acceleration");
    fs.acceleration = {g.number("sigma_mps2", Fields::Check::NonNegative),
                       g.number("beta_per_s", Fields::Check::Positive)};
    g.finish();
  }
  if (const JsonValue* c = f.get("current")) {
    Fields g(top.file(), *c, "filter.current");
    fs.current = gaussMarkov(g, "variance_m2_s2", "sigma_mps");
    g.finish();
  }
  fs.initialPositionSdM = f.numberOr("initial_position_sd_m", fs.initialPositionSdM, Fields::Check::Positive);
  fs.initialVelocitySdMps =
      f.numberOr("initial_velocity_sd_mps", fs.initialVelocitySdMps, Fields::Check::Positive);
  if (const JsonValue* g = f.get("gate_probability")) {
    fs.gateProbability = f.checkedNumber(*g, f.pathOf("gate_probability"), Fields::Check::NonNegative);
    if (!(fs.gateProbability < 1.0))
      f.fail(*g, f.pathOf("gate_probability"), "must be in [0, 1) (0 disables gating)");
  }
  fs.gateReopenS = f.numberOr("gate_reopen_s", fs.gateReopenS, Fields::Check::NonNegative);
  fs.minSpeedMps = f.numberOr("min_speed_mps", fs.minSpeedMps, Fields::Check::NonNegative);
  if (const JsonValue* ag = f.get("adaptive_gnss_noise"))
    fs.adaptiveGnssNoise = f.boolean(*ag, f.pathOf("adaptive_gnss_noise"));
  if (const JsonValue* sm = f.get("ship_motion")) {
    Fields g(top.file(), *sm, "filter.ship_motion");
    auto& m = fs.shipMotion;
    m.enabled = true;
    if (const JsonValue* e = g.get("enabled")) m.enabled = g.boolean(*e, g.pathOf("enabled"));
    m.alongAcceleration = {
        g.numberOr("along_sigma_mps2", m.alongAcceleration.sigma, Fields::Check::NonNegative),
        g.numberOr("along_beta_per_s", m.alongAcceleration.betaPerS, Fields::Check::Positive)};
    m.turnRate = {
        degToRad(g.numberOr("turn_sigma_dps", radToDeg(m.turnRate.sigma), Fields::Check::NonNegative)),
        g.numberOr("turn_beta_per_s", m.turnRate.betaPerS, Fields::Check::Positive)};
    m.whiteAccelerationQ =
        g.numberOr("white_acceleration_m2_s3", m.whiteAccelerationQ, Fields::Check::NonNegative);
    m.minSpeedMps = g.numberOr("min_speed_mps", m.minSpeedMps, Fields::Check::Positive);
    g.finish();
  }
  f.finish();
}

}  // namespace reckoner::files::scenario_detail
