#pragma once
// A uniformly sampled signal with what it measures: the unit of exchange
// between the solvers (DEM, FEM sensors), the signal tools and the files.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace mesowave::signal {

struct Signal {
  std::string name;       ///< sensor or channel name ("B", "excitation", "P-wave")
  std::string quantity;   ///< acceleration | velocity | displacement | force | strain | voltage | ...
  std::string unit;       ///< SI unit of the samples ("m/s^2", "N", "V")
  std::string component;  ///< x | y | z | normal | magnitude | "" (scalar channel)
  double t0_s = 0;        ///< time of the first sample
  double dt_s = 0;        ///< sampling interval (> 0)
  std::vector<double> samples;
  std::optional<std::array<double, 3>> position_m;  ///< where it was recorded, if known

  std::size_t size() const { return samples.size(); }
  double time(std::size_t i) const { return t0_s + double(i) * dt_s; }
  double duration_s() const { return double(samples.size()) * dt_s; }
};

/// The name of the record of the load itself (the actuator's force history) that
/// a solver writes beside its sensors: a record of the input, not a measurement,
/// so comparisons sensor by sensor leave it out unless it is named.
inline constexpr const char* kExcitationName = "excitation";

}  // namespace mesowave::signal
