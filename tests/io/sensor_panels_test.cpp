// Sensor-by-sensor figures (io/sensor_panels): the decimation keeps every
// extreme of a long record, curves are normalised to their peak in the plotted
// range, and the script lays out one panel per sensor.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mesowave/core/error.hpp"
#include "mesowave/io/sensor_panels.hpp"

using namespace mesowave;
using namespace mesowave::io;

namespace {

Curve sine(std::size_t n, double cycles) {
  Curve c;
  for (std::size_t i = 0; i < n; ++i) {
    c.x.push_back(double(i));
    c.y.push_back(std::sin(2 * 3.141592653589793 * cycles * double(i) / double(n)));
  }
  return c;
}

}  // namespace

TEST(SensorPanels, DecimationKeepsEveryExtremeInOrder) {
  auto c = sine(30000, 37);
  c.y[12345] = 5.0;   // a spike one sample wide must survive
  c.y[20001] = -4.0;
  const auto d = decimate_min_max(c, 1000);
  EXPECT_LE(d.x.size(), 2000u);
  EXPECT_GE(d.x.size(), 1000u);
  EXPECT_TRUE(std::is_sorted(d.x.begin(), d.x.end()));
  EXPECT_EQ(*std::max_element(d.y.begin(), d.y.end()), 5.0);
  EXPECT_EQ(*std::min_element(d.y.begin(), d.y.end()), -4.0);
  EXPECT_EQ(d.x.front(), 0.0);
  // Short curves come back as they are; a range keeps only its points.
  const auto s = sine(100, 1);
  EXPECT_EQ(decimate_min_max(s, 1000).y, s.y);
  const auto r = decimate_min_max(s, 1000, std::pair{10.0, 19.0});
  ASSERT_EQ(r.x.size(), 10u);
  EXPECT_EQ(r.x.front(), 10.0);
  EXPECT_EQ(r.x.back(), 19.0);
}

TEST(SensorPanels, ScriptHasOnePanelPerSensorAndNormalisedData) {
  SensorPanelsFigure f;
  f.title = "cube";
  f.label_a = "FEM";
  f.label_b = "DEM";
  for (const char* name : {"B", "C", "D", "E", "F"}) {
    Curve a{{0, 1, 2}, {0, 4, -2}}, b{{0, 1, 2}, {0, -0.5, 0.25}};
    f.panels.push_back({name, a, b});
  }
  const auto script = sensor_panels_script(f, "fig.png", "/tmp/x.png");
  EXPECT_NE(script.find("set terminal pngcairo"), std::string::npos);
  EXPECT_NE(script.find("set multiplot layout 3,2"), std::string::npos);
  EXPECT_NE(script.find("title \"FEM\""), std::string::npos);
  EXPECT_NE(script.find("title \"DEM\""), std::string::npos);
  // a / max|a| = 0, 1, -0.5 and b / max|b| = 0, -1, 0.5.
  EXPECT_NE(script.find("$a0 << EOD\n0 0\n1 1\n2 -0.5\nEOD"), std::string::npos) << script.substr(0, 400);
  EXPECT_NE(script.find("$b4 << EOD\n0 0\n1 -1\n2 0.5\nEOD"), std::string::npos);
  // Within a range the peak is the range's: from x = 2 on, a is -2 -> -1.
  f.x_range = std::pair{1.5, 2.0};
  EXPECT_NE(sensor_panels_script(f, "fig.svg", "/tmp/x.svg").find("$a0 << EOD\n2 -1\nEOD"), std::string::npos);
  f.normalise = false;
  EXPECT_NE(sensor_panels_script(f, "fig.svg", "/tmp/x.svg").find("$a0 << EOD\n2 -2\nEOD"), std::string::npos);
}

TEST(SensorPanels, RefusesWhatItCannotDraw) {
  SensorPanelsFigure f;
  EXPECT_THROW(sensor_panels_script(f, "fig.png", "/tmp/x.png"), InputError);  // no panel
  f.panels.push_back({"B", Curve{{0, 1}, {0}}, Curve{}});
  EXPECT_THROW(sensor_panels_script(f, "fig.png", "/tmp/x.png"), InputError);  // x and y differ
  f.panels[0].a.y.push_back(1);
  EXPECT_THROW(sensor_panels_script(f, "fig.pdf", "/tmp/x.pdf"), InputError);
  EXPECT_NO_THROW(sensor_panels_script(f, "fig.png", "/tmp/x.png"));
}
