#include "mesowave/io/gnuplot.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "mesowave/core/error.hpp"

namespace mesowave::io {
namespace fs = std::filesystem;

std::string gnuplot_datablock(const std::string& name, const std::vector<std::vector<double>>& columns) {
  std::ostringstream s;
  s.precision(9);
  s << "$" << name << " << EOD\n";
  const std::size_t rows = columns.empty() ? 0 : columns.front().size();
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < columns.size(); ++c) s << (c ? " " : "") << columns[c].at(r);
    s << "\n";
  }
  s << "EOD\n";
  return s.str();
}

std::string gnuplot_quote(const fs::path& path) {
  std::string out = "'";
  for (char c : path.string()) out += (c == '\'') ? std::string("''") : std::string(1, c);
  return out + "'";
}

std::string gnuplot_text(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

void require_plot_extension(const fs::path& path) {
  const auto ext = path.extension().string();
  if (ext != ".png" && ext != ".svg") throw InputError("plot file " + path.string() + " must end in .png or .svg");
}

std::string gnuplot_terminal(const fs::path& final_name, int width_px, int height_px, int font_pt) {
  require_plot_extension(final_name);
  const std::string size = " size " + std::to_string(width_px) + "," + std::to_string(height_px) + " font 'Sans," +
                           std::to_string(font_pt) + "'";
  if (final_name.extension() == ".png") return "set terminal pngcairo" + size + "\n";
  return "set terminal svg" + size + " background '#ffffff'\n";
}

namespace {
std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}
}  // namespace

void run_gnuplot(const std::string& script) {
  std::string tmpl = (fs::temp_directory_path() / "mesowave-plot-XXXXXX").string();
  const int fd = ::mkstemp(tmpl.data());
  if (fd < 0) throw InputError("cannot create a temporary file for gnuplot");
  ::close(fd);
  const fs::path script_path = tmpl, log_path = tmpl + ".log";
  {
    std::ofstream out(script_path);
    out << script;
  }
  const std::string command = "gnuplot " + shell_quote(script_path) + " > " + shell_quote(log_path) + " 2>&1";
  const int status = std::system(command.c_str());
  std::string log;
  {
    std::ifstream in(log_path);
    std::ostringstream s;
    s << in.rdbuf();
    log = s.str();
  }
  std::error_code ignored;
  fs::remove(script_path, ignored);
  fs::remove(log_path, ignored);
  if (status != 0) {
    if (log.find("not found") != std::string::npos || WEXITSTATUS(status) == 127)
      throw InputError("gnuplot is not installed (apt-get install gnuplot-nox), or leave out the plot option");
    for (char& c : log)
      if (c == '\n') c = ' ';
    throw InputError("gnuplot failed: " + log.substr(0, 300));
  }
}

}  // namespace mesowave::io
