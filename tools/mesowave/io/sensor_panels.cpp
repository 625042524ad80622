#include "mesowave/io/sensor_panels.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "mesowave/core/error.hpp"
#include "mesowave/io/gnuplot.hpp"

namespace mesowave::io {
namespace fs = std::filesystem;

namespace {

bool in_range(double x, const std::optional<std::pair<double, double>>& range) {
  return !range || (x >= range->first && x <= range->second);
}

Curve scaled(const Curve& c, const std::optional<std::pair<double, double>>& range, bool normalise) {
  double peak = 0;
  for (std::size_t i = 0; i < c.x.size(); ++i)
    if (in_range(c.x[i], range)) peak = std::max(peak, std::abs(c.y[i]));
  Curve out = c;
  // A record that is zero in the range stays zero (no 0/0).
  if (normalise && peak > 0)
    for (auto& y : out.y) y /= peak;
  return out;
}

}  // namespace

Curve decimate_min_max(const Curve& c, std::size_t bins, std::optional<std::pair<double, double>> range) {
  if (c.x.size() != c.y.size()) throw InputError("a curve needs as many x as y values");
  Curve inside;
  for (std::size_t i = 0; i < c.x.size(); ++i)
    if (in_range(c.x[i], range)) {
      inside.x.push_back(c.x[i]);
      inside.y.push_back(c.y[i]);
    }
  if (bins == 0 || inside.x.size() <= 2 * bins) return inside;
  const double x0 = inside.x.front(), width = (inside.x.back() - x0) / double(bins);
  Curve out;
  std::size_t i = 0;
  while (i < inside.x.size()) {
    // The samples of one interval: [x0 + k width, x0 + (k + 1) width).
    const auto k = std::min(bins - 1, std::size_t((inside.x[i] - x0) / width));
    std::size_t lo = i, hi = i, j = i;
    for (; j < inside.x.size() && std::min(bins - 1, std::size_t((inside.x[j] - x0) / width)) == k; ++j) {
      if (inside.y[j] < inside.y[lo]) lo = j;
      if (inside.y[j] > inside.y[hi]) hi = j;
    }
    for (auto m : {std::min(lo, hi), std::max(lo, hi)}) {
      if (!out.x.empty() && out.x.back() == inside.x[m]) continue;  // lo == hi
      out.x.push_back(inside.x[m]);
      out.y.push_back(inside.y[m]);
    }
    i = j;
  }
  return out;
}

std::string sensor_panels_script(const SensorPanelsFigure& figure, const fs::path& final_name,
                                 const fs::path& write_to) {
  require_plot_extension(final_name);
  if (figure.panels.empty()) throw InputError("a figure of sensors needs at least one sensor");
  const std::size_t columns = std::max<std::size_t>(1, std::min(figure.columns, figure.panels.size()));
  const std::size_t rows = (figure.panels.size() + columns - 1) / columns;
  constexpr std::size_t kBins = 1500;  // per curve: about 3000 points, more than a panel has pixels

  std::ostringstream s;
  s << gnuplot_terminal(final_name, figure.width_px, figure.height_px, 10);
  s << "set output " << gnuplot_quote(write_to) << "\n";
  for (std::size_t p = 0; p < figure.panels.size(); ++p) {
    const auto& panel = figure.panels[p];
    for (const auto* c : {&panel.a, &panel.b}) {
      if (c->x.size() != c->y.size())
        throw InputError("sensor " + panel.title + ": a curve needs as many x as y values");
      const auto d = decimate_min_max(scaled(*c, figure.x_range, figure.normalise), kBins, figure.x_range);
      std::string name(c == &panel.a ? "a" : "b");
      name += std::to_string(p);
      s << gnuplot_datablock(name, {d.x, d.y});
    }
  }
  s << "set multiplot layout " << rows << "," << columns << " title " << gnuplot_text(figure.title) << "\n";
  s << "set grid\nset xlabel " << gnuplot_text(figure.x_label) << "\nset ylabel " << gnuplot_text(figure.y_label) << "\n";
  if (figure.x_range) s << "set xrange [" << figure.x_range->first << ":" << figure.x_range->second << "]\n";
  s << "set key top right opaque box samplen 2\n";
  for (std::size_t p = 0; p < figure.panels.size(); ++p) {
    const auto& panel = figure.panels[p];
    // The legend once, in the first panel; the sets keep their colours throughout.
    if (p == 1) s << "unset key\n";
    s << "set title " << gnuplot_text(panel.title) << "\n";
    s << "plot $a" << p << " using 1:2 with lines lw 1.2 lc rgb '#0060ad' title " << gnuplot_text(figure.label_a);
    if (!panel.b.x.empty())
      s << ", $b" << p << " using 1:2 with lines lw 1 lc rgb '#50dd181f' title " << gnuplot_text(figure.label_b);
    s << "\n";
  }
  s << "unset multiplot\nunset output\n";
  return s.str();
}

void render_sensor_panels(const SensorPanelsFigure& figure, const fs::path& final_name, const fs::path& write_to) {
  run_gnuplot(sensor_panels_script(figure, final_name, write_to));
}

}  // namespace mesowave::io
