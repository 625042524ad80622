#pragma once
// Flowchart step 3 from the pulse analyser's waveforms (concrete paper,
// Section 3.2, Fig. 7): the time of flight of the P and S waves picked on the
// recorded signals with the signal library's pickers, before Eqs. (8)-(10).
//
// Records (docs/formats.md, "Lab raw data"):
//  - CSV as instruments export it: a time column and an amplitude column. With
//    a header, the time unit is the name's suffix (t_us, time_s); without one
//    (--no-header), columns are chosen by 1-based index and the time unit is
//    stated. Time 0 is the trigger; samples before it are the pre-trigger.
//  - WAV (PCM 16 bit or float 32, mono): samples as they are; the sample
//    interval and the trigger sample must be stated when the header's rate is
//    nominal (audio exports of ultrasonic records often are).
//
// Onset picking (pick_onset):
//  1. noise window: the pre-trigger (t < 0), or a stated window;
//  2. a stationarity check of that window - an onset inside the pre-trigger
//     (a late trigger) shows as unequal noise in its first and last quarters,
//     and is refused rather than picked;
//  3. search window: after the noise window and after the electrical
//     cross-talk window that follows the trigger;
//  4. the arrival is located: by default the first crossing of a threshold,
//     the larger of factor x noise RMS and a fraction of the window's peak (so
//     that small wiggles before a weak arrival do not count); or the envelope
//     peak (the S wave in a shear-transducer record, which also carries the P
//     wave's energy). If the record is above the threshold, or its envelope
//     largest, at the very start of the search window, the onset lies before
//     it and is refused;
//  5. the chosen picker: threshold (the crossing), aic (Maeda's AIC on the
//     window from the search start to the crossing + aic_after, or to the
//     envelope peak: the onset where the variance changes; refused if it falls
//     on the window's start), envelope-peak (the group arrival: later than
//     the onset, said so), or xcorr (the matched filter below).
//
// The matched filter (picker xcorr; docs/upv-pickers.md, "The DEM's S records"). The record
// is compared with a known wavelet w (its first motion at its t = 0: a face-to-face record
// of the transducer pair, or a model's load as its receiver records it) at every lag L of
// the window from the search start to the located arrival (the envelope peak less half the
// wavelet's own onset-to-envelope-peak delay d_w: the onset precedes the record's envelope peak by
// about d_w, and a lag a period later would match a smeared burst's longer cycles):
//   c(L) = sum_k (x(L + k dt) - noise mean) w(k dt),
// and the onset is the lag of the largest local maximum of c, refined by a parabola through its neighbours
// (the lag at which the wavelet's first motion best explains the record). It weighs the whole
// burst, so a slow rise under the first half-cycle, which AIC takes for noise and splits at the
// first large half-cycle, moves it only by its correlation with w. Quality: xcorr_coefficient,
// c over the norms of w and of the record's samples it covers (1: the record is the wavelet).
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "mesowave/signal/signal.hpp"
#include "mesowave/signal/time_of_flight.hpp"

