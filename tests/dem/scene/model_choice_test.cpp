// The model choice (model_choice.hpp) on small packings whose answer is known:
// the line test, the force-ratio estimate against its closed form, and the
// rules chain -> linear -> full, forced models and a law's own rule.
#include <gtest/gtest.h>

#include <cmath>

#include "mesowave/core/error.hpp"
#include "mesowave/dem/scene/model_choice.hpp"
#include "dem/test_packings.hpp"

using namespace mesowave::dem;
using mesowave::dem::testing::concrete_material;

namespace {

const double kR = 1e-3;

struct Case {
  Scene scene;
  SphereSet spheres;
  BondNetwork bonds;
  std::vector<ResolvedLoad> loads;
};

// Spheres of radius 1 mm, 2 mm apart (bonded, touching), and one load per actuator.
Case setup(const Packing& packing, std::vector<ActuatorSpec> actuators, const std::vector<std::vector<std::size_t>>& on,
            const std::vector<Vec3>& directions) {
  Case s{mesowave::dem::testing::bare_scene(concrete_material(), 1e-8, 1e-4), {}, {}, {}};
  s.scene.actuators = std::move(actuators);
  s.spheres = make_sphere_set(packing, 2290);
  s.bonds = make_bond_network(s.spheres, 1.1);
  for (std::size_t i = 0; i < s.scene.actuators.size(); ++i)
    s.loads.push_back({&s.scene.actuators[i], on[i], directions[i]});
  return s;
}

Packing square() {  // four spheres in the z = 0 plane: not a line
  Packing p;
  p.centres_m = {{0, 0, 0}, {2 * kR, 0, 0}, {0, 2 * kR, 0}, {2 * kR, 2 * kR, 0}};
  p.radii_m = {kR, kR, kR, kR};
  p.ids = {0, 1, 2, 3};
  return p;
}

ActuatorSpec force(double amplitude_N) {
  return mesowave::dem::testing::force_burst("a", mesowave::dem::testing::end_target(false), "x", amplitude_N, 1e5);
}

}  // namespace

TEST(ModelChoice, LineAxis) {
  const SphereSet line = make_sphere_set(mesowave::dem::testing::line_packing(5, kR, 2 * kR, 2290), 2290);
  const auto axis = line_axis(line);
  ASSERT_TRUE(axis);
  EXPECT_DOUBLE_EQ(std::abs(axis->x), 1.0);
  EXPECT_FALSE(line_axis(make_sphere_set(square(), 2290)));
  Packing one;
  one.centres_m = {{0, 0, 0}};
  one.radii_m = {kR};
  one.ids = {0};
  EXPECT_FALSE(line_axis(make_sphere_set(one, 2290)));
}

// Force: |F| / spheres over the weakest bond there, min(T, C) R^2; unbreakable bonds: over K_n R.
TEST(ModelChoice, ForceRatioEstimateIsItsClosedForm) {
  Case s = setup(square(), {force(2.0)}, {{0, 1}}, {{1, 0, 0}});
  const auto& m = s.scene.material;
  const double strength = std::min(m.tensile_strength_Pa, m.cohesion_Pa) * kR * kR;
  EXPECT_DOUBLE_EQ(estimated_force_ratio(s.loads[0], s.spheres, s.bonds, m, 1e-4), (2.0 / 2) / strength);
  auto unbreakable = concrete_material(false);
  const double kn = normal_stiffness(unbreakable, kR, kR);
  EXPECT_DOUBLE_EQ(estimated_force_ratio(s.loads[0], s.spheres, s.bonds, unbreakable, 1e-4), 1.0 / (kn * kR));
  // A displacement burst: the stiffest K_n there times the amplitude; a platen: times speed x duration.
  s.scene.actuators[0].kind = "displacement";
  s.scene.actuators[0].amplitude = 1e-9;
  EXPECT_DOUBLE_EQ(estimated_force_ratio(s.loads[0], s.spheres, s.bonds, m, 1e-4),
                   normal_stiffness(m, kR, kR) * 1e-9 / strength);
  s.scene.actuators[0].kind = "velocity";
  s.scene.actuators[0].amplitude = 1e-3;
  EXPECT_DOUBLE_EQ(estimated_force_ratio(s.loads[0], s.spheres, s.bonds, m, 1e-4),
                   normal_stiffness(m, kR, kR) * (1e-3 * 1e-4) / strength);
}

