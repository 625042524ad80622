#include "mesowave/wave/plot.hpp"

#include <cmath>
#include <sys/wait.h>

#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/io/gnuplot.hpp"

namespace mesowave::wave {

void require_plot_extension(const std::filesystem::path& path) {
  const auto ext = path.extension().string();
  if (ext != ".png" && ext != ".svg")
    throw InputError("plot file " + path.string() + " must end in .png or .svg");
}

void render_plot(const PlotSpec& spec, const std::filesystem::path& final_name,
                 const std::filesystem::path& write_to) {
  require_plot_extension(final_name);
  std::ostringstream s;
  if (final_name.extension() == ".png")
    s << "set terminal pngcairo size " << spec.width_px << "," << spec.height_px << " font 'Sans,11'\n";
  else
    s << "set terminal svg size " << spec.width_px << "," << spec.height_px << " font 'Sans,11' background '#ffffff'\n";
  s << "set output " << io::gnuplot_quote(write_to) << "\n";
  s << "set title " << io::gnuplot_text(spec.title) << "\nset xlabel " << io::gnuplot_text(spec.x_label) << "\nset ylabel "
    << io::gnuplot_text(spec.y_label) << "\nset grid\nset key " << spec.key << " box opaque\nset datafile missing 'NaN'\n";
  if (!spec.logscale.empty()) s << "set logscale " << spec.logscale << "\n";
  // gnuplot's pngcairo puts a key below the plot on top of the x label unless the margin makes room.
  if (spec.key.rfind("below", 0) == 0) s << "set bmargin 7\n";
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
      << (ser.label.empty() ? " notitle" : " title " + io::gnuplot_text(ser.label));
  }
  s << "\nunset output\n";

  FILE* pipe = popen("gnuplot", "w");
  if (!pipe) throw InputError("cannot start gnuplot (install gnuplot-nox)");
  const std::string script = s.str();
  std::fwrite(script.data(), 1, script.size(), pipe);
  const int status = pclose(pipe);
  if (status != 0) {
    if (WIFEXITED(status) && WEXITSTATUS(status) == 127) throw InputError("gnuplot not found (install gnuplot-nox)");
    throw std::runtime_error("gnuplot failed to draw " + final_name.string());
  }
}

}  // namespace mesowave::wave
