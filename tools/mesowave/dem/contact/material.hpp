#pragma once
// The cohesive-frictional contact material of both papers (Yade's CohFrictMat
// and CohFrictPhys; concrete paper Eqs. 3 and 6):
//   K_n = E_dem 2 R_A R_B / (R_A + R_B),   K_s = nu_dem K_n              (Eq. 3)
//   F_n,min = T R^2,   F_s,max = C R^2,   R = min(R_A, R_B)              (Eq. 6)
#include <algorithm>
#include <limits>
#include <map>
#include <numbers>
#include <string>

namespace mesowave::dem {

struct CohesiveFrictionalMaterial {
  double E_dem_Pa = 0;            ///< E_dem, the contact modulus of Eq. (3)
  double stiffness_ratio = 0;     ///< nu_dem = K_s / K_n (Yade's CohFrictMat.poisson)
  double friction_angle_rad = 0;  ///< mu of Eqs. (4)-(5)
  double friction_angle_deg() const { return friction_angle_rad * 180 / std::numbers::pi; }
  /// T and C of Eq. (6); infinity = a bond that never breaks (no strength given).
  double tensile_strength_Pa = std::numeric_limits<double>::infinity();
  double cohesion_Pa = std::numeric_limits<double>::infinity();
  double density_kg_m3 = 0;       ///< particle density rho_p
  double damping = 0;             ///< alpha_d of Eq. (7), local non-viscous damping
  /// c of a mass-proportional viscous damping, force -c m v and torque -c I w [1/s] (0: none).
  /// Set by [model] damping_law = "viscous" in place of alpha_d (scene.hpp): a linear damping.
  double viscous_damping_1_s = 0;
  double bond_factor = 1.1;       ///< C_f: pairs with |x_j - x_i| <= C_f (r_i + r_j) are bonded at step 0

  bool breakable() const { return tensile_strength_Pa < std::numeric_limits<double>::infinity() ||
                                  cohesion_Pa < std::numeric_limits<double>::infinity(); }
};

/// A law's own parameters beyond these (material_parameters.hpp key -> SI value).
using LawParameters = std::map<std::string, double>;

/// Eq. (3): the harmonic mean of the two spheres' stiffnesses E R_A and E R_B.
inline double normal_stiffness(const CohesiveFrictionalMaterial& m, double r_a, double r_b) {
  return m.E_dem_Pa * 2.0 * r_a * r_b / (r_a + r_b);
}
inline double shear_stiffness(const CohesiveFrictionalMaterial& m, double r_a, double r_b) {
  return m.stiffness_ratio * normal_stiffness(m, r_a, r_b);
}
/// Eq. (6), with R the smaller radius.
inline double tensile_bond_strength(const CohesiveFrictionalMaterial& m, double r_a, double r_b) {
  const double r = std::min(r_a, r_b);
  return m.tensile_strength_Pa * r * r;
}
inline double shear_bond_strength(const CohesiveFrictionalMaterial& m, double r_a, double r_b) {
  const double r = std::min(r_a, r_b);
  return m.cohesion_Pa * r * r;
}

}  // namespace mesowave::dem
