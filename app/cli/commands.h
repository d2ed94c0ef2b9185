#pragma once
// The command groups of reckoner-cli, one file each. A group adds its subcommands to the CLI11 app,
// binds their options, and returns for each the function that runs it once the command line parsed.
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace reckoner::cli {

struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;  // the exit code: 0 success, 1 a failed check (imo), 2 bad input
  /// The error for a positional argument the command does not take (empty: "NAME: unexpected
  /// argument 'X'").
  std::string extraArgument;
};
using Commands = std::vector<Command>;

void addRunCommands(CLI::App& root, Commands& out);       // run, montecarlo (run_commands.cpp)
void addReplayCommands(CLI::App& root, Commands& out);    // replay, export (replay_commands.cpp)
void addStudyCommands(CLI::App& root, Commands& out);     // compare, own-ship-compare, radar-fix
void addImoCommand(CLI::App& root, Commands& out);        // imo (imo_command.cpp)
void addFusionCommand(CLI::App& root, Commands& out);     // fusion (fusion_command.cpp)
void addTrialCommand(CLI::App& root, Commands& out);      // trial (trial_command.cpp)
void addSeedCommands(CLI::App& root, Commands& out);      // seed001, seed003 (seed_commands.cpp)
void addManoeuvreCommand(CLI::App& root, Commands& out);  // manoeuvre-report (manoeuvre_report.cpp)
void addChartCommands(CLI::App& root, Commands& out);     // chart info|render|pick (chart_commands.cpp)
void addScenarioCommands(CLI::App& root, Commands& out);  // validate, scenarios (scenario_commands.cpp)
void addAisCommands(CLI::App& root, Commands& out);       // ais decode (ais_commands.cpp)
void addLiveCommands(CLI::App& root, Commands& out);      // live (live_commands.cpp)
void addRouteCommands(CLI::App& root, Commands& out);     // route check (route_commands.cpp)

}  // namespace reckoner::cli
