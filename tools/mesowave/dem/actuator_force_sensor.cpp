#include "mesowave/dem/actuator_force_sensor.hpp"

namespace mesowave::dem {

ActuatorForceSensor::ActuatorForceSensor(std::string name, const Actuator& actuator, std::int64_t interval_steps)
    : name_(std::move(name)), actuator_(actuator), interval_(interval_steps) {}

void ActuatorForceSensor::record(const Model& /*model*/, std::int64_t step) {
  if (step % interval_ == 0) samples_.push_back(actuator_.applied_force());
}

signal::Signal ActuatorForceSensor::signal(double dt_s) const {
  // Forces of step n act at t_n.
  return signal::Signal{.name = name_,
                        .quantity = std::string("force"),
                        .unit = std::string("N"),
                        .component = std::string("actuator ") + actuator_.name(),
                        .t0_s = 0.0,
                        .dt_s = double(interval_) * dt_s,
                        .samples = samples_,
                        .position_m = std::nullopt};
}

std::string ActuatorForceSensor::description() const {
  return "force applied by actuator " + actuator_.name() + ", every " + std::to_string(interval_) + " steps";
}

}  // namespace mesowave::dem
