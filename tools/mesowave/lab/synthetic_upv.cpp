#include "mesowave/lab/synthetic_upv.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/random.hpp"
#include "mesowave/io/csv.hpp"

namespace mesowave::lab {

namespace {

// Unit-amplitude pulse starting at `onset`, sampled on `t`, low-passed causally.
std::vector<double> pulse(const std::vector<double>& t, double onset, const SyntheticUpvSpec& spec) {
  const double tau_d = spec.ringing_cycles / spec.frequency_Hz;
  std::vector<double> p(t.size(), 0.0);
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double tau = t[i] - onset;
    if (tau >= 0) p[i] = std::sin(2 * std::numbers::pi * spec.frequency_Hz * tau) * std::exp(-tau / tau_d);
  }
  if (spec.bandwidth_Hz > 0) {
    const double rc = 1.0 / (2 * std::numbers::pi * spec.bandwidth_Hz);
    const double alpha = spec.sample_interval_s / (rc + spec.sample_interval_s);
    double y = 0;
    for (double& v : p) v = y = y + alpha * (v - y);
  }
  const double peak = *std::max_element(p.begin(), p.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
  if (peak != 0)
    for (double& v : p) v /= std::abs(peak);
  return p;
}

}  // namespace

SyntheticWaveform synthetic_upv_waveform(const SyntheticUpvSpec& spec) {
  if (!(spec.tof_s > 0 && spec.frequency_Hz > 0 && spec.sample_interval_s > 0 && spec.duration_s > 0))
    throw InputError("synthetic waveform needs positive time of flight, frequency, sample interval and duration");
  if (!(spec.pretrigger_s >= 0 && spec.delay_s >= 0 && spec.ringing_cycles > 0 && spec.amplitude_V > 0))
    throw InputError("synthetic waveform needs pre-trigger >= 0, delay >= 0, ringing > 0, amplitude > 0");
  if (spec.tof_s + spec.delay_s >= spec.duration_s) throw InputError("the onset lies after the end of the record");
  XoshiroRandom rng(spec.seed);
  SyntheticWaveform w;
  const long n_pre = std::lround(spec.pretrigger_s / spec.sample_interval_s);
  const long n_post = std::lround(spec.duration_s / spec.sample_interval_s);
  for (long i = -n_pre; i < n_post; ++i) w.t_s.push_back(double(i) * spec.sample_interval_s);
  w.onset_s = spec.tof_s + spec.delay_s;
  w.peak_V = spec.amplitude_V * std::pow(10.0, -spec.attenuation_dB / 20.0);
  w.noise_rms_V = w.peak_V * std::pow(10.0, -spec.snr_dB / 20.0);
  const auto main = pulse(w.t_s, w.onset_s, spec);
  std::vector<double> early(w.t_s.size(), 0.0);
  if (spec.precursor_tof_s > 0) early = pulse(w.t_s, spec.precursor_tof_s + spec.delay_s, spec);
  for (std::size_t i = 0; i < w.t_s.size(); ++i)
    w.amplitude_V.push_back(w.peak_V * (main[i] + spec.precursor_fraction * early[i] * (spec.precursor_tof_s > 0)) +
                            w.noise_rms_V * rng.normal());
  return w;
}

std::string waveform_csv(const SyntheticWaveform& waveform) {
  std::vector<std::vector<std::string>> rows;
  rows.reserve(waveform.t_s.size());
  for (std::size_t i = 0; i < waveform.t_s.size(); ++i)
    rows.push_back({format_fixed(waveform.t_s[i] * 1e6, 2), format_fixed(waveform.amplitude_V[i], 6)});
  return io::to_csv({"t_us", "amplitude_V"}, rows);
}

}  // namespace mesowave::lab
