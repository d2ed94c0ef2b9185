#pragma once
// SimulationEngine::step() advances truth, sensors and the DRKF by one output cycle and returns a value
// snapshot (SimFrame). Plain C++: the GUI's worker thread and the headless runs drive it the same way.
#include <array>
#include <optional>
#include <vector>

#include "navigation/drkf.h"
#include "sensors/own_ship_simulators.h"
#include "sim/own_ship_truth.h"
#include "sim/scenario.h"

namespace reckoner::sim {

struct SimFrame {
  TimeUs timeUs = 0;
  OwnShipTruth truth;
  est::drkf::State trueState;  ///< truth in the DRKF's coordinates (incl. sensor error states)
  est::drkf::Belief estimate;
  std::vector<sensors::OwnShipSample> measurements;  ///< taken during this cycle
  std::vector<nav::DrkfUpdateReport> updates;        ///< one per measurement epoch of this cycle
  SensorStates sensors;
};

class SimulationEngine {
 public:
  /// Throws std::invalid_argument when checkScenario() finds a problem.
  SimulationEngine(const Scenario& scenario, std::uint64_t seed);

  /// Advances one output cycle (scenario.stepUs, the last one shortened to end at the duration).
  SimFrame step();
  [[nodiscard]] bool finished() const { return timeUs_ >= scenario_.durationUs; }
  [[nodiscard]] TimeUs timeUs() const { return timeUs_; }
  [[nodiscard]] const Scenario& scenario() const { return scenario_; }
  [[nodiscard]] const geo::LocalFrame& frame() const { return frame_; }
  [[nodiscard]] const nav::Drkf& drkf() const { return *drkf_; }

 private:
  struct Clock {
    bool fitted = false;
    TimeUs periodUs = 0;
    TimeUs nextUs = 0;
  };
  [[nodiscard]] est::drkf::State trueState() const;
  const geo::GridInfo& truthGrid();

  Scenario scenario_;
  geo::LocalFrame frame_;
  OwnShipTruthModel truth_;
  sensors::GpsSimulator gps_;
  sensors::LoranSimulator loran_;
  sensors::SpeedlogSimulator speedlog_;
  sensors::GyroSimulator gyro_;
  std::array<Clock, sensors::kOwnShipSensorCount> clocks_{};
  std::optional<nav::Drkf> drkf_;
  TimeUs timeUs_ = 0;
  TimeUs gridTimeUs_ = -1;
  geo::GridInfo grid_;
};

/// The DRKF configuration a scenario implies (the filter is tuned with the sensors' specifications).
nav::DrkfConfig drkfConfigFor(const Scenario& s);

}  // namespace reckoner::sim
