// The critical time step and the hard cases: dt just below / above the
// computed limit, coincident centres, a size ratio of 10, the rod at
// d = 0.95 R where second neighbours overlap.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesowave/core/error.hpp"
#include "mesowave/dem/contact/bond_network.hpp"
#include "mesowave/dem/contact/linear_bonded_network.hpp"
#include "mesowave/dem/engine/sphere_system.hpp"
#include "mesowave/dem/engine/simulation.hpp"
#include "dem/test_packings.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::dem;
using namespace mesowave::dem::testing;

namespace {

Scene network_scene(double dt, double duration, double damping) {
  auto m = concrete_material();
  m.damping = damping;
  Scene s = bare_scene(m, dt, duration);
  const double mid = 0.5 * (3 * 2.5e-3 + 1.25e-3);
  s.actuators.push_back(force_burst("A", patch_target("x-", {0, mid, mid}, 3e-3), "inward", 1e-3, 500e3));
  s.sensors.push_back(motion_sensor("B", patch_target("x+", {0, mid, mid}, 3e-3), MotionQuantity::acceleration, "normal"));
  s.model = "full";
  return s;
}

}  // namespace

TEST(TimeStep, ChainEigenvalueMatchesTheClosedForm) {
  // Free chain of N equal masses and springs: lambda_max = (2k/m)(1 + cos(pi/N)).
  const std::size_t n = 60;
  const double r = 5.1e-3, rho = 7850;
  CohesiveFrictionalMaterial m;
  m.E_dem_Pa = 200e9;
  m.density_kg_m3 = rho;
  m.bond_factor = 1.0;
  Scene s = bare_scene(m, 1e-8, 1e-7);
  s.sensors.push_back(motion_sensor("S", end_target(true), MotionQuantity::acceleration, "x"));
  Simulation sim(s, line_packing(n, r, 1.03 * r, rho));
  const double mass = rho * 4.0 / 3.0 * std::numbers::pi * r * r * r, k = 200e9 * r;
  const double exact = 2 * k / mass * (1 + std::cos(std::numbers::pi / double(n)));
  EXPECT_NEAR(sim.time_step().lambda_max / exact, 1.0, 1e-6);
  EXPECT_NEAR(sim.time_step().eigenvalue_s, 2 / std::sqrt(exact), 1e-6 * 2 / std::sqrt(exact));
  // Gershgorin gives 4k/m here: a safe (smaller) step.
  EXPECT_NEAR(sim.time_step().stiffness_bound_s, 2 / std::sqrt(4 * k / mass), 1e-12);
}

TEST(TimeStep, RunsAtNineTenthsAndRefusesElevenTenthsOfTheLimit) {
  const Packing p = fcc_packing(3, 2.5e-3, 0.8e-3, 1.0e-3, 0.02, 3, 2290);
  const double limit = Simulation(network_scene(1e-9, 1e-8, 0.01), p).time_step().limit_s;
  EXPECT_LE(limit, Simulation(network_scene(1e-9, 1e-8, 0.01), p).time_step().stiffness_bound_s * 10);

  // 0.9: runs, energy bounded by the work put in.
  {
    Simulation sim(network_scene(0.9 * limit, 4000 * 0.9 * limit, 0.01), p);
    const RunReport r = sim.run();
    EXPECT_LE(r.energy.stored(), r.energy.external_work_J * 1.01);
    EXPECT_GT(r.energy.external_work_J, 0.0);
  }
  // 1.1: refused before running, with the limit in the message.
  const std::string refused = test::input_error_of([&] { Simulation(network_scene(1.1 * limit, 1e-5, 0.01), p); });
  EXPECT_NE(refused.find("exceeds the stable limit"), std::string::npos) << refused;
  // ...and rightly so: forced to run, it blows up and is stopped with an error.
  SimulationOptions unchecked;
  unchecked.refuse_unstable_dt = false;
  const std::string blew_up = test::input_error_of([&] { Simulation(network_scene(1.1 * limit, 4000 * 1.1 * limit, 0.01), p, unchecked).run(); });
  EXPECT_TRUE(blew_up.find("energy blow-up") != std::string::npos || blew_up.find("non-finite") != std::string::npos)
      << blew_up;
}

// The system keeps no bond's step-0 normal and u_0 (32 B a bond): it makes them anew from the
// spheres' statics when a law lays a bond out and in every application of the critical step's
// Lanczos. They must be the network's to the bit, or the step, the laws' u_0 and every signal move.
TEST(TimeStep, TheBondsStepZeroGeometryMadeAnewIsTheNetworksToTheBit) {
  const Packing p = fcc_packing(4, 2.5e-3, 0.8e-3, 1.0e-3, 0.05, 11, 2290.0);  // radii and places jittered
  const CohesiveFrictionalMaterial m = concrete_material();
  SphereSet s = make_sphere_set(p, m.density_kg_m3);
  BondNetwork network = make_bond_network(s, m.bond_factor);
  const std::vector<Vec3> normal0 = network.normal0;
  const std::vector<double> overlap0 = network.overlap0_m;
  ASSERT_GT(normal0.size(), 500u);
  const SphereSystem system(std::move(s), std::move(network), m, std::make_unique<LinearBondedNetwork>());
  ASSERT_EQ(system.bond_count(), normal0.size());
  EXPECT_TRUE(system.held_bond_network().normal0.empty());
  std::size_t differ = 0;
  for (std::size_t b = 0; b < normal0.size(); ++b) {
    const BondGeometry g = system.bond_geometry0(b);
    differ += g.overlap_m != overlap0[b] || g.normal.x != normal0[b].x || g.normal.y != normal0[b].y ||
              g.normal.z != normal0[b].z;
  }
  EXPECT_EQ(differ, 0u);
}

