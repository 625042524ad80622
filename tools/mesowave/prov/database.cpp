#include "mesowave/prov/database.hpp"

#include <unistd.h>

#include <chrono>
#include <thread>

#include "mesowave/core/error.hpp"

namespace mesowave::prov {
namespace fs = std::filesystem;

extern const char* const kSchemaSql;

namespace {

// Long enough for 16 tools committing at once on a loaded 2-core machine.
constexpr int kBusyTimeoutMs = 60'000;

[[noreturn]] void fail(sqlite3* db, std::string_view what) {
  throw std::runtime_error(std::string(what) + ": " + (db ? sqlite3_errmsg(db) : "out of memory"));
}

}  // namespace

// ---- Statement --------------------------------------------------------------

Statement::Statement(sqlite3* db, std::string_view sql) : db_(db) {
  if (sqlite3_prepare_v2(db, sql.data(), int(sql.size()), &stmt_, nullptr) != SQLITE_OK)
    fail(db, "cannot prepare SQL");
}

Statement::Statement(Statement&& other) noexcept : db_(other.db_), stmt_(other.stmt_) { other.stmt_ = nullptr; }

Statement::~Statement() { sqlite3_finalize(stmt_); }

Statement& Statement::bind(int index, std::string_view text) {
  if (sqlite3_bind_text(stmt_, index, text.data(), int(text.size()), SQLITE_TRANSIENT) != SQLITE_OK)
    fail(db_, "cannot bind text");
  return *this;
}

Statement& Statement::bind(int index, std::int64_t value) {
  if (sqlite3_bind_int64(stmt_, index, value) != SQLITE_OK) fail(db_, "cannot bind integer");
  return *this;
}

Statement& Statement::bind(int index, double value) {
  if (sqlite3_bind_double(stmt_, index, value) != SQLITE_OK) fail(db_, "cannot bind real");
  return *this;
}

Statement& Statement::bind_null(int index) {
  if (sqlite3_bind_null(stmt_, index) != SQLITE_OK) fail(db_, "cannot bind null");
  return *this;
}

Statement& Statement::bind(int index, const sqlite3_value* value) {
  if (sqlite3_bind_value(stmt_, index, value) != SQLITE_OK) fail(db_, "cannot bind value");
  return *this;
}

bool Statement::step() {
  const int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  fail(db_, "provenance database");
}

void Statement::run() {
  while (step()) {
  }
  sqlite3_reset(stmt_);
  sqlite3_clear_bindings(stmt_);
}

void Statement::reset() { sqlite3_reset(stmt_); }

std::string Statement::text(int column) const {
  const auto* p = sqlite3_column_text(stmt_, column);
  return p ? std::string(reinterpret_cast<const char*>(p), std::size_t(sqlite3_column_bytes(stmt_, column)))
           : std::string();
}

std::int64_t Statement::integer(int column) const { return sqlite3_column_int64(stmt_, column); }
double Statement::real(int column) const { return sqlite3_column_double(stmt_, column); }
const sqlite3_value* Statement::value(int column) const { return sqlite3_column_value(stmt_, column); }
int Statement::column_count() const { return sqlite3_column_count(stmt_); }
std::string Statement::column_name(int column) const { return sqlite3_column_name(stmt_, column); }

// ---- Database ---------------------------------------------------------------

Database::Database(Database&& other) noexcept : db_(other.db_), path_(std::move(other.path_)) {
  other.db_ = nullptr;
}

Database::~Database() { sqlite3_close_v2(db_); }

void Database::exec(std::string_view sql) const {
  char* message = nullptr;
  const std::string text(sql);
  if (sqlite3_exec(db_, text.c_str(), nullptr, nullptr, &message) != SQLITE_OK) {
    std::string what = message ? message : sqlite3_errmsg(db_);
    sqlite3_free(message);
    throw std::runtime_error("provenance database: " + what);
  }
}

Database Database::open(const fs::path& given, Mode mode) {
  const fs::path path = fs::absolute(given).lexically_normal();
  const std::string shown = given.string();
  const fs::path dir = path.parent_path();
  if (!fs::is_directory(dir))
    throw InputError("database directory " + dir.string() + " does not exist (for --db " + shown + ")");
  const bool exists = fs::exists(path);
  if (exists && !fs::is_regular_file(path)) throw InputError("database " + shown + " is not a regular file");
  if (mode == Mode::ReadOnly && !exists) throw InputError("database " + shown + " does not exist");
  if (mode == Mode::ReadWrite) {
    // WAL needs to create -wal and -shm files beside the database.
    if (::access(dir.c_str(), W_OK) != 0)
      throw InputError("database directory " + dir.string() + " is not writable (for --db " + shown + ")");
    if (exists && ::access(path.c_str(), W_OK) != 0) throw InputError("database " + shown + " is read-only");
  }

  const int flags = (mode == Mode::ReadOnly) ? SQLITE_OPEN_READONLY
                                             : (SQLITE_OPEN_READWRITE | (exists ? 0 : SQLITE_OPEN_CREATE));
  sqlite3* handle = nullptr;
  if (sqlite3_open_v2(path.c_str(), &handle, flags | SQLITE_OPEN_NOMUTEX, nullptr) != SQLITE_OK) {
    std::string why = handle ? sqlite3_errmsg(handle) : "out of memory";
    sqlite3_close_v2(handle);
    throw InputError("cannot open database " + shown + ": " + why);
  }
  Database db(handle, path);
  sqlite3_busy_timeout(handle, kBusyTimeoutMs);
  sqlite3_extended_result_codes(handle, 1);

  // Reading the header is what tells a database from a corrupt file. A
  // zero-length file is a database with no tables yet.
  sqlite3_stmt* probe = nullptr;
  int rc = sqlite3_prepare_v2(handle, "SELECT count(*) FROM sqlite_master", -1, &probe, nullptr);
  std::int64_t tables = 0;
  if (rc == SQLITE_OK) {
    rc = sqlite3_step(probe);
    if (rc == SQLITE_ROW) tables = sqlite3_column_int64(probe, 0);
  }
  sqlite3_finalize(probe);
  if (rc != SQLITE_ROW) {
    const int primary = sqlite3_extended_errcode(handle) & 0xff;
    if (primary == SQLITE_NOTADB || primary == SQLITE_CORRUPT)
      throw InputError("database " + shown + " is not a SQLite database (corrupt, or another kind of file); "
                       "it was left untouched");
    throw InputError("cannot read database " + shown + ": " + sqlite3_errmsg(handle));
  }

  if (tables > 0) {
    sqlite3_stmt* meta = nullptr;
    bool ours = sqlite3_prepare_v2(handle, "SELECT value FROM meta WHERE key = 'application'", -1, &meta,
                                   nullptr) == SQLITE_OK &&
                sqlite3_step(meta) == SQLITE_ROW;
    sqlite3_finalize(meta);
    if (!ours)
      throw InputError("database " + shown + " is a SQLite database but not a mesowave provenance database");
    Statement check = db.prepare("PRAGMA quick_check(1)");
    if (!check.step() || check.text(0) != "ok")
      throw InputError("database " + shown + " is corrupt (quick_check: " + check.text(0) + ")");
  }

  if (mode == Mode::ReadWrite) {
    // Switching to WAL takes an exclusive lock for an instant; another process
    // creating the same database at the same moment makes it report busy.
    for (int attempt = 0;; ++attempt) {
      char* message = nullptr;
      rc = sqlite3_exec(handle, "PRAGMA journal_mode = WAL", nullptr, nullptr, &message);
      sqlite3_free(message);
      if (rc == SQLITE_OK) break;
      if ((rc & 0xff) != SQLITE_BUSY || attempt > 600) fail(handle, "cannot switch the database to WAL mode");
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    db.exec("PRAGMA synchronous = NORMAL");
    if (tables == 0) {
      Transaction create(db);
      db.exec(kSchemaSql);
      create.commit();
    }
  }
  db.exec("PRAGMA foreign_keys = ON");
  return db;
}

// ---- Transaction ------------------------------------------------------------

Transaction::Transaction(const Database& db) : db_(db) { db_.exec("BEGIN IMMEDIATE"); }

Transaction::~Transaction() {
  if (open_) sqlite3_exec(db_.handle(), "ROLLBACK", nullptr, nullptr, nullptr);
}

void Transaction::commit() {
  db_.exec("COMMIT");
  open_ = false;
}

}  // namespace mesowave::prov
