#pragma once
// Scenario files (format: docs/scenarios.md). Every problem is reported as one io::InputError naming
// the file, line and field; unknown fields and unknown sensors are errors, not silently ignored.
#include <string>
#include <string_view>

#include "io/input_error.h"
#include "io/text_file.h"
#include "sim/scenario.h"

namespace reckoner::files {

inline constexpr std::string_view kScenarioFormat = "reckoner-scenario/1";

/// Parses scenario JSON text; sourceName is used in error messages. Throws io::InputError.
sim::Scenario parseScenario(std::string_view text, const std::string& sourceName);

/// Reads and parses a scenario file. Throws io::InputError (also for a missing or unreadable file).
sim::Scenario loadScenarioFile(const std::string& path);

/// The scenario as JSON text in the same format, every value written so that parseScenario() gives it
/// back (times to the microsecond, numbers with 17 significant digits).
std::string writeScenario(const sim::Scenario& s);

/// Writes writeScenario(s) to path (through a temporary file, so a failed write leaves the old file).
/// Throws io::InputError naming the file.
void saveScenarioFile(const sim::Scenario& s, const std::string& path);

}  // namespace reckoner::files
