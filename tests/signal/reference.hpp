#pragma once
// Independent references for the signal tests: the DFT by its definition
// (O(N^2), twiddles from exact integer phase j k mod N), scipy.signal.hilbert's
// analytic signal built on it, and reproducible noise.
#include <cmath>
#include <complex>
#include <cstdint>
#include <numbers>
#include <vector>

#include "mesowave/core/random.hpp"
#include "mesowave/signal/noise.hpp"

namespace mesowave::test {

using cplx = std::complex<double>;

/// X_k = sum_j x_j exp(-2 pi i j k / N) (sign = -1) or the unscaled inverse (sign = +1).
inline std::vector<cplx> direct_dft(const std::vector<cplx>& x, int sign = -1) {
  const std::size_t n = x.size();
  std::vector<cplx> X(n);
  for (std::size_t k = 0; k < n; ++k) {
    cplx sum = 0;
    for (std::size_t j = 0; j < n; ++j) {
      const double phase = 2.0 * std::numbers::pi * double((j * k) % n) / double(n);
      sum += x[j] * cplx(std::cos(phase), sign * std::sin(phase));
    }
    X[k] = sum;
  }
  return X;
}

inline std::vector<cplx> to_complex(const std::vector<double>& x) { return {x.begin(), x.end()}; }

/// One bin of the DFT of a real record, by its definition (O(N)).
inline cplx dft_bin(const std::vector<double>& x, std::size_t k) {
  const std::size_t n = x.size();
  cplx sum = 0;
  for (std::size_t j = 0; j < n; ++j) {
    const double phase = 2.0 * std::numbers::pi * double((j * k) % n) / double(n);
    sum += x[j] * cplx(std::cos(phase), -std::sin(phase));
  }
  return sum;
}

/// scipy.signal.hilbert(x): z = IDFT(DFT(x) h) with h_0 = 1, h_k = 2 for
/// 0 < k < N/2, h_{N/2} = 1 for even N, 0 above.
inline std::vector<cplx> scipy_hilbert_definition(const std::vector<double>& x) {
  const std::size_t n = x.size();
  auto X = direct_dft(to_complex(x));
  for (std::size_t k = 0; k < n; ++k) {
    double h = 0;
    if (k == 0) h = 1;
    else if (2 * k < n) h = 2;
    else if (2 * k == n) h = 1;
    X[k] *= h;
  }
  auto z = direct_dft(X, +1);
  for (auto& v : z) v /= double(n);
  return z;
}

/// Reproducible standard normal samples: signal::gaussian_noise at unit RMS
/// (Box-Muller on core/random.hpp's Mt64Random, the same bits everywhere).
inline std::vector<double> gaussian_noise(std::size_t n, std::uint64_t seed) {
  return signal::gaussian_noise(n, 1.0, seed);
}

/// Reproducible uniform samples in [-1, 1).
inline std::vector<double> uniform_values(std::size_t n, std::uint64_t seed) {
  Mt64Random random(seed);
  std::vector<double> out(n);
  for (auto& v : out) v = random.uniform01() * 2.0 - 1.0;
  return out;
}

}  // namespace mesowave::test
