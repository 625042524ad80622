// Line plots (io/plot): the script carries every point exactly, breaks a line at
// a NaN, picks the terminal by the final name, and refuses other formats.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "mesowave/core/error.hpp"
#include "mesowave/io/plot.hpp"

using namespace mesowave;
using namespace mesowave::io;

namespace {

PlotSpec two_series() {
  PlotSpec spec;
  spec.title = "speed \"against\" error";
  spec.series.push_back({"FEM", {1, 2, 3}, {0.1, std::numeric_limits<double>::quiet_NaN(), 0.3}, "lines lw 2"});
  spec.series.push_back({"", {10}, {1e-7}, "points pt 7"});
  return spec;
}

}  // namespace

TEST(Plot, ScriptCarriesThePointsAndBreaksAtNaN) {
  const auto s = plot_script(two_series(), "fig.png", "/tmp/stage.png");
  EXPECT_EQ(s.rfind("set terminal pngcairo size 1000,650 font 'Sans,11'\n", 0), 0u) << s;
  EXPECT_NE(s.find("set output '/tmp/stage.png'\n"), std::string::npos);
  EXPECT_NE(s.find("set title \"speed \\\"against\\\" error\"\n"), std::string::npos);
  // The NaN row is an empty line inside the datablock, so gnuplot lifts the pen there.
  EXPECT_NE(s.find("$d0 << EOD\n1 0.1\n\n3 0.3\nEOD\n"), std::string::npos) << s;
  EXPECT_NE(s.find("$d1 << EOD\n10 1e-07\nEOD\n"), std::string::npos) << s;
  EXPECT_NE(s.find("$d0 using 1:2 with lines lw 2 title \"FEM\""), std::string::npos);
  EXPECT_NE(s.find("$d1 using 1:2 with points pt 7 notitle"), std::string::npos);
  EXPECT_EQ(s.find("set logscale"), std::string::npos);
  EXPECT_EQ(s.find("set offsets"), std::string::npos);
}

TEST(Plot, OptionsReachTheScript) {
  auto spec = two_series();
  spec.logscale = "xy";
  spec.margins = true;
  spec.key = "below";
  spec.x_range = std::pair{45.0, 155.0};
  const auto s = plot_script(spec, "fig.svg", "stage.svg");
  EXPECT_EQ(s.rfind("set terminal svg size 1000,650 font 'Sans,11' background '#ffffff'\n", 0), 0u) << s;
  EXPECT_NE(s.find("set logscale xy\n"), std::string::npos);
  EXPECT_NE(s.find("set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05\n"), std::string::npos);
  EXPECT_NE(s.find("set bmargin 7\n"), std::string::npos);
  EXPECT_NE(s.find("set xrange [45:155]\n"), std::string::npos);
}

// Below the plot the key takes a line per titled series: six of them need 4 more lines of margin
// than the ticks and the axis label leave (gnuplot drew them over the tick labels at 7).
TEST(Plot, AKeyBelowThePlotGetsALineOfMarginPerTitledSeries) {
  auto spec = two_series();
  spec.key = "below";
  for (int i = 0; i < 5; ++i) spec.series.push_back({"run " + std::to_string(i), {1}, {1}, "lines"});
  EXPECT_NE(plot_script(spec, "fig.png", "stage.png").find("set bmargin 10\n"), std::string::npos);
  spec.key = "outside right top";
  EXPECT_EQ(plot_script(spec, "fig.png", "stage.png").find("set bmargin"), std::string::npos);
}

TEST(Plot, OnlyPngAndSvg) {
  EXPECT_THROW(plot_script(two_series(), "fig.pdf", "stage.pdf"), InputError);
  EXPECT_THROW(require_plot_extension("fig"), InputError);
  EXPECT_NO_THROW(require_plot_extension("a/b.svg"));
}
