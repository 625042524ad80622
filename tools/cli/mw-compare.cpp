// mw-compare - mesowave's numbers beside a paper's printed ones.
//
//   mw-compare --ours results/concrete-cube/table1.csv
//              --paper lab-data/concrete-cube/paper/table1.csv --key method
//   mw-compare --ours results/concrete-cube/upv.json --paper lab-data/concrete-cube/upv-printed.toml
//
// The pairing and the rounding to the paper's printed digits: io/printed_comparison.hpp.
#include "mesowave/app/tool.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/io/csv.hpp"
#include "mesowave/io/printed_comparison.hpp"
#include "mesowave/io/text_table.hpp"

using namespace mesowave;
namespace fs = std::filesystem;

int main(int argc, char** argv) {
  app::Tool tool("mw-compare",
                 "Print mesowave's values beside a paper's printed values: the difference, the relative difference, "
                 "and whether mesowave's value rounded to the paper's printed digits equals it.\n\n"
                 "  mw-compare --ours table1.csv --paper lab-data/concrete-cube/paper/table1.csv --key method\n"
                 "  mw-compare --ours upv.json --paper lab-data/concrete-cube/upv-printed.toml");
  fs::path ours_path, paper_path, csv_out, text_out, out;
  std::string key, title;
  std::vector<std::string> columns;
  auto& cli = tool.cli();
  cli.add_option("--ours", ours_path, "mesowave's result: CSV table, or JSON/TOML quantities")->required();
  cli.add_option("--paper", paper_path, "The paper's values, same kind of file (lab-data)")->required();
  cli.add_option("--key", key, "CSV: the column that names a row (e.g. method)");
  cli.add_option("--columns", columns, "CSV: the columns to compare (default: all shared)")->delimiter(',');
  cli.add_option("--title", title, "A heading printed above the table");
  cli.add_option("--csv", csv_out, "Write the comparison as CSV")->type_name("FILE");
  cli.add_option("--text", text_out, "Write the printed table to FILE as well")->type_name("FILE");
  app::add_out_option(cli, out, "a JSON summary");

  return tool.run(argc, argv, [&](app::Run& run) {
    run.input(ours_path);
    run.input(paper_path);
    const auto is_table = [](const fs::path& p) { return p.extension() == ".csv"; };
    if (is_table(ours_path) != is_table(paper_path))
      throw InputError("--ours and --paper must both be CSV tables or both quantity files");
    if (is_table(ours_path) && key.empty()) throw InputError("comparing CSV tables needs --key (the column naming each row)");
    const std::vector<io::PairedValue> values =
        is_table(ours_path) ? io::pair_tables(io::read_csv(ours_path), io::read_csv(paper_path), key, columns)
                            : io::pair_quantities(ours_path, paper_path);
    const io::PrintedComparison c = io::compare_printed(values);
    const std::string text = (title.empty() ? "" : title + "\n") + io::format_text_table(c.header, c.rows);
    run.out() << text;
    if (!text_out.empty()) run.write_text(text_out, text);
    if (!csv_out.empty()) run.write_text(csv_out, io::to_csv(c.header, c.rows));
    nlohmann::ordered_json summary;
    summary["compared"] = values.size();
    summary["same_printed_digits"] = c.same_printed_digits;
    summary["max_abs_rel_difference_pct"] = c.max_abs_rel_difference_pct;
    run.metric("same_printed_digits", double(c.same_printed_digits), "");
    run.metric("compared", double(values.size()), "");
    run.metric("max_abs_rel_difference", c.max_abs_rel_difference_pct, "%");
    if (!out.empty()) run.write_text(out, summary.dump(2) + "\n");
  });
}
