#pragma once
// Pairs of spheres within an interaction range, by a uniform cell grid:
// O(N) for packings of similar-sized spheres. Used for the bonds made at
// step 0 (every pair with |x_i - x_j| <= C_f (r_i + r_j), concrete paper
// Section 4.2: C_f = 1.1), for coordination numbers, and as the broad phase of
// contact detection.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace mesowave::dem {

struct SpherePair {
  std::uint32_t i, j;  ///< i < j
  friend bool operator==(const SpherePair&, const SpherePair&) = default;
};

/// Every pair (i < j) with distance <= factor * (r_i + r_j), sorted by (i, j),
/// so the result is the same whatever the input order of equal positions.
/// `factor` > 0. Coincident centres are returned like any other pair.
std::vector<SpherePair> find_pairs_within(std::span<const std::array<double, 3>> centres,
                                          std::span<const double> radii, double factor);

/// Mean number of partners per sphere: 2 * pairs / spheres.
double coordination_number(std::size_t pair_count, std::size_t sphere_count);

}  // namespace mesowave::dem
