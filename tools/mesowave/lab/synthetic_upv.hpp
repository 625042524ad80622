#pragma once
// Synthetic ultrasonic pulse velocity (UPV) waveforms with a stated time of
// flight, as a pulse analyser exports them (time and amplitude, a pre-trigger
// stretch of noise before t = 0).
//
// The received pulse of a resonant transducer starts at the onset
// t_on = time of flight + transducer/couplant delay with a sharp front and
// rings down:  p(tau) = sin(2 pi f tau) exp(-tau / tau_d),  tau = t - t_on >= 0,
// tau_d = (ringing cycles) / f. Optionally a causal one-pole low-pass (corner
// `bandwidth`) rounds the front as frequency-dependent attenuation does - it
// is causal, so no energy appears before the onset. The amplitude is the source
// amplitude reduced by the path attenuation (10^(-attenuation_dB/20)); white
// Gaussian noise is added at the stated SNR = 20 log10(peak received amplitude /
// noise RMS). An earlier, weaker arrival (the P wave that shear transducers
// also pick up) can be added as a precursor.
#include <cstdint>
#include <string>
#include <vector>

namespace mesowave::lab {

struct SyntheticUpvSpec {
  double tof_s = 35e-6;
  double delay_s = 0;                ///< transducer + couplant delay, part of the recorded onset
  double frequency_Hz = 54e3;
  double ringing_cycles = 1.5;
  double bandwidth_Hz = 0;           ///< 0: no low-pass
  double amplitude_V = 1.0;          ///< source-equivalent amplitude
  double attenuation_dB = 6;         ///< amplitude loss over the path
  double snr_dB = 20;
  double sample_interval_s = 0.1e-6;
  double pretrigger_s = 50e-6;
  double duration_s = 250e-6;        ///< after the trigger
  double precursor_tof_s = 0;        ///< 0: none
  double precursor_fraction = 0.1;   ///< precursor peak / main peak
  std::uint64_t seed = 1;
};

struct SyntheticWaveform {
  std::vector<double> t_s, amplitude_V;
  double onset_s = 0;                ///< tof + delay: where the pulse starts in the record
  double peak_V = 0, noise_rms_V = 0;
};

SyntheticWaveform synthetic_upv_waveform(const SyntheticUpvSpec& spec);

/// Two columns, t_us and amplitude_V, one row per sample.
std::string waveform_csv(const SyntheticWaveform& waveform);

}  // namespace mesowave::lab
