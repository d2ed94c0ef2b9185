#include "files/sqlite_db.h"

#include <sqlite3.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <system_error>

#include "io/input_error.h"

namespace reckoner::files::sqlite {
namespace {

/// SQLite's message, with what it means for a user where SQLite's own words are terse.
std::string explain(sqlite3* db, int code) {
  std::string said = db ? sqlite3_errmsg(db) : sqlite3_errstr(code);  // not const: returned by move
  switch (code & 0xff) {
    case SQLITE_NOTADB:
      return "not a SQLite database (" + said + ")";
    case SQLITE_CORRUPT:
      return "the database is damaged (" + said + ")";
    case SQLITE_FULL:
      return "the disk is full (" + said + ")";
    default:
      return said;
  }
}

/// How long a reader waits for a writer's lock (a checkpoint, WAL recovery) before giving up, ms.
constexpr int kBusyTimeoutMs = 5000;

}  // namespace

Db::Db(std::string path, Mode mode) : path_(std::move(path)) {
  std::error_code ec;
  const bool exists = std::filesystem::exists(path_, ec);
  if (mode == Mode::ReadOnly && !exists) throw io::InputError(path_, 0, "", "cannot open: no such file");
  if (mode == Mode::ReadOnly && std::filesystem::is_directory(path_, ec))
    throw io::InputError(path_, 0, "", "cannot open: a folder, not a file");
  if (mode == Mode::Create && exists)
    throw io::InputError(path_, 0, "", "exists already: a voyage record is never written over");
  const int flags =
      mode == Mode::ReadOnly ? SQLITE_OPEN_READONLY : SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE;
  const int rc = sqlite3_open_v2(path_.c_str(), &db_, flags | SQLITE_OPEN_NOMUTEX, nullptr);
  if (rc != SQLITE_OK) {
    const std::string why = explain(db_, rc);
    sqlite3_close(db_);
    db_ = nullptr;
    throw io::InputError(path_, 0, "", "cannot open: " + why);
  }
  sqlite3_extended_result_codes(db_, 1);
  sqlite3_busy_timeout(db_, kBusyTimeoutMs);
}

Db::~Db() {
  sqlite3_close_v2(db_);
}

void Db::exec(std::string_view sql) {
  const std::string s(sql);
  char* message = nullptr;
  const int rc = sqlite3_exec(db_, s.c_str(), nullptr, nullptr, &message);
  sqlite3_free(message);
  if (rc != SQLITE_OK) fail(s.substr(0, s.find_first_of("(;")));
}

void Db::fail(const std::string& context) const {
  const int code = sqlite3_extended_errcode(db_);
  // A file that is not a database, or a damaged one, is that whatever was asked of it.
  const bool ofTheFile = (code & 0xff) == SQLITE_NOTADB || (code & 0xff) == SQLITE_CORRUPT;
  throw io::InputError(path_, 0, "", (ofTheFile ? "" : context + ": ") + explain(db_, code));
}

void Db::syncWal() {
  sqlite3_file* wal = nullptr;
  if (sqlite3_file_control(db_, "main", SQLITE_FCNTL_JOURNAL_POINTER, &wal) != SQLITE_OK || !wal ||
      !wal->pMethods)
    return;  // no write-ahead log open yet: nothing to make durable
  if (const int rc = wal->pMethods->xSync(wal, SQLITE_SYNC_NORMAL); rc != SQLITE_OK)
    throw io::InputError(path_, 0, "", "sync of the write-ahead log failed: " + explain(nullptr, rc));
}

std::int64_t Db::changes() const {
  return sqlite3_changes64(db_);
}

std::int64_t Db::lastInsertId() const {
  return sqlite3_last_insert_rowid(db_);
}

Statement::Statement(Db& db, std::string_view sql) : db_(db) {
  if (sqlite3_prepare_v3(db.handle(), sql.data(), static_cast<int>(sql.size()), SQLITE_PREPARE_PERSISTENT,
                         &s_, nullptr) != SQLITE_OK)
    db.fail(std::string(sql.substr(0, 60)));
}

Statement::~Statement() {
  sqlite3_finalize(s_);
}

Statement& Statement::bindInteger(int i, std::int64_t v) {
  if (sqlite3_bind_int64(s_, i, v) != SQLITE_OK) db_.fail("bind");
  return *this;
}

Statement& Statement::bind(int i, double v) {
  if (!std::isfinite(v)) return bindNull(i);
  if (sqlite3_bind_double(s_, i, v) != SQLITE_OK) db_.fail("bind");
  return *this;
}

Statement& Statement::bind(int i, std::string_view text) {
  if (sqlite3_bind_text64(s_, i, text.data(), text.size(), SQLITE_TRANSIENT, SQLITE_UTF8) != SQLITE_OK)
    db_.fail("bind");
  return *this;
}

Statement& Statement::bind(int i, std::optional<std::int64_t> v) {
  return v ? bindInteger(i, *v) : bindNull(i);
}

Statement& Statement::bindNull(int i) {
  if (sqlite3_bind_null(s_, i) != SQLITE_OK) db_.fail("bind");
  return *this;
}

bool Statement::step() {
  const int rc = sqlite3_step(s_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  try {
    db_.fail(std::string(std::string_view(sqlite3_sql(s_)).substr(0, 60)));
  } catch (...) {
    sqlite3_reset(s_);  // after the message is composed: it may clear it
    throw;
  }
}

void Statement::run() {
  while (step()) {
  }
  reset();
}

void Statement::reset() {
  sqlite3_reset(s_);
  sqlite3_clear_bindings(s_);
}

bool Statement::isNull(int col) const {
  return sqlite3_column_type(s_, col) == SQLITE_NULL;
}

std::int64_t Statement::integer(int col) const {
  return sqlite3_column_int64(s_, col);
}

double Statement::real(int col) const {
  return isNull(col) ? std::numeric_limits<double>::quiet_NaN() : sqlite3_column_double(s_, col);
}

std::string Statement::text(int col) const {
  const auto* p = reinterpret_cast<const char*>(sqlite3_column_text(s_, col));
  return p ? std::string(p, static_cast<std::size_t>(sqlite3_column_bytes(s_, col))) : std::string();
}

std::optional<std::int64_t> Statement::optionalInteger(int col) const {
  if (isNull(col)) return std::nullopt;
  return integer(col);
}

}  // namespace reckoner::files::sqlite
