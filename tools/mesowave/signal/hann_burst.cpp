#include "mesowave/signal/hann_burst.hpp"

#include <cmath>
#include <numbers>

#include "mesowave/core/check.hpp"

namespace mesowave::signal {

HannBurst::HannBurst(double f, double n, double a, double delay)
    : frequency_(require_positive("centre frequency", f, "Hz")), cycles_(require_positive("cycles", n)),
      amplitude_(require_finite("amplitude", a)), delay_(require_finite("delay", delay, "s")) {
  if (delay < 0) throw InputError("delay (" + format_quantity(delay, "s") + ") must not be negative");
}

double HannBurst::operator()(double t) const {
  const double local = t - delay_;
  if (local < 0 || local > duration_s()) return 0.0;
  const double phase = 2.0 * std::numbers::pi * frequency_ * local;
  return amplitude_ * std::sin(phase) * 0.5 * (1.0 - std::cos(phase / cycles_));
}

double HannBurst::rate(double t) const {
  const double local = t - delay_;
  if (local <= 0 || local >= duration_s()) return 0.0;
  const double w = 2.0 * std::numbers::pi * frequency_, phase = w * local;
  return amplitude_ * (w * std::cos(phase) * 0.5 * (1.0 - std::cos(phase / cycles_)) +
                       std::sin(phase) * 0.5 * (w / cycles_) * std::sin(phase / cycles_));
}

std::vector<double> HannBurst::sample(double dt, std::size_t count, double t0) const {
  require_positive("sampling interval", dt, "s");
  std::vector<double> samples(count);
  for (std::size_t i = 0; i < count; ++i) samples[i] = (*this)(t0 + double(i) * dt);
  return samples;
}

}  // namespace mesowave::signal
