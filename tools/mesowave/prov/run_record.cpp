#include "mesowave/prov/run_record.hpp"

#include <cmath>
#include <stdexcept>

#include "mesowave/io/sha256.hpp"

namespace mesowave::prov {
namespace fs = std::filesystem;

FileRecord describe_file(const fs::path& path, const fs::path& content_path) {
  FileRecord file;
  file.path = fs::absolute(path).lexically_normal().string();
  file.size_bytes = std::int64_t(fs::file_size(content_path));
  file.sha256 = io::sha256_file(content_path);
  return file;
}

FileRecord describe_file(const fs::path& path) { return describe_file(path, path); }

std::int64_t record_run(const Database& db, const RunRecord& run) {
  Transaction transaction(db);
  auto insert = db.prepare(
      "INSERT INTO runs (tool, version, binary_sha256, argv, params, cwd, host, started_at, ended_at,"
      " exit_status, error, wall_s, cpu_s, peak_rss_kib) VALUES (?,?,?,?,?,?,?,?,?,?,?,?,?,?)");
  insert.bind(1, run.tool).bind(2, run.version).bind(3, run.binary_sha256);
  insert.bind(4, nlohmann::json(run.argv).dump()).bind(5, run.params.dump());
  insert.bind(6, run.cwd).bind(7, run.host).bind(8, run.started_at).bind(9, run.ended_at);
  insert.bind(10, std::int64_t(run.exit_status));
  if (run.error.empty()) insert.bind_null(11);
  else insert.bind(11, run.error);
  insert.bind(12, run.wall_s).bind(13, run.cpu_s).bind(14, run.peak_rss_kib);
  insert.run();
  const std::int64_t id = sqlite3_last_insert_rowid(db.handle());

  auto file = db.prepare("INSERT OR REPLACE INTO files (run_id, role, path, size_bytes, sha256) VALUES (?,?,?,?,?)");
  auto add_files = [&](const std::vector<FileRecord>& files, std::string_view role) {
    for (const auto& f : files) {
      file.bind(1, id).bind(2, role).bind(3, f.path).bind(4, f.size_bytes).bind(5, f.sha256);
      file.run();
    }
  };
  add_files(run.inputs, "input");
  add_files(run.outputs, "output");

  auto metric = db.prepare("INSERT OR REPLACE INTO metrics (run_id, name, value, unit) VALUES (?,?,?,?)");
  for (const auto& m : run.metrics) {
    if (!std::isfinite(m.value)) throw std::logic_error("metric " + m.name + " is not finite");
    metric.bind(1, id).bind(2, m.name).bind(3, m.value).bind(4, m.unit);
    metric.run();
  }
  transaction.commit();
  return id;
}

}  // namespace mesowave::prov
