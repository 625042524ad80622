// mw-compare - mesowave's numbers beside a paper's printed ones.
//
//   mw-compare --ours results/concrete-cube/table1.csv
//              --paper lab-data/concrete-cube/paper/table1.csv --key method
//   mw-compare --ours results/concrete-cube/upv.json --paper lab-data/concrete-cube/upv-printed.toml
//
// Tables (CSV) are matched row by row on --key and column by column on their
// names; quantity files (JSON/TOML) on their names with units. Each value is
// also rounded to the digits the paper printed, so "matches the paper" means
// exactly that: the same printed digits.
#include <cmath>
#include <map>

#include "mesowave/app/tool.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/io/csv.hpp"
#include "mesowave/io/quantity_file.hpp"
#include "mesowave/io/text_table.hpp"

using namespace mesowave;
namespace fs = std::filesystem;

namespace {

struct Value {
  std::string row, column, ours_text, paper_text;
};

bool is_number(const std::string& s, double& value) {
  if (s.empty()) return false;
  char* end = nullptr;
  value = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && std::isfinite(value);
}

int printed_decimals(const std::string& text) {
  const auto dot = text.find('.');
  if (dot == std::string::npos) return 0;
  const auto exp = text.find_first_of("eE");
  return int((exp == std::string::npos ? text.size() : exp) - dot - 1);
}

bool is_table(const fs::path& p) { return p.extension() == ".csv"; }

std::vector<Value> pair_tables(const io::CsvTable& ours, const io::CsvTable& paper, const std::string& key,
                               const std::vector<std::string>& columns) {
  const std::size_t ours_key = ours.column(key), paper_key = paper.column(key);
  std::vector<std::string> compared = columns;
  if (compared.empty())
    for (const auto& c : paper.header)
      if (c != key && c != "source" && c != "cite" && ours.find_column(c)) compared.push_back(c);
  if (compared.empty()) throw InputError("the two tables share no column besides '" + key + "'");
  std::vector<Value> values;
  for (std::size_t pr = 0; pr < paper.rows.size(); ++pr) {
    const std::string& name = paper.text(pr, paper_key);
    std::optional<std::size_t> or_row;
    for (std::size_t r = 0; r < ours.rows.size(); ++r)
      if (ours.text(r, ours_key) == name) or_row = r;
    if (!or_row) throw InputError(ours.origin + " has no row with " + key + " = '" + name + "' (the paper has one)");
    for (const auto& c : compared) {
      const std::string& p = paper.text(pr, paper.column(c));
      if (p.empty()) continue;
      values.push_back({name, c, ours.text(*or_row, ours.column(c)), p});
    }
  }
  return values;
}

std::vector<Value> pair_quantities(const fs::path& ours_path, const fs::path& paper_path) {
  std::map<std::string, std::string> ours;
  for (const auto& q : io::read_quantity_file(ours_path)) ours[q.option_name()] = q.value;
  std::vector<Value> values;
  for (const auto& q : io::read_quantity_file(paper_path)) {
    auto it = ours.find(q.option_name());
    if (it == ours.end()) continue;
    std::string name = q.unit.empty() ? q.name : q.name + " [" + q.unit + "]";
    values.push_back({name, "value", it->second, q.value});
  }
  if (values.empty())
    throw InputError(ours_path.string() + " and " + paper_path.string() + " share no quantity (name and unit)");
  return values;
}

}  // namespace

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
    std::vector<Value> values;
    if (is_table(ours_path) != is_table(paper_path))
      throw InputError("--ours and --paper must both be CSV tables or both quantity files");
    if (is_table(ours_path)) {
      if (key.empty()) throw InputError("comparing CSV tables needs --key (the column naming each row)");
      values = pair_tables(io::read_csv(ours_path), io::read_csv(paper_path), key, columns);
    } else {
      values = pair_quantities(ours_path, paper_path);
    }

    std::vector<std::vector<std::string>> rows;
    std::size_t matches = 0;
    double max_rel = 0;
    for (const auto& v : values) {
      double ours = 0, paper = 0;
      if (!is_number(v.ours_text, ours) || !is_number(v.paper_text, paper)) {
        const bool same = v.ours_text == v.paper_text;
        matches += same;
        rows.push_back({v.row, v.column, v.ours_text, v.ours_text, v.paper_text, "", "", same ? "yes" : "no"});
        continue;
      }
      const int digits = printed_decimals(v.paper_text);
      const std::string rounded = format_fixed(ours, digits);
      const bool same = rounded == format_fixed(paper, digits);
      const double rel = paper != 0 ? 100.0 * (ours - paper) / std::abs(paper) : 0.0;
      matches += same;
      max_rel = std::max(max_rel, std::abs(rel));
      rows.push_back({v.row, v.column, format_fixed(ours, digits + 3), rounded, v.paper_text,
                      format_fixed(ours - paper, digits + 2), format_fixed(rel, 2), same ? "yes" : "no"});
    }
    const std::vector<std::string> header = {"row", "column", "mesowave", "rounded", "paper", "difference", "diff_%",
                                             "same_digits"};
    const std::string text = (title.empty() ? "" : title + "\n") + io::format_text_table(header, rows);
    run.out() << text;
    if (!text_out.empty()) run.write_text(text_out, text);
    if (!csv_out.empty()) run.write_text(csv_out, io::to_csv(header, rows));
    nlohmann::ordered_json summary;
    summary["compared"] = values.size();
    summary["same_printed_digits"] = matches;
    summary["max_abs_rel_difference_pct"] = max_rel;
    run.metric("same_printed_digits", double(matches), "");
    run.metric("compared", double(values.size()), "");
    run.metric("max_abs_rel_difference", max_rel, "%");
    if (!out.empty()) run.write_text(out, summary.dump(2) + "\n");
  });
}