TEST(ModelChoice, RulesInOrder) {
  // A line loaded along it: the chain.
  Case line = setup(mesowave::dem::testing::line_packing(5, kR, 2 * kR, 2290), {force(1e-3)}, {{0}}, {{1, 0, 0}});
  EXPECT_EQ(choose_model("auto", line.scene, line.spheres, line.bonds, line.loads).model, "chain");
  // Loaded across it: small loads run the linear network, large ones the full law.
  line.loads[0].direction = {0, 1, 0};
  const ModelChoice small = choose_model("auto", line.scene, line.spheres, line.bonds, line.loads);
  EXPECT_EQ(small.model, "linear");
  EXPECT_LT(small.estimated_force_ratio, line.scene.linear_validity_bound);
  line.scene.actuators[0].amplitude = 1e4;
  const ModelChoice big = choose_model("auto", line.scene, line.spheres, line.bonds, line.loads);
  EXPECT_EQ(big.model, "full");
  EXPECT_GE(big.estimated_force_ratio, line.scene.linear_validity_bound);
  // Forced models; the chain only on a line loaded along it.
  EXPECT_EQ(choose_model("linear", line.scene, line.spheres, line.bonds, line.loads).model, "linear");
  EXPECT_THROW(choose_model("chain", line.scene, line.spheres, line.bonds, line.loads), mesowave::InputError);
  Case sq = setup(square(), {force(1e-3)}, {{0}}, {{1, 0, 0}});
  EXPECT_THROW(choose_model("chain", sq.scene, sq.spheres, sq.bonds, sq.loads), mesowave::InputError);
  EXPECT_EQ(choose_model("auto", sq.scene, sq.spheres, sq.bonds, sq.loads).model, "linear");
}

// With damping the chain needs a line along x, y or z (Yade damps per global component).
TEST(ModelChoice, DampedChainNeedsACoordinateAxis) {
  Packing p;
  for (int i = 0; i < 4; ++i) {
    p.centres_m.push_back({2 * kR * i * 0.6, 2 * kR * i * 0.8, 0});
    p.radii_m.push_back(kR);
    p.ids.push_back(i);
  }
  Case s = setup(p, {force(1e-3)}, {{0}}, {{0.6, 0.8, 0}});
  EXPECT_EQ(choose_model("auto", s.scene, s.spheres, s.bonds, s.loads).model, "chain");
  s.scene.material.damping = 0.05;
  EXPECT_EQ(choose_model("auto", s.scene, s.spheres, s.bonds, s.loads).model, "linear");
}

// A law without a linearised network (the moment law) runs small waves on the full law.
TEST(ModelChoice, TheLawsOwnModels) {
  Case sq = setup(square(), {force(1e-3)}, {{0}}, {{1, 0, 0}});
  sq.scene.contact_law = "cohesive_moment";
  const ModelChoice c = choose_model("auto", sq.scene, sq.spheres, sq.bonds, sq.loads);
  EXPECT_EQ(c.model, "full");
  EXPECT_NE(c.reason.find("no linear model"), std::string::npos) << c.reason;
  EXPECT_THROW(choose_model("linear", sq.scene, sq.spheres, sq.bonds, sq.loads), mesowave::InputError);
  Case line = setup(mesowave::dem::testing::line_packing(5, kR, 2 * kR, 2290), {force(1e-3)}, {{0}}, {{1, 0, 0}});
  line.scene.contact_law = "cohesive_moment";
  EXPECT_EQ(choose_model("auto", line.scene, line.spheres, line.bonds, line.loads).model, "chain");
}
