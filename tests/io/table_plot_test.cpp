// mw-table plot's spec (io/table_plot): what each cell becomes on the plot,
// worked out by hand for a small table.
#include "mesowave/io/table_plot.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "mesowave/core/error.hpp"
#include "support/input_error.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using namespace mesowave::io;
using mesowave::test::TempDir;
using mesowave::test::write_file;

namespace {

const io::CsvTable table = io::parse_csv("f_kHz,pcc,paper,run\n100,0.75,-,a\n150,1,0.5,b\n200,,0.25,c\n", "t.csv");

TEST(TablePlot, OneSeriesPerColumnWithGapsForMissingCells) {
  TablePlotOptions o;
  o.x_column = "f_kHz";
  o.y_columns = {"pcc=mesowave", "paper"};
  const auto spec = table_plot(table, o);
  EXPECT_EQ(spec.x_label, "f_kHz");
  EXPECT_EQ(spec.y_label, "pcc");
  EXPECT_EQ(spec.logscale, "");
  ASSERT_EQ(spec.series.size(), 2u);
  EXPECT_EQ(spec.series[0].label, "mesowave");
  EXPECT_EQ(spec.series[1].label, "paper");
  EXPECT_EQ(spec.series[0].x, (std::vector<double>{100, 150, 200}));
  EXPECT_EQ(spec.series[0].y[0], 0.75);
  EXPECT_EQ(spec.series[0].y[1], 1.0);
  EXPECT_TRUE(std::isnan(spec.series[0].y[2]));  // empty: a gap, never a zero
  EXPECT_TRUE(std::isnan(spec.series[1].y[0]));  // "-"
  EXPECT_EQ(spec.series[1].y[2], 0.25);
  EXPECT_EQ(spec.series[0].style, "linespoints lw 2 pt 7 ps 1.2");
}

TEST(TablePlot, OneMinusOnALogAxisLeavesOutWhatItCannotShow) {
  TablePlotOptions o;
  o.x_column = "f_kHz";
  o.y_columns = {"pcc"};
  o.one_minus = o.log_y = o.log_x = true;
  o.style = "lines";
  const auto spec = table_plot(table, o);
  EXPECT_EQ(spec.y_label, "1 - pcc");
  EXPECT_EQ(spec.logscale, "xy");
  EXPECT_DOUBLE_EQ(spec.series[0].y[0], 0.25);
  EXPECT_TRUE(std::isnan(spec.series[0].y[1]));  // 1 - 1 = 0 has no place on a log axis
  EXPECT_EQ(spec.series[0].style, "lines lw 2");
}

TEST(TablePlot, ALabelColumnGivesOnePointPerRow) {
  TablePlotOptions o;
  o.x_column = "f_kHz";
  o.y_columns = {"paper"};
  o.label_column = "run";
  o.y_range = std::pair{0.0, 1.0};
  o.x_label = "frequency";
  const auto spec = table_plot(table, o);
  EXPECT_TRUE(spec.margins);
  EXPECT_EQ(spec.x_label, "frequency");
  ASSERT_TRUE(spec.y_range);
  EXPECT_EQ(spec.y_range->second, 1.0);
  ASSERT_EQ(spec.series.size(), 3u);
  EXPECT_EQ(spec.series[2].label, "c");
  EXPECT_EQ(spec.series[2].x, (std::vector<double>{200}));
  EXPECT_EQ(spec.series[2].y, (std::vector<double>{0.25}));
  EXPECT_EQ(spec.series[0].style, "points pt 4 ps 1.8");  // a marker of its own per point
  EXPECT_EQ(spec.series[2].style, "points pt 6 ps 1.8");
}

TEST(TablePlot, BadOptionsAndColumnsAreInputErrors) {
  TablePlotOptions o;
  o.x_column = "f_kHz";
  o.y_columns = {"pcc"};
  o.style = "bars";
  EXPECT_THROW(require_table_plot_options(o), InputError);
  EXPECT_THROW(table_plot(table, o), InputError);
  o.style = "points";
  o.y_range = std::pair{1.0, 1.0};
  EXPECT_THROW(require_table_plot_options(o), InputError);
  o.y_range.reset();
  o.y_columns = {"missing"};
  EXPECT_THROW(table_plot(table, o), InputError);
  o.y_columns = {"pcc"};
  o.x_column = "run";  // not numeric
  EXPECT_THROW(table_plot(table, o), InputError);
}

// An overlay: another table's column against that table's own x, beside the main series.
TEST(TablePlot, AnOverlayDrawsAnotherTablesColumnAgainstItsOwnX) {
  TempDir dir;
  write_file(dir / "b.csv", "f_kHz,pcc\n120,0.5\n180,\n");
  TablePlotOptions o;
  o.x_column = "f_kHz";
  o.y_columns = {"pcc=a"};
  o.overlays = {(dir / "b.csv").string() + ":pcc=b"};
  EXPECT_EQ(table_plot_overlay_files(o), (std::vector<std::string>{(dir / "b.csv").string()}));
  const auto spec = table_plot(table, o);
  ASSERT_EQ(spec.series.size(), 2u);
  EXPECT_EQ(spec.series[1].label, "b");
  EXPECT_EQ(spec.series[1].x, (std::vector<double>{120, 180}));
  EXPECT_EQ(spec.series[1].y[0], 0.5);
  EXPECT_TRUE(std::isnan(spec.series[1].y[1]));  // an empty cell is a gap there too
  o.overlays = {(dir / "b.csv").string() + ":pcc"};
  EXPECT_EQ(table_plot(table, o).series[1].label, "pcc");  // the legend defaults to the column
  o.overlays = {(dir / "b.csv").string()};
  EXPECT_NE(test::input_error_of([&] { table_plot(table, o); }).find("FILE:COLUMN"), std::string::npos);
  o.overlays = {(dir / "b.csv").string() + ":missing"};
  EXPECT_THROW(table_plot(table, o), InputError);
}

}  // namespace
