#include "mesowave/lab/transducer_record.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "mesowave/core/error.hpp"
#include "mesowave/signal/hann_burst.hpp"
#include "mesowave/signal/noise.hpp"

namespace mesowave::lab {

namespace {

// A record's time base as a lab instrument's: `pretrigger_s` before the trigger at t = 0, then
// `duration_s`, at `dt_s`; the samples zero.
signal::Signal record_of(double pretrigger_s, double duration_s, double dt_s, std::string name, std::string quantity,
                         std::string unit) {
  signal::Signal r;
  r.name = std::move(name);
  r.quantity = std::move(quantity);
  r.unit = std::move(unit);
  const long n_pre = std::lround(pretrigger_s / dt_s), n_post = std::lround(duration_s / dt_s);
  r.t0_s = -double(n_pre) * dt_s;
  r.dt_s = dt_s;
  r.samples.assign(std::size_t(n_pre + n_post), 0.0);
  return r;
}

}  // namespace

double transducer_decay_rate(double frequency_Hz, double rise_periods) {
  if (!(frequency_Hz > 0) || !(rise_periods > 0) || !std::isfinite(frequency_Hz) || !std::isfinite(rise_periods))
    throw InputError("transducer response: frequency and rise must be positive");
  const double w = 2 * std::numbers::pi * frequency_Hz, tau_r = rise_periods / frequency_Hz;
  return w * w * tau_r / (1 + w * w * tau_r * tau_r);
}

double transducer_response(double tau_s, double frequency_Hz, double a) {
  if (tau_s <= 0) return 0.0;
  const double w = 2 * std::numbers::pi * frequency_Hz, x = w * tau_s;
  return std::exp(-a * tau_s) * (std::sin(x) - x * std::cos(x)) / (2 * w * w * w);
}

signal::Signal transducer_record(const TransducerRecordSpec& s) {
  if (!(s.sample_interval_s > 0) || !(s.duration_s > 0) || !(s.pretrigger_s >= 0) || !(s.amplitude > 0))
    throw InputError("transducer record: sample interval, duration and amplitude must be positive, pre-trigger >= 0");
  if (!std::isfinite(s.snr_dB)) throw InputError("transducer record: snr_dB must be finite");
  if (!(s.precursor_fraction >= 0 && s.precursor_fraction <= 1))
    throw InputError("transducer record: precursor_fraction " + std::to_string(s.precursor_fraction) +
                     " is not in [0, 1]");
  if (!(s.onset_s > 0 && s.onset_s < s.duration_s)) throw InputError("transducer record: the onset lies outside the record");
  if (s.precursor_onset_s != 0 && !(s.precursor_onset_s > 0 && s.precursor_onset_s < s.onset_s))
    throw InputError("transducer record: the precursor must arrive after the trigger and before the main onset");
  if (!(s.slow_rise_fraction >= 0 && s.slow_rise_fraction <= 1) || !(s.slow_rise_periods > 0) ||
      !(s.slow_rise_lead_periods >= 0))
    throw InputError("transducer record: slow_rise_fraction must be in [0, 1], slow_rise_periods positive and "
                     "slow_rise_lead_periods >= 0");
  const double a = transducer_decay_rate(s.frequency_Hz, s.rise_periods);
  const double rise_begin = s.onset_s - s.slow_rise_lead_periods / s.frequency_Hz;
  const double rise_length = s.slow_rise_periods / s.frequency_Hz;
  // The envelope's peak value: normalising by it (not by the largest sample)
  // keeps the amplitude independent of where the samples fall on the carrier.
  const double w = 2 * std::numbers::pi * s.frequency_Hz, tau_r = s.rise_periods / s.frequency_Hz;
  const double peak = std::exp(-a * tau_r) * std::sqrt(1 + w * w * tau_r * tau_r) / (2 * w * w * w);

  signal::Signal r = record_of(s.pretrigger_s, s.duration_s, s.sample_interval_s, "synthetic", "voltage", "V");
  const auto noise = signal::gaussian_noise(r.size(), s.amplitude * std::pow(10.0, -s.snr_dB / 20), s.seed);
  for (std::size_t i = 0; i < noise.size(); ++i) {
    const double t = r.time(i);
    double v = transducer_response(t - s.onset_s, s.frequency_Hz, a);
    if (s.precursor_onset_s > 0) v += s.precursor_fraction * transducer_response(t - s.precursor_onset_s, s.frequency_Hz, a);
    double x = s.amplitude * v / peak;  // (without a slow rise: the same bits as before it existed)
    if (s.slow_rise_fraction > 0 && t >= rise_begin && t <= rise_begin + rise_length) {
      const double q = std::sin(std::numbers::pi * (t - rise_begin) / rise_length);
      x += s.amplitude * s.slow_rise_fraction * q * q;
    }
    r.samples[i] = x + noise[i];
  }
  return r;
}

signal::Signal point_force_record(const PointForceRecordSpec& s) {
  if (!(s.frequency_Hz > 0) || !(s.cycles > 0) || !(s.distance_m > 0) || !(s.sample_interval_s > 0) ||
      !(s.duration_s > 0) || !(s.pretrigger_s >= 0))
    throw InputError("point-force record: frequency, cycles, distance, sample interval and duration must be positive");
  if (!(s.s_speed_m_s > 0 && s.p_speed_m_s > s.s_speed_m_s))
    throw InputError("point-force record: the speeds must satisfy alpha > beta > 0");
  const double r = s.distance_m, ta = r / s.p_speed_m_s, tb = r / s.s_speed_m_s, T = s.cycles / s.frequency_Hz;
  const signal::HannBurst burst(s.frequency_Hz, s.cycles);  // F(t); its rate F'(t) drives the velocity
  // int_{ta}^{tb} tau F'(t - tau) dtau over F's support, Simpson's rule (F' is smooth inside it).
  const auto near = [&](double t) {
    const double lo = std::max(ta, t - T), hi = std::min(tb, t);
    if (!(hi > lo)) return 0.0;
    const int n = 64;  // 32 intervals a period of F' at 2 cycles: Simpson's error ~ (h f)^4 ~ 1e-6
    const double h = (hi - lo) / n;
    double sum = 0;
    for (int k = 0; k <= n; ++k) {
      const double tau = lo + k * h;
      sum += (k == 0 || k == n ? 1 : (k % 2 ? 4 : 2)) * tau * burst.rate(t - tau);
    }
    return sum * h / 3;
  };
  signal::Signal rec = record_of(s.pretrigger_s, s.duration_s, s.sample_interval_s,
                                 s.axial ? "point force, axial" : "point force, transverse", "velocity", "1");
  double peak = 0;
  for (std::size_t i = 0; i < rec.samples.size(); ++i) {
    const double t = rec.time(i);
    const double v = s.axial ? 2 * near(t) / (r * r * r) + burst.rate(t - ta) / (s.p_speed_m_s * s.p_speed_m_s * r)
                             : -near(t) / (r * r * r) + burst.rate(t - tb) / (s.s_speed_m_s * s.s_speed_m_s * r);
    rec.samples[i] = v;
    peak = std::max(peak, std::abs(v));
  }
  const bool noisy = std::isfinite(s.snr_dB);
  const auto noise = noisy ? signal::gaussian_noise(rec.samples.size(), std::pow(10.0, -s.snr_dB / 20), s.seed)
                           : std::vector<double>(rec.samples.size(), 0.0);
  for (std::size_t i = 0; i < rec.samples.size(); ++i) rec.samples[i] = rec.samples[i] / peak + noise[i];
  return rec;
}

}  // namespace mesowave::lab
