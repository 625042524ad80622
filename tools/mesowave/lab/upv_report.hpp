#pragma once
// What mw-upv computes and writes (flowchart step 3, dynamic route): the
// times of flight, given or picked on the recorded waveforms, and from them
// the velocities, the Poisson ratio and the dynamic moduli of concrete paper
// Eqs. (8)-(10) - or, with the P wave alone, ASTM C597's relation with an
// assumed Poisson ratio, which the result records.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "mesowave/lab/upv_waveform.hpp"

namespace mesowave::lab {

/// The test as the operator states it, in the lab's units (mm, us, kHz, kg/m3).
struct UpvMeasurement {
  double path_mm = 0;                         ///< distance between the transducers
  std::optional<double> t_p_us, t_s_us;       ///< given times of flight ...
  std::filesystem::path p_wave, s_wave;       ///< ... or the records to pick them on
  std::optional<double> density_kg_m3;        ///< none: velocities and nu_d only
  std::optional<double> nu_assumed;           ///< P wave alone: the Poisson ratio to assume
  WaveformReadOptions read;                   ///< sample_interval_s is set from sample_interval_us
  std::optional<double> sample_interval_us;   ///< WAV: the true sample interval
  OnsetOptions pick;                          ///< picker and its factors; the times below override its *_s
  std::string s_locator;                      ///< threshold | envelope-peak for S ("": after a P pick, envelope-peak)
  double delay_us = 0;                        ///< transducers + couplant, subtracted from the picks
  std::optional<double> s_delay_us;           ///< the S transducers', if it differs
  double crosstalk_us = 0, aic_after_us = 10, lowpass_kHz = 0;
  std::optional<double> s_lowpass_kHz;
  std::vector<double> noise_us, p_search_us, s_search_us;  ///< begin,end windows (empty: default)
  /// The S onset by the matched filter (picker xcorr, upv_waveform.hpp) with a wavelet: a record
  /// (its first motion at its t = 0; read with the S record's column options) ...
  std::filesystem::path s_wavelet;
  /// ... or a Hann burst load: frequency [kHz], cycles; with s_wavelet_derivative its time
  /// derivative (the velocity a receiver records of a force load).
  std::vector<double> s_wavelet_burst;
  bool s_wavelet_derivative = false;
};

struct UpvReport {
  /// path_mm, t_p_us, t_s_us, density_kg_m3, v_p_m_s, v_s_m_s, nu_d (and its
  /// source), E_d_GPa, G_d_GPa, method, each pick's details and the remaining
  /// bias of its picker from the picker table (lab/picker_study.hpp), warnings.
  nlohmann::ordered_json summary;
  std::optional<TimeOfFlightPick> p_pick, s_pick;  ///< the picks on records, if any
  std::vector<std::string> warnings;               ///< the pickers'

  /// The picked records for upv_figure_script (pointing into this report).
  std::vector<PickedTrace> traces() const;
};

/// Validates the measurement (InputError naming the option, e.g. --t-p-us),
/// picks what is to be picked and evaluates Eqs. (8)-(10).
UpvReport upv_report(const UpvMeasurement& measurement);

}  // namespace mesowave::lab
