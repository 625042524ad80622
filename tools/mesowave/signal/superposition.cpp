#include "mesowave/signal/superposition.hpp"

#include <algorithm>
#include <cmath>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/signal/correlation.hpp"

namespace mesowave::signal {

ForceHistory force_history(const std::function<double(double)>& force_N, double dt_s, std::int64_t steps) {
  ForceHistory h;
  h.force_N.assign(std::size_t(std::max<std::int64_t>(steps, 0)), 0.0);
  for (std::int64_t n = 0; n < steps; ++n) {
    const double f = force_N(double(n) * dt_s);
    h.force_N[std::size_t(n)] = f;
    if (f != 0) {
      if (h.last < 0) h.first = n;
      h.last = n;
    }
    h.l1_N += std::abs(f);
  }
  return h;
}

std::vector<double> convolve_sampled(const std::vector<ConvolutionTerm>& terms, std::int64_t every,
                                     std::int64_t samples, std::span<const double> window) {
  if (every < 1) throw InputError("convolution: the sampling interval must be at least one step");
  const std::int64_t last_n = (samples - 1) * every;
  for (const auto& t : terms)
    if (t.force->last >= 0 && std::int64_t(t.response.size()) <= last_n - t.force->first)
      throw InputError("convolution: an impulse response of " + std::to_string(t.response.size()) +
                       " steps is shorter than the record (" + std::to_string(last_n + 1) + " steps)");
  if (!window.empty() && std::int64_t(window.size()) <= last_n)
    throw InputError("convolution: the window is shorter than the record");
  std::vector<double> y(std::size_t(std::max<std::int64_t>(samples, 0)), 0.0);
  double* out = y.data();
  // Each output is its own sum in a fixed order: the same bits for any thread count.
#pragma omp parallel for schedule(static)
  for (std::int64_t m = 0; m < samples; ++m) {
    const std::int64_t n = m * every;
    double sum = 0;
    for (const auto& t : terms) {
      const double* f = t.force->force_N.data();
      const double* h = t.response.data();
      const std::int64_t end = std::min(t.force->last, n);
      if (window.empty())
        for (std::int64_t k = t.force->first; k <= end; ++k) sum += f[k] * h[n - k];
      else
        for (std::int64_t k = t.force->first; k <= end; ++k) sum += f[k] * (window[std::size_t(n - k)] * h[n - k]);
    }
    out[m] = sum;
  }
  return y;
}

SuperpositionError superposition_error(const std::vector<Signal>& direct, const std::vector<Signal>& superposed) {
  if (direct.size() != superposed.size())
    throw InputError("superposition check: " + std::to_string(direct.size()) + " direct signals against " +
                     std::to_string(superposed.size()) + " superposed");
  SuperpositionError e;
  for (std::size_t s = 0; s < direct.size(); ++s) {
    const Signal &d = direct[s], &p = superposed[s];
    if (d.name != p.name || d.size() != p.size() || d.dt_s != p.dt_s || d.t0_s != p.t0_s)
      throw InputError("superposition check: sensor " + d.name + " and " + p.name + " do not share a time base");
    double peak = 0, diff = 0;
    for (std::size_t i = 0; i < d.size(); ++i) {
      peak = std::max(peak, std::abs(d.samples[i]));
      diff = std::max(diff, std::abs(p.samples[i] - d.samples[i]));
    }
    e.sensors.push_back(d.name);
    e.pcc.push_back(pearson(d.samples, p.samples, "sensor " + d.name));
    e.max_diff_over_peak.push_back(peak > 0 ? diff / peak : diff);
    e.min_pcc = std::min(e.min_pcc, e.pcc.back());
    e.max_diff_over_peak_all = std::max(e.max_diff_over_peak_all, e.max_diff_over_peak.back());
  }
  return e;
}

void check_frequencies(const std::vector<double>& frequencies_kHz, const std::vector<double>& check_kHz) {
  if (frequencies_kHz.empty()) throw InputError("--frequencies-kHz names no frequency");
  for (std::size_t i = 0; i < frequencies_kHz.size(); ++i) {
    require_positive("--frequencies-kHz", frequencies_kHz[i], "kHz");
    for (std::size_t j = 0; j < i; ++j)
      if (frequencies_kHz[j] == frequencies_kHz[i])
        throw InputError("--frequencies-kHz names " + format_number(frequencies_kHz[i]) + " kHz twice");
  }
  for (double c : check_kHz)
    if (std::find(frequencies_kHz.begin(), frequencies_kHz.end(), c) == frequencies_kHz.end())
      throw InputError("--check-kHz (" + format_number(c) + " kHz) must be one of --frequencies-kHz");
}

std::string frequency_text(double frequency_hz) { return format_number(frequency_hz / units::kHz); }

std::filesystem::path frequency_path(const std::string& pattern, const std::string& option, double frequency_hz) {
  const std::string key = "{f}";
  if (pattern.find(key) == std::string::npos)
    throw InputError(option + " (" + pattern + ") needs {f}, the frequency in kHz, or every frequency writes one file");
  std::string path = pattern;
  const std::string text = frequency_text(frequency_hz);
  for (std::size_t at = path.find(key); at != std::string::npos; at = path.find(key, at + text.size()))
    path.replace(at, key.size(), text);
  return path;
}

}  // namespace mesowave::signal
