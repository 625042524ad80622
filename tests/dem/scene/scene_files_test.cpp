// The shipped scenes parse, and the cube scene's transducers are the ones in
// lab-data/concrete-cube/experiment.toml (as fractions of the cube), with D/F and E/G mirror pairs on
// opposite faces (the paper: G = E and F = D for an ideal cube); the rod scenes, which take
// lab-data/steel-rod/experiment.toml, run as they did when they named their end spheres.
#include <gtest/gtest.h>

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "mesowave/core/units.hpp"
#include "mesowave/dem/engine/simulation.hpp"
#include "mesowave/dem/packing/packing_request.hpp"
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
  // The transducers, the burst and the record are lab-data/steel-rod/experiment.toml's: A pushes
  // inward from the z- end, S reads the normal of the z+ end (rod paper Section 4.2), the
  // five-cycle 100 kHz burst of 1 N, 1.5 ms (Sections 4.2-4.3).
  EXPECT_EQ(s.experiment_file, (kSource / "lab-data/steel-rod/experiment.toml").lexically_normal());
  ASSERT_EQ(s.actuators.size(), 1u);
  ASSERT_EQ(s.sensors.size(), 1u);
  EXPECT_EQ(s.actuators[0].name, "A");
  EXPECT_EQ(s.actuators[0].direction, "inward");
  EXPECT_EQ(s.actuators[0].target.patch.face.name(), "z-");
  EXPECT_DOUBLE_EQ(s.actuators[0].amplitude, 1.0);
  EXPECT_DOUBLE_EQ(s.actuators[0].frequency_hz, 100e3);
  EXPECT_DOUBLE_EQ(s.actuators[0].cycles, 5.0);
  EXPECT_EQ(s.sensors[0].name, "S");
  EXPECT_EQ(s.sensors[0].component, "normal");
  EXPECT_EQ(s.sensors[0].target.patch.face.name(), "z+");
  EXPECT_DOUBLE_EQ(s.duration_s, 1.5e-3);
  EXPECT_FALSE(s.material.breakable());
}

namespace {

// The transducers the rod scenes typed themselves before they took the experiment (main at
// 90fc0b3): the force burst on the first sphere along the line, the acceleration of the last.
const char* kEndSphereScene = R"toml(
[packing]
file = "unused.h5"
[material]
E_dem_GPa = 1.0
[time]
dt_ns = 50
duration_ms = 1.5
[[actuator]]
name = "A"
kind = "force"
sphere = "first"
direction = "line"
amplitude_N = 1.0
frequency_kHz = 100
cycles = 5
[[sensor]]
name = "S"
quantity = "acceleration"
component = "line"
sphere = "last"
)toml";

}  // namespace

// Each rod scene read through the experiment drives and reads what it did when it named the
// spheres (kEndSphereScene), on the chain mw-pack line makes of the experiment at its spacing:
// the same spheres (the first and the last), the same direction vectors to the bit, the chain
// model, and the same samples to the bit - the pipeline's DEM results do not move. 0.95R is the
// chain where a face patch needs the line rule (sphere_selection.hpp): by depth alone A would
// also take the second sphere, whose surface lies 0.95 R from the face.
TEST(SceneFiles, RodScenesThroughTheExperimentRunAsTheirEndSphereForm) {
  const Scene ends = parse_scene(kEndSphereScene, "end-sphere scene");
  const std::pair<const char*, double> scenes[] = {{"rod-wave-0.95R.toml", 0.95}, {"rod-wave.toml", 1.03},
                                                   {"rod-wave-1.05R.toml", 1.05}, {"rod-wave-1.15R.toml", 1.15},
                                                   {"rod-wave-0.95R-EDEM.toml", 0.95}};
  for (const auto& [file, spacing_R] : scenes) {
    PackingRequest request;
    request.container = "line";
    request.experiment = kSource / "lab-data/steel-rod/experiment.toml";
    request.spacing_R = spacing_R;
    const Packing packing = make_packing(request).packing;
    const Scene shipped = read_scene_file(kSource / "pipeline/steel-rod/scenes" / file);
    Scene own = shipped;  // its material and step, the transducers and record of before
    own.experiment_file.clear();
    own.actuators = ends.actuators;
    own.sensors = ends.sensors;
    own.duration_s = ends.duration_s;
    const RunReport a = Simulation(shipped, packing).run(), b = Simulation(own, packing).run();
    EXPECT_EQ(a.choice.model, "chain") << file;
    EXPECT_EQ(b.choice.model, "chain") << file;
    EXPECT_EQ(a.steps, b.steps) << file;
    ASSERT_EQ(a.actuator_placements.size(), 1u);
    ASSERT_EQ(a.sensor_placements.size(), 1u);
    const auto last = std::uint32_t(packing.size() - 1);  // mw-pack numbers the line from z = 0
    EXPECT_EQ(a.actuator_placements[0].spheres, (std::vector<std::uint32_t>{0})) << file;
    EXPECT_EQ(a.sensor_placements[0].spheres, (std::vector<std::uint32_t>{last})) << file;
    EXPECT_EQ(a.actuator_placements[0].spheres, b.actuator_placements.at(0).spheres) << file;
    EXPECT_EQ(a.sensor_placements[0].spheres, b.sensor_placements.at(0).spheres) << file;
    for (int d = 0; d < 3; ++d) {
      EXPECT_EQ(a.actuator_placements[0].direction[d], b.actuator_placements[0].direction[d]) << file << d;
      EXPECT_EQ(a.sensor_placements[0].direction[d], b.sensor_placements[0].direction[d]) << file << d;
    }
    EXPECT_EQ(a.actuator_placements[0].direction.z, 1.0) << file;  // inward from z- = along the line, +z
    EXPECT_EQ(a.actuator_placements[0].amplitude, b.actuator_placements[0].amplitude) << file;
    EXPECT_EQ(a.actuator_placements[0].frequency_hz, b.actuator_placements[0].frequency_hz) << file;
    EXPECT_EQ(a.actuator_placements[0].cycles, b.actuator_placements[0].cycles) << file;
    ASSERT_EQ(a.signals.size(), 1u);
    ASSERT_EQ(b.signals.size(), 1u);
    EXPECT_EQ(a.signals[0].component, "normal");  // the experiment's name for the same +z
    EXPECT_EQ(a.signals[0].samples, b.signals[0].samples) << file;  // bit for bit
    EXPECT_GT(*std::max_element(a.signals[0].samples.begin(), a.signals[0].samples.end()), 0.0) << file;  // the wave arrived
  }
}
