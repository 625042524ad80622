#include "mesowave/dem/force_actuator.hpp"

#include "mesowave/core/format.hpp"

namespace mesowave::dem {

ForceActuator::ForceActuator(std::string name, std::vector<std::size_t> spheres, const Vec3& direction,
                             signal::HannBurst force_N)
    : name_(std::move(name)), spheres_(std::move(spheres)), direction_((1.0 / norm(direction)) * direction),
      force_(force_N) {}

void ForceActuator::before_step(Model& model, double t_s, double /*dt_s*/) {
  last_force_ = 0;
  if (t_s < force_.delay_s() || t_s > force_.end_s()) return;
  last_force_ = force_(t_s);
  const Vec3 share = (last_force_ / double(spheres_.size())) * direction_;
  for (std::size_t k : spheres_) model.add_external_force(k, share);
}

std::string ForceActuator::description() const {
  return "force " + format_number(force_.amplitude()) + " N, " + format_number(force_.centre_frequency_hz() / 1e3) +
         " kHz " + format_number(force_.cycles()) + "-cycle Hann burst along (" + format_number(direction_.x + 0.0) + ", " +
         format_number(direction_.y + 0.0) + ", " + format_number(direction_.z + 0.0) + ") shared by " +
         std::to_string(spheres_.size()) + " spheres";
}

}  // namespace mesowave::dem
