#include "mesowave/dem/loading/rigid_wall.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mesowave/core/error.hpp"
#include "mesowave/core/check.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/dem/scene/plugins.hpp"

namespace mesowave::dem {

RigidWall::RigidWall(std::string name, SpherePart& spheres, const Box& box, Face face, double E_dem_Pa,
                     const VelocityRamp& motion, double reach_m)
    : name_(std::move(name)), face_(face), motion_(motion) {
  const int a = face.axis;
  inward_ = face.upper ? -1.0 : 1.0;
  plane0_ = face.upper ? box.upper[a] : box.lower[a];
  // A sphere can meet the wall only if the wall travels to it, or it to the
  // wall; two radii of slack cover the specimen's own motion toward the wall.
  const double reach = std::max(reach_m, 0.0) + 2.0 * spheres.radius_max();
  const SphereSet& s = spheres.spheres();
  candidates_ = spheres.select([&](std::size_t l) {
    return inward_ * (s.centre_m[l][a] - plane0_) - s.radius_m[l] <= reach;  // surface to plane, >= 0 at the start
  });
  spheres.fetch(candidates_);
  for (const std::size_t k : candidates_) {
    const double c = spheres.reference_position(k)[a], r = spheres.radius(k), m = spheres.mass(k);
    radius_.push_back(r);
    centre0_.push_back(c);
    stiffness_.push_back(E_dem_Pa * r);
    max_stiffness_per_mass_ = std::max(max_stiffness_per_mass_, E_dem_Pa * r / m);
  }
  if (candidates_.empty()) throw InputError("wall " + name_ + ": no sphere near face " + face.name());
}

double RigidWall::plane_at(double t_s) const {
  return plane0_ + inward_ * motion_.travel_m(t_s);
}

void RigidWall::before_step(Model& model, double t_s, double /*dt_s*/) {
  const int a = face_.axis;
  const double plane = plane_at(t_s);
  double total = 0;
  for (std::size_t i = 0; i < candidates_.size(); ++i) {
    const std::size_t k = candidates_[i];
    const double c = centre0_[i] + model.displacement(k)[a];
    const double u = radius_[i] - inward_ * (c - plane);  // overlap of the sphere with the wall
    if (u <= 0) continue;
    const double f = stiffness_[i] * u;
    Vec3 force;
    force[a] = inward_ * f;
    model.add_external_force(k, force);
    total += f;
  }
  last_force_ = total;
}

std::string RigidWall::description() const {
  return "rigid frictionless wall on face " + face_.name() + ", " +
         (motion_.velocity_m_s == 0 ? std::string("fixed")
                                    : "moving inward at " + format_number(motion_.velocity_m_s * 1e3) + " mm/s" +
                                          (motion_.ramp_s > 0 ? " (reached over " + format_number(motion_.ramp_s * 1e6) + " us)" : "")) +
         ", k_w = E_dem r, " + std::to_string(candidates_.size()) + " spheres within reach";
}

namespace {

// A platen: the whole face, moving inward (or fixed).
void read_wall(SceneKeys& k, ActuatorSpec& spec) {
  auto face = k.text("face");
  if (!face) throw InputError(k.where() + ": a wall needs face (x-, x+, y-, y+, z- or z+)");
  for (const char* key : {"centre_mm", "patch_mm", "point_mm", "sphere", "direction", "amplitude_N"})
    if (k.has(key)) throw InputError(k.where() + ": a wall covers its whole face and moves along its normal; drop " + key);
  spec.target.kind = SphereTarget::Kind::patch;
  spec.target.patch.face = Face::parse(*face);
  spec.target.patch.size_m[0] = spec.target.patch.size_m[1] = std::numeric_limits<double>::infinity();
  spec.direction = "inward";
  spec.amplitude = require_in_range(k.where() + ".velocity_mm_s", k.number("velocity_mm_s", 0.0), 0.0, 1e6, "mm/s") * units::mm;
  spec.delay_s = require_in_range(k.where() + ".delay_us", k.number("delay_us", 0.0), 0.0, 1e9, "us") * units::us;
  spec.ramp_s = read_ramp(k);
}

}  // namespace

void register_rigid_wall(Plugins& p) {
  p.actuators.add({
      .name = "wall",
      .summary = "a rigid frictionless wall over a whole face, fixed or moving inward (contact springs k_w = E_dem r)",
      .keys = {{"velocity_mm_s", "mm/s", 0, 1e6, "inward speed (0: fixed)"},
               {"ramp_us", "us", 0, 1e12, "time to reach it"},
               {"delay_us", "us", 0, 1e9, "start"}},
      .parse = read_wall,
      .make = [](const ActuatorSite& site) -> std::unique_ptr<Actuator> {
        const ActuatorSpec& a = site.spec;
        return std::make_unique<RigidWall>(a.name, site.statics, site.box, a.target.patch.face, site.material.E_dem_Pa,
                                           VelocityRamp{a.amplitude, a.delay_s, a.ramp_s}, a.amplitude * site.duration_s);
      },
      .peak_sphere_force = platen_peak_force,
      .amplitude_key = "velocity_mm_s",
      .report_key = "velocity_m_s",
      .moving = true,
  });
}

}  // namespace mesowave::dem
