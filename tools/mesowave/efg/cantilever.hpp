#pragma once
// The EFG solution of Timoshenko & Goodier's cantilever (efg/beam_theory.hpp), the standard
// validation of a meshless elasticity solver (Belytschko, Lu & Gu 1994): plane stress, clamped by
// imposing the closed form's displacements on the x = 0 edge (weakly, by hat-function averages, or
// collocated at its nodes for comparison: efg/constraints.hpp),
// loaded by the closed form's traction (sigma_xx, tau_xy) on x = L; the top and bottom are free.
// One call builds, solves and measures it, so the convergence test and the speed-against-error
// study share the same steps and report the cost of each.
#include <cstddef>
#include <string>

#include "mesowave/efg/beam_theory.hpp"
#include "mesowave/efg/mls.hpp"

namespace mesowave::efg {

struct CantileverSetup {
  CantileverBeam beam{};
  int cells_x = 16, cells_y = 4;  ///< background cells; their corners are the nodes
  int gauss = 2;                  ///< per direction and cell (the paper's 2 x 2)
  double support_scale = 2.5;     ///< support radius / nodal spacing
  MlsOptions mls{};
  int error_gauss = 6;            ///< per direction and cell of the error quadrature
  bool collocated_clamp = false;  ///< true: u at the edge's nodes (fails the patch test, kept to show it)
};

struct CantileverRun {
  std::size_t nodes = 0, gauss_points = 0, dofs = 0, constraints = 0;
  double spacing_m = 0;
  CantileverErrors error{};          ///< displacement L2, energy (stress), tip deflection
  double reaction_N[2] = {0, 0};     ///< sum of the clamp's reactions (x, y)
  double applied_N[2] = {0, 0};      ///< resultant of the consistent end load
  std::string solver;
  std::size_t reduced_nonzeros = 0, factor_nonzeros = 0;
  double shape_s = 0, assemble_s = 0, factorise_s = 0, solve_s = 0, wall_s = 0;  ///< cost by step
};

CantileverRun solve_cantilever(const CantileverSetup& setup);

}  // namespace mesowave::efg
