#pragma once
// The cantilever study of mw-efg cantilever and bench/efg (issue 15, Must show 2 and 4): Timoshenko
// & Goodier's cantilever (efg/beam_theory.hpp) solved by the EFG (efg/cantilever.hpp's
// solve_cantilever) and by the Q4 FEM (fem/plane_static.hpp) on the same cells - the FEM clamped by
// the closed form's displacements at the nodes of x = 0, loaded by the same end traction - both
// measured by efg::cantilever_errors with the same rule, as the spacing halves; the observed orders
// and the cost of each run.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "mesowave/efg/cantilever.hpp"
#include "mesowave/efg/vtk_output.hpp"

namespace mesowave::efg {

/// One run of either method, in the terms both share.
struct CantileverMethodRun {
  std::string method;  ///< "EFG" | "Q4 FEM"
  int cells_x = 0, cells_y = 0;
  std::size_t nodes = 0, gauss_points = 0, dofs = 0;
  double spacing_m = 0;
  CantileverErrors errors;
  double solution_s = 0;            ///< build, assemble, constrain and solve (what a user waits for)
  double wall_s = 0;                ///< and the error measurement
  std::size_t stiffness_nonzeros = 0, factor_nonzeros = 0;
  double matrix_MiB = 0;            ///< K and its factor, a value and an index per nonzero
  std::string solver;
  NodeSnapshot snapshot;            ///< u^h and the stress at the nodes (the FEM's; empty for the EFG)
};

/// The Q4 FEM on setup.cells_x x setup.cells_y elements (2 x 2 Gauss; setup.gauss is the EFG's).
CantileverMethodRun run_fem_cantilever(const CantileverSetup& setup);
/// The EFG (solve_cantilever) in the same terms.
CantileverMethodRun run_efg_cantilever(const CantileverSetup& setup);

struct CantileverStudy {
  std::vector<CantileverMethodRun> runs;  ///< by method (EFG first), then coarse to fine
  nlohmann::ordered_json summary;         ///< beam, options, runs, orders log2(e_coarse / e_fine)
  std::vector<std::string> table_header;
  std::vector<std::vector<std::string>> table_rows;  ///< one per run
};
/// `refinements` + 1 runs of each chosen method, the cells doubled in each direction from one to the
/// next. InputError for refinements outside [0, 6], no method, or what the runs refuse.
CantileverStudy run_cantilever_study(const CantileverSetup& setup, bool efg, bool fem, int refinements);

}  // namespace mesowave::efg
