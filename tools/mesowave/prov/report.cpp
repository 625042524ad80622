#include "mesowave/prov/report.hpp"

#include <map>
#include <set>
#include <sstream>

#include "mesowave/core/format.hpp"
#include "mesowave/io/text_table.hpp"
#include "mesowave/prov/run_status.hpp"

namespace mesowave::prov {
namespace fs = std::filesystem;

namespace {

std::string short_hash(const std::string& sha) { return sha.empty() ? "(none)" : sha.substr(0, 16); }

std::string status_text(int status) { return status_name(status); }

nlohmann::ordered_json summary_json(const RunSummary& r) {
  return {{"id", r.id},         {"tool", r.tool},       {"version", r.version}, {"started_at", r.started_at},
          {"exit_status", r.exit_status}, {"status", status_text(r.exit_status)}, {"wall_s", r.wall_s},
          {"error", r.error}};
}

std::string producer_text(const RunSummary& r) {
  return "run " + std::to_string(r.id) + " " + r.tool + " " + r.version + " " + r.started_at;
}

std::string node_flags(const LineageNode& n) {
  std::string flags;
  if (n.current_sha256.empty()) flags += "  MISSING now";
  else if (n.current_sha256 != n.sha256) flags += "  CHANGED since (now " + short_hash(n.current_sha256) + ")";
  if (n.producer && !n.producer_matches) flags += "  (newest run to write it wrote other content)";
  return flags;
}

void tree_lines(const LineageNode& n, const fs::path& base, const std::string& prefix, bool root, bool last,
                std::ostringstream& out) {
  const std::string branch = root ? "" : (last ? "└── " : "├── ");
  out << prefix << branch << display_path(n.path, base) << "  sha256:" << short_hash(n.sha256);
  if (n.producer) out << "  <- " << producer_text(*n.producer) << (n.expanded_elsewhere ? " (shown above)" : "");
  else out << "  (source: no recorded run made it)";
  out << node_flags(n) << "\n";
  const std::string child_prefix = root ? "" : prefix + (last ? "    " : "│   ");
  for (std::size_t i = 0; i < n.inputs.size(); ++i)
    tree_lines(n.inputs[i], base, child_prefix, false, i + 1 == n.inputs.size(), out);
}

std::string dot_escape(const std::string& s) {
  std::string e;
  for (char c : s) e += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return e;
}

// One DOT node per (path, content) pair: two versions of a file are two nodes.
std::string file_node_id(const LineageNode& n) { return "f_" + std::to_string(std::hash<std::string>{}(n.path + n.sha256)); }

void dot_nodes(const LineageNode& n, const fs::path& base, std::set<std::string>& seen, std::ostringstream& out) {
  const std::string file_id = file_node_id(n);
  if (seen.insert(file_id).second)
    out << "  \"" << file_id << "\" [shape=note, label=\"" << dot_escape(display_path(n.path, base)) << "\\nsha256 "
        << short_hash(n.sha256) << "\"" << (n.producer ? "" : ", style=filled, fillcolor=\"#e8f4e8\"") << "];\n";
  if (!n.producer) return;
  const std::string run_id = "r_" + std::to_string(n.producer->id);
  if (seen.insert(run_id).second)
    out << "  \"" << run_id << "\" [shape=box, style=rounded, label=\"run " << n.producer->id << "\\n"
        << dot_escape(n.producer->tool) << "\\n" << dot_escape(n.producer->version) << "\"];\n";
  if (seen.insert(run_id + "->" + file_id).second)
    out << "  \"" << run_id << "\" -> \"" << file_id << "\" [label=\"wrote\"];\n";
  for (const auto& input : n.inputs) {
    dot_nodes(input, base, seen, out);
    const std::string in_id = file_node_id(input);
    if (seen.insert(in_id + "->" + run_id).second) out << "  \"" << in_id << "\" -> \"" << run_id << "\" [label=\"read\"];\n";
  }
}

}  // namespace

std::string display_path(const std::string& path, const fs::path& base) {
  const fs::path rel = fs::path(path).lexically_relative(base);
  if (rel.empty() || *rel.begin() == "..") return path;
  return rel.string();
}

std::string runs_text(const std::vector<RunSummary>& runs) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& r : runs)
    rows.push_back({std::to_string(r.id), r.tool, r.started_at, status_text(r.exit_status), format_fixed(r.wall_s, 3),
                    r.version, r.error});
  return io::format_text_table({"run", "tool", "started (UTC)", "status", "wall_s", "version", "error"}, rows);
}

