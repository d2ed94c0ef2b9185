// reckoner-cli: headless runs of the Reckoner engine (docs/cli.md). The commands, one group per file:
//   run SCENARIO, montecarlo SCENARIO --runs N              run_commands.cpp
//   replay --nmea FILE, export SCENARIO                    replay_commands.cpp
//   compare, own-ship-compare, radar-fix SCENARIO          study_commands.cpp
//   imo [SCENARIO...]                                      imo_command.cpp
//   fusion [SCENARIO...]                                   fusion_command.cpp
//   trial SCENARIO --at T --course C --speed S --delay D   trial_command.cpp
//   seed001, seed003                                       seed_commands.cpp
//   manoeuvre-report                                       manoeuvre_report.cpp
//   chart info|render|pick PATH...                         chart_commands.cpp
//   validate SCENARIO..., scenarios                        scenario_commands.cpp
//   ais decode FILE... [--json]                            ais_commands.cpp
//   route check ROUTE --enc PATH                           route_commands.cpp
// `reckoner-cli --help` lists them, `reckoner-cli COMMAND --help` a command's options with their units.
// Outputs: a table on stdout, files under --out DIR, --json for summary.json's text on stdout (run,
// montecarlo, replay); the chart commands print JSON. SCENARIO is a JSON file or builtin:NAME.
// Exit codes: 0 success, 2 bad input or usage (one line on stderr), 1 any other failure (and imo when
// a cell fails).
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "charts/s57/s57_loader.h"
#include "cli/cli_options.h"
#include "cli/commands.h"
#include "common/allocator_settings.h"
#include "common/library_versions.h"
#include "io/error_line.h"
#include "io/input_error.h"
#include "reckoner_version.h"

namespace {

using namespace reckoner;
using namespace reckoner::cli;

/// CLI11's help with positional arguments shown as required unless they may be left out.
class HelpFormatter : public CLI::Formatter {
 public:
  HelpFormatter() { column_width(36); }
  std::string make_option_usage(const CLI::Option* opt) const override {
    std::string s = make_option_name(opt, true);
    if (opt->get_expected_max() >= CLI::detail::expected_max_vector_size) s += "...";
    return opt->get_expected_min() == 0 ? "[" + s + "]" : s;
  }
};

constexpr const char* kFooter =
    "SCENARIO is a JSON file (docs/scenarios.md) or builtin:NAME (see `reckoner-cli scenarios`).\n"
    "`reckoner-cli COMMAND --help` lists a command's options. Outputs: a table on stdout, files under\n"
    "--out DIR, --json for the summary on stdout (run, montecarlo, replay). Exit codes: 0 success,\n"
    "2 bad input or usage (one line on stderr), 1 any other failure (imo: a cell fails).";

/// "run", "chart render".
std::string commandPath(const CLI::App* app) {
  std::vector<std::string> names;  // innermost first
  for (; app && app->get_parent(); app = app->get_parent()) names.push_back(app->get_name());
  std::string path;
  for (auto it = names.rbegin(); it != names.rend(); ++it) {
    if (!path.empty()) path += ' ';
    path += *it;
  }
  return path;
}

/// The words that name the command exist: "unknown command 'fly'" rather than CLI11's usage text.
void checkCommandWords(CLI::App& root, int argc, char** argv) {
  if (argc < 2) throw UsageError("no command given (see reckoner-cli --help)");
  CLI::App* app = &root;
  for (int i = 1;; ++i) {
    const auto subs = app->get_subcommands([](CLI::App*) { return true; });
    if (subs.empty()) return;
    std::string known;
    for (const CLI::App* s : subs) known += (known.empty() ? "" : ", ") + s->get_name();
    if (i >= argc) throw UsageError(commandPath(app) + " needs a subcommand: " + known);
    const std::string word = argv[i];
    if (word == "-h" || word == "--help" || (app == &root && word == "--version")) return;
    CLI::App* next = nullptr;
    for (CLI::App* s : subs)
      if (s->get_name() == word) next = s;
    if (!next) {
      if (app == &root) throw UsageError("unknown command " + io::quoted(word));
      throw UsageError("unknown " + commandPath(app) + " subcommand " + io::quoted(word) +
                       " (known: " + known + ")");
    }
    app = next;
  }
}

/// What the user typed that the command does not take.
void checkRemaining(const Command& cmd) {
  const std::vector<std::string> extras = cmd.app->remaining();
  for (const auto& x : extras)
    if (x.size() > 1 && x[0] == '-') throw UsageError("unknown option " + io::quoted(x));
  if (extras.empty()) return;
  if (!cmd.extraArgument.empty()) throw UsageError(cmd.extraArgument);
  throw UsageError(commandPath(cmd.app) + ": unexpected argument " + io::quoted(extras.front()));
}

/// CLI11's parse errors as the one line the old parser printed.
std::string oneLineMessage(const CLI::ParseError& e) {
  const std::string what = e.what();
  if (e.get_name() == "ArgumentMismatch") {
    const std::string option = what.substr(0, what.find(':'));
    if (what.find("missing") != std::string::npos) return "option " + io::quoted(option) + " needs a value";
    if (what.find("At Most") != std::string::npos) return "option " + io::quoted(option) + " given twice";
  }
  return io::oneLine(what);
}

int usageError(const std::string& message) {
  std::fprintf(stderr, "reckoner-cli: error: %s\n", io::oneLine(message).c_str());
  return 2;
}

int run(int argc, char** argv) {
  CLI::App root("reckoner-cli: headless runs of the Reckoner engine", "reckoner-cli");
  root.formatter(std::make_shared<HelpFormatter>());
  root.require_subcommand(1);
  // GNU style: the program's version alone on the first line (help2man takes it for the man page).
  root.set_version_flag("--version",
                        std::string("reckoner-cli ") + RECKONER_VERSION + "\nEigen " + eigenVersion() +
                            ", GeographicLib " + geographicLibVersion() + ", GDAL " + charts::gdalVersion(),
                        "Print the version of reckoner-cli and of the libraries it runs on, and exit");
  Commands commands;
  for (const auto add : {addRunCommands, addReplayCommands, addStudyCommands, addImoCommand, addFusionCommand,
                         addTrialCommand, addSeedCommands, addManoeuvreCommand, addChartCommands,
                         addScenarioCommands, addAisCommands, addLiveCommands, addRouteCommands})
    add(root, commands);
  for (const auto& c : commands) c.app->allow_extras();
  root.footer(kFooter);  // after the commands: theirs would inherit it

  if (argc == 2 && std::string(argv[1]) == "help") {
    std::fputs(root.help().c_str(), stdout);
    return 0;
  }
  checkCommandWords(root, argc, argv);
  try {
    root.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return root.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return root.exit(e);
  } catch (const CLI::ParseError& e) {
    return usageError(oneLineMessage(e));
  }
  for (const auto& c : commands) {
    if (!c.app->parsed()) continue;
    checkRemaining(c);
    return c.run();
  }
  throw UsageError("no command given (see reckoner-cli --help)");
}

}  // namespace

int main(int argc, char** argv) {
  reckoner::applyAllocatorSettings();
  try {
    return run(argc, argv);
  } catch (const UsageError& e) {
    return usageError(e.what());
  } catch (const io::InputError& e) {
    std::fprintf(stderr, "reckoner-cli: error: %s\n", e.what());
    return 2;
  } catch (const std::invalid_argument& e) {
    return usageError(e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "reckoner-cli: failed: %s\n", io::oneLine(e.what()).c_str());
    return 1;
  }
}
