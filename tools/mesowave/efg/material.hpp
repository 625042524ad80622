#pragma once
// The linear-elastic continuum between the cracks of the EFG model (shock paper Section 2.4):
// 2D plane stress (a thin slab, sigma_zz = 0) or plane strain (a long body, eps_zz = 0) with a
// thickness t, so that the weak form Eq. (18) integrates sigma = D eps over t dA and a force in
// newtons is the whole thickness's. Voigt order (xx, yy, xy) with the engineering shear strain
// gamma_xy = 2 eps_xy, the order of the B matrix's rows in Eq. (17).
#include <Eigen/Core>
#include <string_view>

namespace mesowave::efg {

enum class PlaneState { plane_stress, plane_strain };

/// "plane-stress" | "plane-strain"; InputError for anything else.
PlaneState parse_plane_state(std::string_view text);
std::string_view to_string(PlaneState state);

struct ElasticMaterial2D {
  double E_Pa = 0, nu = 0, thickness_m = 0, density_kg_m3 = 0;
  PlaneState state = PlaneState::plane_stress;

  /// InputError: E <= 0, nu outside (-1, 0.5), thickness <= 0, density < 0 (0: a static model).
  void validate() const;
  /// stress = D strain, Voigt (xx, yy, xy engineering): plane stress E/(1-nu^2) [1 nu 0; nu 1 0;
  /// 0 0 (1-nu)/2], plane strain E/((1+nu)(1-2nu)) [1-nu nu 0; nu 1-nu 0; 0 0 (1-2nu)/2].
  Eigen::Matrix3d D() const;
};

}  // namespace mesowave::efg
