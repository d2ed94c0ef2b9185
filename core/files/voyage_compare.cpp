#include "files/voyage_compare.h"

#include <cmath>
#include <cstdio>

#include "io/iso8601.h"
#include "tracking/track.h"

namespace reckoner::files {
namespace {

/// Recorded rows are read this far ahead of the replay, so a long voyage is never in memory at once.
constexpr TimeUs kFetchAheadUs = 3600 * kMicrosPerSecond;

bool same(double a, double b) {
  return a == b || (std::isnan(a) && std::isnan(b));
}

struct Field {
  const char* name;
  double recorded, replayed;
};

/// The first field that differs, as "NAME recorded R, replayed P"; empty when all are the same.
std::string firstDiffering(std::initializer_list<Field> fields) {
  for (const Field& f : fields)
    if (!same(f.recorded, f.replayed)) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "%s recorded %.17g, replayed %.17g", f.name, f.recorded, f.replayed);
      return buf;
    }
  return {};
}

std::string ownDifference(const sim::ReplayOwnRow& a, const sim::ReplayOwnRow& b) {
  const sim::GroundEstimate &e = a.estimate, &f = b.estimate;
  const sim::CalibrationEstimate &c = a.calibration, &d = b.calibration;
  std::string d1 = firstDiffering(
      {{"t_s", toSeconds(a.timeUs), toSeconds(b.timeUs)},
       {"x_m", e.xM, f.xM},
       {"y_m", e.yM, f.yM},
       {"vx_mps", e.vxMps, f.vxMps},
       {"vy_mps", e.vyMps, f.vyMps},
       {"sd_x_m", e.sdXM, f.sdXM},
       {"sd_y_m", e.sdYM, f.sdYM},
       {"sd_vx_mps", e.sdVxMps, f.sdVxMps},
       {"sd_vy_mps", e.sdVyMps, f.sdVyMps},
       {"cov_xy_m2", e.covXYM2, f.covXYM2},
       {"lat_deg", e.latDeg, f.latDeg},
       {"lon_deg", e.lonDeg, f.lonDeg},
       {"heading_rad", e.headingRad, f.headingRad},
       {"rows_applied", static_cast<double>(a.rowsApplied), static_cast<double>(b.rowsApplied)},
       {"dead_reckoning", a.deadReckoning ? 1.0 : 0.0, b.deadReckoning ? 1.0 : 0.0}});
  if (!d1.empty()) return d1;
  std::string d2 = firstDiffering({{"current_x_mps", c.currentXMps, d.currentXMps},
                                   {"current_y_mps", c.currentYMps, d.currentYMps},
                                   {"sd_current_x_mps", c.sdCurrentXMps, d.sdCurrentXMps},
                                   {"sd_current_y_mps", c.sdCurrentYMps, d.sdCurrentYMps},
                                   {"heading_bias_rad", c.headingBiasRad, d.headingBiasRad},
                                   {"sd_heading_bias_rad", c.sdHeadingBiasRad, d.sdHeadingBiasRad},
                                   {"log_scale", c.logScale, d.logScale},
                                   {"sd_log_scale", c.sdLogScale, d.sdLogScale},
                                   {"log_offset_mps", c.logOffsetMps, d.logOffsetMps},
                                   {"sd_log_offset_mps", c.sdLogOffsetMps, d.sdLogOffsetMps}});
  if (!d2.empty()) return d2;
  if (a.sensors != b.sensors) return "sensors recorded " + a.sensors + ", replayed " + b.sensors;
  return {};
}

std::string trackDifference(const RecordedTrack& a, const RecordedTrack& b) {
  const sim::TrackRow &r = a.row, &s = b.row;
  if (a.target != b.target) return "target recorded '" + a.target + "', replayed '" + b.target + "'";
  if (r.status != s.status)
    return std::string("status recorded ") + track::trackStatusName(r.status) + ", replayed " +
           track::trackStatusName(s.status);
  return firstDiffering({{"t_s", toSeconds(r.timeUs), toSeconds(s.timeUs)},
                         {"dangerous", r.dangerous ? 1.0 : 0.0, s.dangerous ? 1.0 : 0.0},
                         {"manual", r.manual ? 1.0 : 0.0, s.manual ? 1.0 : 0.0},
                         {"manoeuvring", r.manoeuvring ? 1.0 : 0.0, s.manoeuvring ? 1.0 : 0.0},
                         {"x_m", r.estXM, s.estXM},
                         {"y_m", r.estYM, s.estYM},
                         {"vx_mps", r.estVxMps, s.estVxMps},
                         {"vy_mps", r.estVyMps, s.estVyMps},
                         {"sd_x_m", r.sdXM, s.sdXM},
                         {"sd_y_m", r.sdYM, s.sdYM},
                         {"sd_vx_mps", r.sdVxMps, s.sdVxMps},
                         {"sd_vy_mps", r.sdVyMps, s.sdVyMps},
                         {"lat_deg", r.estLatDeg, s.estLatDeg},
                         {"lon_deg", r.estLonDeg, s.estLonDeg},
                         {"course_deg", r.courseDeg, s.courseDeg},
                         {"speed_kn", r.speedKn, s.speedKn},
                         {"cpa_nm", r.cpaNm, s.cpaNm},
                         {"tcpa_min", r.tcpaMin, s.tcpaMin},
                         {"nis", r.nis, s.nis},
                         {"range_nm", r.rangeNm, s.rangeNm},
                         {"bearing_deg", r.bearingDeg, s.bearingDeg},
                         {"ais_mmsi", static_cast<double>(r.aisMmsi), static_cast<double>(s.aisMmsi)}});
}

}  // namespace