TEST(HardCases, CoincidentCentresAreAnError) {
  Packing p = fcc_packing(2, 2.5e-3, 0.9e-3, 0.9e-3, 0.0, 1, 2290);
  p.centres_m.push_back(p.centres_m[5]);
  p.radii_m.push_back(0.8e-3);
  p.ids.push_back(999);
  const SphereSet s = make_sphere_set(p, 2290);
  const std::string error = test::input_error_of([&] { make_bond_network(s, 1.1); });
  EXPECT_NE(error.find("coincident centres"), std::string::npos) << error;
  EXPECT_NE(error.find("999"), std::string::npos) << error;
}

TEST(HardCases, SizeRatioTenRunsStably) {
  // A 5 mm sphere with 0.5 mm spheres bonded on its surface and to each other.
  Packing p;
  const double R = 5e-3, r = 0.5e-3;
  p.centres_m.push_back({0, 0, 0});
  p.radii_m.push_back(R);
  const int rings = 8, per_ring = 32;
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < per_ring; ++j) {
      const double th = std::numbers::pi * i / rings, ph = 2 * std::numbers::pi * (j + 0.5 * (i % 2)) / per_ring;
      const double d = R + r - 0.05e-3;
      p.centres_m.push_back({d * std::sin(th) * std::cos(ph), d * std::sin(th) * std::sin(ph), d * std::cos(th)});
      p.radii_m.push_back(r);
    }
  for (std::size_t k = 0; k < p.radii_m.size(); ++k) p.ids.push_back(std::int64_t(k));
  auto m = concrete_material();
  Scene s = bare_scene(m, 1e-9, 1e-8);
  s.actuators.push_back(force_burst("A", SphereTarget{SphereTarget::Kind::point, {}, {R + r, 0, 0}, false}, "x", 1e-3, 1e6));
  s.sensors.push_back(motion_sensor("B", SphereTarget{SphereTarget::Kind::point, {}, {-R - r, 0, 0}, false},
                                    MotionQuantity::velocity, "x"));
  s.model = "full";
  const double limit = Simulation(s, p).time_step().limit_s;
  s.dt_s = 0.9 * limit;
  s.duration_s = 20000 * s.dt_s;
  Simulation sim(s, p);
  EXPECT_GT(sim.model().bond_count(), 224u + 150u);  // every small one to the big one, and rings
  const RunReport rep = sim.run();
  EXPECT_GT(rep.energy.external_work_J, 0.0);
  EXPECT_LT(std::abs(rep.energy.residual()), 1e-2 * rep.energy.external_work_J);
  // The small spheres set the limit: far below the big sphere's own R sqrt(rho/E).
  EXPECT_LT(limit, R * std::sqrt(m.density_kg_m3 / m.E_dem_Pa));
}

TEST(HardCases, RodAtPointNineFiveRBondsSecondNeighbours) {
  // d = 0.95 R: second neighbours are 1.9 R apart, closer than 2 R - they overlap.
  const std::size_t n = 207;
  const double R = 5.1e-3, d = 0.95 * R, rho = 5577.17;
  CohesiveFrictionalMaterial m;
  m.E_dem_Pa = 2.3e11;
  m.density_kg_m3 = rho;
  m.bond_factor = 1.1;  // the concrete paper's C_f: 2.2 R reaches them
  Scene s = bare_scene(m, 5e-8, 5e-5);
  s.actuators.push_back(force_burst("A", end_target(false), "x", 1.0, 100e3));
  s.sensors.push_back(motion_sensor("S", end_target(true), MotionQuantity::acceleration, "x"));
  {
    Simulation sim(s, line_packing(n, R, d, rho));
    EXPECT_EQ(sim.choice().model, "chain");
    EXPECT_EQ(sim.model().bond_count(), (n - 1) + (n - 2));
    const RunReport r = sim.describe();
    ASSERT_EQ(r.notes.size(), 1u);
    EXPECT_NE(r.notes[0].find(std::to_string(n - 2) + " of " + std::to_string(2 * n - 3)), std::string::npos) << r.notes[0];
    EXPECT_NO_THROW(sim.run());
  }
  // The rod paper's L_int < 2d (C_f = 0.9 here): nearest neighbours only. The
  // chain and the linear network never add contacts and run; the full law
  // would meet overlapping unbonded pairs at step 0 and says so.
  s.material.bond_factor = 0.9;
  {
    Simulation sim(s, line_packing(n, R, d, rho));
    EXPECT_EQ(sim.model().bond_count(), n - 1);
    EXPECT_NO_THROW(sim.run());
  }
  const std::string error = test::input_error_of([&] {
    SimulationOptions full;
    full.model = "full";
    Simulation(s, line_packing(n, R, d, rho), full);
  });
  EXPECT_NE(error.find(std::to_string(n - 2) + " pairs of spheres overlap at step 0 without a bond"), std::string::npos)
      << error;
}
