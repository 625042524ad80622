#pragma once
// Flowchart step 3: the static modulus of elasticity estimated from the
// dynamic one by the empirical relations of concrete paper Eqs. (11)-(13),
// compared with a static test as in its Table 1.
#include <string>
#include <vector>

namespace mesowave::lab {

/// One empirical relation E_st = f(E_d, rho). The relations are fitted in
/// GPa and kg/m3; the functions take and return pascals.
struct StaticModulusConversion {
  std::string key;      ///< short identifier for JSON keys (lydon_balendran)
  std::string name;     ///< as in Table 1
  std::string formula;  ///< with its units
  std::string equation; ///< "Eq. (11)"
  double (*estimate)(double E_d_Pa, double density_kg_m3);
};

/// Eq. (11), Lydon and Balendran: E_st = 0.83 E_d.
double lydon_balendran_static_modulus(double E_d_Pa, double density_kg_m3);
/// Eq. (12), BS 8110 Part 2: E_st = 1.25 E_d - 19 GPa. InputError when the
/// result is not positive (E_d <= 15.2 GPa is outside the relation's range).
double bs8110_static_modulus(double E_d_Pa, double density_kg_m3);
/// Eq. (13), Popovics: E_st = 446.09 E_d^1.4 / rho (E in GPa, rho in kg/m3).
double popovics_static_modulus(double E_d_Pa, double density_kg_m3);

/// The three relations in Table 1's order.
const std::vector<StaticModulusConversion>& static_modulus_conversions();

struct StaticModulusEstimate {
  const StaticModulusConversion* conversion = nullptr;  ///< null for the mean row
  double E_st_Pa = 0;
};

/// Each relation's estimate and, last, their mean (Table 1's "mean value").
std::vector<StaticModulusEstimate> estimate_static_moduli(double E_d_Pa, double density_kg_m3);

/// Signed relative error (estimate - measured) / measured.
double relative_error(double estimate, double measured);

}  // namespace mesowave::lab
