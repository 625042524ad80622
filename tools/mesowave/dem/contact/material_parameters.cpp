#include "mesowave/dem/contact/material_parameters.hpp"

#include <numbers>

#include "mesowave/core/error.hpp"
#include "mesowave/core/units.hpp"

namespace mesowave::dem {

const std::vector<MaterialParameter>& material_parameters() {
  using M = CohesiveFrictionalMaterial;
  static const std::vector<MaterialParameter> table = {
      {"E_dem_GPa", "E_dem", "GPa", true, 0, 0, "--E-dem-GPa", "E_dem_Pa", "Contact modulus E_dem of Eq. (3) [GPa]",
       &M::E_dem_Pa, [](double v) { return v * units::GPa; }},
      {"nu_dem", "nu_dem", "", false, 0.0, 10.0, "--nu-dem", "nu_dem", "Stiffness ratio nu_dem = K_s / K_n (Eq. 3)",
       &M::stiffness_ratio, [](double v) { return v; }},
      {"friction_angle_deg", "mu", "deg", false, 0.0, 89.9, "--friction-angle-deg", "friction_angle_rad",
       "Friction angle mu of Eqs. (4)-(5) [deg]", &M::friction_angle_rad,
       [](double v) { return v * std::numbers::pi / 180.0; }},
      {"T_MPa", "T", "MPa", true, 0, 0, "--T-MPa", "T_Pa", "Normal (tensile) bond strength T of Eq. (6) [MPa]",
       &M::tensile_strength_Pa, [](double v) { return v * units::MPa; }},
      {"C_MPa", "C", "MPa", true, 0, 0, "--C-MPa", "C_Pa", "Shear cohesion C of Eq. (6) [MPa]", &M::cohesion_Pa,
       [](double v) { return v * units::MPa; }},
      {"density_kg_m3", "rho_p", "kg/m3", true, 0, 0, "", "density_kg_m3",
       "Particle density rho_p (default: the packing file's) [kg/m3]", &M::density_kg_m3, [](double v) { return v; }},
      {"damping", "alpha_d", "", false, 0.0, 0.99, "--damping", "damping", "Local damping alpha_d of Eq. (7)",
       &M::damping, [](double v) { return v; }},
      {"bond_factor", "C_f", "", true, 0, 0, "--bond-factor", "bond_factor",
       "Detection factor C_f: pairs within C_f (r_i + r_j) are bonded at step 0", &M::bond_factor,
       [](double v) { return v; }},
  };
  return table;
}

const MaterialParameter& material_parameter(const std::string& key, const std::string& who) {
  for (const auto& p : material_parameters())
    if (p.key == key) return p;
  throw InputError(who + ": unknown material key \"" + key + "\"");
}

}  // namespace mesowave::dem
