#pragma once
// The Hugoniot Y-function of the shock paper (Section 3.2, Eqs. (24)-(27), after Schmidt-Hurtienne
// 2001): the stiffness of concrete under large volumetric compression, E_tot = Y(eps_v) E (Eq. (24)),
//
//   Y = [1 - a_v (1 - exp(-x / e_v))] [1 + (x / (b_v e_v))^2],  x = |eps_v| - e_v,th, for eps_v < -e_v,th
//   Y = 1                                                       for eps_v >= -e_v,th       (Eq. (25))
//
// with e_v,th = 0.008, e_v = 0.02, a_v = 0.7, b_v = 3.5 (Eq. (26)); eps_v < 0 in compression.
//
// Shape. Y is continuous at the threshold (Y = 1 at x = 0) but has a kink there: dY/dx = -a_v / e_v
// = -35 just past it, so Y first FALLS below 1 (the damaged micropores, "the waves move more
// slowly"), to its minimum Y = 0.5236 at |eps_v| = 0.0475, and rises again (compaction) only
// after that; it is back at 1 at |eps_v| = 0.1140 and grows like (1 - a_v) (x / (b_v e_v))^2 beyond
// (the Eq. (26) values; hugoniot_Y_minimum() computes them for any parameters).
//
// Tangent, not secant. The paper does not say whether E_tot is a secant or a tangent modulus. Its
// own description of the curve is about the gradient ("the gradient of the stress-strain relation
// becomes smaller than the compression modulus", then "the stiffness is getting higher"), so Y is
// read here as the TANGENT ratio: d sigma = Y(eps_v) D d eps, all of D scaled (Eq. (24) scales E at
// a fixed nu). The wave speed of a strain level is set by the tangent, so a compressive level eps_v
// travels at c_0 sqrt(Y(eps_v)): continuous at the threshold, slower in the dip, faster than the
// elastic wave beyond |eps_v| = 0.114. (A secant reading sigma = Y D eps would give the tangent
// (Y + |eps_v| dY/d|eps_v|) D: a jump of the speed at the threshold to sqrt(0.72) c_0, a dip to
// sqrt(0.34) c_0, and the compaction moved to other strains.) Under uniaxial strain the law is
// exactly sigma_xx = -D_11 P(|eps_v|) with P = the integral of Y (hugoniot_compression_integral):
// the path 1D waves see.
//
// Update. HugoniotElastic integrates d sigma = Y D d eps over each increment exactly for the
// volumetric path: Y is replaced by its mean over the increment of eps_v, from the closed-form
// integral of Eq. (25), so that under proportional (e.g. uniaxial) straining the stress does not
// depend on the step size. For non-proportional paths the hypoelastic law is path dependent (Y D
// is not the Hessian of any energy: Y depends on eps_v only, D couples all components): stated,
// not hidden; the paper's law has the same property.
//
// Unloading, Eq. (27): loading is compression beyond the most compressive eps_v reached
// (PointState::min_eps_v), where Y follows Eq. (25) and max_Y records its largest value;
// unloading and reloading inside that history use Y = 1 if max_Y = 1 and Y = max_Y if max_Y > 1,
// i.e. max(1, max_Y) - also in tension, which the paper does not exclude. So a point that stopped
// in the dip unloads with Y = 1, stiffer than it loaded (compaction energy dissipated), and a
// compacted point unloads with its stiffest tangent. `unloading = false` keeps Eq. (25) both ways
// (a nonlinear elastic law): the paper's steepening test of Section 4.2 runs "without the
// unloading part".
#include <Eigen/Core>

#include "mesowave/efg/material.hpp"
#include "mesowave/efg/point_material.hpp"

namespace mesowave::efg {

/// Eq. (26) as defaults.
struct HugoniotParameters {
  double e_v_th = 0.008;  ///< threshold volumetric strain (magnitude) where Y starts, Eq. (25)
  double e_v = 0.02;      ///< strain scale of the softening exponential
  double a_v = 0.7;       ///< depth of the softening: Y -> (1 - a_v)(...) far past the threshold
  double b_v = 3.5;       ///< strain scale (in e_v) of the quadratic stiffening
  bool unloading = true;  ///< Eq. (27); false: Eq. (25) on unloading too (Section 4.2's test)

  /// InputError: e_v_th < 0, e_v <= 0, a_v outside [0, 1) (a_v >= 1 makes Y vanish or turn
  /// negative: no stiffness), b_v <= 0, or any of them not finite.
  void validate() const;
};

/// Y(eps_v), Eq. (25); eps_v < 0 in compression, 1 in tension and up to the threshold.
double hugoniot_Y(double eps_v, const HugoniotParameters& p);
/// dY / d|eps_v| (the derivative along compression): 0 up to the threshold, -a_v / e_v just past
/// it (the right-hand value at the kink itself).
double hugoniot_dY_dcompression(double eps_v, const HugoniotParameters& p);
/// P(s) = the integral of Y over the compression s' = -eps_v' from 0 to s = -eps_v, in closed form
/// (P = s below the threshold and in tension): the uniaxial-strain stress is -D_11 P.
double hugoniot_compression_integral(double eps_v, const HugoniotParameters& p);
/// The mean of Y over the compression interval between eps_v_a and eps_v_b (either order): the
/// closed-form integral over intervals of 1e-3 and more, 3-point Gauss below (no cancellation).
double hugoniot_mean_Y(double eps_v_a, double eps_v_b, const HugoniotParameters& p);

struct HugoniotMinimum {
  double eps_v = 0;  ///< where Y is smallest (< 0)
  double Y = 1;
  double eps_v_back_at_one = 0;  ///< where the rising branch reaches Y = 1 again (< eps_v)
};
/// The dip of Eq. (25) past the threshold (bisection on dY/d|eps_v| = 0 and on Y = 1); Y = 1 at
/// the threshold itself when a_v = 0 (no dip).
HugoniotMinimum hugoniot_Y_minimum(const HugoniotParameters& p);

/// The volumetric strain eps_xx + eps_yy + eps_zz of a Voigt in-plane strain: eps_zz = 0 in plane
/// strain, -nu / (1 - nu) (eps_xx + eps_yy) in plane stress (sigma_zz = 0 under d sigma = Y D d eps
/// for any Y: the scale does not move the ratio).
double volumetric_strain(const Eigen::Vector3d& strain, const ElasticMaterial2D& material);

/// The Y-function law at a Gauss point of the explicit solver: d sigma = Y D d eps (see the top of
/// this file), Eq. (27) on unloading. modulus_scale is the stiffest tangent the next increment can
/// meet: with unloading, max(1, max_Y) (the unloading tangent is never softer than the loading one,
/// and equals it on the rising branch); without, Y(eps_v) itself (which is < 1 in the dip: an
/// integrator that takes the largest scale over all points should not let a dip lengthen its step
/// beyond the linear one).
class HugoniotElastic final : public PointMaterial {
 public:
  HugoniotElastic(const ElasticMaterial2D& material, const HugoniotParameters& parameters);
  Eigen::Vector3d update(const Eigen::Vector3d& strain, PointState& state) const override;
  const HugoniotParameters& parameters() const { return p_; }

 private:
  ElasticMaterial2D material_;
  HugoniotParameters p_;
  Eigen::Matrix3d D_;
};

}  // namespace mesowave::efg
