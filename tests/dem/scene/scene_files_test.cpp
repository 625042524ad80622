// The shipped scenes parse, and the cube scene's transducers are the ones in
// lab-data/concrete-cube/experiment.toml (as fractions of the cube), with D/F and E/G mirror pairs on
// opposite faces (the paper: G = E and F = D for an ideal cube).
#include <gtest/gtest.h>

#include <toml++/toml.h>

#include <cmath>
#include <filesystem>
#include <map>

#include "mesowave/core/units.hpp"
#include "mesowave/dem/scene/scene.hpp"
#include "mesowave/experiment/experiment.hpp"

using namespace mesowave::dem;
namespace fs = std::filesystem;

namespace {

const fs::path kSource = MESOWAVE_SOURCE_DIR;

struct Transducer {
  std::string face;
  std::array<double, 3> centre_mm;
};

std::map<std::string, Transducer> lab_positions() {
  const auto lab = mesowave::experiment::read_experiment_file(kSource / "lab-data/concrete-cube/experiment.toml");
  std::map<std::string, Transducer> out;
  for (const auto& t : lab.transducers) {
    EXPECT_EQ(t.source, "assumed") << t.name;
    EXPECT_FALSE(t.cite.empty()) << t.name;
    Transducer x;
    x.face = t.face;
    for (std::size_t i = 0; i < 3; ++i) x.centre_mm[i] = t.centre_m[i] / mesowave::units::mm;
    out[t.name] = x;
  }
  return out;
}

}  // namespace

TEST(SceneFiles, CubeSceneMatchesTheLabDataPositions) {
  const Scene s = read_scene_file(kSource / "pipeline/concrete-cube/scenes/cube-wave.toml");
  const auto lab = lab_positions();
  ASSERT_EQ(lab.size(), 7u);
  ASSERT_EQ(s.actuators.size(), 1u);
  ASSERT_EQ(s.sensors.size(), 6u);
  // The scene places them as fractions of the packing's extent (so that it fits the quick
  // pipeline's smaller cube too); on the wave test's cube of porosity.toml they are experiment.toml's.
  const double side_mm =
      toml::parse_file((kSource / "lab-data/concrete-cube/porosity.toml").string())["cube_side"]["value"].value_or(0.0);
  ASSERT_EQ(side_mm, 50.0);
  // porosity.toml's cube (mw-pack's) is the experiment's specimen.
  const auto specimen = mesowave::experiment::read_experiment_file(kSource / "lab-data/concrete-cube/experiment.toml").specimen;
  for (double a : specimen.size_m) EXPECT_DOUBLE_EQ(a, side_mm * 1e-3);
  EXPECT_DOUBLE_EQ(s.actuators[0].amplitude, 0.01);
  auto check = [&](const std::string& name, const SphereTarget& t) {
    ASSERT_TRUE(lab.count(name)) << name;
    EXPECT_EQ(t.patch.face.name(), lab.at(name).face) << name;
    ASSERT_TRUE(t.patch.relative) << name;
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(t.patch.centre_rel[d] * side_mm, lab.at(name).centre_mm[std::size_t(d)], 1e-12) << name;
  };
  check(s.actuators[0].name, s.actuators[0].target);
  for (const auto& sensor : s.sensors) check(sensor.name, sensor.target);
  // The paper's Section 4.1-4.2 values.
  EXPECT_DOUBLE_EQ(s.dt_s, 5e-8);
  EXPECT_DOUBLE_EQ(s.duration_s, 1.5e-3);
  EXPECT_DOUBLE_EQ(s.material.E_dem_Pa, 23.31e9);
  EXPECT_DOUBLE_EQ(s.material.stiffness_ratio, 0.32);
  EXPECT_DOUBLE_EQ(s.material.damping, 0.01);
  EXPECT_DOUBLE_EQ(s.material.bond_factor, 1.1);
  EXPECT_DOUBLE_EQ(s.material.tensile_strength_Pa, 24.4e6);
}

TEST(SceneFiles, MirrorPairsSitOnOppositeFacesSymmetricAboutTheActuatorAxis) {
  const auto lab = lab_positions();
  const auto& A = lab.at("A");
  EXPECT_EQ(A.face, "x-");
  EXPECT_DOUBLE_EQ(A.centre_mm[1], 25.0);
  EXPECT_DOUBLE_EQ(A.centre_mm[2], 25.0);
  for (auto [p, q, axis] : {std::tuple{"D", "F", 1}, std::tuple{"E", "G", 2}}) {
    const auto &a = lab.at(p), &b = lab.at(q);
    EXPECT_EQ(a.face[0], b.face[0]);
    EXPECT_NE(a.face[1], b.face[1]);
    for (int d = 0; d < 3; ++d) {
      const double expected = d == axis ? 50.0 - a.centre_mm[std::size_t(d)] : a.centre_mm[std::size_t(d)];
      EXPECT_DOUBLE_EQ(b.centre_mm[std::size_t(d)], expected) << p << q << d;
    }
  }
  // The two pairs are not equivalent to each other (else the paper would also write D = E).
  EXPECT_NE(lab.at("D").centre_mm[0], lab.at("E").centre_mm[0]);
}

TEST(SceneFiles, RodSceneParses) {
  const Scene s = read_scene_file(kSource / "pipeline/steel-rod/scenes/rod-wave.toml");
  EXPECT_DOUBLE_EQ(s.material.E_dem_Pa, 660e9);
  EXPECT_DOUBLE_EQ(s.material.bond_factor, 1.0);
  EXPECT_EQ(s.actuators.at(0).direction, "line");
  EXPECT_EQ(s.sensors.at(0).component, "line");
  EXPECT_FALSE(s.material.breakable());
}
