// mw-dem's scene overrides (scene_overrides.hpp): each option lands in the
// scene in SI, with the scene file's checks, and names itself when wrong.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesowave/core/error.hpp"
#include "mesowave/dem/scene/scene_overrides.hpp"

using namespace mesowave::dem;

namespace {

const std::string kScene = R"(
[packing]
file = "p.h5"
[material]
E_dem_GPa = 20
T_MPa = 5
C_MPa = 6
[time]
dt_ns = 10
duration_ms = 1
[[actuator]]
name = "burst"
point_mm = [0, 0, 0]
direction = "x"
amplitude_N = 1
frequency_kHz = 100
[[actuator]]
name = "platen"
kind = "wall"
face = "z+"
velocity_mm_s = 10
[[actuator]]
name = "fixed"
kind = "wall"
face = "z-"
[[sensor]]
name = "load"
quantity = "force"
actuator = "platen"
[[sensor]]
name = "gauge"
quantity = "strain"
component = "z"
face = "x+"
centre_mm = [0, 0, 0]
gauge_mm = 2
patch_mm = [1, 1]
[test]
kind = "compression"
load = "load"
axial = "gauge"
)";

std::string message(const Scene& base, const SceneOverrides& o) {
  Scene s = base;
  try {
    apply_overrides(s, o);
  } catch (const mesowave::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(SceneOverrides, EachOptionLandsInSI) {
  const Scene base = parse_scene(kScene, "t.toml");
  SceneOverrides o;
  o.packing = "other.h5";
  o.material = {{"E_dem_GPa", 30}, {"nu_dem", 0.25}, {"friction_angle_deg", 30}};
  o.frequency_kHz = 250;
  o.dt_ns = 5;
  o.duration_ms = 2;
  o.snapshot_us = 10;
  o.velocity_mm_s = 40;
  o.stop_at_MPa = 7;
  o.modulus_levels_MPa = {1, 3};
  Scene s = base;
  apply_overrides(s, o);
  EXPECT_EQ(s.packing_file, "other.h5");
  EXPECT_DOUBLE_EQ(s.material.E_dem_Pa, 30e9);
  EXPECT_DOUBLE_EQ(s.material.stiffness_ratio, 0.25);
  EXPECT_DOUBLE_EQ(s.material.friction_angle_rad, std::numbers::pi / 6);
  EXPECT_DOUBLE_EQ(s.material.tensile_strength_Pa, 5e6);  // untouched
  EXPECT_DOUBLE_EQ(s.actuators[0].frequency_hz, 250e3);
  EXPECT_DOUBLE_EQ(s.dt_s, 5e-9);
  EXPECT_DOUBLE_EQ(s.duration_s, 2e-3);
  EXPECT_DOUBLE_EQ(s.snapshot_interval_s, 10e-6);
  EXPECT_DOUBLE_EQ(s.actuators[1].amplitude, 40e-3);  // the moving wall
  EXPECT_DOUBLE_EQ(s.actuators[2].amplitude, 0.0);    // a fixed wall stays fixed
  EXPECT_DOUBLE_EQ(s.actuators[0].amplitude, 1.0);    // a force burst is no platen
  EXPECT_DOUBLE_EQ(s.test.stop_at_Pa, 7e6);
  EXPECT_TRUE(s.test.levels_absolute);
  EXPECT_DOUBLE_EQ(s.test.levels[1], 3e6);
  // Nothing given: the scene as read.
  Scene same = base;
  apply_overrides(same, SceneOverrides{});
  EXPECT_EQ(same.packing_file, base.packing_file);
  EXPECT_EQ(same.dt_s, base.dt_s);
  EXPECT_EQ(same.material.E_dem_Pa, base.material.E_dem_Pa);
  SceneOverrides elastic;
  elastic.unbreakable = true;
  apply_overrides(same, elastic);
  EXPECT_TRUE(std::isinf(same.material.tensile_strength_Pa) && std::isinf(same.material.cohesion_Pa));
}

TEST(SceneOverrides, ErrorsNameTheOption) {
  const Scene base = parse_scene(kScene, "t.toml");
  SceneOverrides o;
  o.material = {{"nu_dem", 11}};
  EXPECT_NE(message(base, o).find("--nu-dem"), std::string::npos);
  o = {};
  o.dt_ns = -1;
  EXPECT_NE(message(base, o).find("--dt-ns"), std::string::npos);
  o = {};
  o.modulus_levels_MPa = {3, 1};
  EXPECT_NE(message(base, o).find("--modulus-levels-MPa"), std::string::npos);
  Scene no_test = base;
  no_test.test = {};
  o = {};
  o.stop_at_MPa = 5;
  EXPECT_NE(message(no_test, o).find("need a scene with a [test]"), std::string::npos);
  o = {};
  o.curves = true;
  EXPECT_NE(message(no_test, o).find("--curves"), std::string::npos);
  EXPECT_EQ(message(base, o), "");
}

// The options parse into the overrides (the table's option names).
TEST(SceneOverrides, OptionsFillTheOverrides) {
  CLI::App app;
  SceneOverrides o;
  add_override_options(app, o);
  std::vector<std::string> args = {"--E-dem-GPa", "12", "--T-MPa", "3", "--dt-ns", "2", "--modulus-levels-MPa", "1,2",
                                   "--unbreakable-bonds"};
  std::reverse(args.begin(), args.end());
  app.parse(args);
  EXPECT_EQ(o.material.at("E_dem_GPa"), 12);
  EXPECT_EQ(o.material.at("T_MPa"), 3);
  EXPECT_EQ(o.dt_ns, 2);
  EXPECT_EQ(o.modulus_levels_MPa, (std::vector<double>{1, 2}));
  EXPECT_TRUE(o.unbreakable);
}