nlohmann::ordered_json runs_json(const std::vector<RunSummary>& runs) {
  auto list = nlohmann::ordered_json::array();
  for (const auto& r : runs) list.push_back(summary_json(r));
  return list;
}

std::string run_text(std::int64_t id, const RunRecord& r, const fs::path& base) {
  std::ostringstream out;
  out << "run " << id << ": " << r.tool << " " << r.version << " (" << status_text(r.exit_status) << ")\n";
  if (!r.error.empty()) out << "error:    " << r.error << "\n";
  out << "binary:   sha256:" << r.binary_sha256 << "\n";
  out << "host:     " << r.host << "   cwd: " << r.cwd << "\n";
  out << "started:  " << r.started_at << "   ended: " << r.ended_at << "\n";
  out << "cost:     wall " << format_fixed(r.wall_s, 3) << " s, cpu " << format_fixed(r.cpu_s, 3) << " s, peak memory "
      << format_fixed(double(r.peak_rss_kib) / 1024.0, 1) << " MiB";
  for (const auto& m : r.metrics)
    if (m.name == "threads") out << ", " << format_number(m.value) << (m.value == 1 ? " thread" : " threads");
  out << "\n";
  out << "argv:    ";
  for (const auto& a : r.argv) out << " " << a;
  out << "\nparams:   " << r.params.dump() << "\n";
  for (const auto* files : {&r.inputs, &r.outputs}) {
    out << (files == &r.inputs ? "inputs:\n" : "outputs:\n");
    for (const auto& f : *files)
      out << "  " << display_path(f.path, base) << "  " << f.size_bytes << " B  sha256:" << f.sha256 << "\n";
  }
  if (!r.metrics.empty()) {
    out << "metrics:\n";
    for (const auto& m : r.metrics) out << "  " << m.name << " = " << format_number(m.value) << (m.unit.empty() ? "" : " " + m.unit) << "\n";
  }
  return out.str();
}

nlohmann::ordered_json run_json(std::int64_t id, const RunRecord& r) {
  auto files = [](const std::vector<FileRecord>& list) {
    auto out = nlohmann::ordered_json::array();
    for (const auto& f : list) out.push_back({{"path", f.path}, {"size_bytes", f.size_bytes}, {"sha256", f.sha256}});
    return out;
  };
  auto metrics = nlohmann::ordered_json::array();
  for (const auto& m : r.metrics) metrics.push_back({{"name", m.name}, {"value", m.value}, {"unit", m.unit}});
  return {{"id", id},           {"tool", r.tool},         {"version", r.version},       {"binary_sha256", r.binary_sha256},
          {"argv", r.argv},     {"params", r.params},     {"cwd", r.cwd},               {"host", r.host},
          {"started_at", r.started_at}, {"ended_at", r.ended_at}, {"exit_status", r.exit_status}, {"error", r.error},
          {"wall_s", r.wall_s}, {"cpu_s", r.cpu_s},       {"peak_rss_kib", r.peak_rss_kib},
          {"inputs", files(r.inputs)}, {"outputs", files(r.outputs)}, {"metrics", metrics}};
}

std::string lineage_text(const LineageNode& root, const fs::path& base) {
  std::ostringstream out;
  tree_lines(root, base, "", true, true, out);
  return out.str();
}

std::string lineage_dot(const LineageNode& root, const fs::path& base) {
  std::ostringstream out;
  out << "digraph lineage {\n  rankdir=RL;\n  node [fontname=\"Helvetica\", fontsize=10];\n";
  std::set<std::string> seen;
  dot_nodes(root, base, seen, out);
  out << "}\n";
  return out.str();
}

nlohmann::ordered_json lineage_json(const LineageNode& n) {
  nlohmann::ordered_json j = {{"path", n.path}, {"sha256", n.sha256}, {"current_sha256", n.current_sha256}};
  if (n.producer) {
    j["producer"] = summary_json(*n.producer);
    j["producer_matches"] = n.producer_matches;
    j["expanded_elsewhere"] = n.expanded_elsewhere;
  } else {
    j["producer"] = nullptr;
  }
  auto inputs = nlohmann::ordered_json::array();
  for (const auto& i : n.inputs) inputs.push_back(lineage_json(i));
  j["inputs"] = inputs;
  return j;
}

