#pragma once
// What mw-efg bending writes for a three-point bending run (efg/three_point_bending.hpp): the JSON
// summary (peak, work of fracture against G_f times the ligament area - the identity every cohesive
// model must satisfy -, the elastic stiffness beside its references, the cost), the load-deflection
// table and plot, the crack path, and the crack's growth as ParaView files.
#include <nlohmann/json.hpp>
#include <map>
#include <string>
#include <vector>

#include "mesowave/efg/bending_reference.hpp"
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
  /// Per curve point: the crack as the run had it (the notch and the grown part up to the tip).
  std::vector<std::pair<double, CrackSnapshot>> crack_steps;  ///< (deflection [mm], crack)
};

/// The cohesive law's own keys from KEY=VALUE texts (mw-efg --law-key alpha=2); the law checks
/// names and ranges. InputError for a text without '=' or a value that is not a number.
std::map<std::string, double> parse_law_keys(const std::vector<std::string>& texts);

/// `reference` may be null (no FEM run asked for).
BendingOutputs three_point_bending_outputs(const ThreePointBendingOptions& options, const ThreePointBendingResult& result,
                                           const BendingReference* reference);

}  // namespace mesowave::efg
