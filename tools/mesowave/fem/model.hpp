#pragma once
// Meshes and assembled data of the explicit continuum reference solver
// (mw-fem): element connectivity, one precomputed stiffness matrix per distinct
// element shape (elements equal up to a translation share it: one for a uniform
// box, one per cross-section cell for an extruded rod), lumped nodal masses,
// fixed dofs, and a colouring of the elements (no two elements of a colour
// share a node) that makes the parallel force assembly race-free and its
// summation order - hence its bits - independent of the thread count.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mesowave/fem/box_operator.hpp"
#include "mesowave/wave/elastic.hpp"

namespace mesowave::fem {

// E, nu and rho as the dispersion theory has them (wave/elastic.hpp): one definition for both.
using wave::IsotropicMaterial;

struct FemModel {
  int dim = 3;                ///< 3: hexahedra, dofs (u_x, u_y, u_z); 2: axisymmetric rings, dofs (u_r, u_z)
  int nodes_per_element = 8;  ///< 8 or 4
  IsotropicMaterial material;
  std::string description;    ///< "rod, 3D hexahedra, 84 cells per cross-section x 1000 layers"
  double mesh_size_m = 0;     ///< nominal element size h
  std::vector<double> coords;                       ///< dim per node [m] ((x, y, z) or (r, z))
  std::vector<std::int32_t> connectivity;           ///< nodes_per_element per element
  std::vector<std::int32_t> element_type;           ///< index into `stiffness`
  std::vector<std::vector<double>> stiffness;       ///< per type, (npe dim)^2, row-major (symmetric)
  std::vector<double> type_max_eigenvalue;          ///< per type: largest eigenvalue of M_e^-1 K_e [rad^2/s^2]
  std::vector<double> mass;                         ///< lumped, per node [kg]
  std::vector<std::uint8_t> fixed;                  ///< per dof: held at zero (u_r on the axis)
  std::vector<std::vector<std::int32_t>> colours;   ///< element lists, no shared node within one
  /// A box of identical hexahedra (box_hexahedra): the solver applies K as a sum of Kronecker
  /// products of 1-D operators (box_operator.hpp) instead of element by element. Invalid otherwise.
  BoxGrid box;
  /// Upper bound on the largest eigenvalue of M^-1 K (free dofs) [rad^2/s^2]: the
  /// smaller of the element bound and the block bound (see stable_dt()).
  double max_eigenvalue_bound = 0;
  std::string stable_dt_method;  ///< "element bound" or "block bound (...)"

  std::size_t node_count() const { return mass.size(); }
  std::size_t element_count() const { return element_type.size(); }
  std::size_t dof_count() const { return mass.size() * std::size_t(dim); }
  /// Central-difference stable step 2 / sqrt(max_eigenvalue_bound) [s]. The bound
  /// is rigorous: splitting K = sum_b K_b and M = sum_b M_b over disjoint element
  /// sets b (each M_b the lumped masses of its elements) gives
  /// x'Kx <= max_b lambda_max(M_b^-1 K_b) x'Mx (Irons-Treharne). With single
  /// elements as sets this is the element bound; with blocks of elements (one layer
  /// of a rod, 2 x 2 x 2 cells of a box; all blocks equal up to translation, so one
  /// dense eigenproblem per block shape) it is within a few percent of the mesh's
  /// true highest frequency, where the element bound is 25-35 % low for these hexahedra.
  double stable_dt() const;
  /// Position of a node as (x, y, z) [m]; an axisymmetric node lies in the x-z plane (y = 0).
  std::array<double, 3> position(std::size_t node) const;
  /// Node nearest to `p` (x, y, z) [m]; axisymmetric models compare (sqrt(x^2 + y^2), z).
  std::size_t nearest_node(const std::array<double, 3>& p) const;
  /// Total mass [kg].
  double total_mass() const;
};

/// Rod of radius R along z from z = 0 to `length`, axisymmetric ring elements:
/// ceil(R / h) rings across the radius, round(length / h) layers.
FemModel rod_axisymmetric(const IsotropicMaterial& m, double radius_m, double length_m, double h_m);

/// The same rod in 3D hexahedra: the cross-section an O-grid of the disk (an inner
/// square of n x n cells, n even so that a node sits on the axis, and four curved
/// blocks out to the circle; cells about h), extruded in round(length / h) layers.
/// The boundary polygon's vertices lie slightly outside R so that the cross-section
/// area is exactly pi R^2.
FemModel rod_hexahedra(const IsotropicMaterial& m, double radius_m, double length_m, double h_m);

/// Box [0, Lx] x [0, Ly] x [0, Lz] of identical hexahedra, round(L / h) per side.
FemModel box_hexahedra(const IsotropicMaterial& m, const std::array<double, 3>& size_m, double h_m);

/// Nodal weights of a uniform traction on the boundary plane coordinate[axis] = value,
/// limited to the face cells whose centre lies within `radius` of `centre` (all of the
/// plane when radius is infinite): pairs (node, weight) with weights summing to 1.
/// Axisymmetric models: axis 2 only, the patch a disk centred on the axis (centre
/// ignored). Empty if no face cell qualifies.
std::vector<std::pair<std::size_t, double>> surface_patch(const FemModel& model, int axis, double value,
                                                          const std::array<double, 3>& centre, double radius_m);

}  // namespace mesowave::fem
