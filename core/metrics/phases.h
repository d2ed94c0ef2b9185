#pragma once
// Phases of a scenario's outage schedule: maximal intervals with one sensor configuration.
#include <string>
#include <vector>

#include "sim/scenario.h"

namespace reckoner::metrics {

enum class PhaseKind { Gps, LoranC, DeadReckoning };
const char* kindName(PhaseKind k);

struct Phase {
  int index = 0;
  TimeUs startUs = 0;
  TimeUs endUs = 0;
  sim::SensorStates sensors;
  PhaseKind kind = PhaseKind::Gps;  ///< GPS on; else Loran-C on; else dead reckoning
  std::string label;                ///< sim::sensorLabel(sensors)

  bool last = false;  ///< the final phase also holds the scenario's end instant

  /// A row stamped t shows the filter after the epoch at t, taken with the sensors in force at t
  /// (a schedule change at t already applies), so rows belong to [startUs, endUs).
  [[nodiscard]] bool contains(TimeUs t) const { return t >= startUs && (t < endUs || (last && t == endUs)); }
};

std::vector<Phase> derivePhases(const sim::Scenario& s);

}  // namespace reckoner::metrics
