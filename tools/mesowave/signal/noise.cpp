#include "mesowave/signal/noise.hpp"

#include <cmath>
#include <numbers>
#include <random>

#include "mesowave/core/error.hpp"

namespace mesowave::signal {

std::vector<double> gaussian_noise(std::size_t n, double rms, std::uint64_t seed) {
  if (!(rms >= 0) || !std::isfinite(rms)) throw InputError("noise RMS must be finite and not negative");
  std::mt19937_64 rng(seed);
  auto uniform = [&] { return (double(rng() >> 11) + 0.5) * 0x1.0p-53; };  // in (0, 1)
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; i += 2) {
    const double r = rms * std::sqrt(-2.0 * std::log(uniform())), a = 2.0 * std::numbers::pi * uniform();
    out[i] = r * std::cos(a);
    if (i + 1 < n) out[i + 1] = r * std::sin(a);
  }
  return out;
}

}  // namespace mesowave::signal
