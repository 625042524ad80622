#include "mesowave/prov/merge.hpp"

#include <sqlite3.h>

#include <algorithm>
#include <memory>
#include <new>
#include <optional>
#include <tuple>

#include "mesowave/core/error.hpp"
#include "mesowave/prov/database.hpp"

namespace mesowave::prov {
namespace fs = std::filesystem;

extern const char* const kSchemaSql;

namespace {

struct ValueFree {
  void operator()(sqlite3_value* v) const { sqlite3_value_free(v); }
};
using Value = std::unique_ptr<sqlite3_value, ValueFree>;
using Row = std::vector<Value>;

// The schema version and the columns of the three tables, the key each is merged under
// (runs.id is renumbered, files.run_id and metrics.run_id follow it) left out.
struct Columns {
  std::string version;
  std::vector<std::string> runs, files, metrics;
  bool operator==(const Columns&) const = default;
};

std::vector<std::string> columns_of(sqlite3* db, const char* table, const char* key) {
  sqlite3_stmt* stmt = nullptr;
  std::vector<std::string> names;
  if (sqlite3_prepare_v2(db, "SELECT name FROM pragma_table_info(?) ORDER BY cid", -1, &stmt, nullptr) == SQLITE_OK) {
    sqlite3_bind_text(stmt, 1, table, -1, SQLITE_STATIC);
    while (sqlite3_step(stmt) == SQLITE_ROW) {
      const std::string name = reinterpret_cast<const char*>(sqlite3_column_text(stmt, 0));
      if (name != key) names.push_back(name);
    }
  }
  sqlite3_finalize(stmt);
  return names;
}

Columns columns_of(sqlite3* db) {
  std::string version;
  sqlite3_stmt* stmt = nullptr;
  if (sqlite3_prepare_v2(db, "SELECT value FROM meta WHERE key = 'schema_version'", -1, &stmt, nullptr) == SQLITE_OK &&
      sqlite3_step(stmt) == SQLITE_ROW)
    version = reinterpret_cast<const char*>(sqlite3_column_text(stmt, 0));
  sqlite3_finalize(stmt);
  return {version, columns_of(db, "runs", "id"), columns_of(db, "files", "run_id"), columns_of(db, "metrics", "run_id")};
}

// The tables as this build creates them (db/schema.sql, compiled in), from a database in memory.
Columns schema_columns() {
  sqlite3* db = nullptr;
  if (sqlite3_open(":memory:", &db) != SQLITE_OK ||
      sqlite3_exec(db, kSchemaSql, nullptr, nullptr, nullptr) != SQLITE_OK) {
    sqlite3_close(db);
    throw std::runtime_error("cannot apply the provenance schema to a database in memory");
  }
  Columns columns = columns_of(db);
  sqlite3_close(db);
  return columns;
}

std::string joined(const std::vector<std::string>& names, const std::string& separator, const std::string& suffix = "") {
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i) s += (i ? separator : "") + names[i] + suffix;
  return s;
}

std::string placeholders(std::size_t n) {
  std::string s;
  for (std::size_t i = 0; i < n; ++i) s += i ? ",?" : "?";
  return s;
}

Row copy_row(const Statement& row, int first_column) {
  Row copy;
  for (int c = first_column; c < row.column_count(); ++c) {
    sqlite3_value* v = sqlite3_value_dup(row.value(c));
    if (!v) throw std::bad_alloc();
    copy.emplace_back(v);
  }
  return copy;
}

void bind_row(Statement& statement, const Row& row, int first_index) {
  for (std::size_t i = 0; i < row.size(); ++i) statement.bind(first_index + int(i), row[i].get());
}

struct SourceRun {
  std::size_t source = 0;
  std::int64_t id = 0;
  std::string ended_at, started_at;
  Row record;                      // every column of runs but id
  std::vector<Row> files, metrics;  // every column but run_id, in rowid order
};

void check_columns(const Columns& found, const Columns& expected, const std::string& what) {
  if (found.version != expected.version)
    throw InputError(what + " is of schema version '" + found.version + "', not " + expected.version +
                     " (this build's, db/schema.sql)");
  if (found != expected)
    throw InputError(what + " has other columns than this build's provenance schema (db/schema.sql): runs (" +
                     joined(found.runs, ",") + "), files (" + joined(found.files, ",") + "), metrics (" +
                     joined(found.metrics, ",") + ")");
}

std::vector<SourceRun> read_source(const fs::path& path, std::size_t index, const Columns& expected) {
  const auto db = Database::open(path, Database::Mode::ReadOnly);
  const std::string shown = "database " + path.string();
  // One read transaction: a snapshot, so that a run another process commits meanwhile (make -j
  // merging its steps) is either wholly in what is read or not at all.
  db.exec("BEGIN");
  {
    auto tables = db.prepare("SELECT count(*) FROM sqlite_master");
    tables.step();
    if (tables.integer(0) == 0) return {};  // an empty file: a job whose tools recorded nothing
  }
  check_columns(columns_of(db.handle()), expected, shown);

  std::vector<SourceRun> runs;
  auto select = db.prepare("SELECT id, " + joined(expected.runs, ", ") + " FROM runs ORDER BY id");
  const auto column = [&](const std::string& name) {
    return int(std::find(expected.runs.begin(), expected.runs.end(), name) - expected.runs.begin()) + 1;
  };
  const int ended = column("ended_at"), started = column("started_at");
  while (select.step()) {
    SourceRun run;
    run.source = index;
    run.id = select.integer(0);
    run.ended_at = select.text(ended);
    run.started_at = select.text(started);
    run.record = copy_row(select, 1);
    runs.push_back(std::move(run));
  }
  auto files = db.prepare("SELECT run_id, " + joined(expected.files, ", ") + " FROM files ORDER BY run_id, rowid");
  auto metrics =
      db.prepare("SELECT run_id, " + joined(expected.metrics, ", ") + " FROM metrics ORDER BY run_id, rowid");
  // runs is in id order: attach each child row to its run by binary search.
  const auto owner = [&](std::int64_t id) -> SourceRun& {
    auto it = std::lower_bound(runs.begin(), runs.end(), id, [](const SourceRun& r, std::int64_t v) { return r.id < v; });
    if (it == runs.end() || it->id != id)
      throw InputError(shown + " has files or metrics of run " + std::to_string(id) + ", which it does not hold");
    return *it;
  };
  while (files.step()) owner(files.integer(0)).files.push_back(copy_row(files, 1));
  while (metrics.step()) owner(metrics.integer(0)).metrics.push_back(copy_row(metrics, 1));
  db.exec("COMMIT");
  return runs;
}

std::int64_t count_rows(const Database& db, const char* table) {
  auto count = db.prepare(std::string("SELECT count(*) FROM ") + table);
  count.step();
  return count.integer(0);
}

}  // namespace

