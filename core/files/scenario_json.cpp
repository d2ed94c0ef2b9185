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

namespace reckoner::io {
namespace {

using sensors::SpeedlogMode;

std::string formatNumber(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

/// Reads one JSON object's fields, tracking which were used so that unknown ones are reported.
class Fields {
 public:
  Fields(const std::string& file, const JsonValue& v, std::string path)
      : file_(file), v_(v), path_(std::move(path)) {
    if (!v.isObject()) fail(v, path_, std::string("must be an object, got ") + typeName(v.type));
    used_.assign(v.object.size(), false);
  }

  [[noreturn]] void fail(const JsonValue& at, const std::string& path, const std::string& msg) const {
    throw InputError(file_, at.line, path, msg);
  }
  [[nodiscard]] std::string pathOf(std::string_view key) const {
    return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
  }
  [[nodiscard]] const std::string& file() const { return file_; }

  const JsonValue* get(std::string_view key) {
    for (std::size_t i = 0; i < v_.object.size(); ++i) {
      if (v_.object[i].first == key) {
        used_[i] = true;
        return &v_.object[i].second;
      }
    }
    return nullptr;
  }
  const JsonValue& require(std::string_view key) {
    const JsonValue* v = get(key);
    if (!v) fail(v_, pathOf(key), "required field is missing");
    return *v;
  }

  enum class Check { Any, Positive, NonNegative };

  double number(std::string_view key, Check check = Check::Any) {
    return checkedNumber(require(key), pathOf(key), check);
  }
  double numberOr(std::string_view key, double fallback, Check check = Check::Any) {
    const JsonValue* v = get(key);
    return v ? checkedNumber(*v, pathOf(key), check) : fallback;
  }
  /// An optional integer in [lo, hi].
  int integerOr(std::string_view key, int lo, int hi, int fallback) {
    const JsonValue* c = get(key);
    if (!c) return fallback;
    if (!c->isNumber() || c->number < lo || c->number > hi || std::floor(c->number) != c->number)
      fail(*c, pathOf(key), "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return static_cast<int>(c->number);
  }
  double checkedNumber(const JsonValue& v, const std::string& path, Check check) const {
    if (!v.isNumber()) fail(v, path, std::string("must be a number, got ") + typeName(v.type));
    if (check == Check::Positive && !(v.number > 0.0))
      fail(v, path, "must be positive, got " + formatNumber(v.number));
    if (check == Check::NonNegative && !(v.number >= 0.0))
      fail(v, path, "must not be negative, got " + formatNumber(v.number));
    return v.number;
  }
  std::string stringOr(std::string_view key, std::string fallback) {
    const JsonValue* v = get(key);
    if (!v) return fallback;
    if (!v->isString()) fail(*v, pathOf(key), std::string("must be a string, got ") + typeName(v->type));
    return v->string;
  }
  bool boolean(const JsonValue& v, const std::string& path) const {
    if (!v.isBool()) fail(v, path, std::string("must be true or false, got ") + typeName(v.type));
    return v.boolean;
  }
  std::array<double, 2> pair(std::string_view key, std::array<double, 2> fallback) {
    const JsonValue* v = get(key);
    if (!v) return fallback;
    if (!v->isArray() || v->array.size() != 2)
      fail(*v, pathOf(key), "must be an array of two numbers [x, y]");
    return {checkedNumber(v->array[0], pathOf(key) + "[0]", Check::Any),
            checkedNumber(v->array[1], pathOf(key) + "[1]", Check::Any)};
  }

  /// Reports the first field nobody asked for.
  void finish() const {
    for (std::size_t i = 0; i < v_.object.size(); ++i)
      if (!used_[i]) fail(v_.object[i].second, pathOf(v_.object[i].first), "unknown field");
  }

  [[nodiscard]] const JsonValue& json() const { return v_; }

 private:
  const std::string& file_;
  const JsonValue& v_;
  std::string path_;
  std::vector<bool> used_;
};

/// A time of the run, in seconds in [0, duration_s] (compared in seconds: 1e13 s does not fit the
/// microsecond clock).
TimeUs timeField(Fields& f, std::string_view key, TimeUs durationUs) {
  const JsonValue& v = f.require(key);
  const double s = f.checkedNumber(v, f.pathOf(key), Fields::Check::NonNegative);
  if (s > toSeconds(durationUs))
    f.fail(v, f.pathOf(key), "time " + formatNumber(s) + " s lies beyond duration_s");
  return fromSeconds(s);
}

/// The line of the value at a checkScenario path ("sensors.gps.schedule[1].t_s"): the deepest value
/// of the path the file has.
int lineOfPath(const JsonValue& root, std::string_view path) {
  const JsonValue* at = &root;
  std::size_t i = 0;
  while (i < path.size() && at) {
    if (path[i] == '.' && ++i == path.size()) break;
    if (path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string_view::npos || !at->isArray()) break;
      std::size_t k = 0;
      const auto [p, ec] = std::from_chars(path.data() + i + 1, path.data() + close, k);
      if (ec != std::errc() || k >= at->array.size()) break;
      at = &at->array[k];
      i = close + 1;
      continue;
    }
    const std::size_t end = std::min(path.find('.', i), path.find('[', i));
    const JsonValue* next = at->isObject() ? at->find(path.substr(i, end - i)) : nullptr;
    if (!next) break;
    at = next;
    i = end == std::string_view::npos ? path.size() : end;
  }
  return at ? at->line : root.line;
}

/// Gauss-Markov block given by its variance (Table I's units) or sigma, plus beta.
est::GaussMarkov gaussMarkov(Fields& f, std::string_view varianceKey, std::string_view sigmaKey) {
  est::GaussMarkov gm;
  const JsonValue* var = f.get(varianceKey);
  const JsonValue* sig = f.get(sigmaKey);
  if (var && sig)
    f.fail(*sig, f.pathOf(sigmaKey),
           "give either " + std::string(varianceKey) + " or " + std::string(sigmaKey) + ", not both");
  if (!var && !sig) f.fail(f.json(), f.pathOf(varianceKey), "required field is missing");
  gm.sigma = var ? std::sqrt(f.checkedNumber(*var, f.pathOf(varianceKey), Fields::Check::NonNegative))
                 : f.checkedNumber(*sig, f.pathOf(sigmaKey), Fields::Check::NonNegative);
  gm.betaPerS = f.number("beta_per_s", Fields::Check::Positive);
  return gm;
}

/// A sensor's "schedule": [{"t_s": .., "on": bool, ("mode": ..)}]; onMode handles "mode" if given.
void readPowerSchedule(Fields& sensor, StepSchedule<bool>& power, TimeUs durationUs,
                       const std::function<void(Fields&, TimeUs)>& onMode = {}) {
  const JsonValue* sched = sensor.get("schedule");
  if (!sched) return;
  const std::string path = sensor.pathOf("schedule");
  if (!sched->isArray()) sensor.fail(*sched, path, "must be an array of {\"t_s\": ..., \"on\": ...} entries");
  TimeUs last = -1;
  bool lastOn = power.initial();
  for (std::size_t i = 0; i < sched->array.size(); ++i) {
    Fields e(sensor.file(), sched->array[i], path + "[" + std::to_string(i) + "]");
    const TimeUs t = timeField(e, "t_s", durationUs);
    if (t <= last) e.fail(*e.get("t_s"), e.pathOf("t_s"), "schedule times must increase");
    last = t;
    const JsonValue* on = e.get("on");
    const JsonValue* mode = onMode ? e.get("mode") : nullptr;
    if (!on && !mode)
      e.fail(sched->array[i], e.pathOf("on"),
             onMode ? "entry needs \"on\" or \"mode\"" : "required field is missing");
    if (on) lastOn = e.boolean(*on, e.pathOf("on"));
    power.addChange(t, lastOn);
    if (mode) onMode(e, t);
    e.finish();
  }
}

SpeedlogMode speedlogMode(const Fields& f, const JsonValue& v, const std::string& path) {
  if (v.isString() && v.string == "ground_lock") return SpeedlogMode::GroundLock;
  if (v.isString() && v.string == "bottom_lock") return SpeedlogMode::BottomLock;
  f.fail(v, path, "must be \"ground_lock\" (speed over ground) or \"bottom_lock\" (speed through water)");
}

void readSensors(Fields& top, sim::Scenario& s) {
  const JsonValue& sensorsJson = top.require("sensors");
  Fields sensorsF(top.file(), sensorsJson, "sensors");
  s.gps.fitted = s.loran.fitted = s.speedlog.fitted = s.gyro.fitted = false;
  const TimeUs dur = s.durationUs;

  if (const JsonValue* v = sensorsF.get("gps")) {
    Fields f(top.file(), *v, "sensors.gps");
    s.gps.fitted = true;
    s.gps.rateHz = f.numberOr("rate_hz", 1.0, Fields::Check::Positive);
    s.gps.positionVarM2 = f.number("position_variance_m2", Fields::Check::Positive);
    s.gps.velocityVarM2PerS2 = f.number("velocity_variance_m2_s2", Fields::Check::Positive);
    readPowerSchedule(f, s.gps.power, dur);
    f.finish();
  }
  if (const JsonValue* v = sensorsF.get("loran_c")) {
    Fields f(top.file(), *v, "sensors.loran_c");
    s.loran.fitted = true;
    s.loran.rateHz = f.numberOr("rate_hz", 1.0, Fields::Check::Positive);
    const double var = f.number("markov_variance_m2", Fields::Check::NonNegative);
    s.loran.error = {std::sqrt(var), f.number("markov_beta_per_s", Fields::Check::Positive)};
    s.loran.whiteVarM2 = f.number("white_variance_m2", Fields::Check::Positive);
    readPowerSchedule(f, s.loran.power, dur);
    f.finish();
  }
  if (const JsonValue* v = sensorsF.get("speedlog")) {
    Fields f(top.file(), *v, "sensors.speedlog");
    s.speedlog.fitted = true;
    s.speedlog.rateHz = f.numberOr("rate_hz", 1.0, Fields::Check::Positive);
    const double var = f.number("markov_variance_m2_s2", Fields::Check::NonNegative);
    s.speedlog.error = {std::sqrt(var), f.number("markov_beta_per_s", Fields::Check::Positive)};
    s.speedlog.whiteVarM2PerS2 = f.number("white_variance_m2_s2", Fields::Check::Positive);
    if (const JsonValue* k = f.get("scale_error")) {  // not in the paper: none
      Fields g(top.file(), *k, "sensors.speedlog.scale_error");
      s.speedlog.scaleError = {g.number("sigma", Fields::Check::NonNegative),
                               g.number("beta_per_s", Fields::Check::Positive)};
      g.finish();
    }
    SpeedlogMode initial = SpeedlogMode::GroundLock;
    if (const JsonValue* m = f.get("mode")) initial = speedlogMode(f, *m, f.pathOf("mode"));
    s.speedlog.mode = StepSchedule<SpeedlogMode>(initial);
    readPowerSchedule(f, s.speedlog.power, dur, [&](Fields& e, TimeUs t) {
      s.speedlog.mode.addChange(t, speedlogMode(e, *e.get("mode"), e.pathOf("mode")));
    });
    f.finish();
  }
  if (const JsonValue* v = sensorsF.get("gyro")) {
    Fields f(top.file(), *v, "sensors.gyro");
    s.gyro.fitted = true;
    s.gyro.rateHz = f.numberOr("rate_hz", 1.0, Fields::Check::Positive);
    s.gyro.sdRad = degToRad(f.number("sd_deg", Fields::Check::Positive));
    if (const JsonValue* b = f.get("bias")) {  // not in the paper: none
      Fields g(top.file(), *b, "sensors.gyro.bias");
      // Their limits are checkScenario's (sim/scenario_limits.h), as every other field's.
      s.gyro.bias = {degToRad(g.number("sigma_deg", Fields::Check::NonNegative)),
                     g.number("beta_per_s", Fields::Check::Positive)};
      g.finish();
    }
    readPowerSchedule(f, s.gyro.power, dur);
    f.finish();
  }
  if (const JsonValue* v = sensorsF.get("radar")) {
    Fields f(top.file(), *v, "sensors.radar");
    auto& r = s.radar;
    r.fitted = true;
    r.sweepPeriodS = f.numberOr("sweep_period_s", r.sweepPeriodS, Fields::Check::Positive);
    const bool a823 = [&] {
      const JsonValue* budget = f.get("error_budget");
      if (!budget) return false;
      if (!budget->isString() || budget->string != "a823")
        f.fail(*budget, f.pathOf("error_budget"), "must be \"a823\" (IMO A.823(19) sensor errors)");
      return true;
    }();
    if (a823) {
      r.rangeSdM = 20.0;                                  // pulse shape
      r.bearingSdRad = degToRad(std::hypot(0.05, 0.03));  // beam shape and encoder
      r.bearingBacklashRad = degToRad(0.05);
      r.rangeQuantumM = nmToMetres(0.02);   // +-0.01 NM
      r.bearingQuantumRad = degToRad(0.2);  // +-0.1 deg
      r.gyroCalibrationRad = degToRad(0.5);
      r.gyroScatterSdRad = degToRad(0.12);
    }
    const auto P = Fields::Check::Positive;
    const auto NN = Fields::Check::NonNegative;
    r.rangeSdM = a823 ? f.numberOr("range_sd_m", r.rangeSdM, P) : f.number("range_sd_m", P);
    r.bearingSdRad = a823 ? degToRad(f.numberOr("bearing_sd_deg", radToDeg(r.bearingSdRad), P))
                          : degToRad(f.number("bearing_sd_deg", P));
    r.bearingBacklashRad = degToRad(f.numberOr("bearing_backlash_deg", radToDeg(r.bearingBacklashRad), NN));
    r.rangeQuantumM = f.numberOr("range_quantum_m", r.rangeQuantumM, NN);
    r.bearingQuantumRad = degToRad(f.numberOr("bearing_quantum_deg", radToDeg(r.bearingQuantumRad), NN));
    r.gyroCalibrationRad =
        degToRad(f.numberOr("gyro_calibration_deg", radToDeg(r.gyroCalibrationRad), Fields::Check::Any));
    r.gyroScatterSdRad = degToRad(f.numberOr("gyro_scatter_sd_deg", radToDeg(r.gyroScatterSdRad), NN));
    r.maxRangeM = nmToMetres(f.numberOr("max_range_nm", metresToNm(r.maxRangeM), P));
    r.minRangeM = f.numberOr("min_range_m", r.minRangeM, NN);
    if (r.minRangeM >= r.maxRangeM)
      f.fail(*f.get("min_range_m"), f.pathOf("min_range_m"), "must be below max_range_nm");
    if (const JsonValue* pd = f.get("detection_probability")) {
      r.detectionProbability = f.checkedNumber(*pd, f.pathOf("detection_probability"), NN);
      if (r.detectionProbability > 1.0) f.fail(*pd, f.pathOf("detection_probability"), "must lie in [0, 1]");
    }
    r.clutterPerKm2 = f.numberOr("clutter_per_km2", 0.0, NN);
    r.clutterMaxRangeM = nmToMetres(f.numberOr("clutter_max_range_nm", 0.0, NN));
    readPowerSchedule(f, r.power, dur);
    f.finish();
  }
  for (const auto& [key, value] : sensorsJson.object) {
    if (key != "gps" && key != "loran_c" && key != "speedlog" && key != "gyro" && key != "radar")
      sensorsF.fail(value, "sensors." + key,
                    "unknown sensor " + io::quoted(key) + " (known: gps, loran_c, speedlog, gyro, radar)");
  }
}

/// Motion of a vessel: position, velocity, heading, acceleration limit, random acceleration, schedule.
/// Reads the motion fields of f (the caller finishes f).
void readMotion(Fields& f, sim::VesselMotionSpec& o, TimeUs durationUs) {
  const auto p = f.pair("position_m", {0.0, 0.0});
  o.initialPosition = {p[0], p[1]};
  o.initialVelocityMps = f.pair("velocity_mps", {0.0, 0.0});
  if (const JsonValue* h = f.get("heading_deg"))
    o.initialHeadingRad = degToRad(f.checkedNumber(*h, f.pathOf("heading_deg"), Fields::Check::Any));
  o.maxAccelerationMps2 = f.numberOr("max_acceleration_mps2", 0.0, Fields::Check::NonNegative);
  o.maxTurnRateRadPerS = degToRad(f.numberOr("max_turn_rate_dps", 0.0, Fields::Check::NonNegative));
  if (const JsonValue* ra = f.get("random_acceleration")) {
    Fields g(f.file(), *ra, f.pathOf("random_acceleration"));
    o.randomAcceleration = gaussMarkov(g, "variance_m2_s4", "sigma_mps2");
    g.finish();
  }
  if (const JsonValue* sched = f.get("schedule")) {
    const std::string path = f.pathOf("schedule");
    if (!sched->isArray()) f.fail(*sched, path, "must be an array of events");
    TimeUs last = -1;
    for (std::size_t i = 0; i < sched->array.size(); ++i) {
      Fields e(f.file(), sched->array[i], path + "[" + std::to_string(i) + "]");
      sim::KinematicEvent ev;
      ev.timeUs = timeField(e, "t_s", durationUs);
      if (ev.timeUs <= last) e.fail(*e.get("t_s"), e.pathOf("t_s"), "event times must increase");
      last = ev.timeUs;
      if (e.get("velocity_mps")) ev.setVelocityMps = e.pair("velocity_mps", {});
      if (const JsonValue* r = e.get("turn_rate_dps"))
        ev.turnRateRadPerS = degToRad(e.checkedNumber(*r, e.pathOf("turn_rate_dps"), Fields::Check::Any));
      if (const JsonValue* ord = e.get("order")) {
        if (ev.setVelocityMps || ev.turnRateRadPerS)
          e.fail(*ord, e.pathOf("order"), "an order cannot be combined with velocity_mps or turn_rate_dps");
        Fields g(f.file(), *ord, e.pathOf("order"));
        const JsonValue& heading = g.require("heading_deg");
        const double headingDeg =
            g.checkedNumber(heading, g.pathOf("heading_deg"), Fields::Check::NonNegative);
        if (headingDeg >= 360.0) g.fail(heading, g.pathOf("heading_deg"), "must lie in [0, 360)");
        ev.order = sim::HelmOrder{degToRad(headingDeg), g.number("speed_mps", Fields::Check::NonNegative),
                                  degToRad(g.numberOr("turn_rate_dps", 0.0, Fields::Check::NonNegative)),
                                  g.numberOr("acceleration_mps2", 0.0, Fields::Check::NonNegative)};
        g.finish();
      }
      if (!ev.setVelocityMps && !ev.turnRateRadPerS && !ev.order)
        e.fail(sched->array[i], e.pathOf("velocity_mps"),
               "event needs \"velocity_mps\", \"turn_rate_dps\" or \"order\"");
      e.finish();
      o.schedule.push_back(ev);
    }
  }
}

void readOwnShip(Fields& top, sim::Scenario& s) {
  Fields f(top.file(), top.require("own_ship"), "own_ship");
  readMotion(f, s.ownShip, s.durationUs);
  f.finish();
}

void readTargets(Fields& top, sim::Scenario& s) {
  const JsonValue* v = top.get("targets");
  if (!v) return;
  if (!v->isArray()) top.fail(*v, "targets", "must be an array of targets");
  for (std::size_t i = 0; i < v->array.size(); ++i) {
    const std::string path = "targets[" + std::to_string(i) + "]";
    Fields f(top.file(), v->array[i], path);
    sim::TargetSpec t;
    const JsonValue& id = f.require("id");
    if (!id.isNumber() || id.number < 0 || id.number > 1e9 || std::floor(id.number) != id.number)
      f.fail(id, f.pathOf("id"), "must be a non-negative integer");
    t.id = static_cast<int>(id.number);
    for (const auto& other : s.targets)
      if (other.id == t.id)
        f.fail(id, f.pathOf("id"), "id " + std::to_string(t.id) + " is used by another target");
    t.name = f.stringOr("name", "target " + std::to_string(t.id));
    if (f.get("appear_s")) t.appearUs = timeField(f, "appear_s", s.durationUs);
    readMotion(f, t.motion, s.durationUs);
    f.finish();
    s.targets.push_back(std::move(t));
  }
}

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

void readTracker(Fields& top, sim::Scenario& s) {
  const JsonValue* v = top.get("tracker");
  if (!v) return;
  Fields f(top.file(), *v, "tracker");
  auto& tr = s.tracker;
  if (const JsonValue* a = f.get("own_acceleration")) {
    Fields g(top.file(), *a, "tracker.own_acceleration");
    tr.ownAcceleration = gaussMarkov(g, "variance_m2_s4", "sigma_mps2");
    g.finish();
  }
  if (const JsonValue* a = f.get("target_acceleration")) {
    Fields g(top.file(), *a, "tracker.target_acceleration");
    tr.targetAcceleration = gaussMarkov(g, "variance_m2_s4", "sigma_mps2");
    g.finish();
  }
  if (const JsonValue* feed = f.get("own_ship_feed")) {
    if (feed->isString() && feed->string == "marginal")
      tr.feed = track::OwnShipFeed::Marginal;
    else if (feed->isString() && feed->string == "measurement")
      tr.feed = track::OwnShipFeed::Measurement;
    else
      f.fail(*feed, "tracker.own_ship_feed",
             "must be \"marginal\" (consistent) or \"measurement\" (seed 000)");
  }
  if (const JsonValue* g = f.get("gate_probability")) {
    tr.gateProbability = f.checkedNumber(*g, f.pathOf("gate_probability"), Fields::Check::NonNegative);
    if (!(tr.gateProbability < 1.0))
      f.fail(*g, f.pathOf("gate_probability"), "must be in [0, 1) (0 disables gating)");
  }
  tr.initialSpeedSdMps = f.numberOr("initial_speed_sd_mps", tr.initialSpeedSdMps, Fields::Check::Positive);
  tr.capacity = static_cast<std::size_t>(f.integerOr("capacity", 1, 1000000, static_cast<int>(tr.capacity)));
  if (const JsonValue* a = f.get("association")) {
    if (a->isString() && a->string == "nearest")
      tr.association = track::Association::Nearest;
    else if (a->isString() && a->string == "known")
      tr.association = track::Association::Known;
    else
      f.fail(
          *a, f.pathOf("association"),
          "must be \"nearest\" (global nearest neighbour) or \"known\" (seed 000: plots carry their target)");
  }
  // {"hits": M, "of_sweeps": N} with integers 1 <= M <= N <= 32.
  const auto mOfN = [&](std::string_view key, int& hits, int& sweeps) {
    const JsonValue* c = f.get(key);
    if (!c) return;
    Fields g(top.file(), *c, f.pathOf(key));
    const double m = g.number("hits", Fields::Check::Positive);
    const double n = g.number("of_sweeps", Fields::Check::Positive);
    if (m != std::floor(m) || n != std::floor(n) || m > n || n > 32)
      g.fail(*c, f.pathOf(key), "needs integers 1 <= hits <= of_sweeps <= 32");
    g.finish();
    hits = static_cast<int>(m);
    sweeps = static_cast<int>(n);
  };
  mOfN("confirm", tr.confirmHits, tr.confirmSweeps);
  mOfN("keep", tr.keepHits, tr.keepSweeps);
  tr.lostHoldS = f.numberOr("lost_hold_s", tr.lostHoldS, Fields::Check::NonNegative);
  if (const JsonValue* a = f.get("auto_acquire")) tr.autoAcquire = f.boolean(*a, f.pathOf("auto_acquire"));
  if (const JsonValue* z = f.get("acquisition_zones")) {
    if (!z->isArray()) f.fail(*z, f.pathOf("acquisition_zones"), "must be an array of zones");
    for (std::size_t i = 0; i < z->array.size(); ++i) {
      Fields g(top.file(), z->array[i], "tracker.acquisition_zones[" + std::to_string(i) + "]");
      track::AcquisitionZone zone;
      zone.minRangeM = nmToMetres(g.numberOr("min_range_nm", 0.0, Fields::Check::NonNegative));
      zone.maxRangeM = nmToMetres(g.number("max_range_nm", Fields::Check::Positive));
      if (zone.maxRangeM <= zone.minRangeM)
        g.fail(*g.get("max_range_nm"), g.pathOf("max_range_nm"), "must exceed min_range_nm");
      zone.fromBearingRad = degToRad(g.numberOr("from_bearing_deg", 0.0));
      zone.toBearingRad = degToRad(g.numberOr("to_bearing_deg", 0.0));
      g.finish();
      tr.zones.push_back(zone);
    }
  }
  tr.dangerCpaM =
      nmToMetres(f.numberOr("danger_cpa_nm", metresToNm(tr.dangerCpaM), Fields::Check::NonNegative));
  tr.dangerTcpaS = 60.0 * f.numberOr("danger_tcpa_min", tr.dangerTcpaS / 60.0, Fields::Check::NonNegative);
  if (const JsonValue* ie = f.get("input_estimation")) {
    Fields g(top.file(), *ie, f.pathOf("input_estimation"));
    const JsonValue& w = g.require("window");
    if (!w.isNumber() || w.number < 1 || w.number > 100 || std::floor(w.number) != w.number)
      g.fail(w, g.pathOf("window"), "must be an integer in [1, 100] (radar updates)");
    tr.inputEstimationWindow = static_cast<int>(w.number);
    if (const JsonValue* p = g.get("false_alarm_probability")) {
      tr.inputEstimationPfa =
          g.checkedNumber(*p, g.pathOf("false_alarm_probability"), Fields::Check::Positive);
      if (!(tr.inputEstimationPfa < 1.0))
        g.fail(*p, g.pathOf("false_alarm_probability"), "must lie in (0, 1)");
    }
    g.finish();
    tr.kind = track::TrackerKind::EkfInputEstimation;  // unless "filter" says otherwise
  }
  if (const JsonValue* k = f.get("filter")) {
    const auto kind = k->isString() ? track::trackerKindFromName(k->string) : std::nullopt;
    if (!kind)
      f.fail(*k, f.pathOf("filter"),
             "must be \"ekf\", \"ekf-ie\" (with input estimation), \"abg\" (alpha-beta-gamma) or \"imm\"");
    tr.kind = *kind;
  }
  if (const JsonValue* ch = f.get("filter_changes")) {
    if (!ch->isArray()) f.fail(*ch, f.pathOf("filter_changes"), "must be an array of {\"t_s\", \"filter\"}");
    for (std::size_t i = 0; i < ch->array.size(); ++i) {
      Fields g(top.file(), ch->array[i], "tracker.filter_changes[" + std::to_string(i) + "]");
      const TimeUs t = timeField(g, "t_s", s.durationUs);
      if (!tr.kindChanges.empty() && t <= tr.kindChanges.back().first)
        g.fail(*g.get("t_s"), g.pathOf("t_s"), "must increase from change to change");
      const JsonValue& k = g.require("filter");
      const auto kind = k.isString() ? track::trackerKindFromName(k.string) : std::nullopt;
      if (!kind) g.fail(k, g.pathOf("filter"), "must be \"ekf\", \"ekf-ie\", \"abg\" or \"imm\"");
      g.finish();
      tr.kindChanges.emplace_back(t, *kind);
    }
  }
  if (const JsonValue* a = f.get("alpha_beta_gamma")) {
    Fields g(top.file(), *a, f.pathOf("alpha_beta_gamma"));
    if (const JsonValue* al = g.get("alpha")) {
      tr.abg.alpha = g.checkedNumber(*al, g.pathOf("alpha"), Fields::Check::Positive);
      if (!(tr.abg.alpha <= 0.6)) g.fail(*al, g.pathOf("alpha"), "must lie in (0, 0.6] (seed 003's bound)");
    }
    if (const JsonValue* es = g.get("expanding_start"))
      tr.abg.expandingStart = g.boolean(*es, g.pathOf("expanding_start"));
    g.finish();
  }
  if (const JsonValue* m = f.get("imm")) {
    Fields g(top.file(), *m, f.pathOf("imm"));
    auto& c = tr.imm;
    c.cvAccelQ = g.numberOr("cv_accel_q", c.cvAccelQ, Fields::Check::Positive);
    c.ctAccelQ = g.numberOr("ct_accel_q", c.ctAccelQ, Fields::Check::Positive);
    c.ctTurnQ = degToRad(
        degToRad(g.numberOr("ct_turn_q_deg2", radToDeg(radToDeg(c.ctTurnQ)), Fields::Check::NonNegative)));
    c.cvSojournS = g.numberOr("cv_sojourn_s", c.cvSojournS, Fields::Check::Positive);
    c.ctSojournS = g.numberOr("ct_sojourn_s", c.ctSojournS, Fields::Check::Positive);
    c.initialTurnSdRadPerS = degToRad(
        g.numberOr("initial_turn_sd_dps", radToDeg(c.initialTurnSdRadPerS), Fields::Check::Positive));
    if (const JsonValue* mp = g.get("manoeuvre_probability")) {
      c.manoeuvreProbability =
          g.checkedNumber(*mp, g.pathOf("manoeuvre_probability"), Fields::Check::Positive);
      if (!(c.manoeuvreProbability < 1.0))
        g.fail(*mp, g.pathOf("manoeuvre_probability"), "must lie in (0, 1)");
    }
    g.finish();
  }
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

}  // namespace

sim::Scenario parseScenario(std::string_view text, const std::string& sourceName) {
  stripByteOrderMark(text);
  JsonValue root;
  try {
    root = parseJson(text);
  } catch (const JsonParseError& e) {
    throw InputError(sourceName, e.line(), "", std::string("malformed JSON: ") + e.what());
  }
  Fields top(sourceName, root, "");
  sim::Scenario s;
  const JsonValue& format = top.require("format");
  if (!format.isString() || format.string != kScenarioFormat)
    top.fail(format, "format", "must be \"" + std::string(kScenarioFormat) + "\"");
  s.name = top.stringOr("name", sourceName);
  s.description = top.stringOr("description", "");
  {
    Fields o(sourceName, top.require("origin"), "origin");
    s.origin.latDeg = o.number("lat_deg");
    s.origin.lonDeg = o.number("lon_deg");
    if (s.origin.latDeg < -80.0 || s.origin.latDeg > 84.0)
      o.fail(*o.get("lat_deg"), "origin.lat_deg",
             "must lie in [-80, 84] (the UTM band), got " + formatNumber(s.origin.latDeg));
    if (s.origin.lonDeg < -180.0 || s.origin.lonDeg > 180.0)
      o.fail(*o.get("lon_deg"), "origin.lon_deg",
             "must lie in [-180, 180], got " + formatNumber(s.origin.lonDeg));
    o.finish();
  }
  const double duration = top.number("duration_s", Fields::Check::Positive);
  if (duration > sim::limits::kMaxDurationS)
    top.fail(*top.get("duration_s"), "duration_s", "must not exceed 30 days, got " + formatNumber(duration));
  s.durationUs = fromSeconds(duration);
  const double step = top.numberOr("step_s", 1.0, Fields::Check::Positive);
  if (step < sim::limits::kStepS.lo || step > sim::limits::kStepS.hi)
    top.fail(*top.get("step_s"), "step_s", "must lie in [0.001, 3600] s, got " + formatNumber(step));
  s.stepUs = fromSeconds(step);
  if (const JsonValue* seed = top.get("seed")) {
    if (!seed->isNumber() || seed->number < 0 || seed->number > 9007199254740992.0 ||
        std::floor(seed->number) != seed->number)
      top.fail(*seed, "seed", "must be a non-negative integer");
    s.seed = static_cast<std::uint64_t>(seed->number);
  }
  {
    Fields c(sourceName, top.require("current"), "current");
    s.current = gaussMarkov(c, "variance_m2_s2", "sigma_mps");
    c.finish();
  }
  readOwnShip(top, s);
  readSensors(top, s);
  readTargets(top, s);
  readFilter(top, s);
  readTracker(top, s);
  readRadarMatching(top, s);
  top.finish();
  if (const std::string problem = sim::checkScenario(s); !problem.empty()) {
    const auto colon = problem.find(": ");
    if (colon == std::string::npos) throw InputError(sourceName, 0, "", problem);
    const std::string field = problem.substr(0, colon);
    throw InputError(sourceName, lineOfPath(root, field), field, problem.substr(colon + 2));
  }
  return s;
}

sim::Scenario loadScenarioFile(const std::string& path) {
  return parseScenario(readTextFile(path), path);
}

}  // namespace reckoner::io

namespace reckoner::io {
namespace {

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
    if (e.mode) w.key("mode").value(sensors::modeName(*e.mode));
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

