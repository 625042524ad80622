#include "mesowave/signal/envelope.hpp"

#include <algorithm>
#include <cmath>

#include "mesowave/signal/validate.hpp"

namespace mesowave::signal {
namespace {

// H{x} over the record (after detrending), with the (detrended) record kept
// in `real`: since Re z = x, only Im z needs a transform, and Im z is real -
// its spectrum is -i sgn(k) X_k (zero at k = 0 and k = N/2), the
// anti-Hermitian half of X h. One r2c and one c2r transform instead of the
// complex round trip, with the same z.
void hilbert_parts(std::span<const double> x, const HilbertOptions& options, FftBuffer<double>& real,
                   FftBuffer<double>& imag) {
  require_samples(x, "record");
  const std::size_t n = x.size();
  const std::size_t m = options.padding.fft_length(n);
  real = FftBuffer<double>(m);
  std::copy(x.begin(), x.end(), real.begin());
  detrend(std::span<double>(real.data(), n), options.detrend);
  std::fill(real.begin() + n, real.end(), 0.0);

  FftBuffer<Complex> spectrum(m / 2 + 1);
  rfft_into(real, spectrum);
  const double scale = 1.0 / double(m);
  spectrum[0] = 0.0;
  for (std::size_t k = 1; k < spectrum.size(); ++k) {
    const Complex X = spectrum[k];
    spectrum[k] = Complex(X.imag() * scale, -X.real() * scale);  // -i X / m
  }
  if (m % 2 == 0) spectrum[m / 2] = 0.0;
  imag = FftBuffer<double>(m);
  irfft_unscaled_into(spectrum, imag);
}

}  // namespace

std::string HilbertOptions::describe(std::size_t n) const {
  const std::size_t m = padding.fft_length(n);
  return "detrend " + std::string(to_string(detrend)) + ", padding " + padding.name() + " (FFT length " +
         std::to_string(m) + (m == n ? "" : ", zero padded from " + std::to_string(n)) + ")";
}

std::vector<Complex> analytic_signal(std::span<const double> x, const HilbertOptions& options) {
  FftBuffer<double> re, im;
  hilbert_parts(x, options, re, im);
  std::vector<Complex> z(x.size());
  for (std::size_t i = 0; i < z.size(); ++i) z[i] = Complex(re[i], im[i]);
  return z;
}

std::vector<double> hilbert_transform(std::span<const double> x, const HilbertOptions& options) {
  FftBuffer<double> re, im;
  hilbert_parts(x, options, re, im);
  return {im.begin(), im.begin() + x.size()};
}

std::vector<double> envelope(std::span<const double> x, const HilbertOptions& options) {
  FftBuffer<double> re, im;
  hilbert_parts(x, options, re, im);
  std::vector<double> env(x.size());
  for (std::size_t i = 0; i < env.size(); ++i) env[i] = std::sqrt(re[i] * re[i] + im[i] * im[i]);
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
