#pragma once
// Exact dispersion of the 1D monatomic lattice: the DEM chain of the rod paper
// (one line of spheres, each bonded to its two nearest neighbours, Section 4.3.2)
// is, for longitudinal motion, masses m on springs K at spacing d:
//   m u_j'' = K (u_{j+1} - 2 u_j + u_{j-1})
//   omega(k) = 2 sqrt(K/m) |sin(k d / 2)|,            0 <= k d <= pi
//   c_group  = d sqrt(K/m) cos(k d / 2),   c_phase = omega / k
// Long waves travel at c_L = d sqrt(K/m); nothing propagates above the cut-off
// omega_c = 2 sqrt(K/m) (k d = pi, zero group velocity).
#include <optional>

namespace mesowave::wave {

struct MassSpringChain {
  double mass_kg = 0;
  double stiffness_N_m = 0;
  double spacing_m = 0;
};

/// InputError unless all three are positive and finite.
void validate(const MassSpringChain& chain);

/// The rod paper's chain: spheres of radius R and particle density rho_p
/// (m = rho_p 4/3 pi R^3) with K_n = E_dem 2 R_A R_B / (R_A + R_B) = E_dem R (rod
/// paper Eq. (8), equal spheres), centres `spacing_m` apart.
MassSpringChain dem_chain(double sphere_radius_m, double particle_density_kg_m3, double E_dem_Pa,
                          double spacing_m);

double long_wave_speed(const MassSpringChain& chain);   ///< d sqrt(K/m)
double cutoff_omega(const MassSpringChain& chain);      ///< 2 sqrt(K/m)
double lattice_omega(const MassSpringChain& chain, double k_rad_m);
double lattice_group_velocity(const MassSpringChain& chain, double k_rad_m);

struct LatticePoint {
  double omega_rad_s = 0, k_rad_m = 0, c_phase_m_s = 0, c_group_m_s = 0;
};
/// The propagating wave at omega (0 < omega < omega_c); nullopt at or above the
/// cut-off (evanescent).
std::optional<LatticePoint> lattice_at_frequency(const MassSpringChain& chain, double omega_rad_s);

}  // namespace mesowave::wave
