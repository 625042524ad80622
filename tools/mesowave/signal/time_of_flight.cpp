#include "mesowave/signal/time_of_flight.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/signal/resample.hpp"
#include "mesowave/signal/validate.hpp"

namespace mesowave::signal {
namespace {

std::string us(double t_s) { return format_number(t_s * 1e6) + " us"; }

// Sample range [first, last] of `s` within the window, InputError if empty.
std::pair<std::size_t, std::size_t> window_range(const Signal& s, const TimeWindow& w, const std::string& what) {
  const TimeBase base = time_base(s);
  if (w.begin_s) require_finite(what + " window start", *w.begin_s, "s");
  if (w.end_s) require_finite(what + " window end", *w.end_s, "s");
  if (w.begin_s && w.end_s && !(*w.end_s > *w.begin_s))
    throw InputError(what + " window: end (" + us(*w.end_s) + ") must come after its start (" + us(*w.begin_s) + ")");
  const TimeBase part = restrict_time_base(base, w.begin_s.value_or(base.t0_s), w.end_s.value_or(base.end_s()),
                                           "signal " + s.name + ": " + what + " window");
  const auto first = std::size_t(std::llround((part.t0_s - base.t0_s) / base.dt_s));
  return {first, first + part.count - 1};
}

}  // namespace

std::vector<double> aic_curve(std::span<const double> x) {
  require_samples(x, "AIC picker record", 4);
  const std::size_t n = x.size();
  // Variances by Welford's recurrence from both ends: no cancellation for a
  // record riding on an offset, O(N) in all.
  std::vector<double> head(n + 1, 0.0), tail(n + 1, 0.0);  // var of x[0..k-1], var of x[k..n-1]
  double mean = 0, m2 = 0;
  for (std::size_t k = 1; k <= n; ++k) {
    const double d = x[k - 1] - mean;
    mean += d / double(k);
    m2 += d * (x[k - 1] - mean);
    head[k] = m2 / double(k);
  }
  const double total = head[n];
  mean = 0, m2 = 0;
  for (std::size_t k = n; k-- > 0;) {
    const double count = double(n - k);
    const double d = x[k] - mean;
    mean += d / count;
    m2 += d * (x[k] - mean);
    tail[k] = m2 / count;
  }
  double peak = 0;
  for (double v : x) peak = std::max(peak, std::abs(v));
  if (!(std::sqrt(total) > 1e-13 * peak) || total == 0)
    throw InputError("AIC picker: the record is constant, it has no onset");
  const double floor = 1e-30 * total;
  std::vector<double> aic(n - 3);
  for (std::size_t k = 2; k + 2 <= n; ++k)
    aic[k - 2] = double(k) * std::log(std::max(head[k], floor)) +
                 double(n - k - 1) * std::log(std::max(tail[k], floor));  // Maeda (1985)
  return aic;
}

Pick aic_pick(const Signal& s, const AicOptions& options) {
  require_valid(s, 4);
  auto [first, last] = window_range(s, options.search, "AIC search");
  if (!options.search.end_s) {
    std::vector<double> rest(s.samples.begin() + long(first), s.samples.end());
    detrend(rest, options.detrend);
    const auto peak = std::size_t(std::max_element(rest.begin(), rest.end(), [](double a, double b) {
                                    return std::abs(a) < std::abs(b);
                                  }) - rest.begin());
    last = std::min(s.size() - 1, first + std::max<std::size_t>(peak, 3));
  }
  if (last - first + 1 < 4)
    throw InputError("signal " + s.name + ": the AIC search window holds " + std::to_string(last - first + 1) +
                     " samples, needs at least 4");
  std::vector<double> part(s.samples.begin() + long(first), s.samples.begin() + long(last) + 1);
  detrend(part, options.detrend);
  const auto aic = aic_curve(part);
  const std::size_t j = std::size_t(std::min_element(aic.begin(), aic.end()) - aic.begin());
  const double best = aic[j];

  Pick p;
  p.method = "aic";
  p.index = first + j + 2;
  p.time_s = s.time(p.index);
  // Akaike weights: how sharply the data prefer this split over its neighbours.
  double wsum = 0, spread = 0;
  for (std::size_t i = 0; i < aic.size(); ++i) {
    const double w = std::exp(-0.5 * (aic[i] - best));
    const double dt = (double(i) - double(j)) * s.dt_s;
    wsum += w;
    spread += w * dt * dt;
  }
  p.quality = std::sqrt(spread / wsum);
  p.quality_name = "aic_sd_s";
  return p;
}

Pick threshold_pick(const Signal& s, const ThresholdOptions& options) {
  require_valid(s, 3);
  require_positive("threshold factor", options.factor);
  require_in_range("relative threshold", options.relative, 0.0, 1.0);
  if (!options.noise_end_s && !(s.t0_s < 0))
    throw InputError("signal " + s.name + " starts at " + us(s.t0_s) +
                     " and has no pre-trigger samples: give the end of the noise window");
  const double noise_end = options.noise_end_s.value_or(0.0);
  const double noise_begin = options.noise_begin_s.value_or(s.t0_s);
  if (!(noise_end > noise_begin))
    throw InputError("signal " + s.name + ": the noise window " + us(noise_begin) + " .. " + us(noise_end) + " is empty");
  // The noise window is [begin, end): its last sample lies before `end`.
  const auto [n0, n1] = window_range(s, TimeWindow{noise_begin, noise_end - 1e-6 * s.dt_s}, "noise");
  const std::size_t noise_count = n1 - n0 + 1;
  if (noise_count < 2)
    throw InputError("signal " + s.name + ": the noise window " + us(noise_begin) + " .. " + us(noise_end) +
                     " holds " + std::to_string(noise_count) + " sample, needs at least 2");
  double mu = 0;
  for (std::size_t i = n0; i <= n1; ++i) mu += s.samples[i];
  mu /= double(noise_count);
  double var = 0;
  for (std::size_t i = n0; i <= n1; ++i) var += (s.samples[i] - mu) * (s.samples[i] - mu);
  const double sigma = std::sqrt(var / double(noise_count));

  TimeWindow search = options.search;
  if (!search.begin_s) search.begin_s = s.time(n1 + 1 < s.size() ? n1 + 1 : n1);
  const auto [first, last] = window_range(s, search, "threshold search");
  double peak = 0;
  for (std::size_t i = first; i <= last; ++i) peak = std::max(peak, std::abs(s.samples[i] - mu));
  const double threshold = std::max(options.factor * sigma, options.relative * peak);
  if (!(threshold > 0))
    throw InputError("signal " + s.name +
                     ": the pre-trigger noise is exactly zero (a noiseless record); give a relative threshold");

  for (std::size_t i = first; i <= last; ++i) {
    const double v = std::abs(s.samples[i] - mu);
    if (v < threshold) continue;
    Pick p;
    p.method = "threshold";
    p.index = i;
    p.time_s = s.time(i);
    if (i > first) {
      const double prev = std::abs(s.samples[i - 1] - mu);
      if (prev < threshold && v > prev) p.time_s = s.time(i - 1) + (threshold - prev) / (v - prev) * s.dt_s;
    }
    p.quality = 20.0 * std::log10(peak / std::max(sigma, 1e-15 * peak));
    p.quality_name = "snr_dB";
    return p;
  }
  throw InputError("signal " + s.name + ": no sample in " + us(s.time(first)) + " .. " + us(s.time(last)) +
                   " reaches the threshold " + format_number(threshold) + " " + s.unit + " (" +
                   format_number(options.factor) + " x noise RMS " + format_number(sigma) + ")");
}

Pick envelope_peak_pick(const Signal& s, const EnvelopePeakOptions& options) {
  require_valid(s, 1);
  const auto [first, last] = window_range(s, options.search, "envelope-peak search");
  const auto e = envelope(std::span<const double>(s.samples), options.hilbert);
  std::size_t i = first;
  for (std::size_t k = first; k <= last; ++k)
    if (e[k] > e[i]) i = k;
  const double peak = e[i];
  if (!(peak > 0)) throw InputError("signal " + s.name + ": the envelope is zero in the search window");

  Pick p;
  p.method = "envelope-peak";
  p.index = i;
  p.time_s = s.time(i);
  if (i > 0 && i + 1 < e.size()) {
    const double denom = e[i - 1] - 2.0 * e[i] + e[i + 1];
    if (denom < 0) p.time_s += std::clamp(0.5 * (e[i - 1] - e[i + 1]) / denom, -0.5, 0.5) * s.dt_s;
  }
  // The half-maximum lobe around the peak, then the highest local maximum
  // outside it (window edges count when the envelope rises towards them).
  std::size_t lo = i, hi = i;
  while (lo > first && e[lo - 1] >= 0.5 * peak) --lo;
  while (hi < last && e[hi + 1] >= 0.5 * peak) ++hi;
  double rival = 0;
  for (std::size_t k = first; k <= last; ++k) {
    if (k >= lo && k <= hi) continue;
    const bool left_ok = k == first || e[k] >= e[k - 1];
    const bool right_ok = k == last || e[k] >= e[k + 1];
    if (left_ok && right_ok) rival = std::max(rival, e[k]);
  }
  p.quality = std::min(peak / std::max(rival, 1e-6 * peak), 1e6);
  p.quality_name = "peak_ratio";
  return p;
}

}  // namespace mesowave::signal
