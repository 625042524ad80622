// Two bonded spheres: the relative motion along the bond is an oscillator
// of stiffness K_n (Eq. 3) and reduced mass m1 m2/(m1 + m2), period
// T = 2 pi sqrt(mu / K_n). Leapfrog turns omega into
// omega_d = (2/dt) asin(omega dt / 2), which the measured period must match
// to round-off; the continuous period only to O((omega dt)^2).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "mesowave/dem/scene/plugins.hpp"
#include "dem/test_packings.hpp"

using namespace mesowave::dem;
using mesowave::dem::testing::concrete_material;

namespace {

struct Pair {
  Packing packing;
  Vec3 n;
};

// Radii 1 and 0.7 mm, centres 1.6 mm apart (overlap 0.1 mm) along `dir`.
Pair make_pair(Vec3 dir, double distance = 1.6e-3) {
  Pair p;
  p.n = (1.0 / norm(dir)) * dir;
  const Vec3 a{0.01, 0.02, 0.03};
  const Vec3 b = a + distance * p.n;
  p.packing.centres_m = {{a.x, a.y, a.z}, {b.x, b.y, b.z}};
  p.packing.radii_m = {1.0e-3, 0.7e-3};
  p.packing.ids = {0, 1};
  p.packing.particle_density_kg_m3 = 2290;
  return p;
}

std::unique_ptr<Model> build(const std::string& kind, const Pair& pair, const CohesiveFrictionalMaterial& m) {
  SphereSet s = make_sphere_set(pair.packing, m.density_kg_m3);
  BondNetwork b = make_bond_network(s, m.bond_factor);
  if (kind == "full") return make_model("cohesive_frictional", "full", std::move(s), std::move(b), m);
  if (kind == "linear") return make_model("cohesive_frictional", "linear", std::move(s), std::move(b), m);
  return make_model("cohesive_frictional", "chain", std::move(s), std::move(b), m, {}, pair.n);
}

// Mean period from upward zero crossings (linear interpolation) of x(t).
double measured_period(const std::vector<double>& x, double dt) {
  std::vector<double> crossings;
  for (std::size_t i = 1; i < x.size(); ++i)
    if (x[i - 1] < 0 && x[i] >= 0) crossings.push_back((double(i - 1) + x[i - 1] / (x[i - 1] - x[i])) * dt);
  EXPECT_GE(crossings.size(), 5u);
  return (crossings.back() - crossings.front()) / double(crossings.size() - 1);
}

void check_period(const std::string& kind, Vec3 dir) {
  const auto m = concrete_material();
  const Pair pair = make_pair(dir);
  auto model = build(kind, pair, m);
  ASSERT_EQ(model->bond_count(), 1u);
  const double m1 = model->mass(0), m2 = model->mass(1);
  const double mu = m1 * m2 / (m1 + m2);
  const double kn = normal_stiffness(m, 1.0e-3, 0.7e-3);
  const double omega = std::sqrt(kn / mu);
  const double period = 2 * std::numbers::pi / omega;
  const double dt = period / 1000;
  // Zero total momentum, relative speed 0.1 m/s along the bond: an amplitude of
  // 36 nm, far above the round-off of positions in metres (~1e-18 m).
  const double v = 0.1;
  const std::size_t a = model->packing_index(0) == 0 ? 0 : 1, b = 1 - a;  // n points from a to b
  model->set_velocity(a, (-v * model->mass(b) / (m1 + m2)) * pair.n);
  model->set_velocity(b, (v * model->mass(a) / (m1 + m2)) * pair.n);
  std::vector<double> stretch;
  for (int step = 0; step < 20000; ++step) {
    model->step(dt, false);
    stretch.push_back(dot(model->displacement(b) - model->displacement(a), pair.n));
  }
  const double leapfrog_period = 2 * std::numbers::pi / ((2 / dt) * std::asin(omega * dt / 2));
  const double measured = measured_period(stretch, dt);
  EXPECT_NEAR(measured / leapfrog_period, 1.0, 1e-9) << kind;
  EXPECT_NEAR(measured / period, 1.0, 2 * std::pow(omega * dt, 2) / 24) << kind;
  EXPECT_GT(std::abs(measured / period - 1.0), 1e-7) << kind << ": the leapfrog shift must be visible";
}

}  // namespace

TEST(TwoSpheres, PeriodOfTheBondMatchesKnAndTheMasses) {
  for (const char* kind : {"full", "linear"}) check_period(kind, {1.0, 2.0, 3.0});
  check_period("chain", {1.0, 0.0, 0.0});
}

TEST(TwoSpheres, BondedPackingStartsForceFree) {
  // Eq. (1): F_n = K_n (u - u_0) vanishes at step 0, for an overlap and for a gap bond.
  const auto m = concrete_material();
  for (double distance : {1.6e-3, 1.8e-3}) {
    const Pair pair = make_pair({0.3, -1.0, 0.2}, distance);
    for (const char* kind : {"full", "linear"}) {
      auto model = build(kind, pair, m);
      ASSERT_EQ(model->bond_count(), 1u) << distance;
      for (int step = 0; step < 100; ++step) model->step(1e-9, true);
      EXPECT_EQ(norm(model->velocity(0)), 0.0) << kind << " " << distance;
      EXPECT_EQ(norm(model->displacement(1)), 0.0) << kind << " " << distance;
      EXPECT_EQ(model->energy().stored(), 0.0);
    }
  }
}

TEST(TwoSpheres, TensionAboveTRSquaredBreaksTheBondForGood) {
  // Pull the spheres apart: the bond carries K_n (u - u_0) until -F_n > T R^2
  // (Eq. 6), then nothing in tension, ever; pushing back gives compression only.
  auto m = concrete_material();
  const Pair pair = make_pair({1.0, 0.0, 0.0});
  auto model = build("full", pair, m);
  const double strength = m.tensile_strength_Pa * 0.7e-3 * 0.7e-3;
  const double kn = normal_stiffness(m, 1.0e-3, 0.7e-3);
  const double dt = 1e-10;  // the spheres move 0.5 nm per step: 0.1 % of the breaking stretch
  // Separate at 5 m/s: the bond would stretch by 1.8 um, beyond strength/kn = 0.62 um.
  const std::size_t a = model->packing_index(0) == 0 ? 0 : 1, b = 1 - a;
  model->set_velocity(b, {5.0, 0, 0});
  model->set_velocity(a, {-5.0 * model->mass(b) / model->mass(a), 0, 0});
  bool broke = false;
  for (int step = 0; step < 20000 && !broke; ++step) {
    model->step(dt, false);
    broke = model->broken_bond_count() == 1;
  }
  ASSERT_TRUE(broke);
  const double stretch = dot(model->displacement(b) - model->displacement(a), pair.n);
  EXPECT_NEAR(stretch * kn / strength, 1.0, 0.003);
  // After breaking, the spheres fly apart at constant velocity (no force).
  const Vec3 v1 = model->velocity(b);
  for (int step = 0; step < 100; ++step) model->step(dt, false);
  EXPECT_EQ(model->velocity(b).x, v1.x);
}
