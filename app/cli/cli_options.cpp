#include "cli/cli_options.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <system_error>
#include <thread>

#include "files/scenario_json.h"
#include "io/error_line.h"
#include "resources/embedded.h"

namespace reckoner::cli {

std::uint64_t parseCount(const std::string& option, const std::string& text, std::uint64_t min,
                         std::uint64_t max) {
  std::size_t used = 0;
  unsigned long long v = 0;
  try {
    if (text.empty() || text[0] == '-') throw std::invalid_argument("negative");
    v = std::stoull(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || used == 0 || v < min || v > max)
    throw UsageError("--" + option + ": expected an integer in [" + std::to_string(min) + ", " +
                     std::to_string(max) + "], got " + io::quoted(text));
  return v;
}

double parseReal(const std::string& option, const std::string& text, double min, double max) {
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || used == 0 || !std::isfinite(v) || v < min || v > max)
    throw UsageError("--" + option + ": expected a number in [" + std::to_string(min) + ", " +
                     std::to_string(max) + "], got " + io::quoted(text));
  return v;
}

std::pair<double, double> parsePair(const std::string& option, const std::string& text, char sep) {
  const auto at = text.find(sep);
  try {
    if (at == std::string::npos) throw std::invalid_argument("no separator");
    std::size_t u1 = 0, u2 = 0;
    const double a = std::stod(text.substr(0, at), &u1), b = std::stod(text.substr(at + 1), &u2);
    if (u1 != at || u2 != text.size() - at - 1 || !std::isfinite(a) || !std::isfinite(b))
      throw std::invalid_argument("trailing");
    return {a, b};
  } catch (const std::exception&) {
    throw UsageError("--" + option + ": expected two numbers separated by '" + std::string(1, sep) +
                     "', got " + io::quoted(text));
  }
}

std::string choiceList(const std::vector<std::string>& choices) {
  std::string s;
  for (std::size_t i = 0; i < choices.size(); ++i)
    s += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
  return s;
}

CLI::Option* addValue(CLI::App& app, const std::string& name, const std::string& meta,
                      const std::string& help, const std::function<void(const std::string&)>& set) {
  return app.add_option_function<std::string>("--" + name, set, help)->type_name(meta);
}

CLI::Option* addFlag(CLI::App& app, const std::string& name, bool& target, const std::string& help) {
  return app.add_flag("--" + name, target, help);
}

CLI::Option* addText(CLI::App& app, const std::string& name, std::optional<std::string>& target,
                     const std::string& meta, const std::string& help) {
  return addValue(app, name, meta, help, [&target](const std::string& t) { target = t; });
}

CLI::Option* addChoice(CLI::App& app, const std::string& name, const std::vector<std::string>& choices,
                       std::string& target, const std::string& help) {
  std::string meta;
  for (const auto& c : choices) meta += (meta.empty() ? "" : "|") + c;
  const std::string shown = help + (target.empty() ? "" : " (default " + target + ")");
  return addValue(app, name, meta, shown, [&target, name, choices](const std::string& t) {
    if (std::find(choices.begin(), choices.end(), t) == choices.end())
      throw UsageError("--" + name + ": expected " + choiceList(choices) + ", got " + io::quoted(t));
    target = t;
  });
}

std::string rangeText(std::uint64_t min, std::uint64_t max, const std::string& def) {
  const std::string top =
      max == std::numeric_limits<std::uint64_t>::max() ? std::string("2^64-1") : std::to_string(max);
  return " (" + std::to_string(min) + " to " + top + (def.empty() ? "" : ", default " + def) + ")";
}

std::string numberText(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string rangeText(double min, double max, const std::string& def) {
  return " (" + numberText(min) + " to " + numberText(max) + (def.empty() ? "" : ", default " + def) + ")";
}

void addOutputOptions(CLI::App& app, OutputArgs& o, Summary summary, const std::string& files) {
  addText(app, "out", o.out, "DIR", "folder for the files (" + files + "); required, created if missing");
  addFlag(app, "quiet", o.quiet, "no table on stdout (the files are still written)");
  if (summary == Summary::Json)
    addFlag(app, "json", o.json, "summary.json's text on stdout instead of the table");
}

void addIgnoredQuiet(CLI::App& app) {
  // Hidden (empty group): the old parser accepted --quiet everywhere, so it is still accepted here.
  app.add_flag("--quiet")
      ->description("accepted, without effect: the table is this command's only output")
      ->group("");
}

std::string prepareOutDir(const OutputArgs& o) {
  if (!o.out) throw UsageError("--out DIR is required");
  std::error_code ec;
  std::filesystem::create_directories(*o.out, ec);
  if (ec || !std::filesystem::is_directory(*o.out))
    throw UsageError("--out " + *o.out + ": cannot create directory" + (ec ? ": " + ec.message() : ""));
  return *o.out;
}

void printSummary(const OutputArgs& o, const std::string& json) {
  if (!o.json || o.quiet) return;
  std::fputs(json.c_str(), stdout);
  if (json.empty() || json.back() != '\n') std::fputc('\n', stdout);
}

int hardwareThreads() {
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

int MonteCarloArgs::threadCount() const {
  return threads.value_or(hardwareThreads());
}

CLI::Option* addSeed(CLI::App& app, std::optional<std::uint64_t>& seed, const std::string& seedHelp) {
  return addInteger(app, "seed", seed, 0, std::numeric_limits<std::uint64_t>::max(), "N",
                    "first run's random seed", seedHelp);
}

CLI::Option* addThreads(CLI::App& app, std::optional<int>& threads, int maxThreads) {
  return addInteger(app, "threads", threads, 1, static_cast<std::uint64_t>(maxThreads), "K", "worker threads",
                    "the machine's hardware threads");
}

void addMonteCarloOptions(CLI::App& app, MonteCarloArgs& a, int maxRuns, int maxThreads,
                          const std::string& seedHelp) {
  addInteger(app, "runs", a.runs, 1, static_cast<std::uint64_t>(maxRuns), "N", "Monte Carlo runs");
  addThreads(app, a.threads, maxThreads);
  addSeed(app, a.seed, seedHelp);
}

CLI::Option* addProfile(CLI::App& app, std::string& profile, const std::string& help) {
  return addChoice(app, "profile", {"paper", "imo", "realistic"}, profile, help);
}

std::optional<sim::SensorProfile> profileOf(const std::string& name) {
  if (name.empty()) return std::nullopt;
  return sim::sensorProfileFromName(name);
}

CLI::Option* addScenarioArgument(CLI::App& app, std::string& spec) {
  return app.add_option("SCENARIO", spec, "a scenario: a JSON file (docs/scenarios.md) or builtin:NAME")
      ->type_name("")
      ->expected(1);
}

CLI::Option* addListArgument(CLI::App& app, const std::string& name, std::vector<std::string>& list, int min,
                             const std::string& help) {
  return app.add_option(name, list, help)
      ->type_name("")
      ->expected(min, CLI::detail::expected_max_vector_size);
}

sim::Scenario loadScenario(const std::string& spec) {
  if (spec.rfind("builtin:", 0) == 0) {
    const std::string name = spec.substr(8);
    const auto* f = resources::findScenario(name);
    if (!f)
      throw UsageError("unknown built-in scenario " + io::quoted(name) + " (see `reckoner-cli scenarios`)");
    return files::parseScenario(f->text, spec);
  }
  return files::loadScenarioFile(spec);
}

sim::Scenario loadProfiled(const std::string& spec, const std::string& profile) {
  sim::Scenario s = loadScenario(spec);
  if (const auto p = profileOf(profile)) sim::applySensorProfile(s, *p);
  return s;
}

}  // namespace reckoner::cli
