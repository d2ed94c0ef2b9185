// Scenario files: the reader (format: docs/scenarios.md); the tracker, radar-matching and filter
// sections are in scenario_read_tracking.cpp, the writer in scenario_write.cpp.
#include "files/scenario_fields.h"
#include "files/scenario_json.h"

#include <algorithm>
#include <array>
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
namespace scenario_detail {

namespace {

// One reader per sensor: f is the sensor's object (the caller finishes f).

void readGps(Fields& f, sim::Scenario& s) {
  s.gps.fitted = true;
  s.gps.rateHz = f.numberOr("rate_hz", 1.0, Fields::Check::Positive);
  s.gps.positionVarM2 = f.number("position_variance_m2", Fields::Check::Positive);
  s.gps.velocityVarM2PerS2 = f.number("velocity_variance_m2_s2", Fields::Check::Positive);
  readPowerSchedule(f, s.gps.power, s.durationUs);
}

void readLoran(Fields& f, sim::Scenario& s) {
  s.loran.fitted = true;
  s.loran.rateHz = f.numberOr("rate_hz", 1.0, Fields::Check::Positive);
  const double var = f.number("markov_variance_m2", Fields::Check::NonNegative);
  s.loran.error = {std::sqrt(var), f.number("markov_beta_per_s", Fields::Check::Positive)};
  s.loran.whiteVarM2 = f.number("white_variance_m2", Fields::Check::Positive);
  readPowerSchedule(f, s.loran.power, s.durationUs);
}

void readSpeedlog(Fields& f, sim::Scenario& s) {
  s.speedlog.fitted = true;
  s.speedlog.rateHz = f.numberOr("rate_hz", 1.0, Fields::Check::Positive);
  const double var = f.number("markov_variance_m2_s2", Fields::Check::NonNegative);
  s.speedlog.error = {std::sqrt(var), f.number("markov_beta_per_s", Fields::Check::Positive)};
  s.speedlog.whiteVarM2PerS2 = f.number("white_variance_m2_s2", Fields::Check::Positive);
  if (const JsonValue* k = f.get("scale_error")) {  // not in the paper: none
    Fields g(f.file(), *k, f.pathOf("scale_error"));
    s.speedlog.scaleError = {g.number("sigma", Fields::Check::NonNegative),
                             g.number("beta_per_s", Fields::Check::Positive)};
    g.finish();
  }
  SpeedlogMode initial = SpeedlogMode::GroundLock;
  if (const JsonValue* m = f.get("mode")) initial = speedlogMode(f, *m, f.pathOf("mode"));
  s.speedlog.mode = StepSchedule<SpeedlogMode>(initial);
  readPowerSchedule(f, s.speedlog.power, s.durationUs, [&](Fields& e, TimeUs t) {
    s.speedlog.mode.addChange(t, speedlogMode(e, *e.get("mode"), e.pathOf("mode")));
  });
}

void readGyro(Fields& f, sim::Scenario& s) {
  s.gyro.fitted = true;
  s.gyro.rateHz = f.numberOr("rate_hz", 1.0, Fields::Check::Positive);
  s.gyro.sdRad = degToRad(f.number("sd_deg", Fields::Check::Positive));
  if (const JsonValue* b = f.get("bias")) {  // not in the paper: none
    Fields g(f.file(), *b, f.pathOf("bias"));
    // Their limits are checkScenario's (sim/scenario_limits.h), as every other field's.
    s.gyro.bias = {degToRad(g.number("sigma_deg", Fields::Check::NonNegative)),
                   g.number("beta_per_s", Fields::Check::Positive)};
    g.finish();
  }
  readPowerSchedule(f, s.gyro.power, s.durationUs);
}

/// Whether the radar's "error_budget" asks for IMO A.823(19)'s sensor errors (the only budget known).
bool a823ErrorBudget(Fields& f) {
  const JsonValue* budget = f.get("error_budget");
  if (!budget) return false;
  if (!budget->isString() || budget->string != "a823")
    f.fail(*budget, f.pathOf("error_budget"), "must be \"a823\" (IMO A.823(19) sensor errors)");
  return true;
}

/// IMO A.823(19)'s radar and gyro errors: the defaults of the fields that follow.
void setA823Errors(sensors::RadarSpec& r) {
  r.rangeSdM = 20.0;                                  // pulse shape
  r.bearingSdRad = degToRad(std::hypot(0.05, 0.03));  // beam shape and encoder
  r.bearingBacklashRad = degToRad(0.05);
  r.rangeQuantumM = nmToMetres(0.02);   // +-0.01 NM
  r.bearingQuantumRad = degToRad(0.2);  // +-0.1 deg
  r.gyroCalibrationRad = degToRad(0.5);
  r.gyroScatterSdRad = degToRad(0.12);
}

/// The radar's measurement errors (with the A.823 budget every one has a default).
void readRadarErrors(Fields& f, sensors::RadarSpec& r, bool a823) {
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
}

/// The radar's coverage: ranges, detection probability and clutter.
void readRadarCoverage(Fields& f, sensors::RadarSpec& r) {
  const auto P = Fields::Check::Positive;
  const auto NN = Fields::Check::NonNegative;
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
}

void readRadar(Fields& f, sim::Scenario& s) {
  auto& r = s.radar;
  r.fitted = true;
  r.sweepPeriodS = f.numberOr("sweep_period_s", r.sweepPeriodS, Fields::Check::Positive);
  const bool a823 = a823ErrorBudget(f);
  if (a823) setA823Errors(r);
  readRadarErrors(f, r, a823);
  readRadarCoverage(f, r);
  readPowerSchedule(f, r.power, s.durationUs);
}

/// The sensors a scenario may fit, in the order they are read, each with its reader.
struct SensorSection {
  std::string_view key;
  void (*read)(Fields&, sim::Scenario&);
};
constexpr std::array<SensorSection, 5> kSensorSections{{
    {"gps", readGps},
    {"loran_c", readLoran},
    {"speedlog", readSpeedlog},
    {"gyro", readGyro},
    {"radar", readRadar},
}};

bool isSensorKey(std::string_view key) {
  return std::any_of(kSensorSections.begin(), kSensorSections.end(),
                     [key](const SensorSection& section) { return section.key == key; });
}

/// "gps, loran_c, speedlog, gyro, radar".
std::string sensorKeys() {
  std::string keys;
  for (const SensorSection& section : kSensorSections) {
    if (!keys.empty()) keys += ", ";
    keys += section.key;
  }
  return keys;
}

}  // namespace

void readSensors(Fields& top, sim::Scenario& s) {
  const JsonValue& sensorsJson = top.require("sensors");
  Fields sensorsF(top.file(), sensorsJson, "sensors");
  s.gps.fitted = s.loran.fitted = s.speedlog.fitted = s.gyro.fitted = false;
  for (const SensorSection& section : kSensorSections) {
    if (const JsonValue* v = sensorsF.get(section.key)) {
      Fields f(top.file(), *v, sensorsF.pathOf(section.key));
      section.read(f, s);
      f.finish();
    }
  }
  for (const auto& [key, value] : sensorsJson.object) {
    if (!isSensorKey(key))
      sensorsF.fail(value, "sensors." + key,
                    "unknown sensor " + io::quoted(key) + " (known: " + sensorKeys() + ")");
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
    if (const auto* leave = f.get("leave_s")) {
      t.leaveUs = timeField(f, "leave_s", s.durationUs);
      if (*t.leaveUs <= t.appearUs) f.fail(*leave, f.pathOf("leave_s"), "must be after appear_s");
    }
    readMotion(f, t.motion, s.durationUs);
    readTargetAis(f, t);
    f.finish();
    s.targets.push_back(std::move(t));
  }
}

}  // namespace scenario_detail

using namespace scenario_detail;

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
  scenario_detail::readVoyage(top, s);
  top.finish();
  if (const std::string problem = sim::checkScenarioForRows(s); !problem.empty()) {
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

}  // namespace reckoner::files
