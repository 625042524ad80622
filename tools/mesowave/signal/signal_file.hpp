#pragma once
// Signal files (HDF5), the layout every tool that writes or reads signals uses
// (documented for users in docs/formats.md):
//
//   /                      attributes: format = "mesowave-signals", format_version = 1
//   /signals/<name>/       one group per signal, in the order written
//       samples            float64 [n]
//       attributes: t0_s, dt_s (float64), quantity, unit, component (string),
//                   position_m (float64[3], optional)
//
// h5py:   f["signals/B/samples"][:],  f["signals/B"].attrs["dt_s"]
// MATLAB: h5read(file, "/signals/B/samples"), h5readatt(file, "/signals/B", "dt_s")
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "mesowave/signal/signal.hpp"

namespace mesowave::signal {

/// Writes `signals` to `path` (truncating). `file_attributes` become string
/// attributes of the root (e.g. the scene, the model that ran).
void write_signal_file(const std::filesystem::path& path, const std::vector<Signal>& signals,
                       const std::map<std::string, std::string>& file_attributes = {});

/// Reads every signal, in the order written. InputError for a file that is
/// not a mesowave signal file, or a signal without its attributes.
std::vector<Signal> read_signal_file(const std::filesystem::path& path);

}  // namespace mesowave::signal
