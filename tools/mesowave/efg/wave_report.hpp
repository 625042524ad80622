#pragma once
// What mw-efg wave reads and writes (efg/wave_strip): the options in the units a user types (mm, us,
// MPa, GPa), the JSON summary (steps, dt against the stable step, energy drift, the peak's travel
// speed against c_p, the stencil's dispersion, the cost), the sensors' histories as CSV and the node
// snapshots for ParaView. The law is one of efg/strip_law's registry (--law); for a stiffening law
// under the triangular pulse the summary compares the front with the method of characteristics
// (efg/shock_front), and --profiles writes -sigma_xx along the centre line at chosen times.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>
#include <vector>

#include "mesowave/efg/shock_front.hpp"
#include "mesowave/efg/strip_law.hpp"
#include "mesowave/efg/wave_fem_reference.hpp"
#include "mesowave/efg/wave_strip.hpp"

namespace mesowave::efg {

struct WaveCommandLine {
  double length_mm = 500, width_mm = 40, spacing_mm = 5, thickness_mm = 1000;
  double E_GPa = 30, nu = 0.2, density_kg_m3 = 2400;
  std::string pulse = "triangular", basis = "linear", weight = "quartic-spline";
  double peak_MPa = 100, rise_us = 10, fall_us = 10, start_us = 0, positive_us = 20, decay = 1;
  double duration_us = 0, dt_us = 0, dt_fraction = 0.9, alpha_per_s = 0;
  double viscosity_quadratic = 0, viscosity_linear = 0;  ///< C_0, C_1 of the shock viscosity (0, 0: off)
  double support_scale = 2.5;
  int gauss = 2, stiffness_check_every = 10;
  std::int64_t sample_stride = 1, snapshot_stride = 0;
  bool free_sides = false;
  std::vector<double> sensor_mm;
  std::string law = "linear";
  StripLawParameters law_parameters;  ///< --beta; --e-v-th, --e-v, --a-v, --b-v, --unloading (1 | 0)
  int unloading = 1;
  std::vector<double> profile_us;     ///< --profile-us: the times of --profiles
  double frequency_kHz = 20, cycles = 3;  ///< --pulse hann
  bool fem_reference = false;         ///< --fem-reference: mw-fem's bar beside the run (--pulse hann)
  std::filesystem::path history, snapshots, profiles, fronts, out;
  int threads = 0;
  /// The options in SI (InputError naming a value that is out of range).
  WaveStripOptions resolve() const;
};
/// The options, --history, --snapshots and --threads on `app` (the tool adds --out) (mw-efg's `wave` subcommand).
void add_wave_options(CLI::App& app, WaveCommandLine& values);

struct WaveOutputs {
  nlohmann::ordered_json summary;
  std::vector<std::tuple<std::string, double, std::string>> metrics;  ///< (name, value, unit)
  std::vector<std::string> history_header;  ///< t_us, then per sensor sigma_xx_MPa, sigma_yy_MPa, v_x_m_s, v_y_m_s
  std::vector<std::vector<std::string>> history_rows;
  std::vector<std::string> profile_header;  ///< x_mm, then p_MPa_at_<T>us (p = -sigma_xx) per --profile-us
  std::vector<std::vector<std::string>> profile_rows;
  std::vector<std::string> front_header;  ///< sensor, x_mm, width_us, simple_wave_width_us, before_breaking (a stiffening law)
  std::vector<std::vector<std::string>> front_rows;
};
/// `law`: the run's (null: the linear law, no characteristics); `profile_s`: the times of the
/// profiles (each taken from the snapshot nearest it).
/// `fem`: mw-fem's bar (--fem-reference), its v_x beside each sensor's history.
WaveOutputs wave_strip_outputs(const WaveStripOptions& options, const WaveStripResult& result,
                               const StripLaw* law = nullptr, const std::vector<double>& profile_s = {},
                               const FemBarReference* fem = nullptr);

/// What `mw-efg wave` runs: the options resolved, the law made from the registry, the strip run.
struct WaveCommandRun {
  WaveStripOptions options;
  StripLaw law;
  WaveStripResult result;
  std::optional<FemBarReference> fem;
  WaveOutputs outputs;
};
WaveCommandRun run_wave_command(const WaveCommandLine& command_line);

}  // namespace mesowave::efg
