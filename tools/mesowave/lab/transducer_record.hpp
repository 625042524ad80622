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
//
// Slow rise (optional): a low-frequency lobe under the main onset, as the DEM's S records
// carry one (docs/upv-pickers.md, "The DEM's S records": there the P wave's near field,
// Aki & Richards Eq. 4.23, on the tangential receiver), a Hann lobe
//   r(t) = slow_rise_fraction x main peak x sin^2(pi (t - t_0) / D),  t_0 <= t <= t_0 + D,
// t_0 = onset - slow_rise_lead_periods / f, D = slow_rise_periods / f: it starts before the
// onset and peaks after it (the defaults, 0.35 and 1 period: on the DEM's records the rise
// starts 0.3-0.4 periods before the continuum's S time and the first half-cycle rides on it).
// Its spectrum lies below f (a Hann lobe of one period: main lobe to 2 f, centred at 0).
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
  double slow_rise_fraction = 0;    ///< slow rise peak / main peak (0: none); [0, 1]
  double slow_rise_lead_periods = 0.35;  ///< the slow rise starts this long before the onset [periods of f]
  double slow_rise_periods = 1.0;   ///< its duration [periods of f]
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
/// not come before the main onset, an onset outside the record, a slow-rise fraction outside
/// [0, 1], or a non-positive slow-rise duration or negative lead.
signal::Signal transducer_record(const TransducerRecordSpec& spec);

// A point force's record at distance r on the line through it normal to the force (the
// "transverse" receiver of a shear transducer pair) or along it ("axial": the P pair), in an
// infinite elastic solid: Stokes' solution (Aki & Richards, Quantitative Seismology, 2nd ed.,
// Eq. 4.23). With the unit vector gamma from source to receiver and the force along j,
//   4 pi rho u_i = (3 g_i g_j - d_ij) / r^3 int_{r/alpha}^{r/beta} tau F(t - tau) dtau
//                  + g_i g_j / (alpha^2 r) F(t - r/alpha) - (g_i g_j - d_ij) / (beta^2 r) F(t - r/beta),
// so transverse (g_i g_j = 0, d_ij = 1): -1/r^3 int ... + F(t - r/beta) / (beta^2 r), the S wave
// at r/beta riding on the near field that starts at r/alpha; axial (g_i g_j = d_ij = 1):
// 2/r^3 int ... + F(t - r/alpha) / (alpha^2 r), the P wave at r/alpha. The record is the
// velocity (F' in place of F: F(0) = 0), F the Hann burst load of signal/hann_burst.hpp,
// normalised to its largest |v|, plus white Gaussian noise at snr_dB = 20 log10(1 / noise RMS).
// This is the DEM's UPV test without its lattice, patches and faces (docs/upv-pickers.md,
// "The DEM's S records"): its slow rise under the S burst is the near-field integral.
struct PointForceRecordSpec {
  double frequency_Hz = 120e3;   ///< the burst's (upv50-s.toml)
  double cycles = 2;
  double distance_m = 0.05;
  double p_speed_m_s = 0, s_speed_m_s = 0;  ///< alpha > beta > 0
  bool axial = false;            ///< false: the transverse record (S pair); true: the axial one (P pair)
  double snr_dB = 40;            ///< +inf: no noise
  double sample_interval_s = 50e-9;  ///< the DEM's step
  double pretrigger_s = 20e-6;
  double duration_s = 40e-6;     ///< after the load's start (t = 0), the 1/3-scale record's
  std::uint64_t seed = 1;
};

/// The record above (quantity velocity, normalised). InputError for non-positive frequency,
/// cycles, distance, interval or duration, or speeds that are not alpha > beta > 0.
signal::Signal point_force_record(const PointForceRecordSpec& spec);

}  // namespace mesowave::lab
