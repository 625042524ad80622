#pragma once
// Signals as CSV, for spreadsheets, oscilloscope exports and plotting
// (documented for users in docs/formats.md):
//
//   # mesowave signals (CSV): time in the first column, one column per signal, "name [unit]"
//   # signal B: quantity=acceleration; component=z; position_m=0.025 0 0.05
//   t_s,B [m/s^2],C [m/s^2]
//   0,0,0
//   1e-07,1.3e-05,-2.1e-06
//
// The time column is named t_s, t_ms, t_us or t_ns (also "t [us]", "time [s]");
// it must be uniformly sampled (each time within 0.1 dt of t0 + i dt, which
// allows for times printed with few digits). A column without "[unit]" has an
// empty unit unless the reader is given one. The "# signal" comment lines carry
// what the HDF5 layout holds besides the samples; a file without them reads too.
// All signals of one CSV share its time base: writing signals sampled
// differently is an InputError (write HDF5, or resample first).
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "mesowave/signal/signal.hpp"

namespace mesowave::signal {

struct SignalCsvDefaults {
  std::string unit;      ///< for columns without "[unit]"
  std::string quantity;  ///< for signals without a "# signal" line
};

std::string signals_to_csv(const std::vector<Signal>& signals,
                           const std::map<std::string, std::string>& file_attributes = {});
std::vector<Signal> parse_signal_csv(std::string_view text, const std::string& origin,
                                             const SignalCsvDefaults& defaults = {});
std::vector<Signal> read_signal_csv(const std::filesystem::path& path, const SignalCsvDefaults& defaults = {});

/// Signal files by their extension: .h5 / .hdf5 / .hdf (signal/signal_file.hpp) or .csv.
enum class SignalFormat { hdf5, csv };
/// InputError for any other extension.
SignalFormat signal_format_of(const std::filesystem::path& path);

/// Reads either kind, chosen by the extension of `path`.
std::vector<Signal> read_signals(const std::filesystem::path& path, const SignalCsvDefaults& defaults = {});

/// Writes `signals` as `format` to `path` (which may be a staged temporary
/// whose extension says nothing; name the format from the final path).
void write_signals(const std::filesystem::path& path, SignalFormat format, const std::vector<Signal>& signals,
                   const std::map<std::string, std::string>& file_attributes = {});

}  // namespace mesowave::signal
