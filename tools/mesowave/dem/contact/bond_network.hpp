#pragma once
// The bonds made at step 0 (concrete paper Section 4.2; Yade: interactions
// created with interactionDetectionFactor = C_f, then cohesive): every pair
// with |x_j - x_i| <= C_f (r_i + r_j). Each keeps the overlap u_0 it had then
// (negative for a gap), so that F_n = K_n (u - u_0) starts at zero (Eq. 1).
//
// Bonds are a flat array sorted by (first, second); `incidence` lists each
// sphere's bonds in ascending bond order, so summing a sphere's bond forces
// in that order gives the same bits for any thread count.
#include <cstdint>
#include <vector>

#include "mesowave/dem/engine/sphere_set.hpp"
#include "mesowave/dem/engine/vec3.hpp"

namespace mesowave::dem {

/// Bond b touches sphere k as its first (side 0) or second (side 1) sphere.
struct Incidence {
  std::vector<std::uint32_t> offset;  ///< size n + 1
  std::vector<std::uint32_t> entry;   ///< (bond << 1) | side
  static std::uint32_t bond(std::uint32_t e) { return e >> 1; }
  static bool second(std::uint32_t e) { return (e & 1u) != 0; }
};

Incidence make_incidence(std::size_t spheres, const std::vector<std::uint32_t>& first,
                         const std::vector<std::uint32_t>& second);

struct BondNetwork {
  std::vector<std::uint32_t> first, second;  ///< first < second
  std::vector<double> overlap0_m;           ///< u_0 = r_i + r_j - |x_j - x_i| at step 0
  std::vector<Vec3> normal0;                 ///< unit vector first -> second at step 0
  Incidence incidence;
  std::size_t size() const { return first.size(); }
};

/// Bonds for every pair within `bond_factor` (C_f) times the sum of radii.
/// InputError if two bonded spheres have coincident centres (no contact
/// normal exists) or if a sphere is inside another one's centre region
/// (distance below 1e-9 of the radii sum).
BondNetwork make_bond_network(const SphereSet& spheres, double bond_factor);

/// Pairs that overlap (u > 0) at step 0 but are not bonded: possible only
/// with C_f < 1 (the rod paper's L_int). The full law would start them as
/// fresh frictional contacts carrying K_n u, i.e. not force-free.
std::vector<std::pair<std::uint32_t, std::uint32_t>> unbonded_overlaps(const SphereSet& spheres,
                                                                       const BondNetwork& bonds);

}  // namespace mesowave::dem
