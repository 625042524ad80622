#pragma once
// Synthetic UPV records as a resonant transducer pair gives them, for
// measuring the pickers against a known onset (issue 19, item 1).
//
// Transducer response. Transmitter and receiver are each a damped resonator
// (damped angular frequency w = 2 pi f, decay rate a); the pair's impulse
// response is the convolution of the two single-resonator responses
// e^{-a t} sin(w t) / w, which in closed form is
//   h(tau) = e^{-a tau} (sin(w tau) - w tau cos(w tau)) / (2 w^3),  tau = t - onset >= 0,
// (the inverse Laplace transform of 1 / ((s + a)^2 + w^2)^2). Its front is
// gentle, h ~ w^3 tau^3 / 3 for small tau, and its envelope
// e^{-a tau} sqrt(1 + w^2 tau^2) / (2 w^3) peaks at tau_r where
// a w^2 tau_r^2 - w^2 tau_r + a = 0: the record rises over tau_r before it
// rings down. The spec states the rise in periods, rise_periods = tau_r f,
// and a follows as a = w^2 tau_r / (1 + w^2 tau_r^2) (single-resonator
// damping ratio a / w ~ 1 / (2 pi rise_periods): 0.16 for one period, 0.08 for two).
//
// A record: the main arrival (peak amplitude `amplitude`), optionally an
// earlier precursor of the same response at `precursor_fraction` of the main
// peak (the P energy a shear transducer also receives), and white Gaussian
// noise at snr_dB = 20 log10(main peak / noise RMS), drawn with
// signal::gaussian_noise (core/random.hpp's default stream, Mt64Random).
// Samples run from -pretrigger to duration after the trigger (t = 0).
#include <cstdint>

#include "mesowave/signal/signal.hpp"

namespace mesowave::lab {

struct TransducerRecordSpec {
  double frequency_Hz = 40e3;       ///< f, the transducers' frequency
  double rise_periods = 1.5;        ///< envelope peak after the onset, in periods of f
  double onset_s = 55.1e-6;         ///< the main arrival's true onset (record time)
  double precursor_onset_s = 0;     ///< the precursor's true onset; 0: no precursor
  double precursor_fraction = 0.3;  ///< precursor peak / main peak
  double amplitude = 1.0;           ///< main peak
  double snr_dB = 30;               ///< 20 log10(main peak / noise RMS)
  double sample_interval_s = 0.1e-6;
  double pretrigger_s = 50e-6;
  double duration_s = 400e-6;       ///< after the trigger
  std::uint64_t seed = 1;
};

/// The decay rate a [1/s] whose envelope peaks rise_periods / f after the onset.
double transducer_decay_rate(double frequency_Hz, double rise_periods);

/// h(tau) of the header (0 for tau < 0), unnormalised.
double transducer_response(double tau_s, double frequency_Hz, double decay_rate_per_s);

/// The record (quantity voltage, unit V, t0_s = -pretrigger). InputError for
/// non-positive frequency, rise, interval, duration or amplitude, an SNR that
/// is not finite, a precursor fraction outside [0, 1], a precursor that does
/// not come before the main onset, or an onset outside the record.
signal::Signal transducer_record(const TransducerRecordSpec& spec);

}  // namespace mesowave::lab
