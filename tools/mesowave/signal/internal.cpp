#include "mesowave/signal/internal.hpp"

#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

// std::sqrt may set errno, which keeps the compiler from vectorising a loop of
// roots (and -fno-math-errno is a build-wide choice). The roots here are of
// sums of squares, never negative, so SSE2's sqrtpd takes two at a time; it
// rounds exactly as the scalar root does, so the bits are the same either way.

namespace mesowave::signal::internal {

void magnitudes(const double* re, const double* im, double* out, std::size_t n) {
  std::size_t i = 0;
#if defined(__SSE2__)
  for (; i + 2 <= n; i += 2) {
    const __m128d r = _mm_loadu_pd(re + i), m = _mm_loadu_pd(im + i);
    _mm_storeu_pd(out + i, _mm_sqrt_pd(_mm_add_pd(_mm_mul_pd(r, r), _mm_mul_pd(m, m))));
  }
#endif
  for (; i < n; ++i) out[i] = std::sqrt(re[i] * re[i] + im[i] * im[i]);
}

void magnitudes(const Complex* z, double scale, double* out, std::size_t n) {
  const double* p = reinterpret_cast<const double*>(z);  // std::complex<double> is laid out as double[2]
  std::size_t k = 0;
#if defined(__SSE2__)
  const __m128d s = _mm_set1_pd(scale);
  for (; k + 2 <= n; k += 2) {
    const __m128d a = _mm_loadu_pd(p + 2 * k), b = _mm_loadu_pd(p + 2 * k + 2);  // (re0, im0), (re1, im1)
    const __m128d re = _mm_unpacklo_pd(a, b), im = _mm_unpackhi_pd(a, b);
    _mm_storeu_pd(out + k, _mm_mul_pd(_mm_sqrt_pd(_mm_add_pd(_mm_mul_pd(re, re), _mm_mul_pd(im, im))), s));
  }
#endif
  for (; k < n; ++k) out[k] = std::sqrt(p[2 * k] * p[2 * k] + p[2 * k + 1] * p[2 * k + 1]) * scale;
}

// Sums in four interleaved partial sums s_k (element i goes to s_{i mod 4},
// the tail to s_0), combined as (s0 + s1) + (s2 + s3): a fixed order, so the
// same bits with or without SIMD and whatever the thread count.
double sum4(std::span<const double> x) {
  double s[4] = {0, 0, 0, 0};
  const std::size_t n = x.size(), n4 = n - n % 4;
  std::size_t i = 0;
#if defined(__SSE2__)
  __m128d lo = _mm_setzero_pd(), hi = _mm_setzero_pd();
  for (; i < n4; i += 4) {
    lo = _mm_add_pd(lo, _mm_loadu_pd(x.data() + i));
    hi = _mm_add_pd(hi, _mm_loadu_pd(x.data() + i + 2));
  }
  _mm_storeu_pd(s, lo);
  _mm_storeu_pd(s + 2, hi);
#endif
  for (; i < n4; i += 4)
    for (std::size_t k = 0; k < 4; ++k) s[k] += x[i + k];
  for (; i < n; ++i) s[0] += x[i];
  return (s[0] + s[1]) + (s[2] + s[3]);
}

void centred_sums(std::span<const double> a, std::span<const double> b, double ma, double mb, double& saa,
                  double& sbb, double& sab) {
  double aa[4] = {0, 0, 0, 0}, bb[4] = {0, 0, 0, 0}, ab[4] = {0, 0, 0, 0};
  const std::size_t n = a.size(), n4 = n - n % 4;
  std::size_t i = 0;
#if defined(__SSE2__)
  const __m128d vma = _mm_set1_pd(ma), vmb = _mm_set1_pd(mb);
  __m128d aa_lo = _mm_setzero_pd(), aa_hi = aa_lo, bb_lo = aa_lo, bb_hi = aa_lo, ab_lo = aa_lo, ab_hi = aa_lo;
  for (; i < n4; i += 4) {
    const __m128d da_lo = _mm_sub_pd(_mm_loadu_pd(a.data() + i), vma);
    const __m128d da_hi = _mm_sub_pd(_mm_loadu_pd(a.data() + i + 2), vma);
    const __m128d db_lo = _mm_sub_pd(_mm_loadu_pd(b.data() + i), vmb);
    const __m128d db_hi = _mm_sub_pd(_mm_loadu_pd(b.data() + i + 2), vmb);
    aa_lo = _mm_add_pd(aa_lo, _mm_mul_pd(da_lo, da_lo));
    aa_hi = _mm_add_pd(aa_hi, _mm_mul_pd(da_hi, da_hi));
    bb_lo = _mm_add_pd(bb_lo, _mm_mul_pd(db_lo, db_lo));
    bb_hi = _mm_add_pd(bb_hi, _mm_mul_pd(db_hi, db_hi));
    ab_lo = _mm_add_pd(ab_lo, _mm_mul_pd(da_lo, db_lo));
    ab_hi = _mm_add_pd(ab_hi, _mm_mul_pd(da_hi, db_hi));
  }
  _mm_storeu_pd(aa, aa_lo), _mm_storeu_pd(aa + 2, aa_hi);
  _mm_storeu_pd(bb, bb_lo), _mm_storeu_pd(bb + 2, bb_hi);
  _mm_storeu_pd(ab, ab_lo), _mm_storeu_pd(ab + 2, ab_hi);
#endif
  for (; i < n4; i += 4)
    for (std::size_t k = 0; k < 4; ++k) {
      const double da = a[i + k] - ma, db = b[i + k] - mb;
      aa[k] += da * da, bb[k] += db * db, ab[k] += da * db;
    }
  for (; i < n; ++i) {
    const double da = a[i] - ma, db = b[i] - mb;
    aa[0] += da * da, bb[0] += db * db, ab[0] += da * db;
  }
  saa = (aa[0] + aa[1]) + (aa[2] + aa[3]);
  sbb = (bb[0] + bb[1]) + (bb[2] + bb[3]);
  sab = (ab[0] + ab[1]) + (ab[2] + ab[3]);
}

}  // namespace mesowave::signal::internal
