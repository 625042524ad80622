#include "mesowave/efg/material.hpp"

#include <cmath>
#include <string>

#include "mesowave/core/check.hpp"

namespace mesowave::efg {

PlaneState parse_plane_state(std::string_view text) {
  if (text == "plane-stress") return PlaneState::plane_stress;
  if (text == "plane-strain") return PlaneState::plane_strain;
  throw InputError("plane state '" + std::string(text) + "' must be plane-stress or plane-strain");
}

std::string_view to_string(PlaneState state) {
  return state == PlaneState::plane_stress ? "plane-stress" : "plane-strain";
}

void ElasticMaterial2D::validate() const {
  require_positive("Young's modulus E", E_Pa, "Pa");
  if (!std::isfinite(nu) || nu <= -1.0 || nu >= 0.5)
    throw InputError("Poisson ratio nu (" + format_number(nu) +
                     ") must lie in (-1, 0.5): nu >= 0.5 is incompressible (the plane-strain D is infinite)");
  require_positive("thickness", thickness_m, "m");
  if (!std::isfinite(density_kg_m3) || density_kg_m3 < 0)
    throw InputError("density (" + format_quantity(density_kg_m3, "kg/m3") + ") must be >= 0 and finite");
}

Eigen::Matrix3d ElasticMaterial2D::D() const {
  validate();
  Eigen::Matrix3d D = Eigen::Matrix3d::Zero();
  if (state == PlaneState::plane_stress) {
    const double c = E_Pa / (1 - nu * nu);
    D << c, c * nu, 0, c * nu, c, 0, 0, 0, c * (1 - nu) / 2;
  } else {
    const double c = E_Pa / ((1 + nu) * (1 - 2 * nu));
    D << c * (1 - nu), c * nu, 0, c * nu, c * (1 - nu), 0, 0, 0, c * (1 - 2 * nu) / 2;
  }
  return D;
}

}  // namespace mesowave::efg
