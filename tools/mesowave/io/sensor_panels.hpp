#pragma once
// Two sets of sensor records drawn sensor by sensor, one panel per sensor with
// both sets overlaid - the concrete paper's Figs. 12-15 (signals of sensors
// B-G, their envelopes, their spectra), with the second set on the same axes so
// that the two can be compared at a glance. Rendered by gnuplot (gnuplot-nox):
// the data travel inside the script as datablocks.
//
// Each curve is divided by its largest |y| within the plotted range unless
// asked otherwise: the comparison that matters here (PCC, shapes, arrival
// times) does not depend on amplitude, and a DEM and a FEM record of the same
// test differ in amplitude by the actuator model alone.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace mesowave::io {

struct Curve {
  std::vector<double> x, y;  ///< same length; x increasing
};

struct SensorPanel {
  std::string title;  ///< "B" or "B: PCC 0.45"
  Curve a, b;         ///< b may be empty (one set only)
};

struct SensorPanelsFigure {
  std::string title, x_label, y_label;
  std::string label_a = "a", label_b = "b";  ///< legend entries
  std::optional<std::pair<double, double>> x_range;  ///< default: the data's
  bool normalise = true;                     ///< each curve / its largest |y| in range
  std::size_t columns = 2;
  int width_px = 1200, height_px = 900;
  std::vector<SensorPanel> panels;
};

/// At most about 2 * bins points that keep every extreme of `c` over `bins`
/// equal intervals of x (min and max of each interval, in the order they
/// occur), so a 30,000-sample record plots as it looks. Curves with at most
/// 2 * bins points come back unchanged. Only the points inside `range` (if
/// given) are kept.
Curve decimate_min_max(const Curve& c, std::size_t bins, std::optional<std::pair<double, double>> range = std::nullopt);

/// The gnuplot script that draws `figure` into `write_to` as PNG or SVG by the
/// extension of `final_name` (the name the staged file will get). InputError
/// for another extension, no panel, or a curve whose x and y differ in length.
std::string sensor_panels_script(const SensorPanelsFigure& figure, const std::filesystem::path& final_name,
                                 const std::filesystem::path& write_to);

/// Draws it (io::run_gnuplot).
void render_sensor_panels(const SensorPanelsFigure& figure, const std::filesystem::path& final_name,
                          const std::filesystem::path& write_to);

}  // namespace mesowave::io
