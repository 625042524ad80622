#pragma once
// The spheres of a packing as the engine stores them: renumbered along a
// Morton (Z-order) space-filling curve, so that spheres close in space are
// close in memory and a contact's two ends mostly hit the same cache lines
// (the largest single speed-up of the memory-bound step, docs/benchmarks.md).
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "mesowave/dem/packing/packing.hpp"
#include "mesowave/dem/engine/vec3.hpp"

namespace mesowave::dem {

struct SphereSet {
  std::vector<Vec3> centre_m;
  std::vector<double> radius_m, mass_kg, inertia_kg_m2;  ///< inertia of a solid sphere, 2/5 m r^2
  std::vector<std::uint32_t> packing_index;  ///< where sphere k sits in the packing it came from
  std::vector<std::int64_t> ids;
  std::size_t size() const { return radius_m.size(); }
};

/// n spheres, every value zero; with_ids: ids too (the system's held sets keep none).
SphereSet sphere_set_of_size(std::size_t n, bool with_ids);
/// Sphere k of `s` from a packing's row: its centre, radius, packing index and id, and the mass
/// and inertia of a solid sphere of density `density_kg_m3`.
void set_sphere(SphereSet& s, std::size_t k, const std::array<double, 3>& centre_m, double radius_m,
                double density_kg_m3, std::uint32_t packing_index, std::int64_t id);
/// A positive, finite radius and a finite centre.
bool is_sound_sphere(const std::array<double, 3>& centre_m, double radius_m);
/// InputError naming the sphere (`packing_index`) for a non-positive radius or a non-finite centre.
void check_sphere(const std::array<double, 3>& centre_m, double radius_m, std::size_t packing_index);

/// The Morton (Z-order) code of a centre: 21 bits per axis over a bounding box of centres,
/// one scale for all axes (the cells stay cubic, so a rod along x still orders by x first).
struct MortonFrame {
  std::array<double, 3> lower;
  double scale;
  /// The frame of the box [lower, upper] of every centre.
  static MortonFrame of(const std::array<double, 3>& lower, const std::array<double, 3>& upper);
  std::uint64_t code(const std::array<double, 3>& x) const;
};

/// Order of the centres along a Morton curve (MortonFrame over their
/// bounding box); ties keep the input order, so the result is deterministic.
std::vector<std::uint32_t> morton_order(std::span<const std::array<double, 3>> centres);

/// Spheres of `packing` with density `density_kg_m3`, renumbered along the
/// Morton curve unless `renumber` is false. InputError for an empty packing,
/// a non-positive radius or a non-finite centre.
SphereSet make_sphere_set(const Packing& packing, double density_kg_m3, bool renumber = true);

}  // namespace mesowave::dem
