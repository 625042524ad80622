#pragma once
// The constitutive update at one Gauss point of the explicit EFG model (shock paper Sections 3.2,
// 3.3): the explicit integrator (efg/explicit_dynamics) asks each point for its stress from its
// total strain, and the point keeps what its law remembers (the largest Y reached, for the
// unloading rule Eq. (27); the last strain and stress, for an incremental law). The linear law
// needs none of it. `modulus_scale` is the ratio of the law's current tangent stiffness to D()'s:
// the integrator shrinks the stable step by 1 / sqrt(largest scale) when the Y-function stiffens
// the material (Eq. (24)).
//
// Strain rate (Section 3.3: the strengths grow with it). The integrator writes the point's strain
// rate into the state before it calls update: eps_dot^n = B^n v^{n-1/2}, the central difference's
// velocity between t^{n-1} and t^n through the point's current shape functions (zero at the first
// step, from rest). That is (eps^n - eps^{n-1}) / dt_{n-1/2} while the shape functions stay; when a
// crack grows and the point's shape functions change, a difference of stored strains would carry the
// jump of the approximation as a spurious rate, B^n v^{n-1/2} does not. A law, or the crack criterion
// (efg/dynamic_cracks: f_t,dyn = DIF(rate) f_t), reads state.strain_rate_1_s.
#include <Eigen/Core>

#include "mesowave/efg/material.hpp"

namespace mesowave::efg {

struct PointState {
  Eigen::Vector3d strain = Eigen::Vector3d::Zero();  ///< at the last update, Voigt (xx, yy, xy)
  Eigen::Vector3d stress = Eigen::Vector3d::Zero();  ///< at the last update [Pa]
  double max_Y = 1.0;          ///< the largest Y(eps_v) reached on loading, Eq. (27)
  /// the most compressive volumetric strain reached (<= 0): Eq. (27) needs to tell loading (eps_v
  /// below it, on the envelope) from unloading and reloading (above it), which max_Y cannot where
  /// Y < 1 (Eq. (25) dips below 1 past e_v,th)
  double min_eps_v = 0.0;
  double modulus_scale = 1.0;  ///< tangent stiffness / D() at the last update
  /// the strain rate eps_dot = B v^{n-1/2} [1/s] (Voigt, engineering shear), set by the integrator
  /// before update (see the top of this file)
  Eigen::Vector3d strain_rate_1_s = Eigen::Vector3d::Zero();
};

class PointMaterial {
 public:
  virtual ~PointMaterial() = default;
  /// The stress [Pa] for the total `strain` (Voigt, engineering shear), updating `state` (its
  /// strain, stress, max_Y, min_eps_v and modulus_scale) for the next call.
  virtual Eigen::Vector3d update(const Eigen::Vector3d& strain, PointState& state) const = 0;
};

/// sigma = D eps, modulus_scale 1: the linear continuum of the static solver, for the dynamic one.
class LinearElasticPoint final : public PointMaterial {
 public:
  explicit LinearElasticPoint(const ElasticMaterial2D& material) : D_(material.D()) {}
  Eigen::Vector3d update(const Eigen::Vector3d& strain, PointState& state) const override {
    state.strain = strain;
    state.stress = D_ * strain;
    state.modulus_scale = 1.0;
    return state.stress;
  }

 private:
  Eigen::Matrix3d D_;
};

}  // namespace mesowave::efg
