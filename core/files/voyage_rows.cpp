#include "files/voyage_rows.h"

#include <cstring>
#include <limits>
#include <stdexcept>

#include "files/sqlite_db.h"
#include "tracking/track.h"

namespace reckoner::files::voyage {
namespace {

const Table& tableNamed(const char* name) {
  for (const Table& t : tables())
    if (std::strcmp(t.name, name) == 0) return t;
  throw std::logic_error(std::string("no table ") + name);
}

/// The columns after the key (seq), in order.
std::vector<const char*> dataColumns(const char* table) {
  std::vector<const char*> c;
  for (const Column& col : tableNamed(table).columns)
    if (std::strcmp(col.type, "INTEGER PRIMARY KEY") != 0) c.push_back(col.name);
  return c;
}

track::TrackStatus statusNamed(const std::string& name) {
  for (const auto s :
       {track::TrackStatus::Tentative, track::TrackStatus::Confirmed, track::TrackStatus::Lost})
    if (name == track::trackStatusName(s)) return s;
  return track::TrackStatus::Lost;  // a name of another version: shown as lost
}

}  // namespace

std::string insertSql(const char* table) {
  const std::vector<const char*> c = dataColumns(table);
  std::string names, values;
  for (std::size_t i = 0; i < c.size(); ++i) {
    names.append(i ? ", " : "").append(c[i]);
    values.append(i ? ", ?" : "?").append(std::to_string(i + 1));
  }
  return std::string("INSERT INTO ") + table + "(" + names + ") VALUES(" + values + ")";
}

std::string selectSql(const char* table) {
  std::string s = "SELECT ";
  const std::vector<const char*> c = dataColumns(table);
  for (std::size_t i = 0; i < c.size(); ++i) s.append(i ? ", " : "").append(c[i]);
  return s + " FROM " + table;
}

void bindOwnRow(sqlite::Statement& s, const sim::ReplayOwnRow& r, bool minute) {
  const sim::GroundEstimate& e = r.estimate;
  const sim::CalibrationEstimate& c = r.calibration;
  s.bindAll(r.utcUs, r.timeUs, e.xM, e.yM, e.vxMps, e.vyMps, e.sdXM, e.sdYM, e.sdVxMps, e.sdVyMps, e.covXYM2,
            e.latDeg, e.lonDeg, e.headingRad, c.currentXMps, c.currentYMps, c.sdCurrentXMps, c.sdCurrentYMps,
            c.headingBiasRad, c.sdHeadingBiasRad, c.logScale, c.sdLogScale, c.logOffsetMps, c.sdLogOffsetMps,
            std::string_view(r.sensors), r.rowsApplied, r.deadReckoning ? 1 : 0, minute ? 1 : 0);
}

sim::ReplayOwnRow readOwnRow(const sqlite::Statement& s) {
  sim::ReplayOwnRow r;
  int i = 0;
  r.utcUs = s.integer(i++);
  r.timeUs = s.integer(i++);
  sim::GroundEstimate& e = r.estimate;
  for (double* v : {&e.xM, &e.yM, &e.vxMps, &e.vyMps, &e.sdXM, &e.sdYM, &e.sdVxMps, &e.sdVyMps, &e.covXYM2,
                    &e.latDeg, &e.lonDeg, &e.headingRad})
    *v = s.real(i++);
  sim::CalibrationEstimate& c = r.calibration;
  for (double* v : {&c.currentXMps, &c.currentYMps, &c.sdCurrentXMps, &c.sdCurrentYMps, &c.headingBiasRad,
                    &c.sdHeadingBiasRad, &c.logScale, &c.sdLogScale, &c.logOffsetMps, &c.sdLogOffsetMps})
    *v = s.real(i++);
  r.sensors = s.text(i++);
  r.rowsApplied = static_cast<int>(s.integer(i++));
  r.deadReckoning = s.integer(i++) != 0;
  return r;
}

void bindTrack(sqlite::Statement& s, const RecordedTrack& t, bool minute) {
  const sim::TrackRow& r = t.row;
  s.bindAll(t.utc, r.timeUs, r.trackId);
  if (t.target.empty())
    s.bindNull(4);
  else
    s.bind(4, t.target);
  int i = 4;
  s.bind(++i, std::string_view(track::trackStatusName(r.status)));
  for (const bool b : {r.dangerous, r.manual, r.manoeuvring}) s.bind(++i, b ? 1 : 0);
  for (const double v :
       {r.estXM, r.estYM, r.estVxMps, r.estVyMps, r.sdXM, r.sdYM, r.sdVxMps, r.sdVyMps, r.estLatDeg,
        r.estLonDeg, r.courseDeg, r.speedKn, r.cpaNm, r.tcpaMin, r.nis, r.rangeNm, r.bearingDeg})
    s.bind(++i, v);
  s.bind(++i, r.aisMmsi);
  s.bind(++i, minute ? 1 : 0);
}

RecordedTrack readTrack(const sqlite::Statement& s) {
  RecordedTrack t;
  sim::TrackRow& r = t.row;
  int i = 0;
  t.utc = s.integer(i++);
  r.timeUs = s.integer(i++);
  r.trackId = static_cast<int>(s.integer(i++));
  t.target = s.text(i++);
  r.status = statusNamed(s.text(i++));
  for (bool* b : {&r.dangerous, &r.manual, &r.manoeuvring}) *b = s.integer(i++) != 0;
  for (double* v :
       {&r.estXM, &r.estYM, &r.estVxMps, &r.estVyMps, &r.sdXM, &r.sdYM, &r.sdVxMps, &r.sdVyMps, &r.estLatDeg,
        &r.estLonDeg, &r.courseDeg, &r.speedKn, &r.cpaNm, &r.tcpaMin, &r.nis, &r.rangeNm, &r.bearingDeg})
    *v = s.real(i++);
  r.aisMmsi = static_cast<std::uint32_t>(s.integer(i++));
  r.nees = r.positionVelocityNees4 = std::numeric_limits<double>::quiet_NaN();  // no truth
  return t;
}

void bindAlert(sqlite::Statement& s, const RecordedAlert& a) {
  s.bindAll(a.utc, a.timeUs, a.event, a.priority, a.kind, a.source, a.text);
}

RecordedAlert readAlert(const sqlite::Statement& s) {
  RecordedAlert a;
  a.utc = s.integer(0);
  a.timeUs = s.integer(1);
  a.event = s.text(2);
  a.priority = s.text(3);
  a.kind = s.text(4);
  a.source = static_cast<int>(s.integer(5));
  a.text = s.text(6);
  return a;
}

}  // namespace reckoner::files::voyage
