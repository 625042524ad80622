#pragma once
// The elastic references of the notched three-point bending beam (issue 15, Must show 3: "the initial
// stiffness against beam theory with shear deformation and against the FEM's elastic solution of the
// same beam"): the beam of efg/three_point_bending.hpp - length = span, simply supported at the
// bottom corners, loaded through two top points load_width apart about mid-span, both moved down by
// the deflection - solved by the Q4 FEM (fem/plane_static.hpp) with the
// notch as a zero-width slit, and the unnotched beam by Timoshenko beam theory
// (efg/beam_theory.hpp), the notched one adding the notch's fracture-mechanics compliance. Beam
// theory has no local indentation under the point loads and supports, which the FEM (and the EFG)
// show: their stiffness lies below it and falls slowly as the mesh refines. The load is the sum of the load points' reactions, as in the EFG run.
#include "mesowave/efg/three_point_bending.hpp"

namespace mesowave::efg {

struct BendingReference {
  double beam_theory_N_per_m = 0;    ///< unnotched: 1 / three_point_bending_deflection_m per newton
  /// Notched: beam theory plus the notch's LEFM deflection (Tada's fit, three_point_bending_notch_deflection_m).
  /// An eccentric notch at x (ThreePointBendingOptions::notch_x_m): the crack's compliance is driven by the bending
  /// moment there, M(x) = P min(x, S - x) / 2, so by Castigliano its share of the mid-span deflection scales with
  /// (M(x) / M(S/2))^2 - a first estimate (Tada's fit is for the central notch; the shear at x is ignored).
  double beam_theory_notched_N_per_m = 0;
  double fem_unnotched_N_per_m = 0;  ///< the Q4 FEM without the notch (checks the FEM against the beam)
  double fem_notched_N_per_m = 0;    ///< the Q4 FEM of the notched beam: the EFG's elastic stiffness' reference
  int fem_cells_x = 0, fem_cells_y = 0;
  std::size_t fem_nodes = 0;
};

/// The Q4 mesh has cells of load_width / (2 refinement) along the span (so that mid-span and the two
/// load points are nodes), about as tall, with the notch tip on a mesh line. InputError for
/// refinement < 1, bad options (ThreePointBendingOptions::validate), a span that is no even multiple
/// of the cell, or a notch that falls on no mesh line (depth / notch far from a ratio of small integers).
BendingReference three_point_bending_reference(const ThreePointBendingOptions& options, int refinement = 2);

}  // namespace mesowave::efg
