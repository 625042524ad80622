#include "mesowave/signal/noise.hpp"

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

}  // namespace mesowave::signal
