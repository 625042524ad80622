#include "mesowave/lab/pulse_velocity.hpp"

#include <cmath>

#include "mesowave/core/check.hpp"
#include "mesowave/core/format.hpp"

namespace mesowave::lab {

double poisson_ratio_from_velocity_ratio(double r) {
  require_positive("v_p/v_s", r);
  const double r2 = r * r;
  if (r <= std::sqrt(2.0)) {
    const double nu = (r2 == 1.0) ? -INFINITY : (0.5 * r2 - 1.0) / (r2 - 1.0);
    throw InputError("v_p/v_s = " + format_fixed(r, 4) + " must exceed sqrt(2) = 1.4142: Eq. (10) would give nu_d = " +
                     format_fixed(nu, 3) + " <= 0, which no concrete has (check the S-wave pick)");
  }
  return (0.5 * r2 - 1.0) / (r2 - 1.0);
}

DynamicModuli dynamic_moduli_from_p_and_s(double path_m, double t_p_s, double t_s_s, double rho) {
  require_positive("path", path_m, "m");
  require_positive("t_p", t_p_s, "s");
  require_positive("t_s", t_s_s, "s");
  require_positive("density", rho, "kg/m3");
  if (t_s_s <= t_p_s)
    throw InputError("t_s (" + format_quantity(t_s_s * 1e6, "us") + ") must exceed t_p (" +
                     format_quantity(t_p_s * 1e6, "us") + "): the shear wave is the slower one");
  DynamicModuli m;
  m.v_p_m_s = path_m / t_p_s;
  m.v_s_m_s = path_m / t_s_s;
  m.nu_d = poisson_ratio_from_velocity_ratio(m.v_p_m_s / m.v_s_m_s);  // Eq. (10)
  m.G_d_Pa = rho * m.v_s_m_s * m.v_s_m_s;
  m.E_d_Pa = 2.0 * m.G_d_Pa * (1.0 + m.nu_d);  // Eq. (9)
  return m;
}

DynamicModuli dynamic_moduli_from_p_only(double path_m, double t_p_s, double rho, double nu) {
  require_positive("path", path_m, "m");
  require_positive("t_p", t_p_s, "s");
  require_positive("density", rho, "kg/m3");
  if (!std::isfinite(nu) || nu <= 0.0 || nu >= 0.5)
    throw InputError("assumed Poisson ratio (" + format_number(nu) + ") must lie strictly between 0 and 0.5");
  DynamicModuli m;
  m.v_p_m_s = path_m / t_p_s;
  m.nu_d = nu;
  m.E_d_Pa = rho * m.v_p_m_s * m.v_p_m_s * (1.0 + nu) * (1.0 - 2.0 * nu) / (1.0 - nu);  // Eq. (8), P wave
  m.G_d_Pa = m.E_d_Pa / (2.0 * (1.0 + nu));
  m.v_s_m_s = std::sqrt(m.G_d_Pa / rho);  // Eq. (8), S wave
  return m;
}

}  // namespace mesowave::lab
