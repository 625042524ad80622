#pragma once
// What mw-signal writes, one builder per analysing subcommand: the burst
// (hann_burst.hpp) with its description, Hilbert envelopes (envelope.hpp),
// amplitude spectra (spectrum.hpp) and times of flight (time_of_flight.hpp),
// each with its JSON summary and the metrics of the run record. Requests hold
// the options as given (times in us, frequencies in kHz, as on the command line).
#include <cstdint>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "mesowave/signal/signal_csv.hpp"
#include "mesowave/prov/run_record.hpp"
#include "mesowave/signal/signal.hpp"

namespace mesowave::signal {

struct BurstRequest {
  double frequency_kHz = 0, cycles = 5, amplitude = 1, delay_us = 0, sampling_MHz = 10;
  std::optional<double> duration_us;  ///< default: up to the end of the burst
  double noise_rms = 0;               ///< white Gaussian noise added (synthetic test data)
  std::uint64_t seed = 1;
  std::string name = kExcitationName, quantity = "force", unit = "N";
  std::string output;  ///< the file it goes to, named in the summary
};

/// The signals an analysis reads: a file, only those named (all if none).
struct SignalSource {
  std::filesystem::path file;
  std::vector<std::string> names;
};
/// InputError for a missing name (signal::select_signals).
std::vector<Signal> read_source(const SignalSource& source);

/// What each report gives besides the summary.
struct SignalReport {
  std::vector<std::filesystem::path> inputs;     ///< the files read
  std::vector<Signal> signals;                   ///< to write: the burst, envelopes, converted signals
  std::map<std::string, std::string> attributes;  ///< of the written file
  nlohmann::ordered_json summary;
  std::vector<prov::MetricRecord> metrics;
  std::string csv;                                ///< spectra or picks table
  std::string text;                               ///< the picks as a text table
};

/// The burst; the summary: samples, dt, the burst's span and main lobe, the noise.
SignalReport burst_report(const BurstRequest& request);

/// `output` names the file the envelopes go to in the summary.
SignalReport envelope_report(const SignalSource& input, const std::string& output, const std::string& detrend,
                             const std::string& pad);

struct SpectrumRequest {
  std::string detrend = "none", pad = "none", scaling = "amplitude";
  std::optional<double> max_frequency_kHz;  ///< rows up to this only
};
/// InputError when the signals' frequency axes differ.
SignalReport spectrum_report(const SignalSource& input, const std::string& output, const SpectrumRequest& request);

struct TofRequest {
  std::string method = "aic";  ///< threshold | aic | envelope-peak
  std::optional<std::string> detrend;  ///< default none for aic, mean for envelope-peak
  std::string pad = "double";          ///< envelope-peak's FFT padding
  std::optional<double> begin_us, end_us, noise_begin_us, noise_end_us;
  double factor = 5, relative = 0;     ///< threshold: max(factor x noise RMS, relative x peak)
};
SignalReport tof_report(const SignalSource& input, const TofRequest& request);

/// The signals of every file in `inputs`, in order (CSV columns without a unit or
/// quantity take `defaults`'), only those named in `names` if any.
SignalReport convert_report(const std::vector<std::filesystem::path>& inputs, const std::vector<std::string>& names,
                            const signal::SignalCsvDefaults& defaults, const std::string& output);

}  // namespace mesowave::signal
