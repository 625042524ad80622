#pragma once
// Essential boundary conditions of the EFG model. MLS shape functions do not interpolate
// (phi_I(x_J) != delta_IJ), so "u = value at a node" is not a condition on one unknown. Each
// constraint k is collocated at its point instead,
//   C_k u = sum_I phi_I(x_k) u_I,c = s d_k        (c its component, s the load scale),
// and enforced EXACTLY by eliminating one unknown per constraint (master-slave transformation):
//   u = T v + g(s),  C T = 0,  C g(s) = s d.
// Why this method and not the others the issue names:
//  - a penalty makes the condition hold only to O(1/alpha) and ruins K's conditioning as alpha
//    grows - an error to state and tune, and displacement control reads its load from the reaction;
//  - Lagrange multipliers are exact but the saddle-point system is indefinite (no Cholesky) and
//    grows by one row per constraint;
//  - the transformation is exact, keeps T^T K T symmetric positive definite (a sparse Cholesky/LDLT
//    factorises it), works unchanged for any tangent K the nonlinear solver passes, and a load scale
//    is just g(s) = s g(1). Its cost: each slave is a dense combination of the masters its constraint
//    and its neighbours' touch (C_S^-1 C_M), a small dense block along the constrained boundary.
// The slaves are chosen by Gaussian elimination with pivoting on the constraints' rows in the order
// given (the largest remaining coefficient), so a constraint that repeats or contradicts earlier ones
// is refused by name instead of making C_S singular.
//
// Reactions: at equilibrium K u = f + C^T R, R_k the force [N] that constraint k applies to the body
// along its component at x_k (a point force there has the nodal load N(x_k)^T R_k e_c = C_k^T R_k).
// From the full residual r = f_int(u) - f_ext = C^T R, R is the least-squares solution (exact at
// equilibrium). In the contract's multiplier convention r = -C^T mu, mu = -R. By the partition of
// unity (sum_I phi_I = 1) the reactions sum to minus the applied load in each direction.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "mesowave/efg/elastic_model.hpp"

namespace mesowave::efg {

class ConstraintSet {
public:
  /// InputError naming the constraint: component not 0 or 1, a value not finite, a point the MLS
  /// refuses, a constraint that repeats or contradicts the ones before it.
  ConstraintSet(const ElasticModel& model, std::vector<PointConstraint> constraints);
  /// u = T v + g(scale): `scale` multiplies every constraint's value (displacement control).
  Eigen::VectorXd expand(const Eigen::VectorXd& v, double scale = 1.0) const;
  std::size_t reduced_size() const;
  const Eigen::SparseMatrix<double>& T() const { return T_; }
  Eigen::VectorXd g(double scale = 1.0) const { return scale * g_; }
  /// T^T K T and T^T r: the reduced matrix and vector of any full K and r.
  Eigen::SparseMatrix<double> reduce(const Eigen::SparseMatrix<double>& K) const;
  Eigen::VectorXd reduce(const Eigen::VectorXd& r) const;
  /// Reaction force [N] of each constraint for the full residual r = f_int(u) - f_ext (r = -C^T mu, R = -mu).
  std::vector<double> reactions(const Eigen::VectorXd& full_residual) const;
  /// C u - d for the full u at load scale `scale`: how well the constraints hold (0 up to rounding).
  Eigen::VectorXd violation(const Eigen::VectorXd& u, double scale = 1.0) const;
  const std::vector<PointConstraint>& constraints() const { return constraints_; }
  /// The constraint rows C (one per constraint, full width).
  const Eigen::SparseMatrix<double>& C() const { return C_; }

private:
  std::vector<PointConstraint> constraints_;
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
