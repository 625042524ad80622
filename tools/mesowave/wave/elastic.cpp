#include "mesowave/wave/elastic.hpp"

#include <cmath>
#include <string>

#include "mesowave/core/check.hpp"

namespace mesowave::wave {

void validate(const IsotropicMaterial& m) {
  require_positive("Young's modulus E", m.E_Pa, "Pa");
  require_positive("density rho", m.rho_kg_m3, "kg/m3");
  if (!std::isfinite(m.nu) || m.nu <= -1.0 || m.nu >= 0.5)
    throw InputError("Poisson ratio nu (" + format_number(m.nu) +
                     ") must lie in (-1, 0.5): nu >= 0.5 is incompressible, no finite P-wave speed");
}

double lame_lambda(const IsotropicMaterial& m) { return m.E_Pa * m.nu / ((1 + m.nu) * (1 - 2 * m.nu)); }
double lame_mu(const IsotropicMaterial& m) { return m.E_Pa / (2 * (1 + m.nu)); }

double rayleigh_ratio(double nu) {
  const double kappa2 = 2 * (1 - nu) / (1 - 2 * nu);  // (cP/cS)^2
  // Cubic in s = eta^2; exactly one root in (0, 1) for -1 < nu < 0.5.
  const auto cubic = [&](double s) { return ((s - 8) * s + (24 - 16 / kappa2)) * s - 16 * (1 - 1 / kappa2); };
  double lo = 0.0, hi = 1.0;  // cubic(0) < 0 < cubic(1) = 1
  for (int i = 0; i < 200 && hi - lo > 1e-16; ++i) {
    const double mid = 0.5 * (lo + hi);
    (cubic(mid) < 0 ? lo : hi) = mid;
  }
  return std::sqrt(0.5 * (lo + hi));
}

WaveSpeeds wave_speeds(const IsotropicMaterial& m) {
  validate(m);
  WaveSpeeds c;
  c.c0 = std::sqrt(m.E_Pa / m.rho_kg_m3);
  c.cP = std::sqrt(m.E_Pa * (1 - m.nu) / (m.rho_kg_m3 * (1 + m.nu) * (1 - 2 * m.nu)));
  c.cS = std::sqrt(m.E_Pa / (2 * m.rho_kg_m3 * (1 + m.nu)));
  c.cR = rayleigh_ratio(m.nu) * c.cS;
  return c;
}

}  // namespace mesowave::wave
