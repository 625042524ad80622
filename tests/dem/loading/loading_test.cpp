// Prescribed motion and the force it takes: a rod pulled at constant speed
// at one end and held at the other (the rod paper's tension test) carries
// F = K_n / (N - 1) * (v t) once quasi-static: N - 1 bonds in series.
#include <gtest/gtest.h>

#include "mesowave/dem/engine/simulation.hpp"
#include "dem/test_packings.hpp"

using namespace mesowave::dem;
using namespace mesowave::dem::testing;

TEST(Loading, RodPulledAtConstantSpeedCarriesTheSeriesStiffness) {
  const std::size_t n = 20;
  const double R = 5.1e-3, rho = 7850, E = 200e9, v = 1e-3;  // 1 mm/s: far below the wave speed
  CohesiveFrictionalMaterial m;
  m.E_dem_Pa = E;
  m.density_kg_m3 = rho;
  m.bond_factor = 1.0;
  m.damping = 0.2;  // settle the start-up transient
  Scene s = bare_scene(m, 5e-7, 10e-3);
  ActuatorSpec hold;
  hold.name = "hold";
  hold.kind = "velocity";
  hold.target = end_target(false);
  hold.direction = "x";
  hold.amplitude = 0.0;
  ActuatorSpec pull = hold;
  pull.name = "pull";
  pull.target = end_target(true);
  pull.amplitude = v;
  s.actuators = {hold, pull};
  SensorSpec force;
  force.name = "F";
  force.kind = "force";
  force.actuator = "pull";
  s.sensors.push_back(force);
  s.sensors.push_back(motion_sensor("u", end_target(true), MotionQuantity::displacement, "x"));
  Simulation sim(s, line_packing(n, R, 1.03 * R, rho));
  EXPECT_EQ(sim.choice().model, "chain");
  const RunReport r = sim.run();
  const double stretch = r.signals[1].samples.back();
  EXPECT_NEAR(stretch, v * 10e-3, 1e-12);
  const double k_series = E * R / double(n - 1);  // K_n = E R for equal radii (Eq. 3)
  EXPECT_NEAR(r.signals[0].samples.back() / (k_series * stretch), 1.0, 1e-3);
  // The same with the 3-D models (frictionless platens: only x is imposed). The
  // linear network does the chain's arithmetic; the full law works on absolute
  // positions, and the sign switch of the local damping turns their last-bit
  // differences into ~1e-6 relative ones.
  for (const char* model : {"linear", "full"}) {
    SimulationOptions o;
    o.model = model;
    const RunReport f = Simulation(s, line_packing(n, R, 1.03 * R, rho), o).run();
    EXPECT_NEAR(f.signals[0].samples.back() / r.signals[0].samples.back(), 1.0, model[0] == 'l' ? 1e-12 : 1e-5) << model;
  }
}
