// mw-prov - what ran, with what, and where a result came from.
//
//   mw-prov runs [--tool mw-upv] [--limit 20]
//   mw-prov show 12
//   mw-prov lineage results/concrete-cube/table1.csv [--format dot]
//   mw-prov stale
//   mw-prov diff 7 9
//   mw-prov verify
//   mw-prov metrics E_d [--by frequency-kHz]
//   mw-prov export --format prov-json > provenance.json
//   mw-prov why results/concrete-cube/table1.csv
//   mw-prov merge --into db/provenance.sqlite db/jobs/*.sqlite
//
// Reads the database named by --db or MESOWAVE_DB (default
// db/provenance.sqlite); every subcommand also answers in JSON (--json).
#include <iostream>

#include "mesowave/app/tool.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/prov/export.hpp"
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
                 "  mw-prov stale                       live results whose recorded inputs changed since\n"
                 "  mw-prov diff 7 9                    parameters, files and metrics that differ between two runs\n"
                 "  mw-prov verify                      re-hash every live output; report missing or changed ones\n"
                 "  mw-prov metrics E_d --by t-p-us     one metric across runs, beside a parameter\n"
                 "  mw-prov export --format prov-json   the whole graph as W3C PROV-JSON (or --format dot)\n"
                 "  mw-prov why FILE                    which files changed since FILE was made (why make re-runs it)\n"
                 "  mw-prov merge --into DB A.sqlite... add the runs of other databases (one per Slurm job) to DB");
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

  auto* diff = cli.add_subcommand("diff", "What differs between two runs: parameters, inputs, outputs, metrics");
  std::int64_t run_a = 0, run_b = 0;
  diff->add_option("run_a", run_a, "First run id")->required();
  diff->add_option("run_b", run_b, "Second run id")->required();

  auto* verify = cli.add_subcommand("verify", "Re-hash every recorded output (its newest run's version)");

  auto* metrics = cli.add_subcommand("metrics", "One named metric across runs (e.g. E_d, steps_per_s, pcc_mean)");
  std::string metric_name, by_param;
  metrics->add_option("name", metric_name, "Metric name as the tools record it")->required();
  metrics->add_option("--tool", tool_filter, "Only runs of this tool");
  metrics->add_option("--by", by_param, "Show this parameter of each run beside it (an option name, e.g. frequency-kHz)");

  auto* exporter = cli.add_subcommand("export", "The whole database as a provenance graph");
  std::string export_format = "prov-json";
  exporter->add_option("--format", export_format, "prov-json (W3C PROV-JSON) | dot (Graphviz)")
      ->check(CLI::IsMember({"prov-json", "dot"}))
      ->capture_default_str();

  auto* why = cli.add_subcommand("why", "Why make would re-run FILE: the files in its lineage that changed since");
  std::string why_file;
  why->add_option("file", why_file, "A file made by a recorded run")->required();

  auto* merge = cli.add_subcommand("merge",
                                   "Add to --into the runs of other databases it does not hold yet (a run is there when "
                                   "its whole record is; merging again adds nothing); whole or nothing");
  std::string merge_into;
  std::vector<std::string> merge_sources;
  merge->add_option("--into", merge_into, "The database merged into (created if absent)")->required();
  merge->add_option("sources", merge_sources, "Databases whose runs are added (read only)")->required();

  for (auto* sub : {runs, show, lineage, stale, diff, verify, metrics, why, merge})
    sub->add_flag("--json", json, "Answer in JSON");

  return tool.run(argc, argv, [&](app::Run& run) {
    if (merge->parsed()) {
      const auto result = prov::merge_databases(merge_into, {merge_sources.begin(), merge_sources.end()});
      run.out() << (json ? prov::merge_json(merge_into, result).dump(2) + "\n"
                         : prov::merge_text(merge_into, result, fs::current_path()));
      return;
    }
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
    } else if (diff->parsed()) {
      const auto d = prov::diff_runs(db, run_a, run_b);
      out << (json ? prov::diff_json(run_a, run_b, d).dump(2) + "\n" : prov::diff_text(run_a, run_b, d, base));
    } else if (verify->parsed()) {
      const auto checks = prov::verify_outputs(db);
      out << (json ? prov::verify_json(checks).dump(2) + "\n" : prov::verify_text(checks, base));
    } else if (metrics->parsed()) {
      const auto rows = prov::metric_history(db, metric_name,
                                             tool_filter.empty() ? std::nullopt : std::optional(tool_filter), by_param);
      out << (json ? prov::metrics_json(metric_name, rows, by_param).dump(2) + "\n"
                   : prov::metrics_text(metric_name, rows, by_param));
    } else if (exporter->parsed()) {
      out << (export_format == "dot" ? prov::export_dot(db, base) : prov::export_prov_json(db).dump(2) + "\n");
    } else if (why->parsed()) {
      const auto changed = prov::why_changed(db, why_file);
      out << (json ? prov::why_json(why_file, changed).dump(2) + "\n" : prov::why_text(why_file, changed, base));
    }
  });
}
