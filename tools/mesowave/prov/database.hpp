#pragma once
// The provenance database: a SQLite file in WAL mode with a busy timeout, so
// that many tools started at once by `make -j` each add their run in one short
// transaction without "database is locked" reaching the user. All SQL is
// prepared with bound parameters; nothing a user typed is pasted into SQL.
#include <sqlite3.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace mesowave::prov {

/// A prepared statement; bind with 1-based indices, step() until false.
class Statement {
public:
  Statement(sqlite3* db, std::string_view sql);
  Statement(Statement&& other) noexcept;
  Statement(const Statement&) = delete;
  ~Statement();

  Statement& bind(int index, std::string_view text);
  Statement& bind(int index, std::int64_t value);
  Statement& bind(int index, double value);
  Statement& bind_null(int index);
  /// Binds a value as it is (any type; NULL included), e.g. one read from another database.
  Statement& bind(int index, const sqlite3_value* value);
  /// Advances to the next row; false when done.
  bool step();
  /// Runs to completion, for statements that return no rows, then resets
  /// the statement so it can be bound and run again.
  void run();
  /// Rewinds the statement so it can be stepped again; bindings are kept until rebound.
  void reset();

  std::string text(int column) const;
  std::int64_t integer(int column) const;
  double real(int column) const;
  /// The column of the current row as SQLite holds it, valid until the next step or reset.
  const sqlite3_value* value(int column) const;
  int column_count() const;
  std::string column_name(int column) const;

private:
  sqlite3* db_;
  sqlite3_stmt* stmt_ = nullptr;
};

class Database {
public:
  enum class Mode { ReadWrite, ReadOnly };

  /// Opens (ReadWrite: creating it if absent) and validates a provenance
  /// database. InputError, never a crash or a silently new empty database, for
  /// a missing or read-only directory, an unwritable file, a file that is not
  /// SQLite (corrupt) or a SQLite file that is not a mesowave database.
  static Database open(const std::filesystem::path& path, Mode mode = Mode::ReadWrite);

  Database(Database&& other) noexcept;
  Database(const Database&) = delete;
  ~Database();

  Statement prepare(std::string_view sql) const { return Statement(db_, sql); }
  /// Executes SQL text without parameters (schema, BEGIN/COMMIT).
  void exec(std::string_view sql) const;
  const std::filesystem::path& path() const { return path_; }
  sqlite3* handle() const { return db_; }

private:
  Database(sqlite3* db, std::filesystem::path path) : db_(db), path_(std::move(path)) {}
  sqlite3* db_;
  std::filesystem::path path_;
};

/// RAII `BEGIN IMMEDIATE ... COMMIT`: the write lock is taken up front (and
/// waited for under the busy timeout), so two writers can never deadlock by
/// both upgrading a read lock. Rolls back if not committed.
class Transaction {
public:
  explicit Transaction(const Database& db);
  ~Transaction();
  void commit();

private:
  const Database& db_;
  bool open_ = true;
};

}  // namespace mesowave::prov
