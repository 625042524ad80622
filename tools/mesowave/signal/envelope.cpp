#include "mesowave/signal/envelope.hpp"

#include <algorithm>
#include <stdexcept>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <numbers>

#include "mesowave/signal/internal.hpp"
#include "mesowave/signal/unit_root.hpp"
#include "mesowave/signal/validate.hpp"

namespace mesowave::signal {
namespace {

// At a length FFTW is slow at (a large prime factor), H{x} is computed as what
// it is, the cyclic convolution of x with the discrete Hilbert kernel
//   h_m = (1/N) sum_k s_k e^{2 pi i m k/N} = (2/N) sum_{k=1}^{K} sin(2 pi m k/N)
//       = (2/N) sin(pi K m/N) sin(pi (K+1) m/N) / sin(pi m/N),   h_0 = 0,
// (s_k = -i for 1 <= k <= K, +i for the mirrored bins; K = (N-1)/2 for odd N,
// N/2 - 1 for even N), done exactly by FFTs of a fast length L >= 2N - 1.
struct HilbertKernel {
  std::size_t n = 0, fft_length = 0;
  FftBuffer<Complex> spectrum;  // of h over the offsets -(N-1)..N-1, scaled by 1/L
};

const HilbertKernel& hilbert_kernel(std::size_t n) {
  static std::mutex mutex;
  static auto* kernels = new std::map<std::size_t, std::unique_ptr<HilbertKernel>>();
  {
    std::lock_guard lock(mutex);
    if (auto it = kernels->find(n); it != kernels->end()) return *it->second;
  }
  auto kernel = std::make_unique<HilbertKernel>();
  kernel->n = n;
  kernel->fft_length = fast_fft_length(2 * n - 1);
  const std::size_t L = kernel->fft_length;
  const std::uint64_t K = n % 2 ? (n - 1) / 2 : n / 2 - 1;
  auto sin_pi_over_n = [&](std::uint64_t r) { return unit_root(r, 2 * n).imag(); };  // sin(pi r / N)
  std::vector<double> h(n, 0.0);
  for (std::uint64_t m = 1; m < n; ++m)
    h[m] = 2.0 / double(n) * sin_pi_over_n(K * m) * sin_pi_over_n((K + 1) * m) / sin_pi_over_n(m);
  // y_j = sum_i x_i h_{(j-i) mod N} = (x * g)_{j+N-1} with g_t = h_{(t-(N-1)) mod N}, t < 2N - 1.
  FftBuffer<double> g(L);
  std::fill(g.begin(), g.end(), 0.0);
  for (std::size_t t = 0; t + 1 < 2 * n; ++t) g[t] = h[(t + 1) % n] / double(L);  // (t - (N-1)) mod N = (t+1) mod N
  kernel->spectrum = FftBuffer<Complex>(L / 2 + 1);
  rfft_into(g, kernel->spectrum);
  std::lock_guard lock(mutex);
  auto [it, inserted] = kernels->emplace(n, std::move(kernel));
  return *it->second;
}

// Scratch slots of this file (see ScratchBuffer).
constexpr int slot_real = 4, slot_imag = 5, slot_spectrum = 6, slot_padded = 7;

// Detrends and pads x, computes H{x} and hands `use` the detrended record
// and its Hilbert transform (the first n values of each are the record's).
// Since Re z = x, only Im z needs transforms, and Im z is real: its spectrum
// is -i sgn(k) X_k (zero at k = 0 and k = N/2), the anti-Hermitian half of
// X h. One r2c and one c2r transform instead of the complex round trip.
template <class Use>
void hilbert_core(std::span<const double> x, const HilbertOptions& options, Use&& use, bool checked = true) {
  if (checked) require_samples(x, "record");
  const std::size_t n = x.size();
  const std::size_t m = options.padding.fft_length(n);
  ScratchBuffer<double> real(slot_real, m);
  std::copy(x.begin(), x.end(), real.begin());
  detrend(std::span<double>(real.data(), n), options.detrend);
  std::fill(real.begin() + n, real.begin() + m, 0.0);

  if (slow_fft_length(m)) {
    const auto& kernel = hilbert_kernel(m);
    const std::size_t L = kernel.fft_length;
    ScratchBuffer<double> padded(slot_padded, L);
    ScratchBuffer<Complex> spectrum(slot_spectrum, L / 2 + 1);
    std::copy(real.begin(), real.begin() + m, padded.begin());
    std::fill(padded.begin() + m, padded.begin() + L, 0.0);
    rfft_unscaled(padded.data(), spectrum.data(), L);
    for (std::size_t k = 0; k <= L / 2; ++k) spectrum[k] *= kernel.spectrum[k];
    irfft_unscaled(spectrum.data(), padded.data(), L);
    use(real.data(), padded.data() + (m - 1));
    return;
  }
  ScratchBuffer<Complex> spectrum(slot_spectrum, m / 2 + 1);
  rfft_unscaled(real.data(), spectrum.data(), m);
  const double scale = 1.0 / double(m);
  spectrum[0] = 0.0;
  for (std::size_t k = 1; k <= m / 2; ++k) {
    const Complex X = spectrum[k];
    spectrum[k] = Complex(X.imag() * scale, -X.real() * scale);  // -i X / m
  }
  if (m % 2 == 0) spectrum[m / 2] = 0.0;
  ScratchBuffer<double> imag(slot_imag, m);
  irfft_unscaled(spectrum.data(), imag.data(), m);
  use(real.data(), imag.data());
}

}  // namespace

std::string HilbertOptions::describe(std::size_t n) const {
  const std::size_t m = padding.fft_length(n);
  return "detrend " + std::string(to_string(detrend)) + ", padding " + padding.name() + " (FFT length " +
         std::to_string(m) + (m == n ? "" : ", zero padded from " + std::to_string(n)) + ")";
}

std::vector<Complex> analytic_signal(std::span<const double> x, const HilbertOptions& options) {
  std::vector<Complex> z(x.size());
  hilbert_core(x, options, [&](const double* re, const double* im) {
    for (std::size_t i = 0; i < z.size(); ++i) z[i] = Complex(re[i], im[i]);
  });
  return z;
}

std::vector<double> hilbert_transform(std::span<const double> x, const HilbertOptions& options) {
  std::vector<double> h(x.size());
  hilbert_core(x, options, [&](const double*, const double* im) { std::copy(im, im + h.size(), h.begin()); });
  return h;
}

void envelope_into(std::span<const double> x, std::span<double> out, const HilbertOptions& options) {
  if (out.size() != x.size()) throw std::logic_error("envelope_into: output and record differ in length");
  hilbert_core(x, options, [&](const double* re, const double* im) {
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = std::sqrt(re[i] * re[i] + im[i] * im[i]);
  });
}

void internal::envelope_into_unchecked(std::span<const double> x, std::span<double> out, const HilbertOptions& options) {
  hilbert_core(
      x, options,
      [&](const double* re, const double* im) {
        for (std::size_t i = 0; i < out.size(); ++i) out[i] = std::sqrt(re[i] * re[i] + im[i] * im[i]);
      },
      false);
}

std::vector<double> envelope(std::span<const double> x, const HilbertOptions& options) {
  std::vector<double> env(x.size());
  envelope_into(x, env, options);
  return env;
}

Signal envelope(const Signal& s, const HilbertOptions& options) {
  require_valid(s);
  Signal e = s;
  e.quantity = s.quantity.empty() ? "envelope" : s.quantity + " envelope";
  e.samples = envelope(std::span<const double>(s.samples), options);
  return e;
}

}  // namespace mesowave::signal