std::string stale_text(const std::vector<StaleInput>& stale, const fs::path& base) {
  if (stale.empty()) return "nothing is stale: every recorded input of the live runs is unchanged\n";
  std::vector<std::vector<std::string>> rows;
  for (const auto& s : stale) {
    std::string outputs;
    for (const auto& o : s.outputs) outputs += (outputs.empty() ? "" : " ") + display_path(o, base);
    rows.push_back({std::to_string(s.run.id), s.run.tool, display_path(s.input_path, base),
                    s.current_sha256.empty() ? "missing" : "changed", short_hash(s.recorded_sha256),
                    short_hash(s.current_sha256), outputs});
  }
  return io::format_text_table({"run", "tool", "input", "state", "recorded", "now", "outputs made from it"}, rows);
}

nlohmann::ordered_json stale_json(const std::vector<StaleInput>& stale) {
  auto list = nlohmann::ordered_json::array();
  for (const auto& s : stale)
    list.push_back({{"run", summary_json(s.run)},
                    {"input", s.input_path},
                    {"recorded_sha256", s.recorded_sha256},
                    {"current_sha256", s.current_sha256},
                    {"outputs", s.outputs}});
  return list;
}

namespace {

std::string file_state(const std::string& recorded, const std::string& current) {
  if (current.empty()) return "missing";
  return recorded == current ? "unchanged" : "changed";
}

}  // namespace

std::string diff_text(std::int64_t a, std::int64_t b, const RunDiff& d, const fs::path& base) {
  if (d.empty()) return "runs " + std::to_string(a) + " and " + std::to_string(b) + " do not differ\n";
  std::ostringstream out;
  const std::string ra = "run " + std::to_string(a), rb = "run " + std::to_string(b);
  auto section = [&](const std::string& title, const std::vector<RunDiff::Value>& values, bool files) {
    if (values.empty()) return;
    std::vector<std::vector<std::string>> rows;
    for (const auto& v : values) {
      auto show = [&](const std::string& x) { return x.empty() ? std::string("-") : files ? short_hash(x) : x; };
      rows.push_back({files ? display_path(v.key, base) : v.key, show(v.a), show(v.b)});
    }
    out << title << ":\n" << io::format_text_table({files ? "path" : "name", ra, rb}, rows) << "\n";
  };
  section("parameters", d.params, false);
  section("inputs (sha256)", d.inputs, true);
  section("outputs (sha256)", d.outputs, true);
  section("metrics", d.metrics, false);
  return out.str();
}

nlohmann::ordered_json diff_json(std::int64_t a, std::int64_t b, const RunDiff& d) {
  auto list = [](const std::vector<RunDiff::Value>& values) {
    auto out = nlohmann::ordered_json::array();
    for (const auto& v : values) out.push_back({{"key", v.key}, {"a", v.a}, {"b", v.b}});
    return out;
  };
  return {{"a", a}, {"b", b}, {"params", list(d.params)}, {"inputs", list(d.inputs)},
          {"outputs", list(d.outputs)}, {"metrics", list(d.metrics)}};
}

std::string verify_text(const std::vector<OutputCheck>& checks, const fs::path& base) {
  std::vector<std::vector<std::string>> rows;
  std::size_t bad = 0;
  for (const auto& c : checks) {
    if (c.ok()) continue;
    ++bad;
    rows.push_back({display_path(c.path, base), std::to_string(c.run_id), file_state(c.recorded_sha256, c.current_sha256),
                    short_hash(c.recorded_sha256), short_hash(c.current_sha256)});
  }
  std::string out = std::to_string(checks.size()) + " recorded outputs re-hashed: " +
                    std::to_string(checks.size() - bad) + " as recorded, " + std::to_string(bad) + " missing or changed\n";
  if (bad) out += io::format_text_table({"output", "run", "state", "recorded", "now"}, rows);
  return out;
}

nlohmann::ordered_json verify_json(const std::vector<OutputCheck>& checks) {
  auto list = nlohmann::ordered_json::array();
  for (const auto& c : checks)
    list.push_back({{"path", c.path}, {"run", c.run_id}, {"state", file_state(c.recorded_sha256, c.current_sha256)},
                    {"recorded_sha256", c.recorded_sha256}, {"current_sha256", c.current_sha256}});
  return list;
}

