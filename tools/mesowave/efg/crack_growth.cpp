#include "mesowave/efg/crack_growth.hpp"

#include <cmath>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"

namespace mesowave::efg {

PrincipalStrain principal_strain(const Eigen::Vector3d& e) {
  const double exx = e[0], eyy = e[1], exy = 0.5 * e[2];  // tensor shear
  const double mean = 0.5 * (exx + eyy), radius = std::hypot(0.5 * (exx - eyy), exy);
  PrincipalStrain p;
  p.largest = mean + radius;
  p.smallest = mean - radius;
  const double theta = 0.5 * std::atan2(2 * exy, exx - eyy);  // angle of the largest principal direction
  p.direction = Vec2(std::cos(theta), std::sin(theta));
  return p;
}

bool st_venant_exceeded(const Eigen::Vector3d& strain, double f_t_Pa, double E_Pa) {
  return principal_strain(strain).largest >= f_t_Pa / E_Pa;
}

Vec2 growth_direction(const Eigen::Vector3d& strain, const Vec2& heading, const CrackGrowthOptions& o) {
  Vec2 dir = o.rule == GrowthDirectionRule::prescribed ? Vec2(o.prescribed.normalized())
                                                       : Vec2(-principal_strain(strain).direction.y(),
                                                              principal_strain(strain).direction.x());
  if (dir.dot(heading) < 0) dir = -dir;
  return dir;
}

void validate(const CrackGrowthOptions& o) {
  auto text = [](double v) { return format_number(v); };
  if (!(o.segment_length_m > 0)) throw InputError("crack growth: segment length (" + text(o.segment_length_m) + " m) must be > 0");
  if (!(o.probe_fraction > 0 && o.probe_fraction <= 1))
    throw InputError("crack growth: probe fraction (" + text(o.probe_fraction) + ") must be in (0, 1]");
  if (o.rule == GrowthDirectionRule::prescribed && !(o.prescribed.norm() > 0))
    throw InputError("crack growth: the prescribed direction must not be zero");
}

}  // namespace mesowave::efg
