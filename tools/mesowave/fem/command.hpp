#pragma once
// mw-fem's subcommands (rod, box, cylinder) as library calls (tools/cli/mw-fem.cpp is their
// narrative): the options a user types and the run they make, one of two:
//  - direct (case.hpp): one burst frequency (--frequency-kHz), --signals and the JSON report;
//  - superposed (--frequencies-kHz, superposition.hpp): every burst frequency from one
//    unit-impulse run of the mesh, --signals-pattern and --out-pattern files per frequency
//    whose layout and attributes are a direct run's but for method = superposition.
// Everything is staged through app::Run: a bad value or a failed run writes nothing.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "mesowave/app/tool.hpp"

namespace mesowave::fem {

struct FemCommandLine {
  double mesh_mm = 1, alpha = 0;
  // Unset: the experiment's (--experiment), else FemCase's defaults (100 kHz, 5 cycles, 1 N, 1.5 ms, 0.1 us, a point).
  std::optional<double> E_GPa, nu, rho, dt_us, f_kHz, cycles, force_N, duration_ms, sample_dt_us, patch_mm;
  int threads = 0;
  bool quiet = false;
  std::optional<std::string> quantity;
  std::vector<std::string> sensors;
  std::filesystem::path signals_path, out, experiment_path;
  std::vector<double> frequencies_kHz, check_kHz;
  std::string signals_pattern, out_pattern;
  // rod
  std::optional<double> radius_mm, length_mm;
  double st_step_mm = 0;
  std::string model_kind = "axisymmetric";
  std::filesystem::path spacetime_path;
  // box
  std::string size_text, source_text;
};

/// The options every subcommand takes (the material, mesh, burst, record, sensors, outputs).
void add_common_options(CLI::App& sub, FemCommandLine& values);
/// rod's own options (its size, the ring or 3D model, the space-time record).
void add_rod_options(CLI::App& rod, FemCommandLine& values);
/// box's own options (its size and the source point).
void add_box_options(CLI::App& box, FemCommandLine& values);

enum class FemBody { rod, box, cylinder };
/// The run of subcommand `body`: the case from the options (and --experiment), the direct or
/// superposed run, its files, metrics and the JSON report.
void run_fem_command(const FemCommandLine& values, FemBody body, app::Run& run);

}  // namespace mesowave::fem
