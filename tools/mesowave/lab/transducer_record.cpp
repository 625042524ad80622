#include "mesowave/lab/transducer_record.hpp"

#include <cmath>
#include <numbers>

#include "mesowave/core/error.hpp"
#include "mesowave/signal/noise.hpp"

namespace mesowave::lab {

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
  const double a = transducer_decay_rate(s.frequency_Hz, s.rise_periods);
  // The envelope's peak value: normalising by it (not by the largest sample)
  // keeps the amplitude independent of where the samples fall on the carrier.
  const double w = 2 * std::numbers::pi * s.frequency_Hz, tau_r = s.rise_periods / s.frequency_Hz;
  const double peak = std::exp(-a * tau_r) * std::sqrt(1 + w * w * tau_r * tau_r) / (2 * w * w * w);

  signal::Signal r;
  r.name = "synthetic";
  r.quantity = "voltage";
  r.unit = "V";
  const long n_pre = std::lround(s.pretrigger_s / s.sample_interval_s);
  const long n_post = std::lround(s.duration_s / s.sample_interval_s);
  r.t0_s = -double(n_pre) * s.sample_interval_s;
  r.dt_s = s.sample_interval_s;
  const auto noise = signal::gaussian_noise(std::size_t(n_pre + n_post), s.amplitude * std::pow(10.0, -s.snr_dB / 20),
                                            s.seed);
  r.samples.resize(noise.size());
  for (std::size_t i = 0; i < noise.size(); ++i) {
    const double t = r.time(i);
    double v = transducer_response(t - s.onset_s, s.frequency_Hz, a);
    if (s.precursor_onset_s > 0) v += s.precursor_fraction * transducer_response(t - s.precursor_onset_s, s.frequency_Hz, a);
    r.samples[i] = s.amplitude * v / peak + noise[i];
  }
  return r;
}

}  // namespace mesowave::lab
