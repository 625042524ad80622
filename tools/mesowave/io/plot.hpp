#pragma once
// Line plots of any table (mw-table plot, mw-dispersion theory's Figure 9): a
// spec of series, turned into a gnuplot script whose data travel inside it as
// datablocks and drawn by io::run_gnuplot; the terminal (pngcairo or svg)
// follows the final file name.
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mesowave/io/gnuplot.hpp"

namespace mesowave::io {

struct PlotSeries {
  std::string label;              ///< legend entry ("" = no entry)
  std::vector<double> x, y;       ///< a NaN in y breaks the line
  std::string style = "lines lw 2";
};

struct PlotSpec {
  std::string title, x_label, y_label;
  std::optional<std::pair<double, double>> x_range, y_range;
  std::vector<PlotSeries> series;
  int width_px = 1000, height_px = 650;
  std::string key = "outside right top";  ///< gnuplot key position ("inside bottom left", ...)
  std::string logscale;                   ///< axes on a log scale: "", "x", "y" or "xy"
  bool margins = false;                   ///< keep points off the frame (5 % of the range on each side)
};

/// The gnuplot script that draws `spec` into `write_to` (a staged temporary) in the
/// format named by `final_name`'s extension (InputError unless .png or .svg).
std::string plot_script(const PlotSpec& spec, const std::filesystem::path& final_name,
                        const std::filesystem::path& write_to);

/// Draws it (io::run_gnuplot: InputError when gnuplot is missing or fails).
void render_plot(const PlotSpec& spec, const std::filesystem::path& final_name,
                 const std::filesystem::path& write_to);

}  // namespace mesowave::io
