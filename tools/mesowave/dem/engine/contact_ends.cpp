#include "mesowave/dem/engine/contact_ends.hpp"

#include <algorithm>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace mesowave::dem {
namespace {

using Fill = void (*)(const Vec3* const*, std::size_t, const std::uint32_t*, const std::uint32_t*, std::size_t, std::size_t,
                      double*);

// One source at one end: row[c * kEndsChunk + q] = src[index[q]][c], q < m.
void rows_plain(const Vec3* src, const std::uint32_t* index, std::size_t m, double* row) {
  for (std::size_t q = 0; q < m; ++q) {
    const Vec3& p = src[index[q]];
    row[q] = p.x, row[kEndsChunk + q] = p.y, row[2 * kEndsChunk + q] = p.z;
  }
}

// Source s at end e (0 first, 1 second) fills rows out + (2 s + e) 3 kEndsChunk.
void fill_plain(const Vec3* const* sources, std::size_t count, const std::uint32_t* first, const std::uint32_t* second,
                std::size_t b, std::size_t m, double* out) {
  for (std::size_t s = 0; s < count; ++s) {
    rows_plain(sources[s], first + b, m, out + 2 * s * 3 * kEndsChunk);
    rows_plain(sources[s], second + b, m, out + (2 * s + 1) * 3 * kEndsChunk);
  }
}

#if defined(__x86_64__)
// GCC 12's intrinsics header initialises _mm512_undefined_pd from itself, which
// -Wmaybe-uninitialized reports wherever a cast leaves a register's upper half undefined.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
// Eight spheres' (x, y, z) rows into three vectors of eight: masked loads of three doubles (the
// fourth is never read, so no load passes the array's end), then pairs of rows in one register
// and seven two-source permutations.
__attribute__((target("avx512f,avx512vl"))) inline void transpose8(const Vec3* src, const std::uint32_t* index, double* row) {
  __m256d a[8];
  for (int k = 0; k < 8; ++k) a[k] = _mm256_maskz_loadu_pd(0x7, &src[index[k]].x);
  const __m512d r01 = _mm512_insertf64x4(_mm512_castpd256_pd512(a[0]), a[1], 1);  // x0 y0 z0 . x1 y1 z1 .
  const __m512d r23 = _mm512_insertf64x4(_mm512_castpd256_pd512(a[2]), a[3], 1);
  const __m512d r45 = _mm512_insertf64x4(_mm512_castpd256_pd512(a[4]), a[5], 1);
  const __m512d r67 = _mm512_insertf64x4(_mm512_castpd256_pd512(a[6]), a[7], 1);
  const __m512i xy = _mm512_setr_epi64(0, 4, 8, 12, 1, 5, 9, 13), zz = _mm512_setr_epi64(2, 6, 10, 14, 2, 6, 10, 14);
  const __m512i lo = _mm512_setr_epi64(0, 1, 2, 3, 8, 9, 10, 11), hi = _mm512_setr_epi64(4, 5, 6, 7, 12, 13, 14, 15);
  const __m512d t0 = _mm512_permutex2var_pd(r01, xy, r23), t1 = _mm512_permutex2var_pd(r45, xy, r67);  // x0-3 y0-3, x4-7 y4-7
  const __m512d z0 = _mm512_permutex2var_pd(r01, zz, r23), z1 = _mm512_permutex2var_pd(r45, zz, r67);
  _mm512_store_pd(row, _mm512_permutex2var_pd(t0, lo, t1));
  _mm512_store_pd(row + kEndsChunk, _mm512_permutex2var_pd(t0, hi, t1));
  _mm512_store_pd(row + 2 * kEndsChunk, _mm512_permutex2var_pd(z0, lo, z1));
}

// fill_plain's rows, eight contacts at a time by transposes; a chunk's last m % 8 plainly.
__attribute__((target("avx512f,avx512vl"))) void fill_avx512(const Vec3* const* sources, std::size_t count,
                                                           const std::uint32_t* first, const std::uint32_t* second,
                                                           std::size_t b, std::size_t m, double* out) {
  const std::size_t whole = m / 8 * 8;
  for (std::size_t s = 0; s < count; ++s)
    for (std::size_t end = 0; end < 2; ++end) {
      const std::uint32_t* index = (end == 0 ? first : second) + b;
      double* row = out + (2 * s + end) * 3 * kEndsChunk;
      for (std::size_t q = 0; q < whole; q += 8) transpose8(sources[s], index + q, row + q);
      rows_plain(sources[s], index + whole, m - whole, row + whole);
    }
}

// fill_record_ends' rows for one end, eight records at a time: eight line loads and an 8 x 8
// transpose (row 7, the records' padding, is not stored: kRecordValues rows). Lanes from m on
// repeat the last contact's record, so that no load reads past the records in use.
static_assert(kRecordValues == 7, "record_rows_avx512 stores rows 0-6");
__attribute__((target("avx512f"))) void record_rows_avx512(const SphereRecord* records, const std::uint32_t* index,
                                                            std::size_t m, double* rows) {
  for (std::size_t q0 = 0; q0 < m; q0 += 8) {
    __m512d r[8];
    for (std::size_t l = 0; l < 8; ++l) r[l] = _mm512_load_pd(records[index[std::min(q0 + l, m - 1)]].v);
    // Pairs of records interleaved, then 128-bit lanes: t = (r0 r1) unpacked, u = four rows' pairs.
    const __m512d t0 = _mm512_unpacklo_pd(r[0], r[1]), t1 = _mm512_unpackhi_pd(r[0], r[1]);
    const __m512d t2 = _mm512_unpacklo_pd(r[2], r[3]), t3 = _mm512_unpackhi_pd(r[2], r[3]);
    const __m512d t4 = _mm512_unpacklo_pd(r[4], r[5]), t5 = _mm512_unpackhi_pd(r[4], r[5]);
    const __m512d t6 = _mm512_unpacklo_pd(r[6], r[7]), t7 = _mm512_unpackhi_pd(r[6], r[7]);
    const __m512d u0 = _mm512_shuffle_f64x2(t0, t2, 0x88), u1 = _mm512_shuffle_f64x2(t1, t3, 0x88);
    const __m512d u2 = _mm512_shuffle_f64x2(t0, t2, 0xdd), u3 = _mm512_shuffle_f64x2(t1, t3, 0xdd);
    const __m512d u4 = _mm512_shuffle_f64x2(t4, t6, 0x88), u5 = _mm512_shuffle_f64x2(t5, t7, 0x88);
    const __m512d u6 = _mm512_shuffle_f64x2(t4, t6, 0xdd), u7 = _mm512_shuffle_f64x2(t5, t7, 0xdd);
    double* row = rows + q0;
    _mm512_store_pd(row, _mm512_shuffle_f64x2(u0, u4, 0x88));
    _mm512_store_pd(row + kEndsChunk, _mm512_shuffle_f64x2(u1, u5, 0x88));
    _mm512_store_pd(row + 2 * kEndsChunk, _mm512_shuffle_f64x2(u2, u6, 0x88));
    _mm512_store_pd(row + 3 * kEndsChunk, _mm512_shuffle_f64x2(u3, u7, 0x88));
    _mm512_store_pd(row + 4 * kEndsChunk, _mm512_shuffle_f64x2(u0, u4, 0xdd));
    _mm512_store_pd(row + 5 * kEndsChunk, _mm512_shuffle_f64x2(u1, u5, 0xdd));
    _mm512_store_pd(row + 6 * kEndsChunk, _mm512_shuffle_f64x2(u2, u6, 0xdd));
  }
}
#pragma GCC diagnostic pop
#endif

void record_rows_plain(const SphereRecord* records, const std::uint32_t* index, std::size_t m, double* rows) {
  for (std::size_t q = 0; q < m; ++q)
    for (std::size_t c = 0; c < kRecordValues; ++c) rows[c * kEndsChunk + q] = records[index[q]].v[c];
}

using RecordRows = void (*)(const SphereRecord*, const std::uint32_t*, std::size_t, double*);
RecordRows chosen_record_rows() {
#if defined(__x86_64__)
  if (__builtin_cpu_supports("avx512f")) return record_rows_avx512;
#endif
  return record_rows_plain;
}

Fill chosen() {
#if defined(__x86_64__)
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl")) return fill_avx512;
#endif
  return fill_plain;
}

}  // namespace

void fill_contact_ends(const Vec3* const* sources, std::size_t count, const std::uint32_t* first, const std::uint32_t* second,
                       std::size_t b, std::size_t m, double* out) {
  static const Fill fill = chosen();
  fill(sources, count, first, second, b, m, out);
}

void pack_sphere_records(const Vec3* a, const Vec3* b, const double* s, std::size_t begin, std::size_t end,
                         SphereRecord* records) {
  for (std::size_t k = begin; k < end; ++k) records[k] = {{a[k].x, a[k].y, a[k].z, b[k].x, b[k].y, b[k].z, s[k], 0.0}};
}

void fill_record_ends(const SphereRecord* records, const std::uint32_t* first, const std::uint32_t* second, std::size_t b,
                      std::size_t m, double* out) {
  static const RecordRows rows = chosen_record_rows();
  if (m == 0) return;
  rows(records, first + b, m, out);
  rows(records, second + b, m, out + kRecordValues * kEndsChunk);
}

}  // namespace mesowave::dem
