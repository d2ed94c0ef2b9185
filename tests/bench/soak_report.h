#pragma once
// The soak's figures (docs/robustness.md, "Soak"): memory and record samples every simulated minute,
// what the record holds at the end, the verdict against the bars, soak.json and the summary.
#include <cstdint>
#include <string>
#include <vector>

#include "sim/simulation_engine.h"
#include "soak_checks.h"
#include "soak_scenario.h"

namespace reckoner::soak {

struct Sample {
  double simS = 0.0, wallS = 0.0;
  double rssMb = 0.0, anonMb = 0.0, fileBackedMb = 0.0;  ///< RSS and its anonymous and file-backed parts
  double heapMb = 0.0, recordMb = 0.0;
  int tracks = 0, aisTargets = 0,
      alertsShown = 0;  ///< alertsShown: on the list before the minute's acknowledgement
};

struct Samples {
  std::vector<Sample> all;
  void add(const Sample& s) { all.push_back(s); }
  /// One progress line (the latest sample) on stdout.
  void printHour(const FrameChecks& c) const;
  /// Mean RSS of the samples in [fromS, toS) of simulated time (0 when none).
  [[nodiscard]] double meanRss(double fromS, double toS) const;
  /// Mean heap in use of the samples in [fromS, toS) (0 when none).
  [[nodiscard]] double meanHeap(double fromS, double toS) const;
  /// The first sample at or after t (the last when none).
  [[nodiscard]] const Sample& at(double simS) const;
};

struct RecordFigures {
  double sizeMb = 0.0;
  std::int64_t lines = 0, prunedRows = 0;
  std::int64_t ownRows = 0, trackRows = 0;
  /// Full-rate rows older than the recorder's window (plus its one-minute pruning period): must be 0.
  std::int64_t ownRowsBeyondWindow = 0, trackRowsBeyondWindow = 0;
};
/// Reads the finished record (SQLite) for its rows and their ages.
RecordFigures recordFigures(const std::string& path, double maxHours, UtcUs endUtc);

struct Verdict {
  bool pass = false;
  double baselineS = 0.0;         ///< the windows' length: an hour (a quarter of a shorter run)
  double rssGrowthPercent = 0.0;  ///< mean RSS of the last window over that of the second, less 1, percent
  double rssPeakMb = 0.0;         ///< after the first window
  est::ChiSquareBounds ownBand, trackBand;
  bool ownInBand = false, trackInBand = false, memoryFlat = false, recordBounded = false;
  std::vector<std::string> failures;
};
/// The bars: no NaN, symmetric positive definite covariances, RSS growth under 1% after the
/// first hour (the last hour's mean over the second's; quarters of a run under two hours), NEES in band
/// over the run and in every hour, the record bounded.
Verdict verdict(const SoakPlan& plan, const FrameChecks& c, const Samples& s, const RecordFigures& r);

void writeReport(const std::string& path, const SoakPlan& plan, std::uint64_t seed, const FrameChecks& c,
                 const Samples& s, const RecordFigures& r, const sim::SimulationEngine& engine,
                 const Verdict& v);
void printSummary(const FrameChecks& c, const Samples& s, const RecordFigures& r,
                  const sim::SimulationEngine& engine, const Verdict& v);

}  // namespace reckoner::soak
