// mw-prov - what ran, with what, and where a result came from.
//
//   mw-prov runs [--tool mw-upv] [--limit 20]
//   mw-prov show 12
//   mw-prov lineage results/concrete-cube/table1.csv [--format dot]
//   mw-prov stale
//
// Reads the database named by --db or MESOWAVE_DB (default
// db/provenance.sqlite); every subcommand also answers in JSON (--json).
#include <iostream>

#include "mesowave/app/tool.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/prov/queries.hpp"
#include "mesowave/prov/report.hpp"

using namespace mesowave;
namespace fs = std::filesystem;

int main(int argc, char** argv) {
  app::Tool tool("mw-prov",
                 "Query the provenance database that every mesowave tool writes when given --db or MESOWAVE_DB "
                 "(default here: db/provenance.sqlite).\n\n"
                 "  mw-prov runs --tool mw-upv          runs, oldest first\n"
                 "  mw-prov show 12                     one run: argv, parameters, files with SHA-256, metrics\n"
                 "  mw-prov lineage FILE [--format dot] the runs and files FILE was made from, back to lab-data\n"
                 "  mw-prov stale                       live results whose recorded inputs changed since");
  tool.set_records_runs(false);
  auto& cli = tool.cli();
  cli.require_subcommand(1);
  bool json = false;
  cli.add_flag("--json", json, "Answer in JSON");

  auto* runs = cli.add_subcommand("runs", "List runs, oldest first");
  std::string tool_filter;
  std::size_t limit = 0;
  runs->add_option("--tool", tool_filter, "Only runs of this tool (e.g. mw-upv)");
  runs->add_option("--limit", limit, "Only the newest N runs");

  auto* show = cli.add_subcommand("show", "Everything recorded about one run");
  std::int64_t run_id = 0;
  show->add_option("run", run_id, "Run id (from `mw-prov runs`)")->required();

  auto* lineage = cli.add_subcommand("lineage", "Trace a file back through the runs that made it");
  std::string file, format = "tree";
  lineage->add_option("file", file, "The file to trace")->required();
  lineage->add_option("--format", format, "tree | dot | json")
      ->check(CLI::IsMember({"tree", "dot", "json"}))
      ->capture_default_str();

  auto* stale = cli.add_subcommand("stale", "Recorded inputs whose content changed since the live run read them");

  for (auto* sub : {runs, show, lineage, stale}) sub->add_flag("--json", json, "Answer in JSON");

  return tool.run(argc, argv, [&](app::Run& run) {
    const std::string path = tool.db_path().empty() ? "db/provenance.sqlite" : tool.db_path();
    const auto db = prov::Database::open(path, prov::Database::Mode::ReadOnly);
    const fs::path base = fs::current_path();
    auto& out = run.out();
    if (runs->parsed()) {
      prov::RunFilter filter;
      if (!tool_filter.empty()) filter.tool = tool_filter;
      filter.limit = limit;
      const auto list = prov::list_runs(db, filter);
      out << (json ? prov::runs_json(list).dump(2) + "\n" : prov::runs_text(list));
    } else if (show->parsed()) {
      const auto record = prov::load_run(db, run_id);
      out << (json ? prov::run_json(run_id, record).dump(2) + "\n" : prov::run_text(run_id, record, base));
    } else if (lineage->parsed()) {
      const auto root = prov::lineage(db, file);
      if (json || format == "json") out << prov::lineage_json(root).dump(2) << "\n";
      else if (format == "dot") out << prov::lineage_dot(root, base);
      else out << prov::lineage_text(root, base);
    } else if (stale->parsed()) {
      const auto list = prov::stale_inputs(db);
      out << (json ? prov::stale_json(list).dump(2) + "\n" : prov::stale_text(list, base));
    }
  });
}