std::string metrics_text(const std::string& name, const std::vector<MetricRow>& rows, const std::string& by) {
  if (rows.empty()) return "no run recorded a metric named '" + name + "'\n";
  std::vector<std::vector<std::string>> table;
  for (const auto& r : rows) {
    std::vector<std::string> row = {std::to_string(r.run.id), r.run.tool, r.run.started_at};
    if (!by.empty()) row.push_back(r.by_value);
    row.push_back(format_number(r.value));
    row.push_back(r.unit);
    table.push_back(row);
  }
  std::vector<std::string> header = {"run", "tool", "started (UTC)"};
  if (!by.empty()) header.push_back(by);
  header.push_back(name);
  header.push_back("unit");
  return io::format_text_table(header, table);
}

nlohmann::ordered_json metrics_json(const std::string& name, const std::vector<MetricRow>& rows, const std::string& by) {
  auto list = nlohmann::ordered_json::array();
  for (const auto& r : rows) {
    nlohmann::ordered_json j = {{"run", r.run.id}, {"tool", r.run.tool}, {"started_at", r.run.started_at},
                                {"name", name},     {"value", r.value},   {"unit", r.unit}};
    if (!by.empty()) j[by] = r.by_value;
    list.push_back(j);
  }
  return list;
}

std::string why_text(const std::string& path, const std::vector<ChangedUpstream>& changed, const fs::path& base) {
  const std::string shown = display_path(fs::absolute(path).lexically_normal().string(), base);
  if (changed.empty()) return shown + " is up to date: every file it was made from is as its runs read it\n";
  std::vector<std::vector<std::string>> rows;
  for (const auto& c : changed)
    rows.push_back({std::to_string(c.depth), display_path(c.path, base), file_state(c.recorded_sha256, c.current_sha256),
                    "run " + std::to_string(c.read_by.id) + " " + c.read_by.tool, short_hash(c.recorded_sha256),
                    short_hash(c.current_sha256)});
  return shown + " would be re-made: these files changed since the runs that made it read them\n" +
         io::format_text_table({"depth", "file", "state", "read by", "recorded", "now"}, rows);
}

nlohmann::ordered_json why_json(const std::string& path, const std::vector<ChangedUpstream>& changed) {
  auto list = nlohmann::ordered_json::array();
  for (const auto& c : changed)
    list.push_back({{"path", c.path}, {"depth", c.depth}, {"state", file_state(c.recorded_sha256, c.current_sha256)},
                    {"read_by", summary_json(c.read_by)}, {"recorded_sha256", c.recorded_sha256},
                    {"current_sha256", c.current_sha256}});
  return {{"file", path}, {"up_to_date", changed.empty()}, {"changed", list}};
}

std::string merge_text(const std::string& into, const MergeResult& result, const fs::path& base) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& s : result.sources)
    rows.push_back({display_path(fs::absolute(s.path).lexically_normal().string(), base), std::to_string(s.runs),
                    std::to_string(s.runs_added), std::to_string(s.runs_present), std::to_string(s.files_added),
                    std::to_string(s.metrics_added)});
  std::ostringstream out;
  out << io::format_text_table({"source", "runs", "added", "already there", "files added", "metrics added"}, rows);
  out << "into " << into << ": runs " << result.runs_before << " -> " << result.runs_after << ", files "
      << result.files_before << " -> " << result.files_after << ", metrics " << result.metrics_before << " -> "
      << result.metrics_after << "\n";
  return out.str();
}

nlohmann::ordered_json merge_json(const std::string& into, const MergeResult& result) {
  auto sources = nlohmann::ordered_json::array();
  for (const auto& s : result.sources)
    sources.push_back({{"path", s.path}, {"runs", s.runs}, {"runs_added", s.runs_added},
                       {"runs_present", s.runs_present}, {"files_added", s.files_added},
                       {"metrics_added", s.metrics_added}});
  return {{"into", into},
          {"sources", sources},
          {"runs", {{"before", result.runs_before}, {"after", result.runs_after}}},
          {"files", {{"before", result.files_before}, {"after", result.files_after}}},
          {"metrics", {{"before", result.metrics_before}, {"after", result.metrics_after}}}};
}

}  // namespace mesowave::prov
