#include "soak_report.h"

#include <algorithm>
#include <cstdio>
#include <fstream>

#include "files/sqlite_db.h"

namespace reckoner::soak {
namespace {

/// The project's band for a NEES on realistic data (tst_ais_fusion's, docs/robustness.md "Soak"):
/// errors inside the sd (a mean below twice the dimension) and the sd not far above them (above a
/// quarter of it: the sd at most twice the error); for the whole run and for every hour of it.
est::ChiSquareBounds bandOf(const NeesSeries& n) {
  return {0.25 * n.dof, 2.0 * n.dof};
}

bool everyHourIn(const NeesSeries& n, const est::ChiSquareBounds& b) {
  for (const NeesHour& h : n.hours)
    if (h.count > 0 && !b.contains(h.mean())) return false;
  return b.contains(n.total().mean());
}

}  // namespace

void Samples::printHour(const FrameChecks& c) const {
  const Sample& s = all.back();
  const std::size_t h = static_cast<std::size_t>(s.simS / 3600.0);
  const double own = h > 0 && h - 1 < c.own.hours.size() ? c.own.hours[h - 1].mean() : 0.0;
  const double trk = h > 0 && h - 1 < c.tracks.hours.size() ? c.tracks.hours[h - 1].mean() : 0.0;
  std::printf(
      "hour %3zu  wall %7.1f s  RSS %7.2f MB (anon %6.2f, file %5.2f)  heap %6.2f MB  record %7.1f MB  "
      "tracks %3d  AIS %4d  NEES own "
      "%.2f  tracks "
      "%.2f%s\n",
      h, s.wallS, s.rssMb, s.anonMb, s.fileBackedMb, s.heapMb, s.recordMb, s.tracks, s.aisTargets, own, trk,
      c.clean() ? "" : "  PROBLEMS");
  std::fflush(stdout);
}

namespace {
double meanOf(const std::vector<Sample>& all, double fromS, double toS, double Sample::*field) {
  double sum = 0.0;
  int n = 0;
  for (const Sample& x : all)
    if (x.simS >= fromS && x.simS < toS) {
      sum += x.*field;
      ++n;
    }
  return n > 0 ? sum / n : 0.0;
}
}  // namespace

double Samples::meanRss(double fromS, double toS) const {
  return meanOf(all, fromS, toS, &Sample::rssMb);
}
double Samples::meanHeap(double fromS, double toS) const {
  return meanOf(all, fromS, toS, &Sample::heapMb);
}

const Sample& Samples::at(double simS) const {
  for (const Sample& s : all)
    if (s.simS >= simS) return s;
  return all.back();
}

RecordFigures recordFigures(const std::string& path, double maxHours, UtcUs endUtc) {
  RecordFigures r;
  std::ifstream f(path, std::ios::binary | std::ios::ate);
  r.sizeMb = static_cast<double>(f.tellg()) / (1024.0 * 1024.0);
  files::sqlite::Db db(path, files::sqlite::Db::Mode::ReadOnly);
  const auto count = [&](const char* sql, std::optional<std::int64_t> before) {
    files::sqlite::Statement q(db, sql);
    if (before) q.bind(1, *before);
    return q.step() ? q.integer(0) : 0;
  };
  const UtcUs window = endUtc - fromSeconds(maxHours * 3600.0 + 120.0);
  r.ownRows = count("SELECT COUNT(*) FROM ownship", std::nullopt);
  r.trackRows = count("SELECT COUNT(*) FROM tracks", std::nullopt);
  r.ownRowsBeyondWindow = count("SELECT COUNT(*) FROM ownship WHERE minute = 0 AND utc_us < ?1", window);
  r.trackRowsBeyondWindow = count("SELECT COUNT(*) FROM tracks WHERE minute = 0 AND utc_us < ?1", window);
  return r;
}

Verdict verdict(const SoakPlan& plan, const FrameChecks& c, const Samples& s, const RecordFigures& r) {
  Verdict v;
  const double durationS = plan.hours * 3600.0;
  // Growth is a trend, not the working set's breathing with the traffic: the mean RSS of the run's
  // last hour against that of its second (of the last quarter against the second quarter when the run
  // is shorter than two hours).
  const double window = plan.hours >= 2.0 ? 3600.0 : durationS / 4.0;
  v.baselineS = window;
  const double base = s.meanRss(window, 2.0 * window), end = s.meanRss(durationS - window, durationS + 1.0);
  v.rssGrowthPercent = 100.0 * (end - base) / base;
  for (const Sample& x : s.all)
    if (x.simS >= window) v.rssPeakMb = std::max(v.rssPeakMb, x.rssMb);
  v.memoryFlat = v.rssGrowthPercent < 1.0;
  v.ownBand = bandOf(c.own);
  v.trackBand = bandOf(c.tracks);
  v.ownInBand = everyHourIn(c.own, v.ownBand);
  v.trackInBand = everyHourIn(c.tracks, v.trackBand);
  v.recordBounded = r.ownRowsBeyondWindow == 0 && r.trackRowsBeyondWindow == 0;
  if (!c.clean()) v.failures.emplace_back("non-finite values or covariances not symmetric positive definite");
  if (!v.memoryFlat) v.failures.emplace_back("RSS grew 1% or more from the second hour to the last");
  if (!v.ownInBand) v.failures.emplace_back("own-ship NEES outside its band (the run or an hour)");
  if (!v.trackInBand) v.failures.emplace_back("track NEES outside its band (the run or an hour)");
  if (!v.recordBounded) v.failures.emplace_back("full-rate rows older than the recorder's window");
  v.pass = v.failures.empty();
  return v;
}

void writeReport(const std::string& path, const SoakPlan& plan, std::uint64_t seed, const FrameChecks& c,
                 const Samples& s, const RecordFigures& r, const sim::SimulationEngine& engine,
                 const Verdict& v) {
  std::ofstream out(path);
  const auto& tc = engine.trackers().counters();
  const NeesHour own = c.own.total(), trk = c.tracks.total();
  out << "{\n  \"hours\": " << plan.hours << ",\n  \"seed\": " << seed
      << ",\n  \"targets_in_scenario\": " << engine.scenario().targets.size()
      << ",\n  \"wall_s\": " << s.all.back().wallS << ",\n  \"frames\": " << c.frames
      << ",\n  \"covariances_checked\": " << c.covariancesChecked << ",\n  \"non_finite\": " << c.nonFinite
      << ",\n  \"asymmetric\": " << c.asymmetric
      << ",\n  \"not_positive_definite\": " << c.notPositiveDefinite << ",\n  \"max_tracks\": " << c.maxTracks
      << ",\n  \"max_ais_targets\": " << c.maxAisTargets
      << ",\n  \"max_targets_present\": " << c.maxTargetsPresent
      << ",\n  \"tracks_started\": " << tc.tracksStarted
      << ",\n  \"tracks_confirmed\": " << tc.tracksConfirmed
      << ",\n  \"tracks_dropped\": " << tc.tracksDropped << ",\n  \"own_nees_mean\": " << own.mean()
      << ",\n  \"own_nees_dof\": " << c.own.dof << ",\n  \"own_nees_band\": [" << v.ownBand.lower << ", "
      << v.ownBand.upper << "],\n  \"track_nees4_mean\": " << trk.mean()
      << ",\n  \"track_nees4_values\": " << trk.count << ",\n  \"track_nees4_band\": [" << v.trackBand.lower
      << ", " << v.trackBand.upper
      << "],\n  \"rss_second_window_mean_mb\": " << s.meanRss(v.baselineS, 2.0 * v.baselineS)
      << ",\n  \"rss_end_mb\": " << s.all.back().rssMb
      << ",\n  \"rss_peak_after_first_window_mb\": " << v.rssPeakMb
      << ",\n  \"rss_growth_percent\": " << v.rssGrowthPercent
      << ",\n  \"heap_second_window_mean_mb\": " << s.meanHeap(v.baselineS, 2.0 * v.baselineS)
      << ",\n  \"heap_last_window_mean_mb\": "
      << s.meanHeap(s.all.back().simS - v.baselineS, s.all.back().simS + 1.0)
      << ",\n  \"record_mb\": " << r.sizeMb << ",\n  \"record_lines\": " << r.lines
      << ",\n  \"record_own_rows\": " << r.ownRows << ",\n  \"record_track_rows\": " << r.trackRows
      << ",\n  \"record_pruned_rows\": " << r.prunedRows
      << ",\n  \"record_rows_beyond_window\": " << r.ownRowsBeyondWindow + r.trackRowsBeyondWindow
      << ",\n  \"pass\": " << (v.pass ? "true" : "false") << ",\n  \"hourly\": [";
  for (std::size_t i = 0; i < s.all.size(); ++i) {
    const Sample& x = s.all[i];
    if (i % 60 != 0 && i + 1 != s.all.size()) continue;
    const std::size_t h = static_cast<std::size_t>(x.simS / 3600.0);
    out << (i ? ",\n    " : "\n    ") << "{\"sim_s\": " << x.simS << ", \"wall_s\": " << x.wallS
        << ", \"rss_mb\": " << x.rssMb << ", \"rss_anon_mb\": " << x.anonMb
        << ", \"rss_file_mb\": " << x.fileBackedMb << ", \"heap_mb\": " << x.heapMb
        << ", \"record_mb\": " << x.recordMb << ", \"tracks\": " << x.tracks
        << ", \"ais_targets\": " << x.aisTargets << ", \"alerts_shown\": " << x.alertsShown
        << ", \"own_nees_hour_mean\": " << (h < c.own.hours.size() ? c.own.hours[h].mean() : 0.0)
        << ", \"track_nees4_hour_mean\": " << (h < c.tracks.hours.size() ? c.tracks.hours[h].mean() : 0.0)
        << "}";
  }
  out << "\n  ]\n}\n";
}

void printSummary(const FrameChecks& c, const Samples& s, const RecordFigures& r,
                  const sim::SimulationEngine& engine, const Verdict& v) {
  const NeesHour own = c.own.total(), trk = c.tracks.total();
  std::printf("\n%.1f simulated hours in %.1f s of wall time; %lld frames, %lld covariances checked\n",
              s.all.back().simS / 3600.0, s.all.back().wallS, static_cast<long long>(c.frames),
              static_cast<long long>(c.covariancesChecked));
  std::printf("non-finite %lld, asymmetric %lld, not positive definite %lld\n",
              static_cast<long long>(c.nonFinite), static_cast<long long>(c.asymmetric),
              static_cast<long long>(c.notPositiveDefinite));
  for (const std::string& p : c.problems) std::printf("  %s\n", p.c_str());
  std::printf("targets in the scenario %zu; at most %lld present, %lld tracks, %lld AIS targets\n",
              engine.scenario().targets.size(), static_cast<long long>(c.maxTargetsPresent),
              static_cast<long long>(c.maxTracks), static_cast<long long>(c.maxAisTargets));
  std::printf(
      "own-ship NEES %.2f (dof %d, band %.2f-%.2f, %.2f%% above the 99%% quantile)\n", own.mean(), c.own.dof,
      v.ownBand.lower, v.ownBand.upper,
      100.0 * static_cast<double>(own.aboveQ99) / std::max<double>(1.0, static_cast<double>(own.count)));
  std::printf(
      "track NEES (x, y, vx, vy) %.2f over %lld values (band %.2f-%.2f, %.2f%% above the 99%% quantile)\n",
      trk.mean(), static_cast<long long>(trk.count), v.trackBand.lower, v.trackBand.upper,
      100.0 * static_cast<double>(trk.aboveQ99) / std::max<double>(1.0, static_cast<double>(trk.count)));
  std::printf(
      "RSS mean %.2f MB over %.0f-%.0f s, %.2f MB over the last %.0f s: growth %.3f%% (peak %.2f MB)\n",
      s.meanRss(v.baselineS, 2.0 * v.baselineS), v.baselineS, 2.0 * v.baselineS,
      s.meanRss(s.all.back().simS - v.baselineS, s.all.back().simS + 1.0), v.baselineS, v.rssGrowthPercent,
      v.rssPeakMb);
  std::printf("heap in use: mean %.2f MB over %.0f-%.0f s, %.2f MB over the last %.0f s\n",
              s.meanHeap(v.baselineS, 2.0 * v.baselineS), v.baselineS, 2.0 * v.baselineS,
              s.meanHeap(s.all.back().simS - v.baselineS, s.all.back().simS + 1.0), v.baselineS);
  std::printf(
      "record %.1f MB: %lld lines, %lld own-ship rows, %lld track rows (%lld pruned), %lld full-rate rows "
      "beyond the window\n",
      r.sizeMb, static_cast<long long>(r.lines), static_cast<long long>(r.ownRows),
      static_cast<long long>(r.trackRows), static_cast<long long>(r.prunedRows),
      static_cast<long long>(r.ownRowsBeyondWindow) + static_cast<long long>(r.trackRowsBeyondWindow));
  std::printf("%s\n", v.pass ? "PASS" : "FAIL");
  for (const std::string& f : v.failures) std::printf("  %s\n", f.c_str());
}

}  // namespace reckoner::soak
