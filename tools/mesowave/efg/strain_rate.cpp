#include "mesowave/efg/strain_rate.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "mesowave/core/check.hpp"

namespace mesowave::efg {
namespace {

constexpr double f_cm0_Pa = 10e6;  // CEB-FIP 1990 and Malvar & Ross: the strength unit 10 MPa

double checked_rate(double rate_1_s, const StrainRateParameters& p) {
  if (!std::isfinite(rate_1_s) || rate_1_s < 0)
    throw InputError("strain rate (" + format_quantity(rate_1_s, "1/s") + ") must be >= 0 and finite");
  p.validate();
  return std::min(rate_1_s, p.max_strain_rate_1_s);
}

/// The bilinear log-log form the three formulas share: (r / r0)^low below r_t, g (r / r0)^(1/3) above, 1 below r0.
double bilinear_dif(double rate, double rate_0, double rate_t, double low_exponent, double log10_g) {
  if (rate <= rate_0) return 1.0;
  const double ratio = rate / rate_0;
  return rate <= rate_t ? std::pow(ratio, low_exponent) : std::pow(10.0, log10_g) * std::cbrt(ratio);
}

}  // namespace

TensileDifLaw parse_tensile_dif_law(std::string_view text) {
  if (text == "ceb-fip-1990") return TensileDifLaw::ceb_fip_1990;
  if (text == "malvar-ross-1998") return TensileDifLaw::malvar_ross_1998;
  throw InputError("tensile DIF law '" + std::string(text) + "' must be ceb-fip-1990 or malvar-ross-1998");
}

std::string_view to_string(TensileDifLaw law) {
  return law == TensileDifLaw::ceb_fip_1990 ? "ceb-fip-1990" : "malvar-ross-1998";
}

void StrainRateParameters::validate() const {
  if (!std::isfinite(f_cm_Pa) || f_cm_Pa <= 0 || f_cm_Pa > 200e6)
    throw InputError("compressive strength f_cm (" + format_quantity(f_cm_Pa / 1e6, "MPa") +
                     ") must lie in (0, 200] MPa, the range the DIF formulas were fitted to");
  if (!std::isfinite(max_strain_rate_1_s) || max_strain_rate_1_s < 30e-6)
    throw InputError("DIF cap max_strain_rate (" + format_quantity(max_strain_rate_1_s, "1/s") +
                     ") must be finite and at least the static reference rate 30e-6 1/s");
}

double compressive_dif(double rate_1_s, const StrainRateParameters& p) {
  const double rate = checked_rate(rate_1_s, p);
  const double alpha_s = 1 / (5 + 9 * p.f_cm_Pa / f_cm0_Pa);
  return bilinear_dif(rate, 30e-6, 30, 1.026 * alpha_s, 6.156 * alpha_s - 2);
}

double tensile_dif(double rate_1_s, const StrainRateParameters& p) {
  const double rate = checked_rate(rate_1_s, p);
  if (p.tension == TensileDifLaw::ceb_fip_1990) {
    const double delta_s = 1 / (10 + 6 * p.f_cm_Pa / f_cm0_Pa);
    return bilinear_dif(rate, 3e-6, 30, 1.016 * delta_s, 7.11 * delta_s - 2.33);
  }
  const double delta = 1 / (1 + 8 * p.f_cm_Pa / f_cm0_Pa);
  return bilinear_dif(rate, 1e-6, 1, delta, 6 * delta - 2);
}

PrincipalStrainRates principal_strain_rates(const Eigen::Vector3d& r) {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(r(i))) throw InputError("strain rate component " + std::to_string(i) + " is not finite");
  const double mean = 0.5 * (r(0) + r(1));
  const double radius = std::hypot(0.5 * (r(0) - r(1)), 0.5 * r(2));  // engineering shear: eps_xy = gamma / 2
  return {std::max(0.0, mean + radius), std::max(0.0, radius - mean)};
}

double dynamic_tensile_strength_Pa(double f_t_Pa, const Eigen::Vector3d& strain_rate_1_s, const StrainRateParameters& p) {
  return tensile_dif(principal_strain_rates(strain_rate_1_s).tension_1_s, p) * f_t_Pa;
}

}  // namespace mesowave::efg
