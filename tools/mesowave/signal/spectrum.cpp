#include "mesowave/signal/spectrum.hpp"

#include <algorithm>
#include <cmath>

#include "mesowave/core/check.hpp"
#include "mesowave/signal/validate.hpp"

namespace mesowave::signal {

std::string_view to_string(SpectrumScaling scaling) {
  switch (scaling) {
    case SpectrumScaling::amplitude: return "amplitude";
    case SpectrumScaling::density: return "density";
    case SpectrumScaling::raw: return "raw";
  }
  return "amplitude";
}

SpectrumScaling parse_spectrum_scaling(std::string_view text) {
  if (text == "amplitude") return SpectrumScaling::amplitude;
  if (text == "density") return SpectrumScaling::density;
  if (text == "raw") return SpectrumScaling::raw;
  throw InputError("spectrum scaling '" + std::string(text) + "' must be amplitude, density or raw");
}

std::string Spectrum::unit(std::string_view signal_unit) const {
  const std::string u(signal_unit);
  switch (scaling) {
    case SpectrumScaling::amplitude: return u;
    case SpectrumScaling::density: return u.empty() ? "s" : u + " s";
    case SpectrumScaling::raw: return u;
  }
  return u;
}

void amplitude_spectrum(std::span<const double> x, double dt_s, const SpectrumOptions& options, Spectrum& s) {
  require_positive("sampling interval dt", dt_s, "s");
  require_samples(x, "record");
  const std::size_t n = x.size();
  const std::size_t m = options.padding.fft_length(n);
  ScratchBuffer<double> record(8, m);  // scratch slots 8 and 9 (see ScratchBuffer)
  std::copy(x.begin(), x.end(), record.begin());
  detrend(std::span<double>(record.data(), n), options.detrend);
  std::fill(record.begin() + n, record.begin() + m, 0.0);
  const std::size_t nbins = m / 2 + 1;
  ScratchBuffer<Complex> bins(9, nbins);
  rfft_unscaled(record.data(), bins.data(), m);

  s.samples = n;
  s.fft_length = m;
  s.scaling = options.scaling;
  s.df_hz = 1.0 / (double(m) * dt_s);
  s.frequency_hz.resize(nbins);
  s.amplitude.resize(nbins);
  const double scale = options.scaling == SpectrumScaling::amplitude ? 2.0 / double(n)
                       : options.scaling == SpectrumScaling::density ? dt_s
                                                                      : 1.0;
  for (std::size_t k = 0; k < nbins; ++k) {
    const Complex X = bins[k];
    s.frequency_hz[k] = double(k) * s.df_hz;
    s.amplitude[k] = std::sqrt(X.real() * X.real() + X.imag() * X.imag()) * scale;
  }
  if (options.scaling == SpectrumScaling::amplitude) {
    s.amplitude[0] *= 0.5;  // DC and Nyquist have no mirror image to fold in
    if (m % 2 == 0 && m > 1) s.amplitude[m / 2] *= 0.5;
  }
}

Spectrum amplitude_spectrum(std::span<const double> x, double dt_s, const SpectrumOptions& options) {
  Spectrum s;
  amplitude_spectrum(x, dt_s, options, s);
  return s;
}

Spectrum amplitude_spectrum(const Signal& s, const SpectrumOptions& options) {
  require_valid(s);
  return amplitude_spectrum(std::span<const double>(s.samples), s.dt_s, options);
}

double peak_frequency_hz(const Spectrum& spectrum, double min_frequency_hz) {
  const auto& a = spectrum.amplitude;
  std::size_t best = a.size();
  for (std::size_t k = 0; k < a.size(); ++k)
    if (spectrum.frequency_hz[k] >= min_frequency_hz && (best == a.size() || a[k] > a[best])) best = k;
  if (best == a.size()) throw InputError("no spectrum bin at or above " + format_quantity(min_frequency_hz, "Hz"));
  if (best == 0 || best + 1 >= a.size() || !(a[best - 1] > 0) || !(a[best + 1] > 0) || !(a[best] > 0))
    return spectrum.frequency_hz[best];
  const double l = std::log(a[best - 1]), c = std::log(a[best]), r = std::log(a[best + 1]);
  const double denom = l - 2 * c + r;
  const double offset = denom < 0 ? 0.5 * (l - r) / denom : 0.0;
  return (double(best) + std::clamp(offset, -0.5, 0.5)) * spectrum.df_hz;
}

}  // namespace mesowave::signal
