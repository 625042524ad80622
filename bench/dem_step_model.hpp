#pragma once
// What the DEM step benchmarks step (dem_bench.cpp, dem_sizes_bench.cpp): a packing with the
// concrete paper's parameters (Section 4.2: E_dem 23.31 GPa, nu_dem 0.32, mu 18 deg, T = C =
// 24.4 MPa, alpha_d 0.01, C_f 1.1), 50 spheres pushed so that the step has work to do, and 20
// steps to warm the caches. Those 50 are the observed spheres (Model::observe), as an actuator's
// patch is in a run: the others' accelerations are not kept.
#include <memory>
#include <numeric>
#include <vector>

#include "mesowave/dem/engine/sphere_system.hpp"
#include "mesowave/dem/packing/packing_file.hpp"

namespace mesowave::bench {

inline dem::CohesiveFrictionalMaterial concrete(const dem::Packing& packing) {
  dem::CohesiveFrictionalMaterial m;
  m.E_dem_Pa = 23.31e9;
  m.stiffness_ratio = 0.32;
  m.friction_angle_rad = 18.0 * 3.14159265358979 / 180;
  m.tensile_strength_Pa = m.cohesion_Pa = 24.4e6;
  m.density_kg_m3 = packing.particle_density_kg_m3 > 0 ? packing.particle_density_kg_m3 : 2290;
  m.damping = 0.01;
  m.bond_factor = 1.1;
  return m;
}

/// The spheres a benchmark model pushes and observes (step_model).
inline constexpr std::size_t kPushedSpheres = 50;

/// Spheres 0 to n - 1 (Model::observe's list).
inline std::vector<std::size_t> first_spheres(std::size_t n) {
  std::vector<std::size_t> ids(n);
  std::iota(ids.begin(), ids.end(), std::size_t(0));
  return ids;
}

/// `spheres_per_partition`: the engine's unless a benchmark compares another (SphereSystem::partition_count).
template <class Law>
std::unique_ptr<dem::SphereSystem> step_model(const dem::Packing& packing,
                                              std::size_t spheres_per_partition = dem::SphereSystem::kSpheresPerPartition) {
  const auto m = concrete(packing);
  dem::SphereSet s = dem::make_sphere_set(packing, m.density_kg_m3);
  dem::BondNetwork b = dem::make_bond_network(s, m.bond_factor);
  auto model = std::make_unique<dem::SphereSystem>(std::move(s), std::move(b), m, std::make_unique<Law>(), nullptr,
                                                   spheres_per_partition);
  const std::vector<std::size_t> pushed = first_spheres(kPushedSpheres);
  model->observe(pushed);
  for (std::size_t k : pushed) model->add_external_force(k, {1e-3, 0, 0});
  for (int i = 0; i < 20; ++i) model->step(5e-8, false);
  return model;
}

}  // namespace mesowave::bench
