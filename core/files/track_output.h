#pragma once
// targets.csv and the tracking part of summary.json (formats: docs/outputs.md).
#include <functional>
#include <span>
#include <string>

#include "io/json.h"
#include "metrics/track_stats.h"
#include "sim/replay.h"
#include "sim/scenario_run.h"

namespace reckoner::files {

/// The targets.csv header line (without newline).
std::string targetsCsvHeader();
/// One targets.csv line (without newline); truth columns and nees empty without truth, cpa and tcpa
/// empty without relative motion.
std::string targetsCsvLine(const sim::TrackRow& r);
void writeTargetsCsv(const std::string& path, std::span<const sim::TrackRow> rows);

/// Replay outputs: ownship.csv and targets.csv without truth columns, with a utc column; summary.json
/// with the input counts.
void writeReplayOwnShipCsv(const std::string& path, const sim::ReplayResult& r);
void writeReplayTargetsCsv(const std::string& path, const sim::ReplayResult& r);
std::string replaySummaryJson(const sim::ReplayResult& r, const std::string& nmeaName);
/// The same with the own-ship time span given (a live run writes its rows as they come, so r.own holds
/// only the last ones) and extra keys (a live run's "ais" object) written by extra before the end.
std::string replaySummaryJson(const sim::ReplayResult& r, const std::string& nmeaName, double ownSpanS,
                              const std::function<void(io::JsonWriter&)>& extra = {});

/// The replay's ownship.csv and targets.csv one line at a time (without newline), for a live run.
std::string replayOwnShipCsvHeader();
std::string replayOwnShipCsvLine(const sim::ReplayOwnRow& r);
std::string replayTargetsCsvHeader();
/// targetLabels: ReplayResult::targetLabels (TrackRow::targetId indexes it).
std::string replayTargetsCsvLine(const sim::TrackRow& r, UtcUs utc,
                                 std::span<const std::string> targetLabels);

/// Writes the "tracking" object (key included) of a run summary.
void writeTrackingSummary(io::JsonWriter& w, const metrics::TrackingStats& s, const track::TrackCounters& c);
/// "key": {"covariance": n, "nis": m}: filters restarted by their divergence guard, by what tripped it.
void writeFilterResets(io::JsonWriter& w, const char* key, const est::DivergenceCounts& c);

}  // namespace reckoner::files
