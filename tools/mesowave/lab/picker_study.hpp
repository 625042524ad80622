#pragma once
// How far the UPV pickers land from the true onset on records as instruments
// give them (issue 19, item 1): a resonant transducer response that rises over
// 1-2 periods, a P precursor on the shear channel, noise at 20-40 dB
// (lab/transducer_record.hpp). The study runs mw-upv's own chain
// (lab::pick_onset with mw-upv's defaults) on a grid of synthetic P/S record
// pairs and reports, per picker and SNR, the median and the MAD of
// error = pick - true onset, in periods of the transducer frequency (the
// pickers' errors scale with the period; a table in periods holds for any f).
//
// Geometry: t_p = 35 us and t_s = 55.1 us, the paper's 150 mm cube
// (Section 3.2, lab-data/concrete-cube/upv.toml): the S wave arrives 20 us
// after the P wave, less than one period of a 30-60 kHz transducer, so on the
// shear channel the S onset lies under the still rising P precursor.
//
// Strategies (one entry each in picker_strategies(), looked up by arrival and name):
//   P threshold | aic | envelope-peak   on the P channel, mw-upv's P chain;
//   P aic-window-30us                   aic with --aic-after-us 30 (its arrival check and
//                                       AIC window about one period long);
//   S threshold | aic | envelope-peak   the same chain on the S channel, knowing
//                                       nothing of the P wave: they find the precursor;
//   S aic-after-p                       mw-upv's S chain: t_p picked (AIC) on the P
//                                       channel, then AIC on the S channel in a window
//                                       from 1.3 t_p to the envelope peak in 1.3 .. 3.5 t_p
//                                       (lab::shear_wave_options);
//   S envelope-peak-after-p             that window's envelope peak (the group arrival);
//   S envelope-aic-after-p              AIC on the Hilbert envelope in that window: the
//                                       envelope's second rise, where the S energy adds
//                                       to the precursor's.
//   S xcorr-after-p                     the matched filter (picker xcorr, upv_waveform.hpp) in
//                                       mw-upv's S window, the wavelet the noiseless transducer
//                                       response (what a face-to-face record of the pair gives):
//                                       mw-upv --s-wavelet.
//
// Slow rise (TransducerRecordSpec::slow_rise_fraction): the S channel's records are also made
// with a low-frequency lobe under the S onset at each of slow_rise_fraction (the DEM's S
// records carry one). The pooled and by-fraction rows are over the records without it (0),
// as the table was before it existed; by_slow_rise holds the S strategies per slow rise.
//
// measured_picker_bias() is the table docs/upv-pickers.md prints, as
// `mw-pickers study` computed it with the default grid; a test recomputes it.
// mw-upv states the row of the picker it used (state_pick_bias).
#include <cstddef>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "mesowave/lab/upv_waveform.hpp"
#include "mesowave/signal/signal.hpp"

