#pragma once
// What mw-efg bending writes for a three-point bending run (efg/three_point_bending.hpp): the JSON
// summary (peak, work of fracture against G_f times the ligament area - the identity every cohesive
// model must satisfy -, the elastic stiffness beside its references, the cost), the load-deflection
// table and plot, the crack path, and the crack's growth as ParaView files.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <map>
#include <string>
#include <vector>

#include "mesowave/efg/bending_reference.hpp"
#include "mesowave/efg/cohesive_law.hpp"
#include "mesowave/efg/three_point_bending.hpp"
#include "mesowave/efg/vtk_output.hpp"
#include "mesowave/io/plot.hpp"

namespace mesowave::efg {

struct BendingOutputs {
  nlohmann::ordered_json summary;
  std::vector<std::string> curve_header;  ///< deflection_mm, load_N, iterations, crack_tip_mm, dissipated_Nmm
  std::vector<std::vector<std::string>> curve_rows;
  std::vector<std::string> crack_header;  ///< x_mm, y_mm
  std::vector<std::vector<std::string>> crack_rows;
  io::PlotSpec plot;                      ///< load [kN] against deflection [mm]
  /// Per curve point, when the run kept snapshots: the crack as the run had it (ThreePointBendingResult::crack_steps).
  std::vector<std::pair<double, CrackSnapshot>> crack_steps;  ///< (deflection [mm], crack)
};

/// mw-efg bending's options in the lab-data file's units (lab-data/shock-concrete/three-point-bending.toml:
/// E_GPa, f_t_MPa, G_f_N_m, span_mm, ...; `--from` fills them), added to a CLI11 (sub)command like
/// dem::add_override_options, and the SI options they give.
struct BendingCommandLine {
  ThreePointBendingOptions options;  ///< nu, G_f, law, gauss, support_scale, steps are bound directly
  double E_GPa = 20, f_t_MPa = 2.4, span_mm = 450, depth_mm = 100, notch_mm = 50, thickness_mm = 100;
  double spacing_mm = 5, load_width_mm = 10, max_deflection_mm = 1.0;
  double notch_x_mm = 0, f_c_MPa = 0;  ///< taken only when given (notch_x_option, f_c_option)
  const CLI::Option* notch_x_option = nullptr;
  const CLI::Option* f_c_option = nullptr;
  /// One option per key the law registry declares (cohesive_laws(): --alpha, --alpha-t), so that a lab-data file
  /// fills them as it fills --f-t-MPa; a key not given is left to the law's fallback (the one place it lives).
  std::map<std::string, double> law_key_values;
  std::map<std::string, const CLI::Option*> law_key_options;
  std::string crack_weight = "visibility";
  int fem_refinement = 2;              ///< 0: no FEM reference
  /// The options in SI, validated (InputError naming the value).
  ThreePointBendingOptions resolve() const;
};
void add_bending_options(CLI::App& app, BendingCommandLine& values);

/// The option a law key is given by: the key, its unit appended unless it is "1" or the key ends in it,
/// '_' as '-' (alpha_t -> alpha-t): the name a lab-data entry [alpha_t] fills (docs/formats.md, --from).
std::string law_key_option_name(const CohesiveKeySpec& key);

/// `reference` may be null (no FEM run asked for).
BendingOutputs three_point_bending_outputs(const ThreePointBendingOptions& options, const ThreePointBendingResult& result,
                                           const BendingReference* reference);

}  // namespace mesowave::efg
