#include "files/track_output.h"
#include "io/iso8601.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "common/angles.h"
#include "files/own_ship_output.h"

// The file formats are written with the codecs of io/: their names unqualified here.
using namespace reckoner::io;

namespace reckoner::files {
namespace {
void appendNumber(std::string& s, double v, const char* fmt) {
  s += ',';
  if (!std::isfinite(v)) return;  // empty field
  char buf[48];
  std::snprintf(buf, sizeof buf, fmt, v);
  s += buf;
}
}  // namespace

std::string targetsCsvHeader() {
  return "t_s,track_id,target_id,status,true_x_m,true_y_m,true_vx_mps,true_vy_mps,est_x_m,est_y_m,"
         "est_vx_mps,est_vy_mps,sd_x_m,sd_y_m,sd_vx_mps,sd_vy_mps,est_lat_deg,est_lon_deg,course_deg,"
         "speed_kn,cpa_nm,tcpa_min,nees,nis,ais_mmsi";
}

std::string targetsCsvLine(const sim::TrackRow& r) {
  char head[96];
  std::snprintf(head, sizeof head, "%.6f,%d,", toSeconds(r.timeUs), r.trackId);
  std::string s = head;
  if (r.targetId >= 0) s.append(std::to_string(r.targetId));
  s += ',';
  s.append(track::trackStatusName(r.status));
  constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
  appendNumber(s, r.hasTruth ? r.trueXM : kNan, "%.3f");
  appendNumber(s, r.hasTruth ? r.trueYM : kNan, "%.3f");
  appendNumber(s, r.hasTruth ? r.trueVxMps : kNan, "%.4f");
  appendNumber(s, r.hasTruth ? r.trueVyMps : kNan, "%.4f");
  appendNumber(s, r.estXM, "%.3f");
  appendNumber(s, r.estYM, "%.3f");
  appendNumber(s, r.estVxMps, "%.4f");
  appendNumber(s, r.estVyMps, "%.4f");
  appendNumber(s, r.sdXM, "%.4f");
  appendNumber(s, r.sdYM, "%.4f");
  appendNumber(s, r.sdVxMps, "%.5f");
  appendNumber(s, r.sdVyMps, "%.5f");
  appendNumber(s, r.estLatDeg, "%.9f");
  appendNumber(s, r.estLonDeg, "%.9f");
  appendNumber(s, r.courseDeg, "%.3f");
  appendNumber(s, r.speedKn, "%.3f");
  appendNumber(s, r.cpaNm, "%.5f");
  appendNumber(s, r.tcpaMin, "%.4f");
  appendNumber(s, r.nees, "%.4f");
  appendNumber(s, r.nis, "%.4f");
  s += ',';
  if (r.aisMmsi != 0) s.append(std::to_string(r.aisMmsi));
  return s;
}

void writeTargetsCsv(const std::string& path, std::span<const sim::TrackRow> rows) {
  std::string text = targetsCsvHeader();
  text += '\n';
  text.reserve(rows.size() * 220);
  for (const auto& r : rows) {
    text.append(targetsCsvLine(r));
    text += '\n';
  }
  writeTextFile(path, text);
}

std::string replayOwnShipCsvHeader() {
  return "t_s,utc,est_x_m,est_y_m,est_vx_mps,est_vy_mps,sd_x_m,sd_y_m,sd_vx_mps,sd_vy_mps,"
         "est_lat_deg,est_lon_deg,sensors,rows,est_current_x_mps,est_current_y_mps,sd_current_x_mps,"
         "sd_current_y_mps,heading_bias_deg,sd_heading_bias_deg,log_scale_pct,sd_log_scale_pct,log_offset_"
         "mps,"
         "sd_log_offset_mps";
}

std::string replayOwnShipCsvLine(const sim::ReplayOwnRow& o) {
  const sim::CalibrationEstimate& c = o.calibration;
  char buf[768];
  std::snprintf(
      buf, sizeof buf,
      "%.6f,%s,%.3f,%.3f,%.4f,%.4f,%.4f,%.4f,%.5f,%.5f,%.9f,%.9f,%s,%d,%.4f,%.4f,%.4f,%.4f,%.3f,%.3f,"
      "%.3f,%.3f,%.4f,%.4f",
      toSeconds(o.timeUs), io::formatIso8601(o.utcUs).c_str(), o.estimate.xM, o.estimate.yM, o.estimate.vxMps,
      o.estimate.vyMps, o.estimate.sdXM, o.estimate.sdYM, o.estimate.sdVxMps, o.estimate.sdVyMps,
      o.estimate.latDeg, o.estimate.lonDeg, o.sensors.c_str(), o.rowsApplied, c.currentXMps, c.currentYMps,
      c.sdCurrentXMps, c.sdCurrentYMps, radToDeg(c.headingBiasRad), radToDeg(c.sdHeadingBiasRad),
      100.0 * c.logScale, 100.0 * c.sdLogScale, c.logOffsetMps, c.sdLogOffsetMps);
  return buf;
}

void writeReplayOwnShipCsv(const std::string& path, const sim::ReplayResult& r) {
  std::string text = replayOwnShipCsvHeader();
  text += '\n';
  for (const auto& o : r.own) text.append(replayOwnShipCsvLine(o)).append("\n");
  writeTextFile(path, text);
}

std::string replayTargetsCsvHeader() {
  return "t_s,utc,track_id,target_id,status,est_x_m,est_y_m,est_vx_mps,est_vy_mps,sd_x_m,sd_y_m,sd_vx_mps,"
         "sd_vy_mps,est_lat_deg,est_lon_deg,course_deg,speed_kn,cpa_nm,tcpa_min,nis,manoeuvring";
}

std::string replayTargetsCsvLine(const sim::TrackRow& t, UtcUs utc,
                                 std::span<const std::string> targetLabels) {
  char head[128];
  std::snprintf(head, sizeof head, "%.6f,%s,%d,", toSeconds(t.timeUs), io::formatIso8601(utc).c_str(),
                t.trackId);
  std::string s = head;
  if (t.targetId >= 0 && static_cast<std::size_t>(t.targetId) < targetLabels.size())
    s.append(targetLabels[static_cast<std::size_t>(t.targetId)]);
  s += ',';
  s.append(track::trackStatusName(t.status));
  appendNumber(s, t.estXM, "%.3f");
  appendNumber(s, t.estYM, "%.3f");
  appendNumber(s, t.estVxMps, "%.4f");
  appendNumber(s, t.estVyMps, "%.4f");
  appendNumber(s, t.sdXM, "%.4f");
  appendNumber(s, t.sdYM, "%.4f");
  appendNumber(s, t.sdVxMps, "%.5f");
  appendNumber(s, t.sdVyMps, "%.5f");
  appendNumber(s, t.estLatDeg, "%.9f");
  appendNumber(s, t.estLonDeg, "%.9f");
  appendNumber(s, t.courseDeg, "%.3f");
  appendNumber(s, t.speedKn, "%.3f");
  appendNumber(s, t.cpaNm, "%.5f");
  appendNumber(s, t.tcpaMin, "%.4f");
  appendNumber(s, t.nis, "%.4f");
  s.append(t.manoeuvring ? ",1" : ",0");
  return s;
}

void writeReplayTargetsCsv(const std::string& path, const sim::ReplayResult& r) {
  std::string text = replayTargetsCsvHeader();
  text += '\n';
  for (std::size_t i = 0; i < r.tracks.size(); ++i)
    text.append(replayTargetsCsvLine(r.tracks[i], r.trackRowUtc[i], r.targetLabels)).append("\n");
  writeTextFile(path, text);
}

namespace {
/// "key": count.
void writeCount(JsonWriter& w, const char* key, long v) {
  w.key(key).value(static_cast<std::int64_t>(v));
}

/// The "nmea" block: what became of the recording's lines.
void writeNmeaCounts(JsonWriter& w, const sim::ReplayStats& s) {
  w.key("nmea").beginObject();
  writeCount(w, "lines", s.nmeaLines);
  writeCount(w, "sentences_used", s.sentencesUsed);
  writeCount(w, "skipped", s.nmeaSkipped());
  writeCount(w, "comments", s.comments);
  writeCount(w, "bad_checksum", s.badChecksum);
  writeCount(w, "unknown", s.unknownSentences);
  writeCount(w, "proprietary", s.proprietary);
  writeCount(w, "malformed", s.malformed);
  writeCount(w, "untimed", s.untimed);
  writeCount(w, "time_jumps", s.timeJumps);
  writeCount(w, "unusable", s.unusable);
  writeCount(w, "not_gnss", s.notGnss);
  writeCount(w, "implausible", s.implausible);
  writeCount(w, "no_variation", s.noVariation);
  writeCount(w, "standby", s.standby);
  writeCount(w, "repeated", s.repeated);
  writeCount(w, "not_used", s.notUsed);
  writeCount(w, "reordered", s.reordered);
  writeCount(w, "outside_frame", s.outsideFrame);
  writeCount(w, "epochs", s.epochs);
  writeCount(w, "epochs_before_fix", s.epochsBeforeFix);
  writeCount(w, "epochs_awaiting_fix", s.epochsAwaitingFix);
  writeCount(w, "epochs_time_only", s.epochsTimeOnly);
  w.endObject();
}

/// One DRKF measurement block's updates (key included): accepted, gated, failed and its NIS windows.
void writeBlockUpdates(JsonWriter& w, nav::DrkfBlock block, const sim::SensorUpdateCounts& c) {
  w.key(nav::blockName(block)).beginObject();
  writeCount(w, "accepted", c.accepted);
  writeCount(w, "gated", c.gated);
  writeCount(w, "failed", c.failed);
  w.key("nis").beginObject();
  writeCount(w, "windows", c.nis.windows);
  writeCount(w, "above", c.nis.above);
  writeCount(w, "below", c.nis.below);
  if (c.nis.dof > 0) w.key("mean_per_dof").value(c.nis.meanPerDof(), 4);
  w.endObject();
  w.endObject();
}

/// The "own_ship_filter" block: updates per measurement block, restarts, the GNSS noise scale.
void writeOwnShipFilter(JsonWriter& w, const sim::ReplayResult& r) {
  w.key("own_ship_filter").beginObject();
  w.key("updates").beginObject();
  for (int b = 0; b < nav::kDrkfBlockCount; ++b)
    writeBlockUpdates(w, static_cast<nav::DrkfBlock>(b), r.updates[static_cast<std::size_t>(b)]);
  w.endObject();
  w.key("restarts").beginObject();
  writeCount(w, "after_gap", r.stats.restartsAfterGap);
  writeCount(w, "after_failure", r.stats.restartsAfterFailure);
  w.endObject();
  writeFilterResets(w, "filter_resets", r.drkf.resets);
  if (r.gnssNoiseScale)
    w.key("gnss_noise_scale")
        .beginArray()
        .value((*r.gnssNoiseScale)[0], 4)
        .value((*r.gnssNoiseScale)[1], 4)
        .endArray();
  w.endObject();
}

/// One source's object of the "sources" array; spanS: the replay's own-ship time span, seconds.
void writeSource(JsonWriter& w, const sim::SourceStats& src, double spanS) {
  w.beginObject();
  w.key("source").value(src.source);
  w.key("quantity").value(src.quantity);
  writeCount(w, "sentences", src.sentences);
  writeCount(w, "used", src.used);
  writeCount(w, "standby", src.standby);
  writeCount(w, "repeated", src.repeated);
  w.key("skipped").beginObject();
  writeCount(w, "unusable", src.unusable);
  writeCount(w, "not_measured", src.notMeasured);
  writeCount(w, "implausible", src.implausible);
  writeCount(w, "time_jumps", src.timeJumps);
  w.endObject();
  w.key("clock_offset_s").value(src.clockOffsetS, 4);
  w.key("clock_resolution_s").value(src.clockResolutionS, 4);
  w.key("clock_corrected").value(src.clockCorrected);
  w.key("active_share").value(spanS > 0.0 ? std::min(1.0, src.activeS / spanS) : 0.0, 4);
  w.endObject();
}

/// The "radar" block: what became of the plots, the sweep period and the track counts.
void writeRadarCounts(JsonWriter& w, const sim::ReplayResult& r) {
  const auto& s = r.stats;
  w.key("radar").beginObject();
  writeCount(w, "lines", s.radarLines);
  writeCount(w, "plots", s.radarPlots);
  writeCount(w, "bad", s.radarBad);
  writeCount(w, "duplicates", s.radarDuplicates);
  writeCount(w, "time_jumps", s.radarTimeJumps);
  writeCount(w, "reordered", s.radarReordered);
  writeCount(w, "before_fix", s.radarBeforeFix);
  w.key("sweep_period_s").value(r.sweepPeriodS, 6);
  w.key("sweep_period_from").value(r.sweepFromPlots ? "plots" : "settings");
  writeCount(w, "tracks_started", r.tracking.tracksStarted);
  writeCount(w, "tracks_confirmed", r.tracking.tracksConfirmed);
  writeCount(w, "tracks_lost", r.tracking.tracksLost);
  writeFilterResets(w, "track_filter_resets", r.tracking.filterResets);
  w.endObject();
}
}  // namespace

std::string replaySummaryJson(const sim::ReplayResult& r, const std::string& nmeaName) {
  const double span = r.own.empty() ? 0.0 : toSeconds(r.own.back().timeUs - r.own.front().timeUs);
  return replaySummaryJson(r, nmeaName, span);
}

std::string replaySummaryJson(const sim::ReplayResult& r, const std::string& nmeaName, double ownSpanS,
                              const std::function<void(JsonWriter&)>& extra) {
  JsonWriter w;
  w.beginObject();
  w.key("nmea_file").value(nmeaName);
  w.key("utc_start").value(io::formatIso8601(r.utc0));
  w.key("origin").beginArray().value(r.origin.latDeg).value(r.origin.lonDeg).endArray();
  writeNmeaCounts(w, r.stats);
  writeOwnShipFilter(w, r);
  w.key("sources").beginArray();
  for (const sim::SourceStats& src : r.sources) writeSource(w, src, ownSpanS);
  w.endArray();
  writeRadarCounts(w, r);
  w.key("warnings").beginArray();
  for (const auto& warning : r.warnings) w.value(warning);
  w.endArray();
  if (extra) extra(w);
  w.endObject();
  return w.str();
}

void writeFilterResets(JsonWriter& w, const char* key, const est::DivergenceCounts& c) {
  w.key(key).beginObject();
  w.key("covariance").value(static_cast<std::int64_t>(c.covariance));
  w.key("nis").value(static_cast<std::int64_t>(c.nis));
  w.endObject();
}

void writeTrackingSummary(JsonWriter& w, const metrics::TrackingStats& s, const track::TrackCounters& c) {
  const auto number = [&w](const char* k, double v) {
    w.key(k);
    if (std::isfinite(v))
      w.value(v, 6);
    else
      w.null();
  };
  w.key("tracking").beginObject();
  number("continuity", s.continuity);
  w.key("breaks").value(s.breaks);
  w.key("swaps").value(s.swaps);
  w.key("far_swaps").value(s.farSwaps);
  w.key("false_tracks").value(s.falseTracks);
  w.key("false_track_sweeps").value(s.falseTrackSweeps);
  w.key("confirmed_tracks").value(s.confirmedTracks);
  w.key("targets_never_held").value(s.targetsNeverHeld);
  w.key("plots").value(static_cast<std::int64_t>(c.plots));
  w.key("plots_associated").value(static_cast<std::int64_t>(c.plotsAssociated));
  w.key("plots_stale").value(static_cast<std::int64_t>(c.plotsStale));
  w.key("plots_refused_full").value(static_cast<std::int64_t>(c.plotsRefusedFull));
  w.key("tracks_started").value(static_cast<std::int64_t>(c.tracksStarted));
  w.key("tracks_confirmed").value(static_cast<std::int64_t>(c.tracksConfirmed));
  w.key("tracks_lost").value(static_cast<std::int64_t>(c.tracksLost));
  w.key("tracks_dropped").value(static_cast<std::int64_t>(c.tracksDropped));
  w.key("largest_cluster").value(static_cast<std::int64_t>(c.largestCluster));
  writeFilterResets(w, "filter_resets", c.filterResets);
  w.key("targets").beginArray();
  for (const auto& t : s.targets) {
    w.beginObject();
    w.key("target_id").value(t.targetId);
    number("continuity", t.continuity);
    w.key("sweeps_tracked").value(t.sweepsTracked);
    w.key("sweeps_held").value(t.sweepsHeld);
    w.key("breaks").value(t.breaks);
    w.key("tracks").value(t.tracks);
    number("first_held_s", t.firstHeldUs >= 0 ? toSeconds(t.firstHeldUs) : std::nan(""));
    w.key("rows").value(t.rows);
    number("rmse_position_m", t.rmsePositionM);
    number("rmse_velocity_mps", t.rmseVelocityMps);
    number("mean_nees", t.meanNees);
    w.endObject();
  }
  w.endArray();
  w.endObject();
}

}  // namespace reckoner::files
