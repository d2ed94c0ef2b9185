#pragma once
// What every reckoner-cli command shares: the usage error (exit code 2, one line), the parsers of option
// values with the messages users see, CLI11 option adders that say each option's unit, range and
// default in --help, the output options (--out DIR, --quiet, --json) and scenario loading.
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "sim/scenario.h"
#include "sim/sensor_profile.h"

namespace reckoner::cli {

/// Bad input or usage: one line on stderr, exit code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// ---- values ------------------------------------------------------------------------------------
/// A decimal integer in [min, max], all of text; else UsageError "--OPTION: expected an integer ...".
std::uint64_t parseCount(const std::string& option, const std::string& text, std::uint64_t min,
                         std::uint64_t max);
/// A finite number in [min, max], all of text; else UsageError "--OPTION: expected a number ...".
double parseReal(const std::string& option, const std::string& text, double min, double max);
/// Two finite numbers separated by sep ("47.2,-122.4", "800x600").
std::pair<double, double> parsePair(const std::string& option, const std::string& text, char sep);
/// "a, b or c".
std::string choiceList(const std::vector<std::string>& choices);

// ---- options (names without the dashes; `meta` is the value's name in --help, its unit) ----------
/// --NAME META: text handed to set, which throws UsageError when the value is bad.
CLI::Option* addValue(CLI::App& app, const std::string& name, const std::string& meta,
                      const std::string& help, const std::function<void(const std::string&)>& set);
/// --NAME: a flag.
CLI::Option* addFlag(CLI::App& app, const std::string& name, bool& target, const std::string& help);
/// --NAME META: any text (a file, a folder, a scenario).
CLI::Option* addText(CLI::App& app, const std::string& name, std::optional<std::string>& target,
                     const std::string& meta, const std::string& help);
/// --NAME a|b|c: one of the choices; help shows the default when target holds one.
CLI::Option* addChoice(CLI::App& app, const std::string& name, const std::vector<std::string>& choices,
                       std::string& target, const std::string& help);

/// " (MIN to MAX)" or " (MIN to MAX, default D)", as --help shows a range.
std::string rangeText(std::uint64_t min, std::uint64_t max, const std::string& def);
std::string rangeText(double min, double max, const std::string& def);
std::string numberText(double v);  ///< %g

namespace detail {
template <class T>
struct Held {
  using type = T;
  static std::string text(const T& v) {
    if constexpr (std::is_floating_point_v<T>)
      return numberText(v);
    else
      return std::to_string(v);
  }
};
template <class T>
struct Held<std::optional<T>> {
  using type = T;
  static std::string text(const std::optional<T>& v) { return v ? Held<T>::text(*v) : std::string(); }
};
}  // namespace detail

/// --NAME META: an integer in [min, max] into target (int, std::uint64_t or an optional of one). The
/// default --help shows: def, else the value target holds.
template <class T>
CLI::Option* addInteger(CLI::App& app, const std::string& name, T& target, std::uint64_t min,
                        std::uint64_t max, const std::string& meta, const std::string& help,
                        const std::string& def = {}) {
  using V = typename detail::Held<T>::type;
  const std::string shown = def.empty() ? detail::Held<T>::text(target) : def;
  return addValue(
      app, name, meta, help + rangeText(min, max, shown),
      [&target, name, min, max](const auto& t) { target = static_cast<V>(parseCount(name, t, min, max)); });
}

/// --NAME META: a number in [min, max] into target (double or std::optional<double>).
template <class T>
CLI::Option* addReal(CLI::App& app, const std::string& name, T& target, double min, double max,
                     const std::string& meta, const std::string& help, const std::string& def = {}) {
  const std::string shown = def.empty() ? detail::Held<T>::text(target) : def;
  return addValue(app, name, meta, help + rangeText(min, max, shown),
                  [&target, name, min, max](const auto& t) { target = parseReal(name, t, min, max); });
}

// ---- what several commands share ----------------------------------------------------------------
/// --out DIR, --quiet and (where the command has a summary) --json.
struct OutputArgs {
  std::optional<std::string> out;
  bool quiet = false;
  bool json = false;
};
enum class Summary { None, Json };
void addOutputOptions(CLI::App& app, OutputArgs& o, Summary summary, const std::string& files);
/// --quiet, accepted and ignored by the commands whose only output is their table (it always was).
void addIgnoredQuiet(CLI::App& app);
/// Creates --out's folder; UsageError when --out is missing or cannot be made.
std::string prepareOutDir(const OutputArgs& o);
/// True when the table should be printed (neither --quiet nor --json).
inline bool wantsTable(const OutputArgs& o) {
  return !o.quiet && !o.json;
}
/// With --json (and not --quiet): the summary's JSON text on stdout, ending in a newline.
void printSummary(const OutputArgs& o, const std::string& json);

/// --runs, --threads and --seed of the Monte Carlo studies.
struct MonteCarloArgs {
  int runs = 0;
  std::optional<int> threads;  // default: the machine's hardware threads
  std::optional<std::uint64_t> seed;
  int threadCount() const;
};
void addMonteCarloOptions(CLI::App& app, MonteCarloArgs& a, int maxRuns, int maxThreads,
                          const std::string& seedHelp);
/// --seed N: the first run's seed (seedHelp: the default, in words).
CLI::Option* addSeed(CLI::App& app, std::optional<std::uint64_t>& seed, const std::string& seedHelp);
/// --threads K (default: the machine's hardware threads).
CLI::Option* addThreads(CLI::App& app, std::optional<int>& threads, int maxThreads);
int hardwareThreads();

/// --profile paper|imo|realistic.
CLI::Option* addProfile(CLI::App& app, std::string& profile, const std::string& help);
std::optional<sim::SensorProfile> profileOf(const std::string& name);

/// SCENARIO (a JSON file or builtin:NAME) as the command's only positional argument.
CLI::Option* addScenarioArgument(CLI::App& app, std::string& spec);
/// SCENARIO... or PATH... (min 0 or 1 of them).
CLI::Option* addListArgument(CLI::App& app, const std::string& name, std::vector<std::string>& list, int min,
                             const std::string& help);

/// A scenario from a file path or builtin:NAME.
sim::Scenario loadScenario(const std::string& spec);
/// The scenario, with the named sensor profile's figures when profile is not empty.
sim::Scenario loadProfiled(const std::string& spec, const std::string& profile);

}  // namespace reckoner::cli
