#include "mesowave/dem/actuator_force_sensor.hpp"

namespace mesowave::dem {

signal::Signal ActuatorForceSensor::signal(double dt_s) const {
  return recorded("force", "N", "actuator " + actuator_.name(), 0.0, dt_s);  // forces of step n act at t_n
}

std::string ActuatorForceSensor::description() const {
  return "force applied by actuator " + actuator_.name() + ", " + every();
}

}  // namespace mesowave::dem
