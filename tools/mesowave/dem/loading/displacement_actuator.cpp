#include "mesowave/dem/loading/displacement_actuator.hpp"

#include <cmath>

#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/dem/scene/plugins.hpp"

namespace mesowave::dem {

DisplacementActuator::DisplacementActuator(std::string name, std::vector<std::size_t> spheres, const Vec3& direction,
                                           std::function<double(double)> displacement_m, std::string what)
    : name_(std::move(name)), spheres_(std::move(spheres)), direction_((1.0 / norm(direction)) * direction),
      displacement_(std::move(displacement_m)), what_(std::move(what)) {}

DisplacementActuator DisplacementActuator::burst(std::string name, std::vector<std::size_t> spheres,
                                                 const Vec3& direction, const signal::HannBurst& u) {
  return DisplacementActuator(std::move(name), std::move(spheres), direction, [u](double t) { return u(t); },
                              "displacement " + format_number(u.amplitude() * 1e9) + " nm, " +
                                  format_number(u.centre_frequency_hz() / 1e3) + " kHz " + format_number(u.cycles()) +
                                  "-cycle Hann burst");
}

DisplacementActuator DisplacementActuator::constant_velocity(std::string name, std::vector<std::size_t> spheres,
                                                             const Vec3& direction, const VelocityRamp& motion) {
  return DisplacementActuator(std::move(name), std::move(spheres), direction,
                              [motion](double t) { return motion.travel_m(t); },
                              "constant velocity " + format_number(motion.velocity_m_s * 1e3) + " mm/s" +
                                  (motion.ramp_s > 0 ? " (reached over " + format_number(motion.ramp_s * 1e6) + " us)" : ""));
}

void DisplacementActuator::after_step(Model& model, double t_s, double dt_s) {
  // The constraint holds at every step, also where u = 0 (before and after a burst).
  const double u_now = displacement_(t_s), u_next = displacement_(t_s + dt_s);
  last_force_ = 0;
  for (std::size_t k : spheres_) last_force_ += model.impose_displacement(k, direction_, u_now, u_next, dt_s);
}

std::string DisplacementActuator::description() const {
  return what_ + " along (" + format_number(direction_.x + 0.0) + ", " + format_number(direction_.y + 0.0) + ", " +
         format_number(direction_.z + 0.0) + ") imposed on " + std::to_string(spheres_.size()) + " spheres";
}

}  // namespace mesowave::dem

namespace mesowave::dem {

void register_displacement_actuators(Plugins& p) {
  p.actuators.add({
      .name = "displacement",
      .summary = "a Hann-windowed displacement burst imposed on the spheres under a patch",
      .keys = {{"amplitude_nm", "nm", -1e12, 1e12, "peak displacement"},
               {"frequency_kHz", "kHz", 0, 1e9, "centre frequency"},
               {"cycles", "", 0, 1e9, "cycles of the burst (5)"},
               {"delay_us", "us", 0, 1e9, "start"}},
      .parse = [](SceneKeys& k, ActuatorSpec& spec) { read_actuator_load(k, spec, units::nm, true); },
      .make = [](const ActuatorSite& site) -> std::unique_ptr<Actuator> {
        const ActuatorSpec& a = site.spec;
        return std::make_unique<DisplacementActuator>(DisplacementActuator::burst(
            a.name, site.spheres, site.direction, signal::HannBurst(a.frequency_hz, a.cycles, a.amplitude, a.delay_s)));
      },
      .peak_sphere_force = [](const ActuatorSpec& a, std::size_t, double stiffest_kn, double) {
        return stiffest_kn * std::abs(a.amplitude);
      },
      .amplitude_key = "amplitude_nm",
      .report_key = "amplitude_m",
  });
  p.actuators.add({
      .name = "velocity",
      .summary = "a platen: the spheres under a patch moved at a constant velocity (reached over ramp_us)",
      .keys = {{"velocity_mm_s", "mm/s", -1e12, 1e12, "platen speed"},
               {"ramp_us", "us", 0, 1e12, "time to reach it"},
               {"delay_us", "us", 0, 1e9, "start"}},
      .parse = [](SceneKeys& k, ActuatorSpec& spec) { read_actuator_load(k, spec, units::mm, false); },
      .make = [](const ActuatorSite& site) -> std::unique_ptr<Actuator> {
        const ActuatorSpec& a = site.spec;
        return std::make_unique<DisplacementActuator>(DisplacementActuator::constant_velocity(
            a.name, site.spheres, site.direction, VelocityRamp{a.amplitude, a.delay_s, a.ramp_s}));
      },
      .peak_sphere_force = platen_peak_force,
      .amplitude_key = "velocity_mm_s",
      .report_key = "velocity_m_s",
      .moving = true,
  });
}

}  // namespace mesowave::dem
