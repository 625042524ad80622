#include "mesowave/io/plot.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "mesowave/core/format.hpp"

namespace mesowave::io {

std::string plot_script(const PlotSpec& spec, const std::filesystem::path& final_name,
                        const std::filesystem::path& write_to) {
  std::ostringstream s;
  s << gnuplot_terminal(final_name, spec.width_px, spec.height_px, 11);
  s << "set output " << gnuplot_quote(write_to) << "\n";
  s << "set title " << gnuplot_text(spec.title) << "\nset xlabel " << gnuplot_text(spec.x_label) << "\nset ylabel "
    << gnuplot_text(spec.y_label) << "\nset grid\nset key " << spec.key << " box opaque\nset datafile missing 'NaN'\n";
  if (!spec.logscale.empty()) s << "set logscale " << spec.logscale << "\n";
  // gnuplot's pngcairo puts a key below the plot on top of the x label and the tick labels unless
  // the margin makes room: a line a titled series (the key's one column), the ticks and the label.
  if (spec.key.rfind("below", 0) == 0) {
    const auto titled = std::count_if(spec.series.begin(), spec.series.end(),
                                      [](const PlotSeries& ser) { return !ser.label.empty(); });
    s << "set bmargin " << std::max<std::ptrdiff_t>(7, 4 + titled) << "\n";
  }
  if (spec.margins) s << "set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05\n";
  if (spec.x_range) s << "set xrange [" << spec.x_range->first << ":" << spec.x_range->second << "]\n";
  if (spec.y_range) s << "set yrange [" << spec.y_range->first << ":" << spec.y_range->second << "]\n";
  for (std::size_t i = 0; i < spec.series.size(); ++i) {
    s << "$d" << i << " << EOD\n";
    const auto& ser = spec.series[i];
    for (std::size_t j = 0; j < ser.x.size(); ++j) {
      if (std::isnan(ser.y[j])) s << "\n";  // blank line: gnuplot breaks the line here
      else s << format_exact(ser.x[j]) << " " << format_exact(ser.y[j]) << "\n";
    }
    s << "EOD\n";
  }
  s << "plot ";
  for (std::size_t i = 0; i < spec.series.size(); ++i) {
    const auto& ser = spec.series[i];
    s << (i ? ", \\\n     " : "") << "$d" << i << " using 1:2 with " << ser.style
      << (ser.label.empty() ? " notitle" : " title " + gnuplot_text(ser.label));
  }
  s << "\nunset output\n";
  return s.str();
}

void render_plot(const PlotSpec& spec, const std::filesystem::path& final_name,
                 const std::filesystem::path& write_to) {
  run_gnuplot(plot_script(spec, final_name, write_to));
}

}  // namespace mesowave::io