RecordComparer::RecordComparer(const VoyageRecord& record) : rec_(record), alerts_(record.alerts()) {}

void RecordComparer::differ(const std::string& what) {
  if (c_.firstDifference.empty()) c_.firstDifference = what;
}

void RecordComparer::fetchOwn(UtcUs upTo) {
  if (ownFetched_ >= upTo) return;
  const UtcUs from = ownFetched_ == INT64_MIN ? INT64_MIN : ownFetched_ + 1;
  const UtcUs to = upTo == INT64_MAX ? upTo : upTo + kFetchAheadUs;
  for (sim::ReplayOwnRow& r : rec_.estimates(from, to)) own_.push_back(std::move(r));
  ownFetched_ = to;
}

void RecordComparer::fetchTracks(UtcUs upTo) {
  if (tracksFetched_ >= upTo) return;
  const UtcUs from = tracksFetched_ == INT64_MIN ? INT64_MIN : tracksFetched_ + 1;
  const UtcUs to = upTo == INT64_MAX ? upTo : upTo + kFetchAheadUs;
  for (RecordedTrack& t : rec_.tracks(from, to)) tracks_.push_back(std::move(t));
  tracksFetched_ = to;
}

void RecordComparer::own(const sim::ReplayOwnRow& r) {
  fetchOwn(r.utcUs);
  while (!own_.empty() && own_.front().utcUs < r.utcUs) {
    differ("own-ship row at " + io::formatIso8601(own_.front().utcUs) + " recorded, not replayed");
    ++c_.ownNotReplayed;
    own_.pop_front();
  }
  if (own_.empty() || own_.front().utcUs != r.utcUs) {
    ++c_.ownNotRecorded;
    return;
  }
  const std::string d = ownDifference(own_.front(), r);
  own_.pop_front();
  if (d.empty()) {
    ++c_.ownEqual;
    return;
  }
  ++c_.ownDifferent;
  differ("own-ship row at " + io::formatIso8601(r.utcUs) + ": " + d);
}

void RecordComparer::track(const RecordedTrack& t) {
  fetchTracks(t.utc);
  while (!tracks_.empty() && tracks_.front().utc < t.utc) {
    differ("track row at " + io::formatIso8601(tracks_.front().utc) + " recorded, not replayed");
    ++c_.tracksNotReplayed;
    tracks_.pop_front();
  }
  auto it = tracks_.begin();
  while (it != tracks_.end() && it->utc == t.utc && it->row.trackId != t.row.trackId) ++it;
  if (it == tracks_.end() || it->utc != t.utc) {
    ++c_.tracksNotRecorded;
    return;
  }
  const std::string d = trackDifference(*it, t);
  tracks_.erase(it);
  if (d.empty()) {
    ++c_.tracksEqual;
    return;
  }
  ++c_.tracksDifferent;
  differ("track " + std::to_string(t.row.trackId) + " at " + io::formatIso8601(t.utc) + ": " + d);
}

void RecordComparer::alert(const RecordedAlert& a) {
  if (nextAlert_ >= alerts_.size()) {
    ++c_.alertsNotRecorded;
    return;
  }
  const RecordedAlert& r = alerts_[nextAlert_++];
  if (r == a) {
    ++c_.alertsEqual;
    return;
  }
  ++c_.alertsDifferent;
  differ("alert log entry " + std::to_string(nextAlert_) + ": recorded " + r.event + " " + r.kind + " at " +
         io::formatIso8601(r.utc) + ", replayed " + a.event + " " + a.kind + " at " +
         io::formatIso8601(a.utc));
}

void RecordComparer::add(const LiveBatch& b, std::span<const std::string> targetLabels) {
  for (const sim::ReplayOwnRow& r : b.own) own(r);
  for (std::size_t i = 0; i < b.tracks.size(); ++i) {
    RecordedTrack t{i < b.trackUtc.size() ? b.trackUtc[i] : 0, {}, b.tracks[i]};
    const int label = t.row.targetId;
    if (label >= 0 && static_cast<std::size_t>(label) < targetLabels.size())
      t.target = targetLabels[static_cast<std::size_t>(label)];
    track(t);
  }
  for (const alerts::AlertLogEntry& e : b.alerts) alert(recordedAlert(e, b.alertZeroUtc));
}

RecordComparison RecordComparer::finish() {
  fetchOwn(INT64_MAX);
  fetchTracks(INT64_MAX);
  for (const sim::ReplayOwnRow& r : own_) {
    differ("own-ship row at " + io::formatIso8601(r.utcUs) + " recorded, not replayed");
    ++c_.ownNotReplayed;
  }
  c_.tracksNotReplayed += static_cast<long>(tracks_.size());
  if (!tracks_.empty())
    differ("track row at " + io::formatIso8601(tracks_.front().utc) + " recorded, not replayed");
  c_.alertsNotReplayed += static_cast<long>(alerts_.size() - nextAlert_);
  if (nextAlert_ < alerts_.size())
    differ("alert log entry " + std::to_string(nextAlert_ + 1) + " recorded, not replayed");
  own_.clear();
  tracks_.clear();
  return c_;
}

}  // namespace reckoner::files
