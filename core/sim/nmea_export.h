#pragma once
// Writes a simulated run as the recorded data a replay reads (docs/outputs.md, "Replay inputs"): the
// own-ship sensors as NMEA 0183 (GPS RMC + GGA with course and speed, Loran-C $LCGLL, gyro $HEHDT,
// speedlog $VWVBW in ground lock or $VWVHW through the water) and the radar plots as CSV with the
// true target in target_id (empty for clutter). For trials of the replay path and its tests.
#include <string>

#include "sim/replay.h"
#include "sim/simulation_engine.h"

namespace reckoner::sim {

struct ExportedRun {
  std::string nmea;
  std::string radarCsv;
  RunResult truth;  ///< the run's own rows and track rows, for scoring a replay against the truth
};

/// Runs the scenario with the seed; time zero is utc0.
ExportedRun exportRun(const Scenario& s, std::uint64_t seed, UtcUs utc0);

}  // namespace reckoner::sim
