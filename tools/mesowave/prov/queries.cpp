#include "mesowave/prov/queries.hpp"

#include <filesystem>
#include <functional>
#include <limits>
#include <set>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/io/sha256.hpp"

namespace mesowave::prov {
namespace fs = std::filesystem;

namespace {

constexpr const char* kSummaryColumns = "id, tool, version, started_at, exit_status, wall_s, error";

RunSummary summary_from(const Statement& row) {
  RunSummary s;
  s.id = row.integer(0);
  s.tool = row.text(1);
  s.version = row.text(2);
  s.started_at = row.text(3);
  s.exit_status = int(row.integer(4));
  s.wall_s = row.real(5);
  s.error = row.text(6);
  return s;
}

RunSummary summary_of(const Database& db, std::int64_t id) {
  auto row = db.prepare(std::string("SELECT ") + kSummaryColumns + " FROM runs WHERE id = ?");
  row.bind(1, id);
  if (!row.step()) throw InputError("no run " + std::to_string(id) + " in " + db.path().string());
  return summary_from(row);
}

std::vector<FileRecord> files_of(const Database& db, std::int64_t id, std::string_view role) {
  auto rows = db.prepare("SELECT path, size_bytes, sha256 FROM files WHERE run_id = ? AND role = ? ORDER BY rowid");
  rows.bind(1, id).bind(2, role);
  std::vector<FileRecord> files;
  while (rows.step()) files.push_back({rows.text(0), rows.integer(1), rows.text(2)});
  return files;
}

// The successful run that wrote `path` with content `sha256`, newest first and
// no newer than `before`; failing an exact match, the newest that wrote `path`.
std::optional<std::pair<std::int64_t, bool>> find_producer(const Database& db, const std::string& path,
                                                           const std::string& sha256, std::int64_t before) {
  auto exact = db.prepare(
      "SELECT f.run_id FROM files f JOIN runs r ON r.id = f.run_id WHERE f.path = ? AND f.role = 'output'"
      " AND f.sha256 = ? AND r.exit_status = 0 AND f.run_id < ? ORDER BY f.run_id DESC LIMIT 1");
  exact.bind(1, path).bind(2, sha256).bind(3, before);
  if (exact.step()) return std::make_pair(exact.integer(0), true);
  auto any = db.prepare(
      "SELECT f.run_id FROM files f JOIN runs r ON r.id = f.run_id WHERE f.path = ? AND f.role = 'output'"
      " AND r.exit_status = 0 AND f.run_id < ? ORDER BY f.run_id DESC LIMIT 1");
  any.bind(1, path).bind(2, before);
  if (any.step()) return std::make_pair(any.integer(0), false);
  return std::nullopt;
}

LineageNode trace(const Database& db, HashCache& hashes, std::string path, std::string sha256,
                  std::int64_t before, std::set<std::int64_t>& expanded) {
  LineageNode node;
  node.path = std::move(path);
  node.sha256 = std::move(sha256);
  node.current_sha256 = hashes(node.path);
  auto producer = find_producer(db, node.path, node.sha256, before);
  if (!producer) return node;
  node.producer = summary_of(db, producer->first);
  node.producer_matches = producer->second;
  if (!expanded.insert(producer->first).second) {
    node.expanded_elsewhere = true;
    return node;
  }
  for (const auto& input : files_of(db, producer->first, "input"))
    node.inputs.push_back(trace(db, hashes, input.path, input.sha256, producer->first, expanded));
  return node;
}

}  // namespace

const std::string& HashCache::operator()(const std::string& path) {
  auto it = hashes_.find(path);
  if (it != hashes_.end()) return it->second;
  std::string hash;
  std::error_code ec;
  if (fs::is_regular_file(path, ec)) hash = io::sha256_file(path);
  return hashes_.emplace(path, hash).first->second;
}

std::vector<RunSummary> list_runs(const Database& db, const RunFilter& filter) {
  std::string sql = std::string("SELECT ") + kSummaryColumns + " FROM runs";
  if (filter.tool) sql += " WHERE tool = ?1";
  sql += " ORDER BY id DESC";
  if (filter.limit) sql += " LIMIT ?2";
  auto rows = db.prepare(sql);
  if (filter.tool) rows.bind(1, *filter.tool);
  if (filter.limit) rows.bind(2, std::int64_t(filter.limit));
  std::vector<RunSummary> runs;
  while (rows.step()) runs.push_back(summary_from(rows));
  return {runs.rbegin(), runs.rend()};
}

RunRecord load_run(const Database& db, std::int64_t id) {
  auto row = db.prepare(
      "SELECT tool, version, binary_sha256, argv, params, cwd, host, started_at, ended_at, exit_status,"
      " error, wall_s, cpu_s, peak_rss_kib FROM runs WHERE id = ?");
  row.bind(1, id);
  if (!row.step()) throw InputError("no run " + std::to_string(id) + " in " + db.path().string());
  RunRecord run;
  run.tool = row.text(0);
  run.version = row.text(1);
  run.binary_sha256 = row.text(2);
  run.argv = nlohmann::json::parse(row.text(3)).get<std::vector<std::string>>();
  run.params = nlohmann::ordered_json::parse(row.text(4));
  run.cwd = row.text(5);
  run.host = row.text(6);
  run.started_at = row.text(7);
  run.ended_at = row.text(8);
  run.exit_status = int(row.integer(9));
  run.error = row.text(10);
  run.wall_s = row.real(11);
  run.cpu_s = row.real(12);
  run.peak_rss_kib = row.integer(13);
  run.inputs = files_of(db, id, "input");
  run.outputs = files_of(db, id, "output");
  auto metrics = db.prepare("SELECT name, value, unit FROM metrics WHERE run_id = ? ORDER BY rowid");
  metrics.bind(1, id);
  while (metrics.step()) run.metrics.push_back({metrics.text(0), metrics.real(1), metrics.text(2)});
  return run;
}

LineageNode lineage(const Database& db, const std::string& given) {
  const std::string path = fs::absolute(given).lexically_normal().string();
  HashCache hashes;
  const std::string current = hashes(path);
  auto known = db.prepare("SELECT 1 FROM files WHERE path = ? LIMIT 1");
  known.bind(1, path);
  if (current.empty() && !known.step())
    throw InputError(given + " does not exist and no run recorded it");
  std::set<std::int64_t> expanded;
  return trace(db, hashes, path, current, std::numeric_limits<std::int64_t>::max(), expanded);
}

std::vector<StaleInput> stale_inputs(const Database& db) {
  // The live run of each output path is the newest successful run that wrote it.
  auto live = db.prepare(
      "SELECT DISTINCT max(f.run_id) FROM files f JOIN runs r ON r.id = f.run_id"
      " WHERE f.role = 'output' AND r.exit_status = 0 GROUP BY f.path ORDER BY 1");
  std::vector<std::int64_t> runs;
  while (live.step()) runs.push_back(live.integer(0));

  HashCache hashes;
  std::vector<StaleInput> stale;
  for (std::int64_t id : runs) {
    std::vector<std::string> outputs;
    for (const auto& out : files_of(db, id, "output")) outputs.push_back(out.path);
    for (const auto& input : files_of(db, id, "input")) {
      const std::string& now = hashes(input.path);
      if (now == input.sha256) continue;
      stale.push_back({summary_of(db, id), input.path, input.sha256, now, outputs});
    }
  }
  return stale;
}

namespace {

void flatten(const nlohmann::ordered_json& j, const std::string& prefix, std::map<std::string, std::string>& out) {
  if (j.is_object()) {
    for (const auto& [k, v] : j.items()) flatten(v, prefix.empty() ? k : prefix + "." + k, out);
  } else {
    out[prefix] = j.is_string() ? j.get<std::string>() : j.dump();
  }
}

std::vector<RunDiff::Value> diff_maps(const std::map<std::string, std::string>& a,
                                      const std::map<std::string, std::string>& b) {
  std::set<std::string> keys;
  for (const auto& [k, v] : a) keys.insert(k);
  for (const auto& [k, v] : b) keys.insert(k);
  std::vector<RunDiff::Value> out;
  for (const auto& k : keys) {
    const auto ia = a.find(k), ib = b.find(k);
    const std::string va = ia == a.end() ? "" : ia->second, vb = ib == b.end() ? "" : ib->second;
    if (ia == a.end() || ib == b.end() || va != vb) out.push_back({k, va, vb});
  }
  return out;
}

std::map<std::string, std::string> file_map(const std::vector<FileRecord>& files) {
  std::map<std::string, std::string> m;
  for (const auto& f : files) m[f.path] = f.sha256;
  return m;
}

}  // namespace

RunDiff diff_runs(const Database& db, std::int64_t a, std::int64_t b) {
  const RunRecord ra = load_run(db, a), rb = load_run(db, b);
  RunDiff d;
  std::map<std::string, std::string> pa, pb;
  flatten(ra.params, "", pa);
  flatten(rb.params, "", pb);
  if (ra.tool != rb.tool) pa["(tool)"] = ra.tool, pb["(tool)"] = rb.tool;
  if (ra.version != rb.version) pa["(version)"] = ra.version, pb["(version)"] = rb.version;
  d.params = diff_maps(pa, pb);
  d.inputs = diff_maps(file_map(ra.inputs), file_map(rb.inputs));
  d.outputs = diff_maps(file_map(ra.outputs), file_map(rb.outputs));
  std::map<std::string, std::string> ma, mb;
  for (const auto& m : ra.metrics) ma[m.name] = format_exact(m.value) + (m.unit.empty() ? "" : " " + m.unit);
  for (const auto& m : rb.metrics) mb[m.name] = format_exact(m.value) + (m.unit.empty() ? "" : " " + m.unit);
  d.metrics = diff_maps(ma, mb);
  return d;
}

std::vector<OutputCheck> verify_outputs(const Database& db) {
  auto rows = db.prepare(
      "SELECT f.path, f.run_id, f.sha256 FROM files f JOIN runs r ON r.id = f.run_id"
      " WHERE f.role = 'output' AND r.exit_status = 0 AND f.run_id ="
      " (SELECT max(g.run_id) FROM files g JOIN runs s ON s.id = g.run_id"
      "  WHERE g.path = f.path AND g.role = 'output' AND s.exit_status = 0) ORDER BY f.path");
  HashCache hashes;
  std::vector<OutputCheck> checks;
  while (rows.step()) checks.push_back({rows.text(0), rows.integer(1), rows.text(2), hashes(rows.text(0))});
  return checks;
}

std::vector<MetricRow> metric_history(const Database& db, const std::string& name, const std::optional<std::string>& tool,
                                      const std::string& by_param) {
  std::string sql = std::string("SELECT r.id, r.tool, r.version, r.started_at, r.exit_status, r.wall_s, r.error,") +
                    " m.value, m.unit, r.params FROM metrics m JOIN runs r ON r.id = m.run_id WHERE m.name = ?1";
  if (tool) sql += " AND r.tool = ?2";
  sql += " ORDER BY r.id";
  auto rows = db.prepare(sql);
  rows.bind(1, name);
  if (tool) rows.bind(2, *tool);
  std::vector<MetricRow> out;
  while (rows.step()) {
    MetricRow row{summary_from(rows), rows.real(7), rows.text(8), ""};
    if (!by_param.empty()) {
      std::map<std::string, std::string> params;
      flatten(nlohmann::ordered_json::parse(rows.text(9)), "", params);
      // A bare option name matches it at any depth (a subcommand's options nest).
      for (const auto& [k, v] : params)
        if (k == by_param || (k.size() > by_param.size() && k.ends_with("." + by_param))) row.by_value = v;
    }
    out.push_back(std::move(row));
  }
  return out;
}

std::vector<ChangedUpstream> why_changed(const Database& db, const std::string& path) {
  const LineageNode root = lineage(db, path);
  std::vector<ChangedUpstream> changed;
  std::function<void(const LineageNode&, std::size_t)> walk = [&](const LineageNode& n, std::size_t depth) {
    if (!n.producer) return;
    for (const auto& input : n.inputs)
      if (input.current_sha256 != input.sha256)
        changed.push_back({input.path, input.sha256, input.current_sha256, *n.producer, depth});
    for (const auto& input : n.inputs) walk(input, depth + 1);
  };
  walk(root, 1);
  std::stable_sort(changed.begin(), changed.end(), [](const auto& a, const auto& b) { return a.depth < b.depth; });
  return changed;
}

}  // namespace mesowave::prov
