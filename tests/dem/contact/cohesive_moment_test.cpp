// The moment law (cohesive_moment_contact.hpp) against closed forms.
//
// A bonded pair of equal spheres counter-rotating about the bond axis (twist)
// or about an axis across it (bending) keeps its centres, its normal and zero
// shear (v_rel = -r (w_i + w_j) x n = 0), so the only interaction is the
// moment spring: at every step the moment on the second sphere, measured as
// I dw/dt, must be -k theta with theta the relative rotation integrated by
// the same leapfrog (theta = sum dt (w_j - w_i).e), to round-off; the
// relative rotation is an oscillator of stiffness k and reduced inertia I/2,
// whose leapfrog period is 2 pi / ((2/dt) asin(omega dt / 2)), omega^2 = 2 k / I;
// and the bond breaks at the first step where k |theta| exceeds the moment
// strength (0.25 T R^3 in bending, 0.5 C R^3 in twist, with F_n = 0 here).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "mesowave/core/error.hpp"
#include "mesowave/dem/contact/cohesive_moment_contact.hpp"
#include "mesowave/dem/scene/plugins.hpp"
#include "mesowave/dem/scene/scene.hpp"
#include "dem/test_packings.hpp"

using namespace mesowave::dem;
using mesowave::dem::testing::concrete_material;

namespace {

constexpr double kR = 1e-3;

// Two spheres of radius 1 mm touching along x (bonded, u_0 = 0).
std::unique_ptr<SphereSystem> pair(const CohesiveFrictionalMaterial& m, const MomentParameters& p) {
  Packing packing;
  packing.centres_m = {{0.01, 0.02, 0.03}, {0.01 + 2 * kR, 0.02, 0.03}};
  packing.radii_m = {kR, kR};
  packing.ids = {0, 1};
  SphereSet s = make_sphere_set(packing, m.density_kg_m3);
  BondNetwork b = make_bond_network(s, m.bond_factor);
  return std::make_unique<SphereSystem>(std::move(s), std::move(b), m, std::make_unique<CohesiveMomentContact>(p));
}

struct Trace {
  std::vector<double> theta, moment;  ///< relative rotation and moment on the second sphere, per step
  std::vector<std::size_t> broken;
};

// Counter-rotation at +-w0 about `e`; the moment measured from the change of w.
Trace rotate(SphereSystem& sys, const Vec3& e, double w0, double dt, int steps) {
  const std::size_t a = sys.packing_index(0) == 0 ? 0 : 1, b = 1 - a;  // n points from a to b
  sys.set_angular_velocity(a, -w0 * e);
  sys.set_angular_velocity(b, w0 * e);
  const double inertia = sys.held_spheres().inertia_kg_m2[b];
  Trace t;
  double theta = 0;
  for (int n = 0; n < steps; ++n) {
    theta += dt * dot(sys.angular_velocity(b) - sys.angular_velocity(a), e);  // w_{n-1/2}: what step n's moment sees
    const double w_before = dot(sys.angular_velocity(b), e);
    sys.step(dt, false);
    t.theta.push_back(theta);
    t.moment.push_back(inertia * (dot(sys.angular_velocity(b), e) - w_before) / dt);
    t.broken.push_back(sys.broken_bond_count());
  }
  return t;
}

double period(const std::vector<double>& x, double dt) {
  std::vector<double> up;
  for (std::size_t i = 1; i < x.size(); ++i)
    if (x[i - 1] < 0 && x[i] >= 0) up.push_back((double(i - 1) + x[i - 1] / (x[i - 1] - x[i])) * dt);
  EXPECT_GE(up.size(), 5u);
  return (up.back() - up.front()) / double(up.size() - 1);
}

void check_spring(const Vec3& e, bool twist) {
  const auto m = concrete_material(false);
  const MomentParameters p{1.5, 0.7, 0.0, 0.0};
  auto sys = pair(m, p);
  const double k = twist ? twisting_stiffness(m, p, kR, kR) : rolling_stiffness(m, p, kR, kR);
  EXPECT_DOUBLE_EQ(k, (twist ? 0.7 : 1.5) * m.stiffness_ratio * m.E_dem_Pa * kR * kR * kR);  // alpha K_s R^2, K_s = nu E R
  const double inertia = sys->held_spheres().inertia_kg_m2[0];
  const double omega = std::sqrt(2 * k / inertia);
  const double dt = 2 * std::numbers::pi / omega / 500;
  const Trace t = rotate(*sys, e, 1.0, dt, 4000);
  for (std::size_t n = 0; n < t.theta.size(); ++n)
    ASSERT_NEAR(t.moment[n], -k * t.theta[n], 1e-9 * k * 2.0 / omega) << "step " << n;
  const double leapfrog = 2 * std::numbers::pi / ((2 / dt) * std::asin(omega * dt / 2));
  EXPECT_NEAR(period(t.theta, dt), leapfrog, 1e-6 * leapfrog);
  EXPECT_EQ(t.broken.back(), 0u);
}

void check_break(const Vec3& e, bool twist) {
  const auto m = concrete_material(true);
  const MomentParameters p{2.0, 2.0, 0.0, 0.0};
  auto sys = pair(m, p);
  const double k = twist ? twisting_stiffness(m, p, kR, kR) : rolling_stiffness(m, p, kR, kR);
  const double strength = twist ? twisting_strength(m, kR, kR) : rolling_strength(m, kR, kR);
  EXPECT_DOUBLE_EQ(strength, twist ? 0.5 * m.cohesion_Pa * kR * kR * kR : 0.25 * m.tensile_strength_Pa * kR * kR * kR);
  const double inertia = sys->held_spheres().inertia_kg_m2[0];
  const double omega = std::sqrt(2 * k / inertia);
  const double dt = 2 * std::numbers::pi / omega / 2000;
  // Peak relative rotation 2 w0 / omega = 3 x the breaking angle strength / k.
  const double w0 = 1.5 * omega * strength / k;
  const Trace t = rotate(*sys, e, w0, dt, 2000);
  std::size_t expected = t.theta.size();
  for (std::size_t n = 0; n < t.theta.size() && expected == t.theta.size(); ++n)
    if (k * std::abs(t.theta[n]) > strength) expected = n;
  ASSERT_LT(expected, t.theta.size());
  EXPECT_NEAR(t.theta[expected], strength / k, 2 * w0 * dt) << "the break angle is strength / k";
  for (std::size_t n = 0; n < expected; ++n) ASSERT_EQ(t.broken[n], 0u) << "step " << n;
  EXPECT_EQ(t.broken[expected], 1u);
  // A broken bond carries no moment: the spheres spin freely from then on.
  for (std::size_t n = expected; n < t.theta.size(); ++n) ASSERT_EQ(t.moment[n], 0.0) << "step " << n;
}

}  // namespace

