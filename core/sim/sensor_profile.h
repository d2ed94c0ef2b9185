#pragma once
// Sensor profiles: the noise and error models of the own-ship sensors, the DRKF's process model and
// the trackers' motion models, as one named set (docs/sensor_profiles.md gives every number with its source).
//   paper      the scenario's own figures, which for every built-in scenario are seed 000's Tables
//              I-III (every reproduction in docs/ uses them; replay: the default scenario's, Table I);
//   imo        the accuracies the IMO performance standards allow (GNSS MSC.112(73), gyrocompass
//              A.424(XI), speed log MSC.96(72), Loran-C A.818(19));
//   realistic  what sensors on real ships do, the default for replaying recorded data: calibration
//              errors constant over a passage, a current that persists for days, a ship that changes
//              its velocity as ships do, targets tracked with an ARPA's long memory and input
//              estimation for their turns.
// A profile sets only noise and error models; which sensors are fitted, their rates and schedules
// stay the scenario's.
#include <optional>
#include <string_view>

#include "sim/scenario.h"

namespace reckoner::sim {

enum class SensorProfile { Paper, Imo, Realistic };

[[nodiscard]] const char* nameOf(SensorProfile p);
/// "paper", "imo" or "realistic"; nullopt for anything else.
[[nodiscard]] std::optional<SensorProfile> sensorProfileFromName(std::string_view name);

/// Sets the scenario's sensor noise and error models, its filter's process model and its trackers'
/// motion models (imo and realistic) to the profile's.
void applySensorProfile(Scenario& s, SensorProfile p);

}  // namespace reckoner::sim
