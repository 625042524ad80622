#pragma once
// Line plots through gnuplot (gnuplot-nox): the data travel inside the script
// as datablocks, the terminal (pngcairo or svg) follows the final file name.
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace mesowave::wave {

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

/// Renders `spec` to `write_to` (a staged temporary) in the format named by
/// `final_name`'s extension (.png or .svg). InputError for another extension
/// or when gnuplot is missing; std::runtime_error when gnuplot fails.
void render_plot(const PlotSpec& spec, const std::filesystem::path& final_name,
                 const std::filesystem::path& write_to);

/// InputError unless `path` ends in .png or .svg (checked before a long run).
void require_plot_extension(const std::filesystem::path& path);

}  // namespace mesowave::wave
