#pragma once
// mw-efg blast: the contact detonation of a plain concrete slab (efg/blast_slab, the shock paper's
// Section 4.3), its options in the units a user types (mm, us, MPa, GPa) and its outputs: the JSON
// summary (cracks, the compacted zone, the energies, the cost), the crack events as CSV (t, crack,
// from, to, speed), the energies over time as CSV, ParaView snapshots (nodes; crack faces as
// polylines; Gauss points with the volumetric strain and the compacted flag) and the figure of the
// crack pattern over the compacted zone (io/plot, gnuplot). Everything is staged through app::Run, so
// a bad value or a failed run writes nothing.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "mesowave/app/tool.hpp"
#include "mesowave/efg/blast_slab.hpp"
#include "mesowave/io/plot.hpp"

namespace mesowave::efg {

struct BlastCommandLine {
  double span_mm = 400, thickness_mm = 100, spacing_mm = 5, support_scale = 2.5;
  int gauss = 2;
  double E_GPa = 20, nu = 0.2, density_kg_m3 = 2400;
  std::string law = "exponential";
  double f_t_MPa = 2.4, G_f_N_m = 113, f_c_MPa = 0;  ///< f_c 0: unset (the bilinear law's beta_t = 0.25)
  double f_cm_MPa = 30.4, max_strain_rate_1_s = 100;
  std::string tensile_dif = "ceb-fip-1990";
  int strain_rate = 1;
  std::string project_fields = "none";  ///< none | u | u-v: projected onto the cut space at each crack change
  double crack_speed_limit_m_s = 500;  ///< 0: no limit (a contrast run)
  double segment_mm = 0, min_crack_spacing_mm = 0, min_crack_radius_mm = 0, penalty_factor = 1;
  HugoniotParameters hugoniot;
  int unloading = 1;
  double charge_width_mm = 30, charge_thickness_mm = 40, explosive_density_kg_m3 = 1630, detonation_velocity_m_s = 6930;
  double gamma = 3, fall_transits = 2, peak_MPa = 0;
  double duration_us = 100, dt_fraction = 0.9, dt_us = 0;
  double crushing_eps_v = 0;  ///< the crater's eps_crush (efg/crater.hpp); 0: the Y-function's minimum
  double viscosity_quadratic = 0, viscosity_linear = 0;  ///< C_0, C_1 of the shock viscosity (0, 0: off)
  std::int64_t sample_stride = 10, snapshot_stride = 0;
  std::filesystem::path cracks_csv, energy_csv, snapshots, plot, out;
  int threads = 0;
  /// The options in SI (InputError naming a value out of range: one line).
  BlastSlabOptions resolve() const;
};
void add_blast_options(CLI::App& app, BlastCommandLine& values);

struct BlastOutputs {
  nlohmann::ordered_json summary;
  std::vector<std::string> crack_header, energy_header;
  std::vector<std::vector<std::string>> crack_rows, energy_rows;
  io::PlotSpec figure;
};
BlastOutputs blast_outputs(const BlastSlabOptions& options, const BlastSlabResult& result);

/// The whole subcommand: resolve, run, stage every output named on the command line, print the
/// summary (with `threads`, the tool's thread choice).
void run_blast_command(const BlastCommandLine& command_line, app::Run& run, const nlohmann::ordered_json& threads);

}  // namespace mesowave::efg
