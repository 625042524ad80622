// mw-report - the studies' results as one static HTML page a researcher reads.
//
//   mw-report --spec pipeline/report.toml --spec pipeline/concrete-cube/report.toml ... --out-dir report
//
// Tables (CSV) and figures (PNG/SVG) named by the spec, each with the
// provenance of its file from the database (--db / MESOWAVE_DB), and the
// machine and compute time behind them. report/index.html opens from disk.
#include <fstream>

#include "mesowave/app/tool.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/prov/database.hpp"
#include "mesowave/report/html_report.hpp"
#include "mesowave/report/report_spec.hpp"

using namespace mesowave;
namespace fs = std::filesystem;

int main(int argc, char** argv) {
  app::Tool tool("mw-report",
                 "Write the report: a static HTML page (report/index.html) with every table and figure named in the "
                 "spec, each with a provenance panel (the run that made its file: tool, version, parameters, input "
                 "hashes, lineage back to lab-data), and the machine and compute time behind the results.\n\n"
                 "  mw-report --spec pipeline/report.toml --spec pipeline/concrete-cube/report.toml --out-dir report\n"
                 "  chromium --headless --screenshot report/index.html   # or open it in any browser");
  std::vector<fs::path> spec_paths;
  fs::path out_dir = "report", base = fs::current_path();
  bool no_provenance = false;
  auto& cli = tool.cli();
  cli.add_option("--spec", spec_paths,
                 "The report spec (TOML: sections with tables, figures, notes); repeat it: the first gives the title "
                 "and opening text, each further one (a study's report.toml) adds its sections in order")
      ->required();
  cli.add_option("--out-dir", out_dir, "Where index.html and figures/ go")->capture_default_str();
  cli.add_option("--base", base, "Directory the spec's file names are relative to (default: here)");
  cli.add_flag("--no-provenance", no_provenance, "Leave out the provenance panels (no database needed)");

  return tool.run(argc, argv, [&](app::Run& run) {
    for (const auto& path : spec_paths) run.input(path);
    const auto spec = report::read_report_spec(spec_paths);
    std::optional<prov::Database> db;
    if (!no_provenance) {
      if (tool.db_path().empty()) throw InputError("provenance panels need the database: give --db or MESOWAVE_DB (or --no-provenance)");
      db.emplace(prov::Database::open(tool.db_path(), prov::Database::Mode::ReadOnly));
    }
    const auto rendered = report::render_report(spec, db ? &*db : nullptr, base);
    for (const auto& section : spec.sections)
      for (const auto& item : section.items) run.input(item.file.is_absolute() ? item.file : base / item.file);
    for (const auto& [source, name] : rendered.figures) fs::copy_file(source, run.output(out_dir / "figures" / name));
    run.write_text(out_dir / "index.html", rendered.html);
    run.metric("tables", double(rendered.tables), "");
    run.metric("figures", double(rendered.figures.size()), "");
    run.metric("runs_behind", double(rendered.runs_behind), "");
    run.out() << "wrote " << (out_dir / "index.html").string() << ": " << spec.sections.size() << " sections, "
              << rendered.tables << " tables, " << rendered.figures.size() << " figures, provenance of "
              << rendered.runs_behind << " runs\n";
  });
}
