#include "sim/scenario.h"

#include <cmath>
#include <string_view>

namespace reckoner::sim {
namespace {
bool positive(double v) {
  return std::isfinite(v) && v > 0.0;
}
bool nonNegative(double v) {
  return std::isfinite(v) && v >= 0.0;
}

std::string checkMotion(const VesselMotionSpec& m) {
  if (!nonNegative(m.maxTurnRateRadPerS)) return "max_turn_rate_dps: must be >= 0";
  for (const auto& e : m.schedule) {
    if (e.order && (e.setVelocityMps || e.turnRateRadPerS))
      return "schedule: an order cannot be combined with velocity_mps or turn_rate_dps";
    if (e.order && (!std::isfinite(e.order->headingRad) || !nonNegative(e.order->speedMps) ||
                    !nonNegative(e.order->turnRateRadPerS) || !nonNegative(e.order->accelerationMps2)))
      return "schedule: order needs a finite heading, a speed >= 0 and rates >= 0";
  }
  return {};
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
  if (!(s.durationUs > 0)) return "duration_s: must be positive";
  if (!(s.stepUs > 0)) return "step_s: must be positive";
  if (!std::isfinite(s.origin.latDeg) || s.origin.latDeg < -80.0 || s.origin.latDeg > 84.0)
    return "origin.lat_deg: must lie in [-80, 84] (UTM band)";
  if (!std::isfinite(s.origin.lonDeg) || s.origin.lonDeg < -180.0 || s.origin.lonDeg > 180.0)
    return "origin.lon_deg: must lie in [-180, 180]";
  if (!s.current.valid()) return "current: sigma must be >= 0 and beta > 0";
  if (!nonNegative(s.ownShip.maxAccelerationMps2)) return "own_ship.max_acceleration_mps2: must be >= 0";
  if (s.ownShip.randomAcceleration && !s.ownShip.randomAcceleration->valid())
    return "own_ship.random_acceleration: sigma must be >= 0 and beta > 0";
  for (std::size_t i = 1; i < s.ownShip.schedule.size(); ++i)
    if (s.ownShip.schedule[i].timeUs <= s.ownShip.schedule[i - 1].timeUs)
      return "own_ship.schedule: times must increase";
  if (std::string p = checkMotion(s.ownShip); !p.empty()) return "own_ship." + p;
  if (s.gps.fitted &&
      (!positive(s.gps.rateHz) || !positive(s.gps.positionVarM2) || !positive(s.gps.velocityVarM2PerS2)))
    return "sensors.gps: rate and variances must be positive";
  if (s.loran.fitted &&
      (!positive(s.loran.rateHz) || !s.loran.error.valid() || !positive(s.loran.whiteVarM2)))
    return "sensors.loran_c: rate and white variance must be positive, Markov sigma >= 0 and beta > 0";
  if (s.speedlog.fitted &&
      (!positive(s.speedlog.rateHz) || !s.speedlog.error.valid() || !positive(s.speedlog.whiteVarM2PerS2)))
    return "sensors.speedlog: rate and white variance must be positive, Markov sigma >= 0 and beta > 0";
  if (s.gyro.fitted && (!positive(s.gyro.rateHz) || !positive(s.gyro.sdRad)))
    return "sensors.gyro: rate and sd must be positive";
  if (s.radar.fitted)
    if (const std::string problem = s.radar.check(); !problem.empty()) return "sensors.radar: " + problem;
  for (std::size_t i = 0; i < s.targets.size(); ++i) {
    const auto& t = s.targets[i];
    if (t.id < 0) return "targets: ids must be >= 0";
    for (std::size_t j = 0; j < i; ++j)
      if (s.targets[j].id == t.id) return "targets: id " + std::to_string(t.id) + " used twice";
    if (!nonNegative(t.motion.maxAccelerationMps2)) return "targets: max_acceleration_mps2 must be >= 0";
    if (t.appearUs < 0) return "targets: appear_s must be >= 0";
    if (std::string p = checkMotion(t.motion); !p.empty()) return "targets: " + p;
    if (t.motion.randomAcceleration && !t.motion.randomAcceleration->valid())
      return "targets: random_acceleration sigma must be >= 0 and beta > 0";
    for (std::size_t k = 1; k < t.motion.schedule.size(); ++k)
      if (t.motion.schedule[k].timeUs <= t.motion.schedule[k - 1].timeUs)
        return "targets: schedule times must increase";
  }
  const TrackerSpec& tr = s.tracker;
  if (!tr.ownAcceleration.valid() || !tr.targetAcceleration.valid())
    return "tracker: accelerations need sigma >= 0 and beta > 0";
  if (!(tr.gateProbability >= 0.0 && tr.gateProbability < 1.0))
    return "tracker.gate_probability: must be in [0, 1)";
  if (!positive(tr.initialSpeedSdMps)) return "tracker.initial_speed_sd_mps: must be positive";
  if (const std::string problem = trackManagerConfigFor(tr, s.radar.sweepPeriodS).check(); !problem.empty())
    return "tracker: " + problem;
  const FilterSpec& f = s.filter;
  if (!f.acceleration.valid()) return "filter.acceleration: sigma must be >= 0 and beta > 0";
  if (f.current && !f.current->valid()) return "filter.current: sigma must be >= 0 and beta > 0";
  if (!positive(f.initialPositionSdM)) return "filter.initial_position_sd_m: must be positive";
  if (!positive(f.initialVelocitySdMps)) return "filter.initial_velocity_sd_mps: must be positive";
  if (!(f.gateProbability >= 0.0 && f.gateProbability < 1.0))
    return "filter.gate_probability: must be in [0, 1)";
  if (!nonNegative(f.gateReopenS)) return "filter.gate_reopen_s: must be >= 0";
  if (!nonNegative(f.minSpeedMps)) return "filter.min_speed_mps: must be >= 0";
  return {};
}

}  // namespace reckoner::sim
