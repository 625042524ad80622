#include "mesowave/io/printed_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/io/quantity_file.hpp"

namespace mesowave::io {
namespace {

bool is_number(const std::string& s, double& value) {
  if (s.empty()) return false;
  char* end = nullptr;
  value = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && std::isfinite(value);
}

}  // namespace

int printed_decimals(const std::string& text) {
  const auto dot = text.find('.');
  if (dot == std::string::npos) return 0;
  const auto exp = text.find_first_of("eE");
  return int((exp == std::string::npos ? text.size() : exp) - dot - 1);
}

std::vector<PairedValue> pair_tables(const CsvTable& ours, const CsvTable& paper, const std::string& key,
                                     const std::vector<std::string>& columns) {
  const std::size_t ours_key = ours.column(key), paper_key = paper.column(key);
  std::vector<std::string> compared = columns;
  if (compared.empty())
    for (const auto& c : paper.header)
      if (c != key && c != "source" && c != "cite" && ours.find_column(c)) compared.push_back(c);
  if (compared.empty()) throw InputError("the two tables share no column besides '" + key + "'");
  std::vector<PairedValue> values;
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

std::vector<PairedValue> pair_quantities(const std::filesystem::path& ours_path, const std::filesystem::path& paper_path) {
  std::map<std::string, std::string> ours;
  for (const auto& q : read_quantity_file(ours_path)) ours[q.option_name()] = q.value;
  std::vector<PairedValue> values;
  for (const auto& q : read_quantity_file(paper_path)) {
    auto it = ours.find(q.option_name());
    if (it == ours.end()) continue;
    std::string name = q.unit.empty() ? q.name : q.name + " [" + q.unit + "]";
    values.push_back({name, "value", it->second, q.value});
  }
  if (values.empty())
    throw InputError(ours_path.string() + " and " + paper_path.string() + " share no quantity (name and unit)");
  return values;
}

PrintedComparison compare_printed(const std::vector<PairedValue>& values) {
  PrintedComparison c;
  c.header = {"row", "column", "mesowave", "rounded", "paper", "difference", "diff_%", "same_digits"};
  for (const auto& v : values) {
    double ours = 0, paper = 0;
    if (!is_number(v.ours_text, ours) || !is_number(v.paper_text, paper)) {
      const bool same = v.ours_text == v.paper_text;
      c.same_printed_digits += same;
      c.rows.push_back({v.row, v.column, v.ours_text, v.ours_text, v.paper_text, "", "", same ? "yes" : "no"});
      continue;
    }
    const int digits = printed_decimals(v.paper_text);
    const std::string rounded = format_fixed(ours, digits);
    const bool same = rounded == format_fixed(paper, digits);
    const double rel = paper != 0 ? 100.0 * (ours - paper) / std::abs(paper) : 0.0;
    c.same_printed_digits += same;
    c.max_abs_rel_difference_pct = std::max(c.max_abs_rel_difference_pct, std::abs(rel));
    c.rows.push_back({v.row, v.column, format_fixed(ours, digits + 3), rounded, v.paper_text,
                      format_fixed(ours - paper, digits + 2), format_fixed(rel, 2), same ? "yes" : "no"});
  }
  return c;
}

}  // namespace mesowave::io
