#pragma once
// What mw-pcc writes: the sensor-by-sensor Pearson correlation table of two sets
// of signals (concrete paper Table 3) as text, CSV and JSON, the amplitude
// spectra of both sets (Fig. 15) and the sensor-panel figures (Figs. 12-15).
// The request holds the options as given; pcc_report reads both sets
// (signal::read_signals), checks the options, correlates and reports.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "mesowave/io/sensor_panels.hpp"
#include "mesowave/prov/run_record.hpp"
#include "mesowave/signal/correlation.hpp"

namespace mesowave::signal {

struct PccRequest {
  std::vector<std::filesystem::path> files;   ///< two files, or
  std::vector<std::filesystem::path> a, b;    ///< each set as one or more files
  std::vector<std::string> sensors;           ///< "" for every shared name
  std::optional<std::string> resampling;      ///< linear | cubic; none: the time bases must agree
  std::optional<double> begin_us, end_us;     ///< the compared window
  std::string detrend = "none", pad = "none";  ///< the envelopes' (and spectra's)
  bool spectra = false;                        ///< the spectra table
  std::optional<double> max_frequency_kHz;     ///< of the spectra table and figure
  bool plot_signals = false, plot_envelopes = false, plot_spectra = false;
  std::vector<std::filesystem::path> plots;    ///< every figure file named (their extensions are checked first)
  std::vector<double> plot_window_us;          ///< from,to of the signal and envelope figures; empty: all
  std::vector<std::string> labels = {"a", "b"};  ///< legend names of the two sets
  std::string title;                           ///< "" for the two sets' files
  /// Also each sensor's arrival in both sets and their peaks (the speed-against-error study's other
  /// error measures beside the PCC): the arrival is the first crossing of this fraction of the
  /// record's peak |x - x_0| (x_0 the mean of its first two samples: a simulated record starts at rest; a lab
  /// record's onset wants mw-upv's pickers), refined linearly between samples (signal::threshold_pick);
  /// the peak is the largest |x| in the compared window. Unset: neither is computed.
  std::optional<double> arrival_relative;
};

struct PccReport {
  std::vector<std::filesystem::path> inputs;
  CorrelationTable table;
  std::vector<prov::MetricRecord> metrics;  ///< pcc_<sensor>, pcc_envelope_<sensor>, the means
  std::string text;                          ///< the table as printed, the resampling and what was not compared
  std::string csv;                           ///< sensor, pcc_signal, pcc_envelope, samples, from_us, to_us; 'mean'
                                             ///< (and arrival_a_us, arrival_b_us, arrival_shift_us, peak_ratio)
  std::string spectra_csv;                   ///< f_kHz, '<sensor> a [unit]', '<sensor> b [unit]' (if asked)
  std::optional<io::SensorPanelsFigure> signals, envelopes, spectra;  ///< the figures asked for
  nlohmann::ordered_json summary;
};

PccReport pcc_report(const PccRequest& request);

}  // namespace mesowave::signal
