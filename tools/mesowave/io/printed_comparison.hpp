#pragma once
// mesowave's numbers beside a paper's printed ones (mw-compare). Tables (CSV)
// are matched row by row on a key column and column by column on their
// names; quantity files (JSON/TOML) on their names with units. Each value is
// also rounded to the digits the paper printed, so "matches the paper" means
// exactly that: the same printed digits.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "mesowave/io/csv.hpp"

namespace mesowave::io {

/// One value of ours beside the paper's, both as printed in their files.
struct PairedValue {
  std::string row, column, ours_text, paper_text;
};

/// The paper's rows matched on `key`, compared on `columns` (default: every
/// column both share, but the key, "source" and "cite"); a paper cell left
/// empty is skipped. InputError for a paper row we lack or no shared column.
std::vector<PairedValue> pair_tables(const CsvTable& ours, const CsvTable& paper, const std::string& key,
                                     const std::vector<std::string>& columns);
/// The quantities both files hold (same name and unit); InputError if none.
std::vector<PairedValue> pair_quantities(const std::filesystem::path& ours, const std::filesystem::path& paper);

/// Decimals printed after the point: "30.44" -> 2, "1.5e-06" -> 1, "27" -> 0.
int printed_decimals(const std::string& text);

/// The comparison as a table (row, column, mesowave, rounded, paper, difference,
/// diff_%, same_digits): ours with three more decimals than the paper printed,
/// rounded to the paper's decimals, the difference and the relative difference
/// (% of the paper's value). Text that is not a number matches when equal.
struct PrintedComparison {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::size_t same_printed_digits = 0;
  double max_abs_rel_difference_pct = 0;
};
PrintedComparison compare_printed(const std::vector<PairedValue>& values);

}  // namespace mesowave::io