namespace mesowave::lab {

struct PickerStudyGrid {
  std::vector<double> frequency_Hz{30e3, 45e3, 60e3};
  std::vector<double> rise_periods{1.0, 1.5, 2.0};
  std::vector<double> precursor_fraction{0.1, 0.3, 0.5};
  /// 20-40 dB as issue 19 asks, and 60 dB: real records are often cleaner
  /// (peak over pre-trigger RMS: 80 dB on TU Graz's cement paste).
  std::vector<double> snr_dB{20, 30, 40, 60};
  /// Slow rise under the S onset, peak / S peak (lab/transducer_record.hpp); must hold 0 (the
  /// pooled rows). 0.1: above the DEM records' 0.06-0.07 (docs/upv-pickers.md).
  std::vector<double> slow_rise_fraction{0, 0.1};
  std::size_t seeds = 30;     ///< noise realisations per grid point (1 .. 999)
  double t_p_s = 35e-6;       ///< paper Section 3.2
  double t_s_s = 55.1e-6;     ///< paper Section 3.2
};

/// One record pair of the study: the P channel (P arrival only) and the S
/// channel (S arrival with the P precursor), same transducer response.
struct UpvRecordPair {
  signal::Signal p_channel, s_channel;
  /// The S channel's transducer response alone, noiseless, from its first motion (t0 = 0) over
  /// 4 rise times + 1 period: the wavelet of the matched filter (a face-to-face record).
  signal::Signal s_wavelet;
  double t_p_s = 0, t_s_s = 0;  ///< the true onsets
};

/// Seeds: P channel 2 seed - 1, S channel 2 seed (independent noise); the
/// study's seed is a function of the grid point's values and the realisation.
UpvRecordPair study_record_pair(const PickerStudyGrid& grid, double frequency_Hz, double rise_periods,
                                double precursor_fraction, double snr_dB, std::uint64_t seed,
                                double slow_rise_fraction = 0);

struct PickerStrategy {
  std::string arrival;      ///< "P" | "S"
  std::string name;         ///< "aic", "aic-after-p", ...
  std::string description;
  /// The picked onset (record time); InputError where mw-upv's chain refuses the record.
  std::function<Onset(const UpvRecordPair&)> pick;
};
const std::vector<PickerStrategy>& picker_strategies();

/// Statistics of error = pick - true onset over a set of records, in periods.
struct PickerBiasRow {
  std::string arrival, picker;
  double snr_dB = 0;
  double frequency_Hz = 0, rise_periods = 0, precursor_fraction = 0;  ///< 0 in pooled rows
  std::size_t records = 0, refused = 0, flagged = 0;  ///< flagged: picked with a warning
  double median_periods = 0;   ///< median error
  double mad_periods = 0;      ///< median |error - median error| (unscaled)
  double p90_abs_periods = 0;  ///< 90th percentile of |error|
  /// The same over the picks mw-upv made without a warning (what a user
  /// with an unflagged pick can expect); 0 where every pick was flagged.
  double unflagged_median_periods = 0, unflagged_mad_periods = 0, unflagged_p90_abs_periods = 0;
  std::string first_refusal;   ///< why the first refused record was refused
  double slow_rise_fraction = 0;  ///< the S channel's slow rise (0: none, and in pooled rows)
};

/// Whether mw-upv warned about the pick (the envelope peak's standing note
/// that it is the group arrival does not count).
bool is_flagged(const Onset& onset);

struct PickerStudy {
  std::vector<PickerBiasRow> pooled;  ///< per strategy and SNR, over frequency, rise and precursor
  std::vector<PickerBiasRow> by_fraction;  ///< per strategy, SNR and precursor fraction, over frequency and rise
  std::vector<PickerBiasRow> by_slow_rise;  ///< S strategies per SNR and slow rise, over frequency, rise and precursor
  std::vector<PickerBiasRow> cells;   ///< per strategy and grid point (P strategies at slow rise 0 only)
};

/// Runs every strategy on every record of the grid (deterministic: the same
/// numbers for any thread count).
PickerStudy run_picker_study(const PickerStudyGrid& grid);

/// The DEM's UPV geometry without its lattice (lab/transducer_record.hpp, point_force_record):
/// a 162 kHz axial P record and a 120 kHz transverse S record, two cycles each, 50 mm from a
/// point force, with the continuum speeds of both calibrations (static: E 27.413 GPa, nu 0.16001;
/// dynamic: E 36.671 GPa, nu 0.1618; rho 2129.56 kg/m3), `seeds` noise realisations per SNR and
/// speed pair. Every S strategy (the S wavelet: the load's time derivative, mw-upv
/// --s-wavelet-burst-kHz 120,2 --s-wavelet-derivative); errors in periods of 120 kHz, pooled over
/// the two speed pairs (frequency_Hz = 120e3 in the rows).
std::vector<PickerBiasRow> run_point_force_study(const std::vector<double>& snr_dB, std::size_t seeds);

/// The pair of run_point_force_study for one speed pair (0 static, 1 dynamic), SNR and seed.
UpvRecordPair point_force_pair(int calibration, double snr_dB, std::uint64_t seed);

/// Rows as a Markdown table: arrival, picker, SNR (and the precursor fraction
/// where the rows have one), records, refused, flagged, median, MAD, p90.
std::string picker_bias_markdown(const std::vector<PickerBiasRow>& pooled);
/// Every row as CSV (pooled rows have frequency, rise and fraction 0).
std::string picker_bias_csv(const std::vector<PickerBiasRow>& rows);

/// Rows as C++ aggregate initialisers, one a line, full precision (%.17g):
/// what measured_picker_bias() is compiled from.
std::string picker_bias_cpp(const std::vector<PickerBiasRow>& rows);

/// The pooled table of the default grid, as docs/upv-pickers.md prints it.
const std::vector<PickerBiasRow>& measured_picker_bias();

/// gnuplot script: one record pair (P channel above, S channel below,
/// normalised) with the true onsets (solid) and every strategy's pick on it
/// (dashed; refused ones left out), the figure of docs/upv-pickers.md.
std::string picker_example_figure_script(const UpvRecordPair& pair, const std::filesystem::path& png,
                                         const std::string& title);

/// What mw-upv says about the pick it made.
struct StatedBias {
  bool measured = false;       ///< false: this strategy is not in the table
  std::string strategy;        ///< "P aic", "S aic-after-p"
  double snr_dB = 0;           ///< the record's, as the table defines it
  bool unflagged = false;      ///< the pick carries no warning: the unflagged statistics are stated
  double median_periods = 0, mad_periods = 0;  ///< interpolated in SNR (clamped to the table's range)
  bool outside_grid = false;   ///< the record's SNR lies outside the table's
  double frequency_Hz = 0;     ///< the record's, from the spectrum after the pick
  double median_s = 0, mad_s = 0;
  std::string source;
};

/// The table's row for `arrival` + `strategy` at the record's SNR (its
/// unflagged statistics if the pick carries no warning), in seconds
/// with the frequency read off the record's spectrum over 200 us after the pick.
StatedBias state_pick_bias(const signal::Signal& record, const Onset& onset, const std::string& arrival,
                           const std::string& strategy);

/// JSON keys prefixed `key`: _pick_bias_us, _pick_bias_mad_us, _pick_bias_periods,
/// _pick_snr_dB, _pick_frequency_kHz, _pick_bias_source (or _pick_bias "not measured").
void describe_bias(nlohmann::ordered_json& json, const std::string& key, const StatedBias& bias);

}  // namespace mesowave::lab
