#pragma once
// A plot of a CSV table's columns against one of them (mw-table plot): one
// series per y column, or one point per row named by a label column (speed
// against error). Beside plot.hpp, whose PlotSpec it fills. Overlays add a column of another
// table against that table's own x column (two runs' curves sampled at different x: the two
// cohesive laws' load-deflection curves).
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mesowave/io/csv.hpp"
#include "mesowave/io/plot.hpp"

namespace mesowave::io {

struct TablePlotOptions {
  std::string x_column;
  std::vector<std::string> y_columns;  ///< COLUMN[=LEGEND]; the legend defaults to the column
  std::string label_column;            ///< non-empty: one point per row, named by this column
  std::string style = "linespoints";   ///< lines | points | linespoints
  std::string title, x_label, y_label; ///< labels default to the x column and the first y column
  std::optional<std::pair<double, double>> y_range;
  bool log_x = false, log_y = false;
  bool one_minus = false;              ///< plot 1 - y (e.g. the decorrelation 1 - PCC)
  std::string key = "outside right top";
  std::vector<std::string> overlays;   ///< FILE:COLUMN[=LEGEND]: a line from another table (its own x column)
};

/// The files the overlays read (for the run's record).
std::vector<std::string> table_plot_overlay_files(const TablePlotOptions& options);

/// InputError for a style other than lines/points/linespoints or a y range
/// whose end does not exceed its start.
void require_table_plot_options(const TablePlotOptions& options);

/// The plot of `table`: x must be numeric; a y cell that is empty or not a
/// number ("-", "n/a") is a gap, never a zero, and so is a value a log y axis
/// cannot show. InputError for a missing column.
PlotSpec table_plot(const CsvTable& table, const TablePlotOptions& options);

}  // namespace mesowave::io