namespace mesowave::lab {

struct WaveformReadOptions {
  std::string time_column;        ///< name, or 1-based index with no_header; default: first t_* / time* column
  std::string amplitude_column;   ///< name or 1-based index; default: the first column after the time column
  bool no_header = false;
  std::string time_unit;          ///< s, ms or us; for headerless CSV (default s)
  std::optional<double> sample_interval_s;  ///< WAV: overrides the header's rate
  std::optional<long> trigger_sample;       ///< WAV: 0-based sample at t = 0 (default 0)
  /// Noise added to the record before picking (signal::with_noise_at_snr), as a lab's record
  /// has it: a model's noise-free record then goes through the lab's exact chain (docs/cube-150.md).
  std::optional<double> added_noise_snr_dB;
  std::uint64_t added_noise_seed = 1;       ///< the S record's noise is drawn with seed + 1 (upv_report)
};

/// The record as a signal (t0_s = time of its first sample, uniform dt_s).
/// InputError for non-monotonic or non-uniform time columns (more than 1 % of
/// dt), unreadable fields, or fewer than 8 samples.
signal::Signal read_upv_waveform(const std::filesystem::path& path, const WaveformReadOptions& options,
                                 const std::string& name);

struct OnsetOptions {
  std::string picker = "aic";     ///< threshold | aic | envelope-peak | xcorr (needs `wavelet`)
  std::string locator = "threshold";  ///< threshold | envelope-peak: what finds the arrival the AIC window ends at
  double threshold_factor = 5;
  double threshold_relative = 0.2;    ///< ... or this fraction of the window's peak, whichever is larger
  double crosstalk_s = 0;         ///< after the trigger: excluded from the search
  std::optional<double> noise_begin_s, noise_end_s;  ///< default: the pre-trigger
  bool check_quiet_noise = true;  ///< refuse a noise window whose quarters differ (an onset inside it);
                                  ///< off for the P coda that precedes an S onset, which decays by nature
  std::optional<double> search_begin_s, search_end_s;
  double aic_after_s = 10e-6;     ///< AIC window reaches this far past the threshold pick
  double lowpass_Hz = 0;          ///< zero-phase low-pass before picking (0: none), see lowpass()
  double min_arrival_snr = 3;     ///< RMS over aic_after from the located arrival / noise RMS, at least
  double min_contrast = 2;        ///< AIC onset: RMS over aic_after after it / before it; less is warned
  /// xcorr: the wavelet (its t0_s is ignored: its first sample is its first motion); resampled
  /// onto the record's interval by linear interpolation where the two differ.
  std::optional<signal::Signal> wavelet;
  double min_xcorr_coefficient = 0.5;  ///< xcorr: a smaller coefficient at the pick is warned
};

/// The wavelet of a Hann-windowed burst load (signal/hann_burst.hpp: f(t) = sin(w t) 0.5 (1 -
/// cos(w t / n)), w = 2 pi f, n cycles) sampled at `dt_s` from its start: the far-field
/// displacement of a force load has the load's shape (Aki & Richards Eq. 4.23, the 1/r terms),
/// its velocity the load's time derivative (`derivative`: f'(t) = w cos(w t) 0.5 (1 - cos(w t / n))
/// + sin(w t) 0.5 (w / n) sin(w t / n)). InputError for a non-positive frequency, cycle count or interval.
signal::Signal burst_wavelet(double frequency_Hz, double cycles, bool derivative, double dt_s);

/// Zero-phase low-pass (FFT, record padded to twice its length, mean of the
/// noise window removed first): gain 1 below `corner`, a raised-cosine taper to
/// 0 at 2 x corner. White noise above the pulse's band is what hides the first
/// half-cycle of an onset; removing it sharpens the picks. Zero phase moves no
/// arrival; its symmetric smear is about 1/(4 corner).
signal::Signal lowpass(const signal::Signal& record, double corner_Hz);

struct Onset {
  signal::Pick pick;              ///< the chosen picker's
  signal::Pick locator;           ///< the locating pick (threshold crossing or envelope peak)
  double search_begin_s = 0, search_end_s = 0;
  double contrast = 0;            ///< AIC onset: RMS after / RMS before (0 if not computed)
  double snr_dB = 0;              ///< 20 log10(max |x - noise mean| in the search window / noise RMS)
  std::vector<std::string> warnings;
};

Onset pick_onset(const signal::Signal& record, const OnsetOptions& options);

/// The S-wave search once the P arrival (record time, `p_arrival_s`) is known:
/// between 1.3 t_p (nu > 0) and 3.5 t_p (nu < 0.45) after the delay, located by
/// the envelope peak - shear transducers also receive the P wave, whose coda
/// would trip a threshold. Explicit search windows in `base` are kept.
OnsetOptions shear_wave_options(OnsetOptions base, double p_arrival_s, double delay_s);

/// A time of flight from a recorded waveform.
struct TimeOfFlightPick {
  signal::Signal record;
  Onset onset;
  double delay_s = 0;
  double tof_s = 0;                 ///< onset - delay
  double added_noise_rms = 0;       ///< of the noise added before picking (0: none), in the record's unit
};

/// Reads `path` (adding the stated noise, if any), picks the onset and subtracts the delay.
/// InputError if the onset does not come after the delay.
TimeOfFlightPick pick_time_of_flight(const std::filesystem::path& path, const WaveformReadOptions& read,
                                     const OnsetOptions& options, double delay_s, const std::string& name);

/// The pick's details as JSON keys prefixed `key` (t_p_pick_us, t_p_picker, ...).
void describe_pick(nlohmann::ordered_json& json, const std::string& key, const TimeOfFlightPick& pick);

}  // namespace mesowave::lab

namespace mesowave::lab {

struct PickedTrace {
  const signal::Signal* record = nullptr;
  Onset onset;
  double delay_s = 0;
  std::string label;   ///< "P wave"
  std::string symbol;  ///< "t_p"
  std::string colour;  ///< gnuplot colour, "#1f4e9c"
};

/// gnuplot script for a figure like the paper's Fig. 7: the records
/// (normalised, one below the other) with the picked onsets marked and the
/// times of flight written beside them.
std::string upv_figure_script(const std::vector<PickedTrace>& traces, const std::filesystem::path& png,
                              const std::string& title);

}  // namespace mesowave::lab
