// Fuzz target: DEM checkpoints (HDF5, dem/engine/checkpoint.hpp) as mw-dem run --restart
// reads them: restored into a small fixed run (27 bonded spheres, the full law, a wall and a
// platen pulling the top layer off, a force sensor and a broken-bond counter), which then
// steps to its end, so that a state that passes the checks must not crash the step either.
// Seeds: corpus/make_checkpoint_seeds.cpp.
#include <cstddef>
#include <cstdint>
#include <string>

#include "mesowave/dem/engine/simulation.hpp"
#include "fuzz_support.hpp"

namespace mesowave::fuzz::checkpoint {

inline dem::Packing packing() {
  dem::Packing p;
  const double r = 1e-3;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        p.centres_m.push_back({r * (1 + 2 * i), r * (1 + 2 * j), r * (1 + 2 * k)});
        p.radii_m.push_back(r);
        p.ids.push_back(std::int64_t(p.ids.size()));
      }
  p.container.upper_m = {6 * r, 6 * r, 6 * r};
  p.particle_density_kg_m3 = 2500;
  return p;
}

inline dem::Scene scene() {
  return dem::parse_scene(R"(
[packing]
file = "unused.h5"
[material]
E_dem_GPa = 20.0
nu_dem = 0.3
T_MPa = 0.2
C_MPa = 0.2
damping = 0.1
bond_factor = 1.05
[time]
dt_ns = 20
duration_ms = 0.001
[model]
choice = "full"
[[actuator]]
name = "bottom"
kind = "wall"
face = "z-"
[[actuator]]
name = "pull"
kind = "velocity"
face = "z+"
centre_rel = [0.5, 0.5, 1.0]
patch_mm = [6.0, 6.0]
direction = "z"
velocity_mm_s = 5000.0
[[sensor]]
name = "P_top"
quantity = "force"
actuator = "pull"
[[sensor]]
name = "broken"
quantity = "broken_bonds"
)",
                          "fuzz-checkpoint");
}

inline dem::CheckpointIdentity identity() { return {"fuzz-scene", "fuzz-packing", "", {{"--model", "auto"}}}; }

}  // namespace mesowave::fuzz::checkpoint

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace c = mesowave::fuzz::checkpoint;
  static mesowave::fuzz::TempFile file(".h5");
  static const mesowave::dem::Scene scene = c::scene();
  static const mesowave::dem::Packing packing = c::packing();
  const auto& path = file.write(data, size);
  mesowave::fuzz::accept_input_error([&] {
    mesowave::dem::Simulation sim(scene, packing);
    sim.restore(path, c::identity());
    sim.run();
  });
  return 0;
}