  w.key("sensors").beginObject();
  if (s.gps.fitted) {
    w.key("gps").beginObject();
    w.key("rate_hz").value(s.gps.rateHz, kExact);
    w.key("position_variance_m2").value(s.gps.positionVarM2, kExact);
    w.key("velocity_variance_m2_s2").value(s.gps.velocityVarM2PerS2, kExact);
    writeSchedule(w, s.gps.power, nullptr);
    w.endObject();
  }
  if (s.loran.fitted) {
    w.key("loran_c").beginObject();
    w.key("rate_hz").value(s.loran.rateHz, kExact);
    w.key("markov_variance_m2").value(s.loran.error.sigma * s.loran.error.sigma, kExact);
    w.key("markov_beta_per_s").value(s.loran.error.betaPerS, kExact);
    w.key("white_variance_m2").value(s.loran.whiteVarM2, kExact);
    writeSchedule(w, s.loran.power, nullptr);
    w.endObject();
  }
  if (s.speedlog.fitted) {
    w.key("speedlog").beginObject();
    w.key("rate_hz").value(s.speedlog.rateHz, kExact);
    w.key("markov_variance_m2_s2").value(s.speedlog.error.sigma * s.speedlog.error.sigma, kExact);
    w.key("markov_beta_per_s").value(s.speedlog.error.betaPerS, kExact);
    w.key("white_variance_m2_s2").value(s.speedlog.whiteVarM2PerS2, kExact);
    if (s.speedlog.scaleError.sigma > 0.0) {
      w.key("scale_error").beginObject();
      w.key("sigma").value(s.speedlog.scaleError.sigma, kExact);
      w.key("beta_per_s").value(s.speedlog.scaleError.betaPerS, kExact);
      w.endObject();
    }
    w.key("mode").value(sensors::modeName(s.speedlog.mode.initial()));
    writeSchedule(w, s.speedlog.power, &s.speedlog.mode);
    w.endObject();
  }
  if (s.gyro.fitted) {
    w.key("gyro").beginObject();
    w.key("rate_hz").value(s.gyro.rateHz, kExact);
    w.key("sd_deg").value(radToDeg(s.gyro.sdRad), kExact);
    if (s.gyro.bias.sigma > 0.0) {
      w.key("bias").beginObject();
      w.key("sigma_deg").value(radToDeg(s.gyro.bias.sigma), kExact);
      w.key("beta_per_s").value(s.gyro.bias.betaPerS, kExact);
      w.endObject();
    }
    writeSchedule(w, s.gyro.power, nullptr);
    w.endObject();
  }
  if (s.radar.fitted) {
    const auto& r = s.radar;
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
  w.endObject();

  if (!s.targets.empty()) {
    w.key("targets").beginArray();
    for (const auto& t : s.targets) {
      w.beginObject();
      w.key("id").value(t.id);
      w.key("name").value(t.name);
      if (t.appearUs > 0) writeTime(w, "appear_s", t.appearUs);
      writeMotion(w, t.motion);
      w.endObject();
    }
    w.endArray();
  }

  const auto& f = s.filter;
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

  const auto& t = s.tracker;
  if (s.radarMatching.active.initial() || !s.radarMatching.active.changes().empty()) {
    const auto& m = s.radarMatching;
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
  w.key("tracker").beginObject();
  w.key("own_acceleration");
  writeGaussMarkov(w, t.ownAcceleration, "sigma_mps2");
  w.key("target_acceleration");
  writeGaussMarkov(w, t.targetAcceleration, "sigma_mps2");
  w.key("own_ship_feed").value(t.feed == track::OwnShipFeed::Marginal ? "marginal" : "measurement");
  w.key("gate_probability").value(t.gateProbability, kExact);
  w.key("initial_speed_sd_mps").value(t.initialSpeedSdMps, kExact);
  w.key("capacity").value(static_cast<std::uint64_t>(t.capacity));
  w.key("association").value(t.association == track::Association::Nearest ? "nearest" : "known");
  w.key("confirm")
      .beginObject()
      .key("hits")
      .value(t.confirmHits)
      .key("of_sweeps")
      .value(t.confirmSweeps)
      .endObject();
  w.key("keep").beginObject().key("hits").value(t.keepHits).key("of_sweeps").value(t.keepSweeps).endObject();
  w.key("lost_hold_s").value(t.lostHoldS, kExact);
  w.key("auto_acquire").value(t.autoAcquire);
  if (!t.zones.empty()) {
    w.key("acquisition_zones").beginArray();
    for (const auto& z : t.zones) {
      w.beginObject();
      w.key("min_range_nm").value(metresToNm(z.minRangeM), kExact);
      w.key("max_range_nm").value(metresToNm(z.maxRangeM), kExact);
      w.key("from_bearing_deg").value(radToDeg(z.fromBearingRad), kExact);
      w.key("to_bearing_deg").value(radToDeg(z.toBearingRad), kExact);
      w.endObject();
    }
    w.endArray();
  }
  w.key("danger_cpa_nm").value(metresToNm(t.dangerCpaM), kExact);
  w.key("danger_tcpa_min").value(t.dangerTcpaS / 60.0, kExact);
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
  w.endObject();
  w.endObject();
  return w.str() + "\n";
}

void saveScenarioFile(const sim::Scenario& s, const std::string& path) {
  const std::string text = writeScenario(s);
  const std::string tmp = path + ".part";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(path, 0, "", std::string("cannot write: ") + std::strerror(errno));
    out << text;
    out.flush();
    if (!out) throw InputError(path, 0, "", std::string("write error: ") + std::strerror(errno));
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(tmp.c_str());
    throw InputError(path, 0, "", "cannot replace the file: " + why);
  }
}

}  // namespace reckoner::io
