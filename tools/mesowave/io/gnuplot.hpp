#pragma once
// Plots through gnuplot (Debian gnuplot-nox): a tool builds a script with its
// data inline (datablocks), and gnuplot renders it to the staged output path.
#include <filesystem>
#include <string>
#include <vector>

namespace mesowave::io {

/// `$name << EOD` ... `EOD`: one line per row, columns separated by spaces,
/// numbers with enough digits to plot faithfully.
std::string gnuplot_datablock(const std::string& name, const std::vector<std::vector<double>>& columns);

/// Quotes a path for a gnuplot string ('...'; single quotes doubled).
std::string gnuplot_quote(const std::filesystem::path& path);

/// Text as a gnuplot string in double quotes, for titles and labels: an
/// apostrophe stays as it is, a double quote or backslash is escaped.
std::string gnuplot_text(const std::string& text);

/// InputError unless `path` ends in .png or .svg, the two terminals the plots use
/// (checked before a long run as well as before drawing).
void require_plot_extension(const std::filesystem::path& path);

/// The `set terminal` line for `final_name`'s extension: pngcairo for .png, svg on
/// a white background for .svg (InputError for another extension).
std::string gnuplot_terminal(const std::filesystem::path& final_name, int width_px, int height_px, int font_pt);

/// Runs gnuplot on `script` (written to a temporary file). InputError if
/// gnuplot is not installed or fails (its message is passed on).
void run_gnuplot(const std::string& script);

}  // namespace mesowave::io
