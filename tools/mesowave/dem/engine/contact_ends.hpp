#pragma once
// A chunk's sphere data at both ends of its contacts, one array per component, filled before the
// contact kernel's vector loop (SphereSystem::for_each_contact's stage): the loop then reads
// contiguous vectors instead of building each from eight scalar loads (GCC's gather emulation:
// about 2.5 instructions a double) or a hardware gather. With AVX-512 eight spheres' x, y, z are
// eight masked loads and a transpose (about 0.9 instructions a double); elsewhere plain loads.
// The values are the ones the kernel would have loaded itself, so the bits are the same
// (docs/benchmarks.md, "The step near the memory limit", seventh part).
#include <array>
#include <cstddef>
#include <cstdint>

#include "mesowave/dem/engine/vec3.hpp"

namespace mesowave::dem {

/// Fills out[s][end][c][q] = sources[s][end == 0 ? first[b + q] : second[b + q]][c] for the
/// `count` sources, q < m <= kEndsChunk; out holds count * 2 * 3 rows of kEndsChunk doubles,
/// 64-byte aligned.
inline constexpr std::size_t kEndsChunk = 32;
void fill_contact_ends(const Vec3* const* sources, std::size_t count, const std::uint32_t* first, const std::uint32_t* second,
                       std::size_t b, std::size_t m, double* out);

/// The ends of `Sources` per-sphere Vec3 arrays (positions, velocities, ...) for one chunk of
/// contacts [begin, begin + m).
template <std::size_t Sources>
struct alignas(64) ContactEnds {
  double v[Sources][2][3][kEndsChunk];
  std::size_t begin = 0;

  void fill(const std::array<const Vec3*, Sources>& sources, const std::uint32_t* first, const std::uint32_t* second,
            std::size_t chunk, std::size_t m) {
    begin = chunk;
    fill_contact_ends(sources.data(), Sources, first, second, chunk, m, &v[0][0][0][0]);
  }
  /// Source s at the first (end 0) or second (end 1) sphere of contact b of the chunk.
  Vec3 at(std::size_t s, int end, std::size_t b) const {
    const std::size_t q = b - begin;
    return {v[s][end][0][q], v[s][end][1][q], v[s][end][2][q]};
  }
};

}  // namespace mesowave::dem
