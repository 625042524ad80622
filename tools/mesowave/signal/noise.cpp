#include "mesowave/signal/noise.hpp"

#include <algorithm>
#include <cmath>

#include "mesowave/core/error.hpp"
#include "mesowave/core/random.hpp"

namespace mesowave::signal {

std::vector<double> gaussian_noise(std::size_t n, double rms, std::uint64_t seed) {
  if (!(rms >= 0) || !std::isfinite(rms)) throw InputError("noise RMS must be finite and not negative");
  Mt64Random random(seed);
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; i += 2) {
    const auto [a, b] = random.gaussian_pair(rms);
    out[i] = a;
    if (i + 1 < n) out[i + 1] = b;
  }
  return out;
}

double noise_rms_at_snr(const Signal& record, double snr_dB) {
  if (!std::isfinite(snr_dB)) throw InputError("the added noise's SNR must be finite (dB)");
  double peak = 0;
  for (double v : record.samples) peak = std::max(peak, std::abs(v));
  if (!(peak > 0)) throw InputError(record.name + ": an all-zero record has no peak to add noise at an SNR to");
  return peak * std::pow(10.0, -snr_dB / 20);
}

Signal with_noise_at_snr(const Signal& record, double snr_dB, std::uint64_t seed) {
  Signal out = record;
  const auto noise = gaussian_noise(record.size(), noise_rms_at_snr(record, snr_dB), seed);
  for (std::size_t i = 0; i < out.size(); ++i) out.samples[i] += noise[i];
  return out;
}

}  // namespace mesowave::signal
