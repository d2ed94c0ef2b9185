#pragma once
// The voyage record's schema (docs/recorder.md): its tables and columns, in one list that both the
// writer's DDL and the reader's checks are made from, and the run's settings as `meta` rows (so a
// recording replays with the settings it was made with, whatever the program's built-ins are by then).
#include <map>
#include <string>
#include <vector>

#include "sim/live_session.h"

namespace reckoner::files::sqlite {
class Db;
}

namespace reckoner::files::voyage {

/// The schema this program writes and reads (meta.schema_version).
inline constexpr int kSchemaVersion = 1;

struct Column {
  const char* name;
  const char* type;  ///< SQL type and constraints
};
struct Table {
  const char* name;
  std::vector<Column> columns;
  std::vector<const char*> indexes;  ///< CREATE INDEX statements
};
/// Every table of a voyage record.
const std::vector<Table>& tables();

/// Creates every table and index (in the caller's transaction).
void createSchema(sqlite::Db& db);
/// The meta table as a map. Throws io::InputError naming the file when it is not a voyage record of
/// kSchemaVersion: no meta table, no or a bad schema_version, another version, a table or a column
/// missing.
std::map<std::string, std::string> checkSchema(sqlite::Db& db);

/// The settings of a live run as meta rows ("settings.*", "live.*"); the scenario as its JSON text.
std::vector<std::pair<std::string, std::string>> optionsMeta(const sim::LiveOptions& o);
/// Those rows read back (path names the file in errors). Throws io::InputError naming the key.
sim::LiveOptions optionsFromMeta(const std::map<std::string, std::string>& meta, const std::string& path);

/// A double as text that reads back to the same double (%.17g).
std::string exactText(double v);

}  // namespace reckoner::files::voyage