TEST(CohesiveMoment, TwistingMomentIsStiffnessTimesAngle) { check_spring({1, 0, 0}, true); }
TEST(CohesiveMoment, RollingMomentIsStiffnessTimesAngle) {
  check_spring({0, 1, 0}, false);
  check_spring({0, 0.6, 0.8}, false);
}
TEST(CohesiveMoment, TwistBreaksTheBondAtItsStrength) { check_break({1, 0, 0}, true); }
TEST(CohesiveMoment, BendingBreaksTheBondAtItsStrength) { check_break({0, 0, 1}, false); }

// The law's keys are [material] keys once it is named; another law's keys are unknown.
TEST(CohesiveMoment, SceneNamesTheLawAndItsKeys) {
  const std::string head = "[packing]\nfile = \"p.h5\"\n[time]\ndt_ns = 1\nduration_ms = 1\n"
                           "[[sensor]]\nname = \"s\"\npoint_mm = [0, 0, 0]\ncomponent = \"x\"\n";
  const Scene s = parse_scene(head + "[material]\nE_dem_GPa = 20\nlaw = \"cohesive_moment\"\nalpha_kr = 1.5\n", "t.toml");
  EXPECT_EQ(s.contact_law, "cohesive_moment");
  EXPECT_EQ(s.law_parameters.at("alpha_kr"), 1.5);
  EXPECT_EQ(s.law_parameters.at("alpha_ktw"), 2.0);
  EXPECT_EQ(s.law_parameters.at("eta_roll"), 0.0);
  EXPECT_THROW(parse_scene(head + "[material]\nE_dem_GPa = 20\nalpha_kr = 1.5\n", "t.toml"), mesowave::InputError);
  EXPECT_THROW(parse_scene(head + "[material]\nE_dem_GPa = 20\nlaw = \"hertz\"\n", "t.toml"), mesowave::InputError);
  EXPECT_THROW(parse_scene(head + "[material]\nE_dem_GPa = 20\nlaw = \"cohesive_moment\"\nalpha_kr = -1\n", "t.toml"),
               mesowave::InputError);
}
