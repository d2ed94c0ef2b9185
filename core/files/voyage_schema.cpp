#include "files/voyage_schema.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>

#include "files/scenario_json.h"
#include "files/sqlite_db.h"
#include "io/error_line.h"
#include "io/input_error.h"

namespace reckoner::files::voyage {
namespace {

constexpr const char* kReal = "REAL";
constexpr const char* kInt = "INTEGER NOT NULL";
constexpr const char* kText = "TEXT NOT NULL";
constexpr const char* kKey = "INTEGER PRIMARY KEY";

/// The estimate columns an own-ship row and a track row share after their own.
std::vector<Column> withMinute(std::vector<Column> c) {
  c.push_back({"minute", kInt});  // 1: the row kept at one-minute intervals (--record-max-hours)
  return c;
}

std::vector<Table> makeTables() {
  return {
      {"meta", {{"key", "TEXT PRIMARY KEY"}, {"value", kText}}, {}},
      {"sources", {{"id", kKey}, {"name", "TEXT NOT NULL UNIQUE"}, {"role", kText}, {"spec", kText}}, {}},
      {"inputs",
       {{"seq", kKey}, {"batch", kInt}, {"rx_utc_us", kInt}, {"source", kInt}, {"line", kText}},
       {}},  // no index on rx_utc_us: a fifth of the file; seeks search by seq (VoyageRecord::inputSeqAt)
      {"ownship",
       withMinute({{"seq", kKey},
                   {"utc_us", kInt},
                   {"t_us", kInt},
                   {"x_m", kReal},
                   {"y_m", kReal},
                   {"vx_mps", kReal},
                   {"vy_mps", kReal},
                   {"sd_x_m", kReal},
                   {"sd_y_m", kReal},
                   {"sd_vx_mps", kReal},
                   {"sd_vy_mps", kReal},
                   {"cov_xy_m2", kReal},
                   {"lat_deg", kReal},
                   {"lon_deg", kReal},
                   {"heading_rad", kReal},
                   {"current_x_mps", kReal},
                   {"current_y_mps", kReal},
                   {"sd_current_x_mps", kReal},
                   {"sd_current_y_mps", kReal},
                   {"heading_bias_rad", kReal},
                   {"sd_heading_bias_rad", kReal},
                   {"log_scale", kReal},
                   {"sd_log_scale", kReal},
                   {"log_offset_mps", kReal},
                   {"sd_log_offset_mps", kReal},
                   {"sensors", kText},
                   {"rows_applied", kInt},
                   {"dead_reckoning", kInt}}),
       {"CREATE INDEX ownship_utc ON ownship(utc_us)"}},
      {"tracks",
       withMinute({{"seq", kKey},         {"utc_us", kInt},       {"t_us", kInt},      {"track_id", kInt},
                   {"target", "TEXT"},    {"status", kText},      {"dangerous", kInt}, {"manual", kInt},
                   {"manoeuvring", kInt}, {"x_m", kReal},         {"y_m", kReal},      {"vx_mps", kReal},
                   {"vy_mps", kReal},     {"sd_x_m", kReal},      {"sd_y_m", kReal},   {"sd_vx_mps", kReal},
                   {"sd_vy_mps", kReal},  {"lat_deg", kReal},     {"lon_deg", kReal},  {"course_deg", kReal},
                   {"speed_kn", kReal},   {"cpa_nm", kReal},      {"tcpa_min", kReal}, {"nis", kReal},
                   {"range_nm", kReal},   {"bearing_deg", kReal}, {"ais_mmsi", kInt}}),
       {"CREATE INDEX tracks_utc ON tracks(utc_us)"}},
      {"alerts",
       {{"seq", kKey},
        {"utc_us", kInt},
        {"t_us", kInt},
        {"event", kText},
        {"priority", kText},
        {"kind", kText},
        {"source", kInt},
        {"text", kText}},
       {}},
      {"operator_actions",
       {{"seq", kKey},
        {"after_batch", kInt},
        {"wall_utc_us", kInt},
        {"stream_utc_us", "INTEGER"},
        {"action", kText},
        {"subject", kText},
        {"value", kText}},
       {}},
      {"charts",
       {{"seq", kKey},
        {"wall_utc_us", kInt},
        {"stream_utc_us", "INTEGER"},
        {"event", kText},
        {"name", kText},
        {"edition", kText},
        {"update_number", kText},
        {"issue_date", kText},
        {"path", kText}},
       {}},
  };
}

std::string createStatement(const Table& t) {
  std::string s = std::string("CREATE TABLE ") + t.name + "(";
  for (std::size_t i = 0; i < t.columns.size(); ++i)
    s.append(i ? ", " : "").append(t.columns[i].name).append(" ").append(t.columns[i].type);
  return s + ")";
}

/// The table names the database holds.
std::set<std::string> tablesIn(sqlite::Db& db) {
  std::set<std::string> names;
  sqlite::Statement q(db, "SELECT name FROM sqlite_schema WHERE type = 'table'");
  while (q.step()) names.insert(q.text(0));
  return names;
}

std::set<std::string> columnsOf(sqlite::Db& db, const std::string& table) {
  std::set<std::string> names;
  sqlite::Statement q(db, "SELECT name FROM pragma_table_info(?1)");
  q.bind(1, table);
  while (q.step()) names.insert(q.text(0));
  return names;
}

[[noreturn]] void bad(const std::string& path, const std::string& field, const std::string& why) {
  throw io::InputError(path, 0, field, why);
}

const std::string& need(const std::map<std::string, std::string>& m, const std::string& key,
                        const std::string& path) {
  const auto it = m.find(key);
  if (it == m.end()) bad(path, "meta", "no " + io::quoted(key));
  return it->second;
}

double number(const std::map<std::string, std::string>& m, const std::string& key, const std::string& path) {
  const std::string& t = need(m, key, path);
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(t.c_str(), &end);
  if (t.empty() || errno != 0 || *end != '\0' || !std::isfinite(v))
    bad(path, "meta." + key, "not a number: " + io::quoted(t));
  return v;
}

/// A number of the meta table within [lo, hi] (a record's options come back into a run: a value no
/// program writes, such as a window of 1e300 timestamps, is refused rather than cast or allocated).
double number(const std::map<std::string, std::string>& m, const std::string& key, const std::string& path,
              double lo, double hi) {
  const double v = number(m, key, path);
  if (v < lo || v > hi)
    bad(path, "meta." + key,
        io::quoted(m.at(key)) + " is outside [" + exactText(lo) + ", " + exactText(hi) + "]");
  return v;
}

/// A whole number of the meta table within [lo, hi].
std::int64_t integer(const std::map<std::string, std::string>& m, const std::string& key,
                     const std::string& path, double lo, double hi) {
  const double v = number(m, key, path, lo, hi);
  if (v != std::floor(v)) bad(path, "meta." + key, "not a whole number: " + io::quoted(m.at(key)));
  return static_cast<std::int64_t>(v);
}

bool flag(const std::map<std::string, std::string>& m, const std::string& key, const std::string& path) {
  const std::string& t = need(m, key, path);
  if (t != "0" && t != "1") bad(path, "meta." + key, "expected 0 or 1, got " + io::quoted(t));
  return t == "1";
}

}  // namespace

const std::vector<Table>& tables() {
  static const std::vector<Table> t = makeTables();
  return t;
}

void createSchema(sqlite::Db& db) {
  for (const Table& t : tables()) {
    db.exec(createStatement(t));
    for (const char* index : t.indexes) db.exec(index);
  }
}

std::map<std::string, std::string> checkSchema(sqlite::Db& db) {
  const std::set<std::string> present = tablesIn(db);  // throws "not a SQLite database" first
  if (!present.contains("meta")) bad(db.path(), "", "not a Reckoner voyage record: no table 'meta'");
  std::map<std::string, std::string> meta;
  sqlite::Statement q(db, "SELECT key, value FROM meta");
  while (q.step()) meta[q.text(0)] = q.text(1);
  const std::string& version = need(meta, "schema_version", db.path());
  if (version != std::to_string(kSchemaVersion))
    bad(db.path(), "meta.schema_version",
        "schema version " + io::quoted(version) + ", this program reads version " +
            std::to_string(kSchemaVersion));
  for (const Table& t : tables()) {
    if (!present.contains(t.name)) bad(db.path(), "", std::string("missing table '") + t.name + "'");
    const std::set<std::string> columns = columnsOf(db, t.name);
    for (const Column& c : t.columns)
      if (!columns.contains(c.name)) bad(db.path(), t.name, std::string("missing column '") + c.name + "'");
  }
  return meta;
}

std::string exactText(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::vector<std::pair<std::string, std::string>> optionsMeta(const sim::LiveOptions& o) {
  const sim::ReplayOptions& r = o.replay;
  std::vector<std::pair<std::string, std::string>> m{
      {"settings.scenario", writeScenario(r.settings)},
      {"settings.name", r.settingsName},
      {"settings.origin_from_settings", r.originFromSettings ? "1" : "0"},
      {"settings.assume_association", r.assumeAssociation ? "1" : "0"},
      {"settings.max_gap_s", exactText(r.maxGapS)},
      {"settings.isolated_jump_us", std::to_string(r.time.isolatedJumpUs)},
      {"settings.time_window", std::to_string(r.time.window)},
      {"settings.magnetic_heading_sd_deg", exactText(r.magneticHeadingSdDeg)},
      {"settings.source_hold_s", exactText(r.sourceHoldS)},
      {"settings.sweep_from_plots", r.sweepFromPlots ? "1" : "0"},
      {"live.name", o.name},
      {"live.reorder_horizon_s", exactText(o.reorderHorizonS)},
      {"live.radar", o.radar ? "1" : "0"},
      {"live.frames", o.frames ? "1" : "0"},
  };
  if (r.date) {
    char d[16];
    std::snprintf(d, sizeof d, "%04d-%02d-%02d", (*r.date)[0], (*r.date)[1], (*r.date)[2]);
    m.emplace_back("settings.date", d);
  }
  if (r.variationDeg) m.emplace_back("settings.variation_deg", exactText(*r.variationDeg));
  return m;
}

sim::LiveOptions optionsFromMeta(const std::map<std::string, std::string>& m, const std::string& path) {
  sim::LiveOptions o;
  sim::ReplayOptions& r = o.replay;
  try {
    r.settings = parseScenario(need(m, "settings.scenario", path), "scenario");
  } catch (const io::InputError& e) {  // the scenario's own error, inside this file's
    bad(path, "meta.settings.scenario", e.what());
  }
  r.settingsName = need(m, "settings.name", path);
  r.originFromSettings = flag(m, "settings.origin_from_settings", path);
  r.assumeAssociation = flag(m, "settings.assume_association", path);
  r.maxGapS = number(m, "settings.max_gap_s", path, 0.0, 1e7);
  r.time.isolatedJumpUs = integer(m, "settings.isolated_jump_us", path, 0.0, 1e12);
  r.time.window = static_cast<int>(integer(m, "settings.time_window", path, 1.0, 1000.0));
  r.magneticHeadingSdDeg = number(m, "settings.magnetic_heading_sd_deg", path, 0.0, 180.0);
  r.sourceHoldS = number(m, "settings.source_hold_s", path, 0.0, 1e7);
  r.sweepFromPlots = flag(m, "settings.sweep_from_plots", path);
  if (m.contains("settings.date")) {
    const std::string& d = m.at("settings.date");
    int y = 0, mo = 0, day = 0;
    if (d.size() != 10 || std::sscanf(d.c_str(), "%4d-%2d-%2d", &y, &mo, &day) != 3)
      bad(path, "meta.settings.date", "expected YYYY-MM-DD, got " + io::quoted(d));
    r.date = std::array<int, 3>{y, mo, day};
  }
  if (m.contains("settings.variation_deg"))
    r.variationDeg = number(m, "settings.variation_deg", path, -180.0, 180.0);
  o.name = need(m, "live.name", path);
  o.reorderHorizonS = number(m, "live.reorder_horizon_s", path, 0.0, 60.0);
  o.radar = flag(m, "live.radar", path);
  o.frames = flag(m, "live.frames", path);
  return o;
}

}  // namespace reckoner::files::voyage
