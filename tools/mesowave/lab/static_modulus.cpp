#include "mesowave/lab/static_modulus.hpp"

#include <cmath>

#include "mesowave/core/check.hpp"
#include "mesowave/core/format.hpp"

namespace mesowave::lab {
namespace {

constexpr double kGPa = 1e9;

}  // namespace

double lydon_balendran_static_modulus(double E_d_Pa, double) { return 0.83 * E_d_Pa; }

double bs8110_static_modulus(double E_d_Pa, double) {
  const double E_st = (1.25 * E_d_Pa / kGPa - 19.0) * kGPa;
  if (E_st <= 0)
    throw InputError("E_d (" + format_quantity(E_d_Pa / kGPa, "GPa") +
                     ") is too small for BS 8110-2: 1.25 E_d - 19 GPa gives a non-positive static modulus (" +
                     format_fixed(E_st / kGPa, 3) + " GPa); the relation needs E_d > 15.2 GPa");
  return E_st;
}

double popovics_static_modulus(double E_d_Pa, double density_kg_m3) {
  return 446.09 * std::pow(E_d_Pa / kGPa, 1.4) / density_kg_m3 * kGPa;
}

const std::vector<StaticModulusConversion>& static_modulus_conversions() {
  static const std::vector<StaticModulusConversion> conversions = {
      {"lydon_balendran", "Lydon and Balendran", "0.83 E_d", "Eq. (11)", &lydon_balendran_static_modulus},
      {"bs8110", "BS 8110 Part 2", "1.25 E_d - 19 [GPa]", "Eq. (12)", &bs8110_static_modulus},
      {"popovics", "Popovics", "446.09 E_d^1.4 / rho [GPa, kg/m3]", "Eq. (13)", &popovics_static_modulus},
  };
  return conversions;
}

std::vector<StaticModulusEstimate> estimate_static_moduli(double E_d_Pa, double rho) {
  require_positive("E_d", E_d_Pa, "Pa");
  require_positive("density", rho, "kg/m3");
  std::vector<StaticModulusEstimate> rows;
  double sum = 0;
  for (const auto& c : static_modulus_conversions()) {
    rows.push_back({&c, c.estimate(E_d_Pa, rho)});
    sum += rows.back().E_st_Pa;
  }
  rows.push_back({nullptr, sum / double(static_modulus_conversions().size())});
  return rows;
}

double relative_error(double estimate, double measured) { return (estimate - measured) / measured; }

}  // namespace mesowave::lab
