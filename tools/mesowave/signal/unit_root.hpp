#pragma once
// exp(2 pi i r / n) to within an ulp or two, for the kernels the FFT code
// precomputes (chirps, Rader and Hilbert kernels). Computing 2 pi r / n in
// doubles and taking its sine loses the relative accuracy of small values
// near pi (sin(pi - d) = d carries the argument's absolute error ~4e-16, i.e.
// 4e-12 of d for d ~ 1e-4), so the angle is reduced exactly in integers to
// j pi/2 + psi with |psi| <= pi/4 first.
#include <cmath>
#include <complex>
#include <cstdint>
#include <numbers>

namespace mesowave::signal {

inline std::complex<double> unit_root(std::uint64_t r, std::uint64_t n) {
  r %= n;
  const std::uint64_t j = (8 * r + n) / (2 * n);                     // nearest quarter turn, 0..4
  const std::int64_t s = std::int64_t(4 * r) - std::int64_t(j * n);  // |s| <= n/2
  const double psi = 0.5 * std::numbers::pi * (double(s) / double(n));
  const double c = std::cos(psi), si = std::sin(psi);
  switch (j % 4) {
    case 0: return {c, si};
    case 1: return {-si, c};
    case 2: return {-c, -si};
    default: return {si, -c};
  }
}

}  // namespace mesowave::signal
