#include "mesowave/io/table_plot.hpp"

#include <cmath>
#include <cstdlib>
#include <limits>

#include "mesowave/core/error.hpp"
#include "mesowave/io/table_gather.hpp"

namespace mesowave::io {

namespace {

double cell_number(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  // An empty or non-numeric cell ("-", "n/a") is a gap in the plot, never a zero.
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v)) return std::numeric_limits<double>::quiet_NaN();
  return v;
}

// What is drawn for a cell: the value, or 1 - value; NaN (a gap) where a log axis cannot show it.
double plotted(const std::string& text, bool one_minus, bool log_y) {
  const double v = one_minus ? 1 - cell_number(text) : cell_number(text);
  return (log_y && !(v > 0)) ? std::numeric_limits<double>::quiet_NaN() : v;
}

struct Overlay {
  std::string file, column, legend;
};

// FILE:COLUMN[=LEGEND]; the last ':' before the legend splits (a path may hold one).
Overlay parse_overlay(const std::string& text) {
  const auto eq = text.find('=');
  const std::string head = text.substr(0, eq);
  const auto colon = head.rfind(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == head.size())
    throw InputError("--overlay " + text + " must be FILE:COLUMN or FILE:COLUMN=LEGEND");
  Overlay o{head.substr(0, colon), head.substr(colon + 1), {}};
  o.legend = eq == std::string::npos ? o.column : text.substr(eq + 1);
  return o;
}

}  // namespace

std::vector<std::string> table_plot_overlay_files(const TablePlotOptions& o) {
  std::vector<std::string> files;
  for (const auto& text : o.overlays) files.push_back(parse_overlay(text).file);
  return files;
}

void require_table_plot_options(const TablePlotOptions& o) {
  if (o.style != "lines" && o.style != "points" && o.style != "linespoints")
    throw InputError("--style " + o.style + " must be lines, points or linespoints");
  if (o.y_range && !(o.y_range->second > o.y_range->first)) throw InputError("--y-range: the end must exceed the start");
}

PlotSpec table_plot(const io::CsvTable& table, const TablePlotOptions& o) {
  require_table_plot_options(o);
  const auto xc = table.column(o.x_column);
  std::vector<double> x;
  for (std::size_t r = 0; r < table.rows.size(); ++r) x.push_back(table.number(r, xc));
  PlotSpec spec;
  spec.title = o.title;
  spec.x_label = o.x_label.empty() ? o.x_column : o.x_label;
  spec.key = o.key;
  std::vector<std::pair<std::size_t, std::string>> ys;
  for (const auto& y : o.y_columns) {
    const auto c = io::parse_column_source(y);  // COLUMN=LEGEND reads like NAME=SOURCE, swapped
    ys.emplace_back(table.column(c.name), c.source);
  }
  if (ys.empty()) throw InputError("a table plot needs at least one y column");
  spec.y_label = o.y_label.empty() ? (o.one_minus ? "1 - " : "") + table.header[ys.front().first] : o.y_label;
  spec.y_range = o.y_range;
  const std::string point_style = o.style == "lines"    ? "lines lw 2"
                                  : o.style == "points" ? "points pt 7 ps 1.5"
                                                        : "linespoints lw 2 pt 7 ps 1.2";
  if (!o.label_column.empty()) {
    spec.margins = true;
    const auto lc = table.column(o.label_column);
    int k = 0;
    for (const auto& [yc, legend] : ys)
      for (std::size_t r = 0; r < table.rows.size(); ++r, ++k)
        spec.series.push_back({table.text(r, lc) + (ys.size() > 1 ? " (" + legend + ")" : ""), {x[r]},
                               {plotted(table.text(r, yc), o.one_minus, o.log_y)},
                               "points pt " + std::to_string(4 + k % 11) + " ps 1.8"});
  } else {
    for (const auto& [yc, legend] : ys) {
      PlotSeries s{legend, x, {}, point_style};
      for (std::size_t r = 0; r < table.rows.size(); ++r) s.y.push_back(plotted(table.text(r, yc), o.one_minus, o.log_y));
      spec.series.push_back(std::move(s));
    }
  }
  for (const auto& text : o.overlays) {
    const Overlay ov = parse_overlay(text);
    const io::CsvTable other = io::read_csv(ov.file);
    const auto ox = other.column(o.x_column), oy = other.column(ov.column);
    PlotSeries s{ov.legend, {}, {}, point_style};
    for (std::size_t r = 0; r < other.rows.size(); ++r)
      s.x.push_back(other.number(r, ox)), s.y.push_back(plotted(other.text(r, oy), o.one_minus, o.log_y));
    spec.series.push_back(std::move(s));
  }
  spec.logscale = std::string(o.log_x ? "x" : "") + (o.log_y ? "y" : "");
  return spec;
}

}  // namespace mesowave::io
