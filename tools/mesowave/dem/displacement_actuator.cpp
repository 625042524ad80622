#include "mesowave/dem/displacement_actuator.hpp"

#include "mesowave/core/format.hpp"

namespace mesowave::dem {

DisplacementActuator::DisplacementActuator(std::string name, std::vector<std::size_t> spheres, const Vec3& direction,
                                           signal::HannBurst displacement_m)
    : name_(std::move(name)), spheres_(std::move(spheres)), direction_((1.0 / norm(direction)) * direction),
      displacement_(displacement_m) {}

void DisplacementActuator::after_step(Model& model, double t_s, double dt_s) {
  // The constraint holds at every step, also before and after the burst (u = 0 there).
  const double u_now = displacement_(t_s), u_next = displacement_(t_s + dt_s);
  for (std::size_t k : spheres_) model.impose_displacement(k, direction_, u_now, u_next, dt_s);
}

std::string DisplacementActuator::description() const {
  return "displacement " + format_number(displacement_.amplitude() * 1e9) + " nm, " +
         format_number(displacement_.centre_frequency_hz() / 1e3) + " kHz " + format_number(displacement_.cycles()) +
         "-cycle Hann burst along (" + format_number(direction_.x) + ", " + format_number(direction_.y) + ", " +
         format_number(direction_.z) + ") imposed on " + std::to_string(spheres_.size()) + " spheres";
}

}  // namespace mesowave::dem
