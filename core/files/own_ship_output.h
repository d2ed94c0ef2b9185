#pragma once
// Files written by headless runs (formats: docs/outputs.md): ownship.csv, summary.json, montecarlo.csv.
#include <span>
#include <string>

#include "io/text_file.h"
#include "metrics/own_ship_stats.h"
#include "sim/scenario_run.h"

namespace reckoner::files {

/// The ownship.csv header line (without newline).
std::string ownShipCsvHeader();
/// One ownship.csv line (without newline).
std::string ownShipCsvLine(const sim::OwnShipRow& r);

void writeOwnShipCsv(const std::string& path, std::span<const sim::OwnShipRow> rows);

/// summary.json of one run: per-phase RMSE, mean NEES, 3-sd containment, update counts, wall time.
/// With radar targets, also the "tracking" object (io/track_output.h).
std::string runSummaryJson(const sim::Scenario& s, const sim::RunResult& run,
                           const std::vector<metrics::PhaseStats>& phases);

/// summary.json of a Monte Carlo study: bounds, per-phase figures and per-time series.
std::string monteCarloSummaryJson(const sim::Scenario& s, const metrics::MonteCarloSummary& m,
                                  std::uint64_t baseSeed, int threads, double wallTimeS);

/// montecarlo.csv: t_s, rmse_position_m, rmse_velocity_mps, mean_nees, nees_lower, nees_upper,
/// rms_sd_position_m.
void writeMonteCarloCsv(const std::string& path, const metrics::MonteCarloSummary& m);

}  // namespace reckoner::files
