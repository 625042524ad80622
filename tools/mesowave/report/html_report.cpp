#include "mesowave/report/html_report.hpp"

#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "mesowave/app/process_info.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/version.hpp"
#include "mesowave/io/csv.hpp"
#include "mesowave/io/sha256.hpp"
#include "mesowave/prov/queries.hpp"
#include "mesowave/prov/report.hpp"

namespace mesowave::report {
namespace fs = std::filesystem;

namespace {

constexpr const char* kStyle = R"css(
body { font-family: system-ui, -apple-system, "Segoe UI", Helvetica, Arial, sans-serif; max-width: 70rem;
       margin: 2rem auto; padding: 0 1rem; color: #1d1d1f; line-height: 1.45; }
h1 { font-size: 1.7rem; margin-bottom: 0.2rem; } h2 { margin-top: 2.5rem; border-bottom: 1px solid #ccc; }
nav ol { columns: 2; font-size: 0.95rem; }
table { border-collapse: collapse; margin: 0.5rem 0; font-size: 0.88rem; }
.table-box { max-width: 100%; overflow-x: auto; }
p, li, figcaption { overflow-wrap: anywhere; }
th, td { border: 1px solid #d0d0d0; padding: 0.2rem 0.5rem; } th { background: #f0f0f2; text-align: left; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
td.yes { background: #e6f4e6; } td.no { background: #fbeaea; }
figure { margin: 1rem 0; } figure img { max-width: 100%; border: 1px solid #e0e0e0; }
figcaption, caption { font-size: 0.9rem; color: #444; text-align: left; caption-side: top; padding-bottom: 0.3rem; }
details { font-size: 0.82rem; margin: 0.3rem 0 1rem; background: #f7f7f9; padding: 0.3rem 0.6rem; }
details pre { overflow-x: auto; font-size: 0.78rem; }
code { font-size: 0.85rem; } .muted { color: #666; }
)css";

bool numeric(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

// `text` in backticks becomes <code>text</code>; everything else is escaped.
std::string inline_html(const std::string& text) {
  std::string out;
  std::size_t at = 0;
  for (;;) {
    const auto open = text.find('`', at);
    const auto close = open == std::string::npos ? open : text.find('`', open + 1);
    if (close == std::string::npos) return out + escape_html(text.substr(at));
    out += escape_html(text.substr(at, open - at)) + "<code>" + escape_html(text.substr(open + 1, close - open - 1)) + "</code>";
    at = close + 1;
  }
}

std::string paragraphs(const std::string& text) {
  std::string out, para;
  std::istringstream in(text);
  std::string line;
  auto flush = [&] {
    if (!para.empty()) out += "<p>" + inline_html(para) + "</p>\n";
    para.clear();
  };
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) flush();
    else para += (para.empty() ? "" : " ") + line;
  }
  flush();
  return out;
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string anchor(std::size_t section) { return "s" + std::to_string(section + 1); }

// Collects the producing runs of every node of a lineage.
void collect_runs(const prov::LineageNode& n, std::set<std::int64_t>& runs) {
  if (n.producer) runs.insert(n.producer->id);
  for (const auto& i : n.inputs) collect_runs(i, runs);
}

std::string provenance_panel(const prov::Database& db, const fs::path& file, const fs::path& base,
                             std::set<std::int64_t>& runs) {
  const auto root = prov::lineage(db, file.string());
  collect_runs(root, runs);
  std::ostringstream out;
  out << "<details class=\"provenance\"><summary>provenance: ";
  if (!root.producer) {
    out << "source file, sha256 " << root.sha256.substr(0, 16) << " (no recorded run made it)</summary>";
  } else {
    const auto run = prov::load_run(db, root.producer->id);
    out << "run " << root.producer->id << " <code>" << escape_html(run.tool) << "</code> "
        << escape_html(run.version) << ", " << escape_html(run.started_at) << "</summary>\n";
    out << "<p>parameters: <code>" << escape_html(run.params.dump()) << "</code></p>\n<p>inputs:</p><ul>";
    for (const auto& f : run.inputs)
      out << "<li><code>" << escape_html(prov::display_path(f.path, base)) << "</code> sha256 "
          << f.sha256.substr(0, 16) << "</li>";
    out << "</ul>\n<p>lineage back to lab-data:</p><pre>" << escape_html(prov::lineage_text(root, base)) << "</pre>";
  }
  out << "</details>\n";
  return out.str();
}

std::string table_html(const io::CsvTable& t, const std::string& caption) {
  std::ostringstream out;
  // A table wider than the page scrolls inside its own box, not the page (a 1280 px window
  // holds Table 3 and the per-sensor tables so; scripts/check-report measures it).
  out << "<div class=\"table-box\"><table>\n";
  if (!caption.empty()) out << "<caption>" << escape_html(caption) << "</caption>\n";
  out << "<thead><tr>";
  for (const auto& h : t.header) out << "<th>" << escape_html(h) << "</th>";
  out << "</tr></thead>\n<tbody>\n";
  for (const auto& row : t.rows) {
    out << "<tr>";
    for (const auto& cell : row) {
      const char* cls = cell == "yes" ? " class=\"yes\"" : cell == "no" ? " class=\"no\"" : numeric(cell) ? " class=\"num\"" : "";
      out << "<td" << cls << ">" << escape_html(cell) << "</td>";
    }
    out << "</tr>\n";
  }
  out << "</tbody></table></div>\n";
  return out.str();
}

std::string first_line_of(const std::string& file, const std::string& key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key, 0) == 0) {
      const auto colon = line.find(':');
      std::string v = colon == std::string::npos ? line : line.substr(colon + 1);
      const auto start = v.find_first_not_of(" \t\"");
      const auto end = v.find_last_not_of(" \t\"");
      return start == std::string::npos ? "" : v.substr(start, end - start + 1);
    }
  return "";
}

// Seconds since the epoch of an ISO 8601 UTC time as the recorder writes it
// ("2026-11-22T04:21:33.390Z"); nullopt for anything else.
std::optional<double> epoch_seconds(const std::string& iso) {
  std::tm t{};
  int millis = 0;
  if (std::sscanf(iso.c_str(), "%4d-%2d-%2dT%2d:%2d:%2d.%3dZ", &t.tm_year, &t.tm_mon, &t.tm_mday, &t.tm_hour, &t.tm_min,
                  &t.tm_sec, &millis) != 7)
    return std::nullopt;
  t.tm_year -= 1900;
  t.tm_mon -= 1;
  return double(timegm(&t)) + millis / 1000.0;
}

std::string machine_html(const prov::Database* db, const std::set<std::int64_t>& runs) {
  std::ostringstream out;
  const std::string cpu = first_line_of("/proc/cpuinfo", "model name");
  std::string memory = first_line_of("/proc/meminfo", "MemTotal");
  const std::string os = first_line_of("/etc/os-release", "PRETTY_NAME=");
  std::size_t cores = 0;
  {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line)) cores += line.rfind("processor", 0) == 0;
  }
  out << "<table><tbody>";
  out << "<tr><th>host</th><td>" << escape_html(app::host_name()) << "</td></tr>";
  out << "<tr><th>processor</th><td>" << escape_html(cpu) << ", " << cores << " logical cores</td></tr>";
  out << "<tr><th>memory</th><td>" << escape_html(memory) << "</td></tr>";
  out << "<tr><th>system</th><td>" << escape_html(os.substr(os.find('=') == std::string::npos ? 0 : os.find('=') + 1))
      << "</td></tr>";
  out << "<tr><th>mesowave</th><td>" << escape_html(source_version()) << "</td></tr>";
  if (db && !runs.empty()) {
    double wall = 0, cpu_s = 0;
    std::string first, last;
    std::map<std::string, std::pair<int, double>> by_tool;
    for (auto id : runs) {
      const auto r = prov::load_run(*db, id);
      wall += r.wall_s;
      cpu_s += r.cpu_s;
      if (first.empty() || r.started_at < first) first = r.started_at;
      if (last.empty() || r.ended_at > last) last = r.ended_at;
      by_tool[r.tool].first += 1;
      by_tool[r.tool].second += r.wall_s;
    }
    out << "<tr><th>runs behind this report</th><td>" << runs.size() << " tool runs, " << format_fixed(wall, 1)
        << " s wall and " << format_fixed(cpu_s, 1) << " s CPU in total, first started " << escape_html(first)
        << ", last ended " << escape_html(last) << "</td></tr>";
    // With -j the runs overlap, so the span, not the sum, is the pipeline's wall time - when one
    // make made them all (runs kept from an earlier make stretch it by the time in between).
    const auto t0 = epoch_seconds(first), t1 = epoch_seconds(last);
    if (t0 && t1)
      out << "<tr><th>wall time of the pipeline</th><td>" << format_number(std::round((*t1 - *t0) * 1000) / 1000) << " s ("
          << format_fixed((*t1 - *t0) / 60, 1) << " min) from the first run's start to the last run's end</td></tr>";
    out << "<tr><th>by tool</th><td>";
    bool comma = false;
    for (const auto& [tool, v] : by_tool) {
      out << (comma ? ", " : "") << "<code>" << escape_html(tool) << "</code> " << v.first << " x, "
          << format_fixed(v.second, 1) << " s";
      comma = true;
    }
    out << "</td></tr>";
  }
  out << "</tbody></table>\n";
  return out.str();
}

}  // namespace

std::string escape_html(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

RenderedReport render_report(const ReportSpec& spec, const prov::Database* db, const fs::path& base) {
  RenderedReport r;
  std::set<std::int64_t> runs;
  std::ostringstream body;
  std::map<std::string, int> figure_names;
  for (std::size_t s = 0; s < spec.sections.size(); ++s) {
    const auto& section = spec.sections[s];
    body << "<section id=\"" << anchor(s) << "\">\n<h2>" << s + 1 << ". " << escape_html(section.title) << "</h2>\n"
         << paragraphs(section.text);
    for (const auto& item : section.items) {
      const fs::path file = item.file.is_absolute() ? item.file : base / item.file;
      if (!fs::is_regular_file(file))
        throw InputError("report item " + item.file.string() + " (section '" + section.title +
                         "') does not exist; run the pipeline first (make reproduce)");
      const std::string panel = db ? provenance_panel(*db, file, base, runs) : "";
      switch (item.kind) {
        case ReportItem::Kind::Table:
          body << table_html(io::read_csv(file), item.caption) << panel;
          ++r.tables;
          break;
        case ReportItem::Kind::Figure: {
          // Unique names under figures/: the file name, numbered if it repeats.
          std::string name = file.filename().string();
          if (int n = figure_names[name]++; n > 0) name = file.stem().string() + "-" + std::to_string(n) + file.extension().string();
          r.figures.emplace_back(file, name);
          body << "<figure><img src=\"figures/" << escape_html(name) << "\" alt=\"" << escape_html(item.caption)
               << "\" onerror=\"this.classList.add('broken')\"><figcaption>" << escape_html(item.caption)
               << "</figcaption></figure>\n"
               << panel;
          break;
        }
        case ReportItem::Kind::Note: body << paragraphs(read_text(file)) << panel; break;
      }
    }
    body << "</section>\n";
  }
  r.runs_behind = runs.size();

  std::ostringstream page;
  page << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << escape_html(spec.title)
       << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n<h1>" << escape_html(spec.title) << "</h1>\n"
       << "<p class=\"muted\">Generated " << escape_html(app::utc_timestamp()) << " by mw-report "
       << escape_html(source_version()) << ". Every table and figure below has a provenance panel: the run that "
       << "made the file (tool, version, parameters, input hashes) and its lineage back to lab-data.</p>\n"
       << paragraphs(spec.text) << "<nav><ol>\n";
  for (std::size_t s = 0; s < spec.sections.size(); ++s)
    page << "<li><a href=\"#" << anchor(s) << "\">" << escape_html(spec.sections[s].title) << "</a></li>\n";
  page << "<li><a href=\"#machine\">Machine and compute time</a></li>\n</ol></nav>\n"
       << body.str() << "<section id=\"machine\">\n<h2>" << spec.sections.size() + 1
       << ". Machine and compute time</h2>\n"
       << machine_html(db, runs) << "</section>\n</body>\n</html>\n";
  r.html = page.str();
  return r;
}

}  // namespace mesowave::report
