#pragma once
// Tables made of other tools' outputs: one row per run (a frequency, a model),
// each value taken from the CSV table or the JSON / TOML summary that run
// wrote, so that a summary table such as the concrete paper's Table 3 (mean PCC
// per frequency, from one mw-pcc table per frequency) is itself a recorded run
// whose inputs are the files its numbers come from.
//
//   row    "100=results/pcc-100kHz.csv,results/dem-100kHz.json"   key, then its files
//   column "pcc_mean=pcc_signal"            output column = a column (CSV) or key (JSON, TOML)
//          "B=pcc_signal@sensor=B"          ... in the CSV row whose column `sensor` is "B"
//          "wall_s"                         same name in and out
//          "residual=energy.residual_relative"   a JSON key inside an object
//          "E=E_glob_GPa|test.E_glob_GPa"   the first of these names a file holds
//          "pcc=mean(pcc_signal)"           the mean over every one of the row's files that
//                                           holds it (median(...): their median)
//          "c=c_group_m_s@f_kHz={f_kHz}"    ... in the row whose f_kHz is this row's key
// In a CSV file the value comes from the row the column's selector (or the
// gather's default selector) picks; a file of one row needs none. The first of
// a row's files that holds the source gives the value. A key of several columns
// ("model,f_kHz") takes a row key of as many parts ("1.03R,50").
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mesowave/io/csv.hpp"
#include "mesowave/io/text_table.hpp"

namespace mesowave::io {

/// "COLUMN=VALUE": pick the CSV row whose COLUMN reads VALUE.
using RowSelector = std::pair<std::string, std::string>;
RowSelector parse_row_selector(const std::string& text);

struct ColumnSource {
  /// How a row's values become one: the first file's, or the mean or median of them all.
  enum class Aggregate { first, mean, median };
  std::string name;                   ///< the output column
  std::string source;                 ///< column (CSV) or key (JSON, TOML) in the files; "A|B": A in any of
                                      ///< the row's files, else B (mean/median: per file, its first name)
  std::optional<RowSelector> where;   ///< CSV: the row; default: the gather's selector. A value
                                      ///< "{KEY}" stands for the row's value of key column KEY
  Aggregate aggregate = Aggregate::first;  ///< SOURCE written "mean(...)" or "median(...)"
};
/// "NAME", "NAME=SOURCE" or "NAME=SOURCE@COLUMN=VALUE" (SOURCE may be mean(S) or
/// median(S)); InputError otherwise.
ColumnSource parse_column_source(const std::string& text);

struct GatherRow {
  std::string key;
  std::vector<std::filesystem::path> files;
};
/// "KEY=FILE[,FILE...]"; InputError otherwise.
GatherRow parse_gather_row(const std::string& text);

/// Columns of a keyed CSV table (e.g. the paper's values) added to a gathered one.
struct TableJoin {
  std::filesystem::path file;
  std::vector<ColumnSource> columns;  ///< NAME=SOURCE: SOURCE a column of `file`
};
/// "FILE:NAME=SOURCE[,NAME=SOURCE...]" (the last ':' ends FILE); InputError otherwise.
TableJoin parse_table_join(const std::string& text);

struct GatherSpec {
  std::string key_name = "key";        ///< header of the first column; "A,B": a key of two columns
  std::vector<GatherRow> rows;
  std::vector<ColumnSource> columns;
  std::optional<RowSelector> where;    ///< default row selector for CSV files
  std::optional<int> significant_digits;  ///< JSON numbers rounded to these (CSV, TOML: as written)
  std::vector<TableJoin> joins;        ///< applied in order after the rows (join_columns on the first key column)
  std::map<std::string, std::string> join_keys;  ///< a row key as the joined tables spell it ("FEM 1 mm" -> "FEM")
  std::map<std::string, ColumnFormat> formats;   ///< by output column (a joined one too)
  /// Two objectives "min:COLUMN" or "max:COLUMN" (wall time and PCC, say): adds a last column
  /// `pareto`, "yes" on every row no other row matches or beats in both and beats in one (the
  /// cheapest model for an accuracy), empty on the others and on rows missing either number.
  std::vector<std::string> pareto;

  /// Every file the table is made of: the rows' in order, then the joins'.
  std::vector<std::filesystem::path> files() const;
};

/// The gathered table: key_name, then the columns, one row per GatherRow in
/// order, then the joins' columns. Numbers are copied as written (CSV) or in
/// their shortest exact form (JSON). InputError naming the file when a CSV has
/// no row or several rows matching the selector (or several rows and no
/// selector), or when none of a row's files holds a column's source.
CsvTable gather_rows(const GatherSpec& spec);

/// Adds `columns` of `other` to `table`, matching rows by `key` (a column of
/// both; numbers compare as numbers, so "100" meets "100.0"). A row `other`
/// lacks gets an empty field; InputError if `other` has a key twice or lacks a
/// column. `aliases` maps a key of `table` to the one `other` has for that row.
void join_columns(CsvTable& table, const CsvTable& other, const std::string& key,
                  const std::vector<ColumnSource>& columns, const std::map<std::string, std::string>& aliases = {});

}  // namespace mesowave::io
