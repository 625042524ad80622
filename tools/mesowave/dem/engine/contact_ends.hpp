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

/// Asks for the cache line of p (prefetcht0). GCC drops __builtin_prefetch from a loop it
/// vectorises (the loops asking for contacts' lines were, and asked for nothing); an asm
/// statement keeps such a loop scalar and the request in it.
inline void prefetch_line(const void* p) {
#if defined(__x86_64__)
  asm volatile("prefetcht0 %0" : : "m"(*static_cast<const char*>(p)));
#else
  __builtin_prefetch(p);
#endif
}

/// Contacts [begin, end) of a task (SphereSystem::for_each_contact): those whose spheres' lines a
/// chunk's stage asks for ahead of time.
struct ContactRange {
  std::size_t begin = 0, end = 0;
};

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
  /// Asks for the cache lines of the second spheres of the contacts `ahead` in each source and
  /// in `radius` (which the kernels gather in their loop): inside a partition a contact's second
  /// sphere falls anywhere in it, a pattern no hardware prefetcher follows, and once the spheres
  /// outgrow the caches each of those misses stalled the chunk (docs/benchmarks.md, "The step
  /// near the memory limit", eighth part). A Vec3 may straddle two lines: its last byte is asked
  /// for too. The first spheres come in runs, in order: the hardware fetches them.
  static void prefetch(const std::array<const Vec3*, Sources>& sources, const double* radius, const std::uint32_t* second,
                       ContactRange ahead) {
    for (std::size_t b = ahead.begin; b < ahead.end; ++b) {
      const std::uint32_t j = second[b];
      for (const Vec3* source : sources) {
        prefetch_line(&source[j]);
        prefetch_line(reinterpret_cast<const char*>(&source[j] + 1) - 1);
      }
      prefetch_line(&radius[j]);
    }
  }
  /// Source s at the first (end 0) or second (end 1) sphere of contact b of the chunk.
  Vec3 at(std::size_t s, int end, std::size_t b) const {
    const std::size_t q = b - begin;
    return {v[s][end][0][q], v[s][end][1][q], v[s][end][2][q]};
  }
};

/// One sphere's data in one cache line: two Vec3 and a scalar (the linearised network's d, theta and
/// r). A chunk's second spheres fall anywhere in their partition: staged from three arrays each
/// costs two to five lines (a Vec3 may straddle two; the radius), and as many requests ahead; from
/// records one. Packing them costs a pass over the spheres each step; the 50 mm step on 2 threads
/// is about 4 % shorter for it (docs/benchmarks.md, "The step near the memory limit", eleventh part).
struct alignas(64) SphereRecord {
  double v[8];  ///< a (0-2), b (3-5), s (6), 0
};
/// The values of a record a contact's end reads (the padding is not staged).
inline constexpr std::size_t kRecordValues = 7;

/// records[k] = {a[k], b[k], s[k], 0} for k in [begin, end).
void pack_sphere_records(const Vec3* a, const Vec3* b, const double* s, std::size_t begin, std::size_t end,
                         SphereRecord* records);

/// Fills out[e][c][q] = records[e == 0 ? first[b + q] : second[b + q]].v[c] for c < kRecordValues,
/// q < m <= kEndsChunk (out: 2 * kRecordValues rows of kEndsChunk doubles, 64-byte aligned; a row's
/// entries from m on are left undefined).
void fill_record_ends(const SphereRecord* records, const std::uint32_t* first, const std::uint32_t* second, std::size_t b,
                      std::size_t m, double* out);

/// ContactEnds for sphere records: a chunk's ends, one array per component.
struct alignas(64) RecordEnds {
  double v[2][kRecordValues][kEndsChunk];
  std::size_t begin = 0;

  void fill(const SphereRecord* records, const std::uint32_t* first, const std::uint32_t* second, std::size_t chunk,
            std::size_t m) {
    begin = chunk;
    fill_record_ends(records, first, second, chunk, m, &v[0][0][0]);
  }
  /// The lines of the contacts' second spheres `ahead` (ContactEnds::prefetch): one a record.
  static void prefetch(const SphereRecord* records, const std::uint32_t* second, ContactRange ahead) {
    for (std::size_t b = ahead.begin; b < ahead.end; ++b) prefetch_line(&records[second[b]]);
  }
  /// The record's first Vec3 (part 0), second (part 1) at end 0 (first sphere) or 1 of contact b.
  Vec3 at(int part, int end, std::size_t b) const {
    const std::size_t q = b - begin;
    const int c = 3 * part;
    return {v[end][c][q], v[end][c + 1][q], v[end][c + 2][q]};
  }
  /// The record's scalar at end 0 or 1 of contact b.
  double scalar(int end, std::size_t b) const { return v[end][kRecordValues - 1][b - begin]; }
};

}  // namespace mesowave::dem
