#pragma once
// The strain-rate effect on the strength of concrete (shock paper Section 3.3): the dynamic
// increase factor DIF = f_dyn / f_static of the tensile and compressive strength, from a published
// formula, with the cap the paper asks for ("in contrary to the CEB Bulletin the strength factor
// should be limited": strengths have not been measured above 100 1/s, blasting reaches 1e6 1/s).
//
// CEB-FIP Model Code 1990, Section 2.1.6.4.3 (the strain-rate forms, Eqs. 2.1-43 to 2.1-49 of the
// code; the coefficients as the code prints them and as Malvar & Crawford 1998, "Dynamic increase
// factors for concrete", 28th DDESB Seminar, quote them - no stored copy of the code was at hand to
// check the numbering of each line), f_cm0 = 10 MPa:
//   compression, eps_0 = 30e-6 1/s (magnitudes):
//     DIF = (rate / eps_0)^(1.026 alpha_s)           for rate <= 30 1/s
//     DIF = gamma_s (rate / eps_0)^(1/3)             for rate >  30 1/s
//     alpha_s = 1 / (5 + 9 f_cm / f_cm0),  log10 gamma_s = 6.156 alpha_s - 2
//   tension, eps_0 = 3e-6 1/s:
//     DIF = (rate / eps_0)^(1.016 delta_s)           for rate <= 30 1/s
//     DIF = beta_s (rate / eps_0)^(1/3)              for rate >  30 1/s
//     delta_s = 1 / (10 + 6 f_cm / f_cm0),  log10 beta_s = 7.11 delta_s - 2.33
// The compressive branches meet exactly at 30 1/s (6.156 = 6 x 1.026); the tensile ones as printed
// do not quite (continuity needs 7.112 delta_s - 7/3): the code's rounding leaves a jump of
// 10^(1/300 - 0.002 delta_s) - 1, +0.75 % at f_cm = 30 MPa. Kept as printed.
//
// Malvar & Ross 1998, "Review of strain rate effects for concrete in tension", ACI Materials
// Journal 95(6) 735-739: the formula it proposes (the CEB form refitted to tension data up to
// 157 1/s; its equation numbers not checked against a stored copy), for tension only:
//     DIF = (rate / 1e-6)^delta                      for rate <= 1 1/s
//     DIF = beta (rate / 1e-6)^(1/3)                 for rate >  1 1/s
//     delta = 1 / (1 + 8 f_c / f_c0), f_c0 = 10 MPa,  log10 beta = 6 delta - 2 (continuous at 1 1/s)
//
// Below the reference rate eps_0 (a static test) DIF = 1 (the formulas would give < 1 there).
// The cap: above max_strain_rate_1_s the DIF stays at its value there. Default 100 1/s, assumed:
// the paper's Section 3.3 gives 100 1/s as the highest rate with measured strengths, so the factor
// is not extrapolated beyond the data (compression 2.33, tension 2.70 by CEB and 8.07 by Malvar &
// Ross at f_cm = 30 MPa).
#include <Eigen/Core>
#include <string_view>

namespace mesowave::efg {

enum class TensileDifLaw { ceb_fip_1990, malvar_ross_1998 };

/// "ceb-fip-1990" | "malvar-ross-1998"; InputError for anything else.
TensileDifLaw parse_tensile_dif_law(std::string_view text);
std::string_view to_string(TensileDifLaw law);

struct StrainRateParameters {
  double f_cm_Pa = 0;                 ///< static mean compressive strength: sets alpha_s, delta_s (required)
  double max_strain_rate_1_s = 100;   ///< the cap (see the top of this file)
  TensileDifLaw tension = TensileDifLaw::ceb_fip_1990;

  /// InputError: f_cm outside (0, 200] MPa (the range the formulas were fitted to: normal to
  /// high-strength concrete), max_strain_rate_1_s below 30e-6 1/s (no dynamic range left) or
  /// not finite.
  void validate() const;
};

/// f_c,dyn / f_c for the strain-rate magnitude `rate_1_s` >= 0 (CEB-FIP 1990, capped).
double compressive_dif(double rate_1_s, const StrainRateParameters& p);
/// f_t,dyn / f_t for the strain-rate magnitude `rate_1_s` >= 0 (p.tension's law, capped).
double tensile_dif(double rate_1_s, const StrainRateParameters& p);

/// The in-plane principal strain rates of a Voigt rate (xx, yy, engineering xy) [1/s]: the
/// stretching one (the largest principal rate, clipped at 0) for the tensile strength and the
/// shortening one (minus the smallest, clipped at 0) for the compressive strength.
struct PrincipalStrainRates {
  double tension_1_s = 0, compression_1_s = 0;
};
PrincipalStrainRates principal_strain_rates(const Eigen::Vector3d& strain_rate_1_s);

/// f_t,dyn = tensile_dif(rate) f_t [Pa] of a point whose strain rate (Voigt, PointState::strain_rate_1_s)
/// is `strain_rate_1_s`: the rate is the stretching principal rate (principal_strain_rates), the rate of
/// the direction that opens a crack; a point that only shortens keeps the static f_t (DIF 1 at rate 0).
double dynamic_tensile_strength_Pa(double f_t_Pa, const Eigen::Vector3d& strain_rate_1_s, const StrainRateParameters& p);

}  // namespace mesowave::efg
