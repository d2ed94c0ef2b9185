#pragma once
// Writes a simulated run as the recorded data a replay reads (docs/outputs.md, "Replay inputs"): the
// own-ship sensors as NMEA 0183 (GPS RMC + GGA with course and speed, Loran-C $LCGLL, gyro $HEHDT,
// speedlog $VWVBW in ground lock or $VWVHW through the water) and the radar plots as CSV with the
// true target in target_id (empty for clutter). For trials of the replay path and its tests.
#include <string>
#include <vector>

#include "sim/replay.h"
#include "sim/simulation_engine.h"

namespace reckoner::sim {

struct ExportedRun {
  std::string nmea;
  std::string radarCsv;
  RunResult truth;  ///< the run's own rows and track rows, for scoring a replay against the truth
};

/// A cycle's own-ship samples as NMEA sentences (without terminators), epoch by epoch, each epoch
/// opened by its ZDA; time zero is utc0.
std::vector<std::string> ownShipSentences(const SimFrame& f, const geo::LocalFrame& frame, UtcUs utc0);
/// A cycle's radar plots as rows of the radar CSV (utc,range_m,bearing_deg,target_id; no header).
std::vector<std::string> radarCsvRows(const SimFrame& f, UtcUs utc0);

/// Runs the scenario with the seed; time zero is utc0.
ExportedRun exportRun(const Scenario& s, std::uint64_t seed, UtcUs utc0);

}  // namespace reckoner::sim
