#pragma once
// The bonds made at step 0 (concrete paper Section 4.2; Yade: interactions
// created with interactionDetectionFactor = C_f, then cohesive): every pair
// with |x_j - x_i| <= C_f (r_i + r_j). Each keeps the overlap u_0 it had then
// (negative for a gap), so that F_n = K_n (u - u_0) starts at zero (Eq. 1).
//
// Bonds are a flat array sorted by (first, second). An Incidence lists each
// sphere's contacts in ascending order, so summing a sphere's forces in that
// order gives the same bits for any thread count (the engine's cross records).
//
// On several MPI ranks (docs/mpi.md) each rank makes only its part: the bonds with an end among
// its own spheres, found by a search over its part of the sphere set (SpherePart: those and the
// spheres within a bond's reach of them),
// each with its index in the whole network (from the ranks' counts, as if one process had made it).
#include <cstdint>
#include <limits>
#include <vector>

#include "mesowave/dem/engine/sphere_part.hpp"
#include "mesowave/dem/engine/vec3.hpp"

namespace mesowave::dem {

/// Contact b touches sphere k as its first (side 0) or second (side 1) sphere.
struct Incidence {
  std::vector<std::uint32_t> offset;  ///< size n + 1
  std::vector<std::uint32_t> entry;   ///< (bond << 1) | side
  static std::uint32_t bond(std::uint32_t e) { return e >> 1; }
  static bool second(std::uint32_t e) { return (e & 1u) != 0; }
};

Incidence make_incidence(std::size_t spheres, const std::vector<std::uint32_t>& first,
                         const std::vector<std::uint32_t>& second);

class Domain;

/// A bond's step-0 geometry from its spheres' centres and radii: the unit normal first -> second
/// and u_0 = r_i + r_j - |x_j - x_i|. One function, so that what is made from it anew (the
/// engine keeps no copy: SphereSystem::bond_geometry0) has the bits it was made with.
struct BondGeometry {
  Vec3 normal;
  double overlap_m;
  double distance_m;  ///< |x_j - x_i|
};
inline BondGeometry bond_geometry(const Vec3& ci, const Vec3& cj, double ri, double rj) {
  const Vec3 d = cj - ci;
  const double dist = norm(d);
  return {(1.0 / dist) * d, (ri + rj) - dist, dist};
}

struct BondNetwork {
  std::vector<std::uint32_t> first, second;  ///< first < second
  std::vector<double> overlap0_m;           ///< u_0 = r_i + r_j - |x_j - x_i| at step 0
  std::vector<Vec3> normal0;                 ///< unit vector first -> second at step 0
  /// A rank's part (make_bond_network with a Domain): every bond with an end among the spheres
  /// [own_begin, own_end), each with its index in the whole network (`ids`, ascending), and the
  /// whole network's size. Whole (one process): `ids` empty, every sphere in the range.
  std::vector<std::uint32_t> ids;
  std::size_t whole_size = 0, own_begin = 0, own_end = std::numeric_limits<std::size_t>::max();
  std::size_t size() const { return first.size(); }
  bool is_part() const { return own_end != std::numeric_limits<std::size_t>::max(); }
  /// Bonds in the whole network.
  std::size_t total() const { return is_part() ? whole_size : first.size(); }
  /// Sphere k's bonds are all listed.
  bool lists_all_of(std::size_t k) const { return k >= own_begin && k < own_end; }
};

/// Bonds for every pair within `bond_factor` (C_f) times the sum of radii.
/// InputError if two bonded spheres have coincident centres (no contact
/// normal exists) or if a sphere is inside another one's centre region
/// (distance below 1e-9 of the radii sum).
///
/// Of a rank's part (collective, SpherePart with a domain): the bonds with an end among its own
/// spheres, their indices from each rank's count of the bonds whose first sphere is its own and,
/// for a bond whose first sphere is another rank's, from that rank. std::logic_error if two ranks
/// find different bonds between their spheres (never, by construction). The part's layer must
/// reach C_f (2 r_max).
BondNetwork make_bond_network(const SpherePart& spheres, double bond_factor);

/// Pairs that overlap (u > 0) at step 0 but are not bonded: possible only
/// with C_f < 1 (the rod paper's L_int). The full law would start them as
/// fresh frictional contacts carrying K_n u, i.e. not force-free. Of a part, the
/// pairs whose first sphere is among its own (each pair on one rank).
/// The part's layer must reach 2 r_max.
std::vector<std::pair<std::uint32_t, std::uint32_t>> unbonded_overlaps(const SpherePart& spheres,
                                                                       const BondNetwork& bonds);

}  // namespace mesowave::dem
