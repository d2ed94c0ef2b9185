#include "sim/simulation_engine.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace reckoner::sim {
namespace {
using namespace est::drkf;
using sensors::SensorId;

TimeUs periodOf(double rateHz) {
  return std::max<TimeUs>(1, fromSeconds(1.0 / rateHz));
}

const Scenario& checked(const Scenario& s) {
  if (const std::string problem = checkScenario(s); !problem.empty())
    throw std::invalid_argument("scenario '" + s.name + "': " + problem);
  return s;
}
}  // namespace

nav::DrkfConfig drkfConfigFor(const Scenario& s) {
  nav::DrkfConfig c;
  c.process.current = s.filter.current.value_or(s.current);
  c.process.acceleration = s.filter.acceleration;
  c.process.loranError = s.loran.error;
  c.process.speedlogError = s.speedlog.error;
  c.gateProbability = s.filter.gateProbability;
  c.gateReopenS = s.filter.gateReopenS;
  c.minSpeedMps = s.filter.minSpeedMps;
  return c;
}

SimulationEngine::SimulationEngine(const Scenario& scenario, std::uint64_t seed)
    : scenario_(checked(scenario)),
      frame_(scenario.origin.latDeg, scenario.origin.lonDeg),
      truth_(scenario.ownShip, scenario.current, Rng(seed, kStreamTruth)),
      gps_(scenario.gps, Rng(seed, kStreamGps)),
      loran_(scenario.loran, Rng(seed, kStreamLoran), 0),
      speedlog_(scenario.speedlog, Rng(seed, kStreamSpeedlog), 0),
      gyro_(scenario.gyro, Rng(seed, kStreamGyro)) {
  const std::array<std::pair<bool, double>, sensors::kOwnShipSensorCount> rates{
      {{scenario.gps.fitted, scenario.gps.rateHz},
       {scenario.loran.fitted, scenario.loran.rateHz},
       {scenario.speedlog.fitted, scenario.speedlog.rateHz},
       {scenario.gyro.fitted, scenario.gyro.rateHz}}};
  for (std::size_t i = 0; i < clocks_.size(); ++i) {
    if (!rates[i].first) continue;
    clocks_[i] = {true, periodOf(rates[i].second), periodOf(rates[i].second)};
  }
  // The filter starts from the truth perturbed by a draw from its own initial covariance.
  const nav::DrkfConfig config = drkfConfigFor(scenario);
  Belief initial;
  initial.P = nav::initialCovariance(config.process, scenario.filter.initialPositionSdM,
                                     scenario.filter.initialVelocitySdMps);
  Rng initRng(seed, kStreamFilterInit);
  initial.x = trueState();
  for (int i = 0; i < kStateDim; ++i) initial.x[i] += initRng.normal(0.0, std::sqrt(initial.P(i, i)));
  drkf_.emplace(config, frame_, initial, 0);
}

const geo::GridInfo& SimulationEngine::truthGrid() {
  if (gridTimeUs_ != truth_.state().timeUs) {
    grid_ = frame_.gridInfo(truth_.state().position);
    gridTimeUs_ = truth_.state().timeUs;
  }
  return grid_;
}

State SimulationEngine::trueState() const {
  const OwnShipTruth& t = truth_.state();
  State x;
  x[kPosX] = t.position.xM;
  x[kCurX] = t.currentXMps;
  x[kVelX] = t.waterVxMps;
  x[kAccX] = t.accelXMps2;
  x[kPosY] = t.position.yM;
  x[kCurY] = t.currentYMps;
  x[kVelY] = t.waterVyMps;
  x[kAccY] = t.accelYMps2;
  x[kLoranX] = loran_.errorXM();
  x[kLoranY] = loran_.errorYM();
  x[kLogBias] = speedlog_.errorMps();
  return x;
}

SimFrame SimulationEngine::step() {
  SimFrame frame;
  if (finished()) return frame;
  const TimeUs end = std::min(timeUs_ + scenario_.stepUs, scenario_.durationUs);

  // Sensor samples due in (timeUs_, end], in time order (ties in SensorId order).
  while (true) {
    std::size_t next = clocks_.size();
    for (std::size_t i = 0; i < clocks_.size(); ++i) {
      if (clocks_[i].fitted && clocks_[i].nextUs <= end &&
          (next == clocks_.size() || clocks_[i].nextUs < clocks_[next].nextUs))
        next = i;
    }
    if (next == clocks_.size()) break;
    const TimeUs t = clocks_[next].nextUs;
    clocks_[next].nextUs += clocks_[next].periodUs;
    truth_.advanceTo(t);
    const OwnShipTruth& tr = truth_.state();
    const auto id = static_cast<SensorId>(next);
    loran_.advanceTo(t);
    speedlog_.advanceTo(t);
    if (!sensorStatesAt(scenario_, t).isOn(id)) continue;
    switch (id) {
      case SensorId::Gps:
        frame.measurements.emplace_back(
            gps_.measure(t, tr.position, tr.groundVxMps(), tr.groundVyMps(), truthGrid()));
        break;
      case SensorId::LoranC:
        frame.measurements.emplace_back(loran_.measure(t, tr.position));
        break;
      case SensorId::Speedlog:
        frame.measurements.emplace_back(speedlog_.measure(t, std::hypot(tr.groundVxMps(), tr.groundVyMps()),
                                                          std::hypot(tr.waterVxMps, tr.waterVyMps),
                                                          truthGrid()));
        break;
      case SensorId::Gyro:
        frame.measurements.emplace_back(gyro_.measure(t, tr.headingRad, truthGrid()));
        break;
    }
  }

  // The filter: one update per measurement epoch, then prediction to the cycle's end.
  const auto& m = frame.measurements;
  for (std::size_t i = 0; i < m.size();) {
    std::size_t j = i;
    while (j < m.size() && sensors::timeOf(m[j]) == sensors::timeOf(m[i])) ++j;
    frame.updates.push_back(drkf_->update(sensors::timeOf(m[i]), std::span(m).subspan(i, j - i)));
    i = j;
  }
  truth_.advanceTo(end);
  loran_.advanceTo(end);
  speedlog_.advanceTo(end);
  drkf_->predictTo(end);
  timeUs_ = end;

  frame.timeUs = end;
  frame.truth = truth_.state();
  frame.trueState = trueState();
  frame.estimate = drkf_->belief();
  frame.sensors = sensorStatesAt(scenario_, end);
  return frame;
}

}  // namespace reckoner::sim
