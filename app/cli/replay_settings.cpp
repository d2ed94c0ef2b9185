#include "cli/replay_settings.h"

#include <array>

#include "cli/cli_options.h"
#include "io/error_line.h"
#include "io/iso8601.h"

namespace reckoner::cli {
namespace {

/// --date YYYY-MM-DD as {year, month, day}.
std::array<int, 3> parseDate(const std::string& date) {
  const auto day = io::parseIso8601(date + "T00:00:00Z");
  if (!day || date.size() != 10) throw UsageError("--date: expected YYYY-MM-DD, got " + io::quoted(date));
  return {std::stoi(date.substr(0, 4)), std::stoi(date.substr(5, 2)), std::stoi(date.substr(8, 2))};
}

}  // namespace

void addReplaySettings(CLI::App& app, ReplaySettings& s) {
  addText(app, "config", s.config, "SCENARIO",
          "settings (sensors, filter, radar, origin) from this scenario; default builtin:default with the "
          "realistic profile");
  addFlag(app, "assume-association", s.assumeAssociation,
          "associate plots to tracks by the plots' target_id (else nearest neighbour)");
  addReal(app, "max-gap", s.maxGapS, 1.0, 1e7, "S",
          "no data for longer than this restarts the DRKF, seconds");
  addText(app, "date", s.date, "YYYY-MM-DD", "the day, for sentences without dates");
  addReal(app, "variation", s.variationDeg, -180.0, 180.0, "DEG",
          "magnetic variation, degrees east positive, when the sentences give none");
  addProfile(app, s.profile, "sensor profile (default realistic, or the --config scenario's own figures)");
  addChoice(app, "adaptive-gnss", {"on", "off"}, s.adaptiveGnss,
            "scale the receiver's position noise by a variational-Bayes estimate (default: the settings')");
}

bool anyGiven(const ReplaySettings& s) {
  return s.config || s.assumeAssociation || s.maxGapS != sim::ReplayOptions{}.maxGapS || s.variationDeg ||
         s.date || !s.profile.empty() || !s.adaptiveGnss.empty();
}

sim::ReplayOptions replayOptions(const ReplaySettings& a) {
  sim::ReplayOptions o;
  const auto profile = profileOf(a.profile);
  if (a.config) {
    o.settings = loadScenario(*a.config);
    o.settingsName = *a.config;
    o.originFromSettings = true;
    if (profile) sim::applySensorProfile(o.settings, *profile);
    sim::assumeRadar(o.settings);
  } else {
    o = sim::recordedDataOptions(loadScenario("builtin:default"),
                                 profile.value_or(sim::SensorProfile::Realistic));
  }
  o.assumeAssociation = a.assumeAssociation;
  if (!a.adaptiveGnss.empty()) o.settings.filter.adaptiveGnssNoise = a.adaptiveGnss == "on";
  o.maxGapS = a.maxGapS;
  if (a.variationDeg) o.variationDeg = *a.variationDeg;
  if (a.date) o.date = parseDate(*a.date);
  return o;
}

}  // namespace reckoner::cli
