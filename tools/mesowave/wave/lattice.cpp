#include "mesowave/wave/lattice.hpp"

#include <cmath>
#include <numbers>

#include "mesowave/core/check.hpp"

namespace mesowave::wave {

void validate(const MassSpringChain& c) {
  require_positive("chain mass", c.mass_kg, "kg");
  require_positive("chain stiffness", c.stiffness_N_m, "N/m");
  require_positive("chain spacing", c.spacing_m, "m");
}

MassSpringChain dem_chain(double R, double rho_p, double E_dem, double d) {
  require_positive("sphere radius", R, "m");
  require_positive("particle density", rho_p, "kg/m3");
  require_positive("contact modulus", E_dem, "Pa");
  require_positive("sphere spacing", d, "m");
  const double mass = rho_p * 4.0 / 3.0 * std::numbers::pi * R * R * R;
  const double K = E_dem * 2 * R * R / (R + R);  // rod paper Eq. (8), R_A = R_B = R
  return {mass, K, d};
}

double long_wave_speed(const MassSpringChain& c) { return c.spacing_m * std::sqrt(c.stiffness_N_m / c.mass_kg); }
double cutoff_omega(const MassSpringChain& c) { return 2 * std::sqrt(c.stiffness_N_m / c.mass_kg); }

double lattice_omega(const MassSpringChain& c, double k) {
  return cutoff_omega(c) * std::abs(std::sin(k * c.spacing_m / 2));
}

double lattice_group_velocity(const MassSpringChain& c, double k) {
  return long_wave_speed(c) * std::cos(k * c.spacing_m / 2);
}

std::optional<LatticePoint> lattice_at_frequency(const MassSpringChain& c, double omega) {
  validate(c);
  const double wc = cutoff_omega(c);
  if (!(omega > 0) || omega >= wc) return std::nullopt;
  LatticePoint p;
  p.omega_rad_s = omega;
  p.k_rad_m = 2 / c.spacing_m * std::asin(omega / wc);
  p.c_phase_m_s = omega / p.k_rad_m;
  // cos(k d / 2) = sqrt(1 - (omega / omega_c)^2), exact and free of the asin round trip.
  p.c_group_m_s = long_wave_speed(c) * std::sqrt(1 - (omega / wc) * (omega / wc));
  return p;
}

}  // namespace mesowave::wave
