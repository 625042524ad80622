#pragma once
// The elastic validation of the EFG solver (issue 15, Must show 2 and 4): Timoshenko & Goodier's
// cantilever (efg/beam_theory.hpp) solved by the EFG - regular nodes on the background cells, MLS
// Eqs. (1)-(12), the weak form Eq. (18) - and by the Q4 FEM (fem/plane_static.hpp) on the same
// cells, each with its errors against the closed form and its cost. The clamped edge x = 0 holds the
// closed form's displacements (both components; chord_vertical clamp): the FEM at its nodes, the EFG
// weakly along the edge (EdgeConstraint, efg/constraints.hpp - collocation at the edge's nodes fails
// the patch test and costs the EFG its orders: displacement 1.7 and energy 0.96 instead of 2.05 and
// 1.0 between 64 x 16 and 128 x 32 cells); the end x = L carries the parabolic shear. Both methods' errors are integrated by the same rule over the same
// cells (efg::cantilever_errors), so the two are compared on one measure.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "mesowave/efg/beam_theory.hpp"
#include "mesowave/efg/mls.hpp"
#include "mesowave/efg/vtk_output.hpp"

namespace mesowave::efg {

struct CantileverOptions {
  int cells_x = 24, cells_y = 6;  ///< background cells = Q4 elements; nodes (cells_x + 1)(cells_y + 1)
  int gauss = 2;                  ///< EFG Gauss points per cell direction (the paper's 2 x 2)
  MlsOptions mls;                 ///< basis and weight
  double support_scale = 2.5;     ///< h_i = scale x the nodal spacing (used when support_count = 0)
  int support_count = 0;          ///< > 0: h_i = support_factor x the distance to the count-th nearest node
  double support_factor = 1.2;
  int error_gauss = 4;            ///< points per cell direction of the error integration
  bool collocated_clamp = false;  ///< EFG: true holds u at the clamp's nodes (kept to show why not)
};

struct CantileverRun {
  std::string method;             ///< "EFG" | "Q4 FEM"
  std::size_t nodes = 0, gauss_points = 0, dofs = 0;
  double spacing_m = 0;
  CantileverErrors errors;
  double tip_deflection_m = 0, exact_tip_deflection_m = 0;
  double max_condition_number = 0;  ///< EFG: the largest of the moment matrices A at the Gauss points
  double setup_s = 0;               ///< EFG: discretisation, supports and shape functions; FEM: mesh
  double assembly_s = 0, solve_s = 0, wall_s = 0;
  std::size_t stiffness_nonzeros = 0, factor_nonzeros = 0;
  /// The stiffness and its factor (value + index per nonzero) and, for the EFG, the cached shape
  /// functions (3 values + an index per node of each Gauss point): the memory the method needs.
  double memory_estimate_MiB = 0;
  std::string solver;
  double clamp_reaction_N[2] = {0, 0};  ///< sum of the clamp's reactions (x, y)
  double applied_N[2] = {0, 0};         ///< resultant of the consistent end load
  NodeSnapshot snapshot;            ///< u^h and the stress at the nodes (for ParaView)
};

/// InputError for a bad beam or options (counts < 1, a support the MLS refuses, naming the point).
CantileverRun run_efg_cantilever(const CantileverBeam& beam, const CantileverOptions& options);
/// The Q4 FEM on options.cells_x x options.cells_y elements (2 x 2 Gauss: `gauss` is the EFG's only).
CantileverRun run_fem_cantilever(const CantileverBeam& beam, const CantileverOptions& options);

nlohmann::ordered_json to_json(const CantileverBeam& beam);
nlohmann::ordered_json to_json(const CantileverRun& run);

/// The convergence study mw-efg cantilever runs: `refinements` + 1 runs of each chosen method, the
/// cells doubled in each direction from one to the next (the spacing halved), and the observed
/// orders log2(e_coarse / e_fine) of each error between neighbours.
struct CantileverStudy {
  std::vector<CantileverRun> runs;     ///< by method, then coarse to fine
  nlohmann::ordered_json summary;      ///< beam, options, runs, orders
  std::vector<std::string> table_header;
  std::vector<std::vector<std::string>> table_rows;  ///< one per run
};
CantileverStudy run_cantilever_study(const CantileverBeam& beam, const CantileverOptions& options, bool efg, bool fem,
                                     int refinements);

}  // namespace mesowave::efg
