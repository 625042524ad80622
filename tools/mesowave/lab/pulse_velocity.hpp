#pragma once
// Flowchart step 3, dynamic route: elastic constants of an isotropic medium
// from the ultrasonic pulse velocity (UPV) test (concrete paper Eqs. 8-10).
namespace mesowave::lab {

struct DynamicModuli {
  double v_p_m_s = 0;
  double v_s_m_s = 0;      ///< 0 when only the P wave was measured
  double nu_d = 0;         ///< dynamic Poisson ratio (measured or assumed)
  double E_d_Pa = 0;       ///< dynamic Young modulus
  double G_d_Pa = 0;       ///< dynamic shear modulus, rho v_s^2
};

/// Eq. (10): nu = (0.5 r^2 - 1) / (r^2 - 1), r = v_p / v_s. InputError unless
/// r > sqrt(2) (otherwise nu <= 0, which no concrete has; the message says so).
double poisson_ratio_from_velocity_ratio(double v_p_over_v_s);

/// Eqs. (9)-(10) from the path length and both times of flight.
/// InputError for non-positive or non-finite inputs, or t_s <= t_p.
DynamicModuli dynamic_moduli_from_p_and_s(double path_m, double t_p_s, double t_s_s, double density_kg_m3);

/// P wave only, with an assumed Poisson ratio (ASTM C597):
/// E_d = rho v_p^2 (1 + nu)(1 - 2 nu) / (1 - nu); then v_s follows from Eq. (8).
DynamicModuli dynamic_moduli_from_p_only(double path_m, double t_p_s, double density_kg_m3, double nu_assumed);

}  // namespace mesowave::lab
