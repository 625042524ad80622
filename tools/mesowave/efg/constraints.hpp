#pragma once
// Essential boundary conditions of the EFG model. MLS shape functions do not interpolate
// (phi_I(x_J) != delta_IJ), so "u = value at a node" is not a condition on one unknown. Every
// condition is a row C_k u = s d_k on the nodal parameters (s: the load scale), of two kinds:
//  - PointConstraint, collocated at its point: C_k u = sum_I phi_I(x_k) u_I,c. Right for what is a
//    point in the model - a support or a load point of the bending beam, whose reaction is a point force.
//  - EdgeConstraint, u_c = value along a segment in the weak sense of Lagrange multipliers with a
//    piecewise-linear multiplier (hat functions N_k at the ends of pieces of the segment, as
//    Belytschko, Lu & Gu 1994 interpolate theirs), one row per hat, normalised to an average:
//      C_k u = int N_k u^h_c ds / int N_k ds = int N_k value ds / int N_k ds.
//    Collocating at the edge's nodes instead leaves the test functions nonzero between the nodes:
//    the weak form then misses int v . sigma n ds on the edge, and the patch test FAILS - a linear
//    field imposed by collocation at the 32 boundary nodes of an 8 x 8 patch has an energy-norm
//    error of 1.0e-2 that no Gauss rule removes (9.9e-3 with 8 x 8 points); the weak rows pass it to
//    the integration error (docs: the patch-test table in the header of tests/efg/patch_test.cpp).
// Every row is enforced EXACTLY by eliminating one unknown per row (master-slave transformation):
//   u = T v + g(s),  C T = 0,  C g(s) = s d,
// which gives the same u as the saddle-point system of multipliers (tests/efg/constraints_test).
// Why the elimination and not the other methods the issue names:
//  - a penalty makes the condition hold only to O(1/alpha) and ruins K's conditioning as alpha
//    grows - an error to state and tune, and displacement control reads its load from the reaction;
//  - the multipliers' saddle-point system is indefinite (no Cholesky) and grows by one row per
//    condition;
//  - the transformation is exact, keeps T^T K T symmetric positive definite (a sparse Cholesky/LDLT
//    factorises it), works unchanged for any tangent K the nonlinear solver passes, and a load scale
//    is just g(s) = s g(1). Its cost: each slave is a dense combination of the masters its row and
//    its neighbours' touch (C_S^-1 C_M), a small dense block along the constrained boundary.
// The slaves are chosen by Gaussian elimination with pivoting on the rows in order (the largest
// remaining coefficient), so a row that repeats or contradicts earlier ones is refused by name
// instead of making C_S singular.
//
// Reactions: at equilibrium K u = f + C^T R. A row's coefficients sum to 1 (partition of unity), so
// R_k is a force [N] along the row's component: at x_k for a point (a point force there has the nodal
// load N(x_k)^T R_k e_c = C_k^T R_k), the share of hat k for an edge. From the full residual
// r = f_int(u) - f_ext = C^T R, R is the least-squares solution (exact at equilibrium). In the
// contract's multiplier convention r = -C^T mu, mu = -R. The reactions sum to minus the applied load
// in each direction.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <string>
#include <vector>

#include "mesowave/efg/elastic_model.hpp"

namespace mesowave::efg {

/// u_c = value(x) along the segment a-b in the weak sense (see above): `pieces` hats' elements
/// (0: one per nodal spacing, the boundary nodes' density), `gauss` points on each piece.
struct EdgeConstraint {
  Segment edge;
  int component;
  std::function<double(const Vec2&)> value_m;
  std::string name;
  int pieces = 0;
  int gauss = 6;
};

class ConstraintSet {
public:
  /// Rows: the point constraints in order, then each edge's pieces + 1 hats from a to b.
  /// InputError naming the constraint: component not 0 or 1, a value not finite, a point the MLS
  /// refuses, a row that repeats or contradicts the ones before it.
  ConstraintSet(const ElasticModel& model, std::vector<PointConstraint> constraints,
                std::vector<EdgeConstraint> edges = {});
  /// u = T v + g(scale): `scale` multiplies every constraint's value (displacement control).
  Eigen::VectorXd expand(const Eigen::VectorXd& v, double scale = 1.0) const;
  std::size_t reduced_size() const;
  const Eigen::SparseMatrix<double>& T() const { return T_; }
  Eigen::VectorXd g(double scale = 1.0) const { return scale * g_; }
  /// T^T K T and T^T r: the reduced matrix and vector of any full K and r.
  Eigen::SparseMatrix<double> reduce(const Eigen::SparseMatrix<double>& K) const;
  Eigen::VectorXd reduce(const Eigen::VectorXd& r) const;
  /// Reaction force [N] of each row for the full residual r = f_int(u) - f_ext (r = -C^T mu, R = -mu).
  std::vector<double> reactions(const Eigen::VectorXd& full_residual) const;
  /// C u - d for the full u at load scale `scale`: how well the constraints hold (0 up to rounding).
  Eigen::VectorXd violation(const Eigen::VectorXd& u, double scale = 1.0) const;
  const std::vector<PointConstraint>& constraints() const { return constraints_; }
  /// The rows C (full width), their values d (scale 1), their names ("<name> hat 3" for an edge's),
  /// the direction (0: x, 1: y) each acts in.
  const Eigen::SparseMatrix<double>& C() const { return C_; }
  const Eigen::VectorXd& d() const { return d_; }
  const std::vector<std::string>& row_names() const { return names_; }
  const std::vector<int>& row_components() const { return components_; }
  /// First row of edge e and one past its last.
  std::pair<std::size_t, std::size_t> edge_rows(std::size_t e) const { return edge_rows_.at(e); }

private:
  std::vector<PointConstraint> constraints_;
  std::vector<std::string> names_;
  std::vector<int> components_;
  std::vector<std::pair<std::size_t, std::size_t>> edge_rows_;
  Eigen::VectorXd d_;
  Eigen::SparseMatrix<double> C_, T_;
  Eigen::VectorXd g_;
  std::vector<Eigen::Index> involved_;  ///< dofs any constraint touches, ascending
  Eigen::MatrixXd C_involved_;          ///< C restricted to those columns (for the reactions)
};

/// Linear static solve K u = f under the constraints: returns u (full) and the reactions. The solver
/// is Eigen's SimplicialLDLT (AMD ordering) on T^T K T; InputError when that is not positive definite
/// (the constraints leave a rigid-body motion free).
struct LinearSolution {
  Eigen::VectorXd u;
  std::vector<double> reactions_N;
  std::string solver;
  double wall_s = 0;               ///< reduction, factorisation and solve
  double factorise_s = 0;          ///< the factorisation alone (analyse + factorise)
  std::size_t reduced_nonzeros = 0;  ///< of T^T K T (both triangles)
  std::size_t factor_nonzeros = 0;   ///< of the factor L (strictly lower part): the fill
};
LinearSolution solve_linear(const Eigen::SparseMatrix<double>& K, const Eigen::VectorXd& f, const ConstraintSet& c,
                            double scale = 1.0);

}  // namespace mesowave::efg
