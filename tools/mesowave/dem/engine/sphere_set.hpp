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

/// Order of the centres along a Morton curve (21 bits per axis over their
/// bounding box); ties keep the input order, so the result is deterministic.
std::vector<std::uint32_t> morton_order(std::span<const std::array<double, 3>> centres);

/// Spheres of `packing` with density `density_kg_m3`, renumbered along the
/// Morton curve unless `renumber` is false. InputError for an empty packing,
/// a non-positive radius or a non-finite centre.
SphereSet make_sphere_set(const Packing& packing, double density_kg_m3, bool renumber = true);

}  // namespace mesowave::dem
