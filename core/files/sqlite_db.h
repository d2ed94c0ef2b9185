#pragma once
// A thin RAII layer on SQLite for the voyage record (files/voyage_record.h, docs/recorder.md): a
// connection, prepared statements, and every failure as one io::InputError naming the file and what
// SQLite said ("file is not a database", "database disk image is malformed", "disk I/O error"). Only
// files/ uses it; sqlite3.h stays in its .cpp files (SQLite::SQLite3 is linked PRIVATE).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

struct sqlite3;
struct sqlite3_stmt;

namespace reckoner::files::sqlite {

class Db;

/// A prepared statement: bind by 1-based index, step, read columns of the current row, reset.
class Statement {
 public:
  Statement(Db& db, std::string_view sql);
  ~Statement();
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  template <class T>
  requires std::is_integral_v<T> Statement& bind(int i, T v) {
    return bindInteger(i, static_cast<std::int64_t>(v));
  }
  /// NaN and infinities are stored as NULL (SQLite keeps no NaN); column() gives NaN back for NULL.
  Statement& bind(int i, double v);
  Statement& bind(int i, std::string_view text);
  Statement& bind(int i, std::optional<std::int64_t> v);
  Statement& bindInteger(int i, std::int64_t v);
  Statement& bindNull(int i);
  /// Binds the values in order from index 1.
  template <class... T>
  Statement& bindAll(const T&... v) {
    int i = 0;
    (bind(++i, v), ...);
    return *this;
  }
  /// Advances: true when a row is there to read, false when done. Throws io::InputError.
  bool step();
  /// step() for statements that return no row, then reset().
  void run();
  void reset();

  [[nodiscard]] bool isNull(int col) const;
  [[nodiscard]] std::int64_t integer(int col) const;
  [[nodiscard]] double real(int col) const;  ///< NaN for NULL
  [[nodiscard]] std::string text(int col) const;
  [[nodiscard]] std::optional<std::int64_t> optionalInteger(int col) const;

 private:
  Db& db_;
  sqlite3_stmt* s_ = nullptr;
};

/// One connection to one database file.
class Db {
 public:
  enum class Mode : std::uint8_t { ReadOnly, Create };
  /// ReadOnly: the file must exist. Create: the file must not exist (a recording is never written
  /// over). Throws io::InputError naming the path.
  Db(std::string path, Mode mode);
  ~Db();
  Db(const Db&) = delete;
  Db& operator=(const Db&) = delete;

  void exec(std::string_view sql);
  /// Throws io::InputError "PATH: context: SQLite's message".
  [[noreturn]] void fail(const std::string& context) const;
  /// Makes what the write-ahead log holds durable (fdatasync of the -wal file), without a checkpoint.
  void syncWal();
  /// Rows changed by the latest INSERT, UPDATE or DELETE; the row id of the latest INSERT.
  [[nodiscard]] std::int64_t changes() const;
  [[nodiscard]] std::int64_t lastInsertId() const;
  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] sqlite3* handle() const { return db_; }

 private:
  std::string path_;
  sqlite3* db_ = nullptr;
};

}  // namespace reckoner::files::sqlite
