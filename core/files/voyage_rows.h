#pragma once
// The voyage record's rows both ways (files/voyage_schema.h's column order): an own-ship row, a track
// row and an alert log entry bound to an INSERT and read back from a SELECT of the same columns, side by
// side so the two orders cannot drift apart. Internal to files/.
#include <string>

#include "files/voyage_record.h"
#include "files/voyage_schema.h"

namespace reckoner::files::sqlite {
class Statement;
}

namespace reckoner::files::voyage {

/// "INSERT INTO t(c1, ...) VALUES(?1, ...)" of every column but the key (seq, id).
std::string insertSql(const char* table);
/// "SELECT c1, ... FROM t" of the same columns.
std::string selectSql(const char* table);

void bindOwnRow(sqlite::Statement& s, const sim::ReplayOwnRow& r, bool minute);
sim::ReplayOwnRow readOwnRow(const sqlite::Statement& s);

void bindTrack(sqlite::Statement& s, const RecordedTrack& t, bool minute);
RecordedTrack readTrack(const sqlite::Statement& s);

void bindAlert(sqlite::Statement& s, const RecordedAlert& a);
RecordedAlert readAlert(const sqlite::Statement& s);

}  // namespace reckoner::files::voyage
