#pragma once
// The discrete equilibrium of the EFG model, shock paper Eqs. (14)-(18): u^h(x) = N(x) u (Eq. 14,
// N of Eq. 15 from the MLS shape functions), eps = B u (Eqs. 16-17) and
//   K u = f,  K = sum over Gauss points of B^T D B t w,  f = int N^T t_bar t dGamma (+ point forces),
// the background-cell quadrature of Section 2.5. The nodal unknowns u are MLS parameters, not the
// displacements at the nodes (MLS does not interpolate): read displacements with displacement(x).
//
// Shape functions at the Gauss points are cached (they cost far more than the B^T D B products);
// update_shape_functions() recomputes them when the CrackSet's version moved. The stiffness is
// assembled into a fixed sparsity pattern (the node pairs that share a Gauss point) by adding the
// points' blocks in point order: the same bits for any thread count (the blocks are computed in
// parallel, the sums are not).
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "mesowave/efg/discretisation.hpp"
#include "mesowave/efg/geometry.hpp"
#include "mesowave/efg/material.hpp"
#include "mesowave/efg/mls.hpp"

namespace mesowave::efg {

/// u_c(x) = value: one displacement component (0: x, 1: y) at a point, enforced by ConstraintSet.
struct PointConstraint {
  Vec2 x;
  int component;
  double value_m;
  std::string name;
};

/// Strain eps = B u (Voigt xx, yy, xy engineering) from shape functions and nodal parameters, Eq. (16).
Eigen::Vector3d strain_of(const ShapeFunctions& sf, const Eigen::VectorXd& u);
/// u^h = N u, Eq. (14).
Eigen::Vector2d displacement_of(const ShapeFunctions& sf, const Eigen::VectorXd& u);

class ElasticModel {
public:
  /// `mls` (and its CrackSet) must outlive the model; its nodes are the discretisation's.
  /// InputError: invalid material, node counts that differ, a Gauss point the MLS refuses.
  ElasticModel(const Discretisation& disc, ElasticMaterial2D material, const MlsApproximation& mls);
  /// Shape functions at every Gauss point (recomputed when the CrackSet's version changed).
  void update_shape_functions();

  Eigen::SparseMatrix<double> stiffness() const;                   ///< K = sum B^T D B t w, Eq. (18)
  Eigen::VectorXd internal_force(const Eigen::VectorXd& u) const;  ///< K u, assembled pointwise
  /// Strain and stress (Voigt) at x for nodal parameters u.
  Eigen::Vector3d strain(const Vec2& x, const Eigen::VectorXd& u) const;
  Eigen::Vector3d stress(const Vec2& x, const Eigen::VectorXd& u) const;
  Eigen::Vector2d displacement(const Vec2& x, const Eigen::VectorXd& u) const;  ///< u^h(x), Eq. (14)
  /// Strain at Gauss point p from the cached shape functions (the crack criterion's input).
  Eigen::Vector3d strain_at_point(std::size_t p, const Eigen::VectorXd& u) const;
  std::size_t dof_count() const;  ///< 2 per node: (u_x, u_y) of node i at 2i, 2i+1

  /// Consistent load of a traction t [Pa] on the boundary segment a-b: the segment is cut into
  /// pieces no longer than the nodal spacing (the shape functions are not polynomials, one Gauss
  /// rule over a long edge would under-resolve them) with `gauss` points on each; times the thickness.
  Eigen::VectorXd traction_load(const Segment& edge, const std::function<Eigen::Vector2d(const Vec2&)>& t,
                                int gauss = 4) const;
  /// A point force [N] (the whole thickness's): f = N(x)^T F.
  Eigen::VectorXd point_load(const Vec2& x, const Eigen::Vector2d& force_N) const;
  /// Body force b [N/m3] (e.g. rho g) over the body: int N^T b t dA.
  Eigen::VectorXd body_load(const Eigen::Vector2d& b_N_m3) const;

  const Discretisation& discretisation() const { return disc_; }
  const ElasticMaterial2D& material() const { return material_; }
  const Eigen::Matrix3d& D() const { return D_; }
  const MlsApproximation& mls() const { return *mls_; }
  const std::vector<ShapeFunctions>& shape_functions() const { return shape_; }

private:
  Discretisation disc_;
  ElasticMaterial2D material_;
  Eigen::Matrix3d D_;
  const MlsApproximation* mls_;
  std::vector<ShapeFunctions> shape_;
  std::uint64_t crack_version_ = 0;
  bool have_shape_ = false;
  Eigen::SparseMatrix<double> pattern_;  ///< K's structure, values zero
  void build_pattern();
};

/// Relative errors of a solution against a closed form over a quadrature (e.g. the Gauss points of a
/// finer rectangular_grid, so the measure does not change with the model's own rule):
///   displacement: ||u^h - u|| / ||u|| (L2),
///   energy: sqrt(int (s^h - s) : C (s^h - s) / int s : C s), C = D^-1 (= the strain form e^T D e).
struct ErrorNorms {
  double displacement_l2 = 0, energy = 0;
};
/// A field at x: displacement [m] and stress (Voigt) [Pa].
using ElasticFieldAt = std::function<std::pair<Eigen::Vector2d, Eigen::Vector3d>(const Vec2&)>;
/// The one norm loop: any approximation (the EFG, the Q4 FEM) against the exact field.
ErrorNorms relative_error(const std::vector<GaussPoint>& quadrature, const Eigen::Matrix3d& D, const ElasticFieldAt& approx,
                          const ElasticFieldAt& exact);
/// The EFG solution u (nodal parameters) of `model`.
ErrorNorms relative_error(const ElasticModel& model, const Eigen::VectorXd& u, const std::vector<GaussPoint>& quadrature,
                          const ElasticFieldAt& exact);

}  // namespace mesowave::efg
