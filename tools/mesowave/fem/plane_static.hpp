#pragma once
// Linear static plane stress / plane strain on a structured rectangle of bilinear quadrilaterals
// (Q4, 2 x 2 Gauss, full integration): the second method beside the EFG solver of the concrete
// paper (Larcher & Stempniewski): the elastic stiffness of the notched three-point bending beam and
// the reference of the EFG's cost (the paper's Fig. 6 asks what EFG costs against FEM).
// The material enters as its 3 x 3 Voigt matrix D (stress = D strain, engineering shear) and a
// thickness, so plane stress and plane strain are the caller's D (efg/material.hpp builds both).
// An optional zero-width notch is a vertical slit from the bottom edge: the nodes on it are doubled
// (the elements left of it keep the originals, those right of it take the copies; the node at its
// top is shared), so its faces are traction free like the EFG's crack. Essential conditions are
// eliminated exactly (prescribed nodal values), the free system is solved by Eigen's sparse
// Cholesky (SimplicialLDLT, AMD ordering): K is symmetric positive definite once rigid motions are
// held, and LDL^T needs no square roots. Its cost: the factor's nonzeros, reported.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace mesowave::fem {

/// A structured mesh of nx x ny equal rectangles over [x0, x0 + length] x [y0, y0 + depth].
struct PlaneMeshSpec {
  double x0_m = 0, y0_m = 0, length_m = 0, depth_m = 0;
  int nx = 0, ny = 0;
  /// Zero-width notch at x = notch_x_m from the bottom edge up to y0 + notch_depth_m (0: none).
  /// Both must lie on mesh lines (InputError otherwise, naming the value and the spacing).
  double notch_x_m = 0, notch_depth_m = 0;
};

struct PlaneMesh {
  PlaneMeshSpec spec;
  std::vector<Eigen::Vector2d> nodes;            ///< grid nodes (row by row from the bottom), then notch copies
  std::vector<std::array<std::int32_t, 4>> quads;  ///< counter-clockwise from the lower left corner
  double dx_m = 0, dy_m = 0;
  std::size_t dof_count() const { return 2 * nodes.size(); }  ///< (u_x, u_y) of node i at 2i, 2i + 1
  /// Nodes within `tolerance_m` of the segment a-b, ascending (a clamped edge, a support line).
  std::vector<std::int32_t> nodes_on_segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                             double tolerance_m = -1) const;
  /// The node at x (within a thousandth of the spacing; on the notch the left one): InputError if none.
  std::int32_t node_at(const Eigen::Vector2d& x, const std::string& what) const;
  /// The element containing x and x's natural coordinates (xi, eta) in [-1, 1]^2 in it.
  std::pair<std::int32_t, Eigen::Vector2d> locate(const Eigen::Vector2d& x) const;
};

/// InputError for nx, ny < 1, a non-positive size, a notch outside the body, not on a mesh line or
/// as deep as the beam.
PlaneMesh structured_plane_mesh(const PlaneMeshSpec& spec);

struct PlanePointLoad { Eigen::Vector2d x; Eigen::Vector2d force_N; };  ///< consistent: N(x)^T F
/// Traction [Pa] on the boundary segment a-b (element edges on it get 2-point Gauss, exact for
/// tractions linear along an edge; parabolic ones converge as h^4).
struct PlaneEdgeLoad { Eigen::Vector2d a, b; std::function<Eigen::Vector2d(const Eigen::Vector2d&)> traction_Pa; };
/// u_component(node at x) = value_m.
struct PlaneConstraint { Eigen::Vector2d x; int component = 0; double value_m = 0; std::string name; };

struct PlaneStaticProblem {
  PlaneMesh mesh;
  Eigen::Matrix3d D;         ///< stress = D strain (Voigt xx, yy, xy engineering) [Pa]
  double thickness_m = 0;
  std::vector<PlanePointLoad> point_loads;
  std::vector<PlaneEdgeLoad> edge_loads;
  std::vector<PlaneConstraint> constraints;
};

struct PlaneStaticSolution {
  Eigen::VectorXd u_m;                 ///< full nodal displacements
  std::vector<double> reactions_N;     ///< per constraint: (K u - f) at its dof
  std::size_t free_dofs = 0;
  std::size_t stiffness_nonzeros = 0;  ///< of the free-free K (both triangles)
  std::size_t factor_nonzeros = 0;     ///< of L in L D L^T
  double assembly_s = 0, solve_s = 0;
  std::string solver = "Eigen SimplicialLDLT (AMD)";
};

/// Element stiffness of a Q4 with corners x (counter-clockwise), 2 x 2 Gauss: 8 x 8, dofs
/// (u_x, u_y) per corner.
Eigen::Matrix<double, 8, 8> quad4_plane_stiffness(const std::array<Eigen::Vector2d, 4>& x, const Eigen::Matrix3d& D,
                                                  double thickness_m);

/// Assembled global stiffness (all dofs).
Eigen::SparseMatrix<double> plane_stiffness(const PlaneMesh& mesh, const Eigen::Matrix3d& D, double thickness_m);

/// Consistent load vector of the problem's point and edge loads.
Eigen::VectorXd plane_load(const PlaneStaticProblem& problem);

/// Solves K u = f with the constraints eliminated. InputError when the constraints leave a rigid
/// motion free (the factorisation fails) or a constraint names no node.
PlaneStaticSolution solve_plane_static(const PlaneStaticProblem& problem);

/// u^h(x) and the stress D B u at x (inside an element; on an element edge, of the one `locate` finds).
Eigen::Vector2d plane_displacement(const PlaneMesh& mesh, const Eigen::VectorXd& u, const Eigen::Vector2d& x);
Eigen::Vector3d plane_stress(const PlaneMesh& mesh, const Eigen::Matrix3d& D, const Eigen::VectorXd& u,
                             const Eigen::Vector2d& x);
/// Nodal stresses: the average of the stresses of the elements meeting at each node (for output).
std::vector<Eigen::Vector3d> plane_nodal_stress(const PlaneMesh& mesh, const Eigen::Matrix3d& D,
                                                const Eigen::VectorXd& u);

}  // namespace mesowave::fem
