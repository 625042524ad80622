#include "mesowave/prov/export.hpp"

#include <map>
#include <set>
#include <sstream>

#include "mesowave/io/sha256.hpp"
#include "mesowave/prov/queries.hpp"
#include "mesowave/prov/report.hpp"
#include "mesowave/prov/run_status.hpp"

namespace mesowave::prov {
namespace {

constexpr const char* kNamespace = "https://github.com/mesowave/mesowave/ns/prov#";

struct Graph {
  struct File {
    std::string path, sha256;
    std::int64_t size_bytes;
  };
  struct Edge {
    std::int64_t run;
    std::string file_id;
  };
  std::map<std::string, File> files;  // keyed by entity id
  std::vector<Edge> used, generated;
  std::vector<RunRecord> runs;
  std::vector<std::int64_t> run_ids;
};

// A file version's identifier: stable across exports, distinct per (path, content).
std::string file_id(const std::string& path, const std::string& sha256) {
  return io::sha256_hex(path + '\n' + sha256).substr(0, 24);
}

std::string agent_id(const RunRecord& r) { return r.tool + "-" + r.binary_sha256.substr(0, 16); }

Graph load_graph(const Database& db) {
  Graph g;
  for (const auto& summary : list_runs(db)) {
    RunRecord r = load_run(db, summary.id);
    for (const auto& f : r.inputs) {
      const auto id = file_id(f.path, f.sha256);
      g.files.emplace(id, Graph::File{f.path, f.sha256, f.size_bytes});
      g.used.push_back({summary.id, id});
    }
    for (const auto& f : r.outputs) {
      const auto id = file_id(f.path, f.sha256);
      g.files.emplace(id, Graph::File{f.path, f.sha256, f.size_bytes});
      g.generated.push_back({summary.id, id});
    }
    g.run_ids.push_back(summary.id);
    g.runs.push_back(std::move(r));
  }
  return g;
}

}  // namespace

nlohmann::ordered_json export_prov_json(const Database& db) {
  const Graph g = load_graph(db);
  nlohmann::ordered_json doc;
  doc["prefix"] = {{"mw", kNamespace}, {"xsd", "http://www.w3.org/2001/XMLSchema#"}};
  auto& entities = doc["entity"] = nlohmann::ordered_json::object();
  for (const auto& [id, f] : g.files)
    entities["mw:file-" + id] = {{"prov:type", {{"$", "mw:File"}, {"type", "xsd:QName"}}}, {"prov:label", f.path}, {"mw:path", f.path},
                                 {"mw:sha256", f.sha256}, {"mw:size_bytes", f.size_bytes}};
  auto& activities = doc["activity"] = nlohmann::ordered_json::object();
  auto& agents = doc["agent"] = nlohmann::ordered_json::object();
  for (std::size_t k = 0; k < g.runs.size(); ++k) {
    const auto& r = g.runs[k];
    activities["mw:run-" + std::to_string(g.run_ids[k])] = {
        {"prov:startTime", r.started_at}, {"prov:endTime", r.ended_at},    {"prov:label", r.tool},
        {"mw:exit_status", r.exit_status}, {"mw:params", r.params.dump()}, {"mw:argv", nlohmann::json(r.argv).dump()},
        {"mw:host", r.host},              {"mw:wall_s", r.wall_s},         {"mw:cpu_s", r.cpu_s},
        {"mw:peak_rss_kib", r.peak_rss_kib}};
    agents["mw:tool-" + agent_id(r)] = {{"prov:type", {{"$", "prov:SoftwareAgent"}, {"type", "xsd:QName"}}},
                                        {"prov:label", r.tool + " " + r.version},
                                        {"mw:version", r.version},
                                        {"mw:binary_sha256", r.binary_sha256}};
  }
  std::size_t n = 0;
  auto& used = doc["used"] = nlohmann::ordered_json::object();
  for (const auto& e : g.used)
    used["_:u" + std::to_string(++n)] = {{"prov:activity", "mw:run-" + std::to_string(e.run)},
                                         {"prov:entity", "mw:file-" + e.file_id}};
  n = 0;
  auto& generated = doc["wasGeneratedBy"] = nlohmann::ordered_json::object();
  for (const auto& e : g.generated)
    generated["_:g" + std::to_string(++n)] = {{"prov:entity", "mw:file-" + e.file_id},
                                              {"prov:activity", "mw:run-" + std::to_string(e.run)}};
  n = 0;
  auto& associated = doc["wasAssociatedWith"] = nlohmann::ordered_json::object();
  for (std::size_t k = 0; k < g.runs.size(); ++k)
    associated["_:a" + std::to_string(++n)] = {{"prov:activity", "mw:run-" + std::to_string(g.run_ids[k])},
                                               {"prov:agent", "mw:tool-" + agent_id(g.runs[k])}};
  return doc;
}

std::string export_dot(const Database& db, const std::filesystem::path& base) {
  const Graph g = load_graph(db);
  auto escape = [](const std::string& s) {
    std::string e;
    for (char c : s) e += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
    return e;
  };
  std::set<std::string> produced;
  for (const auto& e : g.generated) produced.insert(e.file_id);
  std::ostringstream out;
  out << "digraph provenance {\n  rankdir=LR;\n  node [fontname=\"Helvetica\", fontsize=10];\n";
  for (const auto& [id, f] : g.files)
    out << "  \"f" << id << "\" [shape=note, label=\"" << escape(display_path(f.path, base)) << "\\nsha256 "
        << f.sha256.substr(0, 12) << "\"" << (produced.count(id) ? "" : ", style=filled, fillcolor=\"#e8f4e8\"")
        << "];\n";
  for (std::size_t k = 0; k < g.runs.size(); ++k)
    out << "  \"r" << g.run_ids[k] << "\" [shape=box, style=rounded, label=\"run " << g.run_ids[k] << "\\n"
        << escape(g.runs[k].tool)
        << (is_interrupted(g.runs[k].exit_status) ? "\\n(interrupted)" : g.runs[k].exit_status ? "\\n(failed)" : "")
        << "\"];\n";
  for (const auto& e : g.used) out << "  \"f" << e.file_id << "\" -> \"r" << e.run << "\";\n";
  for (const auto& e : g.generated) out << "  \"r" << e.run << "\" -> \"f" << e.file_id << "\";\n";
  out << "}\n";
  return out.str();
}

}  // namespace mesowave::prov
