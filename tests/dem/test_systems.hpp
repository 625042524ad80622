#pragma once
// SphereSystems made in test code from a packing (test_packings.hpp), and the check that two of
// them moved the same, to the bit.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <string>

#include "mesowave/dem/contact/cohesive_frictional_contact.hpp"
#include "mesowave/dem/contact/linear_bonded_network.hpp"
#include "mesowave/dem/engine/sphere_system.hpp"

namespace mesowave::dem::testing {

/// The bonded network of `packing` (density and C_f from `material`) stepped by the full
/// cohesive-frictional law or by the linearised network.
inline std::unique_ptr<SphereSystem> bonded_system(const Packing& packing, const CohesiveFrictionalMaterial& material,
                                                   bool full) {
  SphereSet spheres = make_sphere_set(packing, material.density_kg_m3);
  BondNetwork bonds = make_bond_network(spheres, material.bond_factor);
  std::unique_ptr<ContactKernel> law;
  if (full) law = std::make_unique<CohesiveFrictionalContact>();
  else law = std::make_unique<LinearBondedNetwork>();
  return std::make_unique<SphereSystem>(std::move(spheres), std::move(bonds), material, std::move(law));
}

/// Positions, velocities and angular velocities `memcmp`-equal, and the energies equal.
inline void expect_same_motion(const SphereSystem& a, const SphereSystem& b, const std::string& label) {
  ASSERT_EQ(a.sphere_count(), b.sphere_count()) << label;
  const std::size_t bytes = a.sphere_count() * sizeof(Vec3);
  EXPECT_EQ(std::memcmp(a.positions(), b.positions(), bytes), 0) << label;
  EXPECT_EQ(std::memcmp(a.velocities(), b.velocities(), bytes), 0) << label;
  EXPECT_EQ(std::memcmp(a.angular_velocities(), b.angular_velocities(), bytes), 0) << label;
  EXPECT_EQ(a.energy().kinetic_J, b.energy().kinetic_J) << label;
  EXPECT_EQ(a.energy().elastic_J, b.energy().elastic_J) << label;
  EXPECT_EQ(a.energy().damping_J, b.energy().damping_J) << label;
  EXPECT_EQ(a.energy().external_work_J, b.energy().external_work_J) << label;
}

}  // namespace mesowave::dem::testing
