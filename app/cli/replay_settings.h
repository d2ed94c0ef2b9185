#pragma once
// The settings replay and live share: where the sensors' noise, the filter and the tracker come from
// (--config, --profile), the recording's quirks (--date, --variation) and the engine's choices
// (--max-gap, --adaptive-gnss, --assume-association).
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "sim/replay.h"

namespace reckoner::cli {

struct ReplaySettings {
  std::optional<std::string> config;
  bool assumeAssociation = false;
  double maxGapS = sim::ReplayOptions{}.maxGapS;
  std::optional<double> variationDeg;
  std::optional<std::string> date;
  std::string profile;
  std::string adaptiveGnss;
};

void addReplaySettings(CLI::App& app, ReplaySettings& s);
/// True when any of the settings was given on the command line (--max-gap only when not its default).
bool anyGiven(const ReplaySettings& s);
/// The engine's options; throws UsageError for a bad --date, InputError for a bad --config file.
sim::ReplayOptions replayOptions(const ReplaySettings& s);

}  // namespace reckoner::cli