MergeResult merge_databases(const fs::path& into, const std::vector<fs::path>& sources) {
  const Columns expected = schema_columns();
  const fs::path target_path = fs::weakly_canonical(fs::absolute(into));

  // Every source read before the target is opened: a bad one leaves everything as it was.
  MergeResult result;
  std::vector<SourceRun> runs;
  for (std::size_t i = 0; i < sources.size(); ++i) {
    if (fs::weakly_canonical(fs::absolute(sources[i])) == target_path)
      throw InputError("database " + sources[i].string() + " is the database merged into (--into)");
    auto read = read_source(sources[i], i, expected);
    result.sources.push_back({sources[i].string(), std::int64_t(read.size())});
    std::move(read.begin(), read.end(), std::back_inserter(runs));
  }
  // The order the runs would have recorded themselves in one database: as each ended.
  std::sort(runs.begin(), runs.end(), [](const SourceRun& a, const SourceRun& b) {
    return std::tie(a.ended_at, a.started_at, a.source, a.id) < std::tie(b.ended_at, b.started_at, b.source, b.id);
  });

  const auto db = Database::open(into);
  check_columns(columns_of(db.handle()), expected, "database " + into.string());
  Transaction transaction(db);
  result.runs_before = count_rows(db, "runs");
  result.files_before = count_rows(db, "files");
  result.metrics_before = count_rows(db, "metrics");

  auto find = db.prepare("SELECT id FROM runs WHERE " + joined(expected.runs, " AND ", " IS ?") + " ORDER BY id");
  auto files_of = db.prepare("SELECT count(*) FROM files WHERE run_id = ?");
  auto file_there = db.prepare("SELECT count(*) FROM files WHERE run_id = ? AND " + joined(expected.files, " AND ", " IS ?"));
  auto metrics_of = db.prepare("SELECT count(*) FROM metrics WHERE run_id = ?");
  auto metric_there =
      db.prepare("SELECT count(*) FROM metrics WHERE run_id = ? AND " + joined(expected.metrics, " AND ", " IS ?"));
  auto add_run = db.prepare("INSERT INTO runs (" + joined(expected.runs, ", ") + ") VALUES (" +
                            placeholders(expected.runs.size()) + ")");
  auto add_file = db.prepare("INSERT INTO files (run_id, " + joined(expected.files, ", ") + ") VALUES (?," +
                             placeholders(expected.files.size()) + ")");
  auto add_metric = db.prepare("INSERT INTO metrics (run_id, " + joined(expected.metrics, ", ") + ") VALUES (?," +
                               placeholders(expected.metrics.size()) + ")");
  const auto count = [](Statement& query) {
    query.step();
    const std::int64_t n = query.integer(0);
    query.reset();
    return n;
  };
  // A run already there must have the same files and metrics (each row is unique by its key).
  const auto same_children = [&](std::int64_t id, const std::vector<Row>& rows, Statement& all, Statement& one) {
    all.bind(1, id);
    if (count(all) != std::int64_t(rows.size())) return false;
    for (const auto& row : rows) {
      one.bind(1, id);
      bind_row(one, row, 2);
      if (count(one) != 1) return false;
    }
    return true;
  };

  for (const auto& run : runs) {
    auto& counts = result.sources[run.source];
    bind_row(find, run.record, 1);
    std::optional<std::int64_t> present;
    if (find.step()) present = find.integer(0);
    find.reset();
    if (present) {
      if (!same_children(*present, run.files, files_of, file_there) ||
          !same_children(*present, run.metrics, metrics_of, metric_there))
        throw InputError("run " + std::to_string(run.id) + " of " + counts.path + " has the record of run " +
                         std::to_string(*present) + " of " + into.string() +
                         " but other files or metrics; nothing was merged");
      ++counts.runs_present;
      continue;
    }
    bind_row(add_run, run.record, 1);
    add_run.run();
    const std::int64_t id = sqlite3_last_insert_rowid(db.handle());
    for (const auto& row : run.files) {
      add_file.bind(1, id);
      bind_row(add_file, row, 2);
      add_file.run();
    }
    for (const auto& row : run.metrics) {
      add_metric.bind(1, id);
      bind_row(add_metric, row, 2);
      add_metric.run();
    }
    ++counts.runs_added;
    counts.files_added += std::int64_t(run.files.size());
    counts.metrics_added += std::int64_t(run.metrics.size());
  }
  result.runs_after = count_rows(db, "runs");
  result.files_after = count_rows(db, "files");
  result.metrics_after = count_rows(db, "metrics");
  transaction.commit();
  return result;
}

}  // namespace mesowave::prov
