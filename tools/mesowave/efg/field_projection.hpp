#pragma once
// Projection of the MLS parameters onto a changed approximation space (issue 16: energy across crack
// growth). MLS parameters are not nodal values: when a crack cuts the weights, the same parameters u
// represent another field u^h = Phi_new u near the cut (dynamic_cracks.hpp, "The cut itself changes the
// continuum's energy at a fixed u"). This finds new parameters u' on the nodes the change reaches that keep
// the represented field as nearly as the new space allows, in the mass-weighted L2 sense at the model's
// Gauss points g (m_g = rho t w_g, the quadrature of the consistent mass):
//   u' = argmin sum_g m_g |Phi_new(x_g) u' - Phi_old(x_g) u|^2   over u'_I, I in A; u'_J = u_J for J not in A,
// A = the nodes in the (new) supports of the CHANGED points (those whose shape functions differ, bit for
// bit, before and after). Every point whose new support holds a node of A is in the sum (the unchanged
// points there keep their field too); the others do not depend on u'_A. The normal equations
//   N u'_A = b,  N_IJ = sum_g m_g phi_I phi_J (the consistent mass of the new space on A),
//   b_I = sum_g m_g phi_I (Phi_old u - sum_{J not in A} phi_J u_J)   (per component x, y: the same N)
// are a small sparse SPD system. Solved by Eigen's SimplicialLDLT: a direct factorisation is exact to
// round-off (a field the new space holds is reproduced to ~1e-12, the test's check, which an iterative
// solver would meet only to its tolerance), it is factorised once for both components and for u and v,
// and its operations run in a fixed order (the same bits on any thread count; everything here is serial).
// N is singular only if the new shape functions of A are linearly dependent at the points; a failed
// factorisation or a pivot below 1e-12 of the largest is reported (ok() false), and the caller keeps u.
#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <cstdint>
#include <functional>
#include <vector>

#include "mesowave/efg/mls.hpp"

namespace mesowave::efg {

class ParameterProjection {
 public:
  /// `before` and `after`: the shape functions at the same points (one entry per Gauss point), `point_mass_kg`
  /// m_g per point, `node_count` the nodes (2 parameters each: x at 2I, y at 2I + 1). Sizes must agree
  /// (std::invalid_argument otherwise: a programming error, not user input).
  ParameterProjection(const std::vector<ShapeFunctions>& before, const std::vector<ShapeFunctions>& after,
                      const std::vector<double>& point_mass_kg, std::size_t node_count);

  std::size_t changed_points() const { return changed_; }
  const std::vector<std::int32_t>& nodes() const { return nodes_; }    ///< A, ascending
  const std::vector<std::int32_t>& points() const { return points_; }  ///< in the sum, ascending
  /// The normal matrix was factorised (true also when nothing changed: then u' = u).
  bool ok() const { return ok_; }

  /// u' for parameters u (2 per node) whose field Phi_old u is the target. u' = u when nothing changed
  /// or !ok().
  Eigen::VectorXd project(const Eigen::VectorXd& u) const;
  /// u' for an explicit target field at the summed points (target(g) for g in points()), the parameters
  /// off A taken from `u_fixed`.
  Eigen::VectorXd fit(const Eigen::VectorXd& u_fixed, const std::function<Eigen::Vector2d(std::int32_t point)>& target) const;
  /// The relative misfit sum_g m_g |Phi_new u' - Phi_old u|^2 / sum_g m_g |Phi_old u|^2 over points()
  /// (0 when the target is zero there).
  double relative_misfit(const Eigen::VectorXd& u, const Eigen::VectorXd& u_projected) const;

 private:
  std::size_t changed_ = 0;
  std::vector<std::int32_t> nodes_, points_;
  std::vector<std::int32_t> local_;  ///< node -> index in A, -1 if not in A
  std::vector<ShapeFunctions> before_, after_;  ///< at points_
  std::vector<double> mass_;                    ///< at points_
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
  bool ok_ = true;
};

}  // namespace mesowave::efg
