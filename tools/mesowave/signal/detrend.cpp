#include "mesowave/signal/detrend.hpp"

#include "mesowave/core/error.hpp"

namespace mesowave::signal {

void detrend(std::span<double> x, Detrend mode) {
  const std::size_t n = x.size();
  if (mode == Detrend::none || n == 0) return;
  double mean = 0;
  for (double v : x) mean += v;
  mean /= double(n);
  if (mode == Detrend::mean || n == 1) {
    for (double& v : x) v -= mean;
    return;
  }
  // Least squares on the centred index c_i = i - (n-1)/2, where the normal
  // equations decouple: slope = sum c_i x_i / sum c_i^2.
  const double centre = 0.5 * double(n - 1);
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double c = double(i) - centre;
    sxy += c * (x[i] - mean);
    sxx += c * c;
  }
  const double slope = sxy / sxx;
  for (std::size_t i = 0; i < n; ++i) x[i] -= mean + slope * (double(i) - centre);
}

std::string_view to_string(Detrend mode) {
  switch (mode) {
    case Detrend::none: return "none";
    case Detrend::mean: return "mean";
    case Detrend::linear: return "linear";
  }
  return "none";
}

Detrend parse_detrend(std::string_view text) {
  if (text == "none") return Detrend::none;
  if (text == "mean" || text == "constant") return Detrend::mean;
  if (text == "linear") return Detrend::linear;
  throw InputError("detrend '" + std::string(text) + "' must be none, mean or linear");
}

}  // namespace mesowave::signal
