#include "mesowave/dem/loading/actuator_force_sensor.hpp"

#include "mesowave/core/error.hpp"
#include "mesowave/dem/scene/plugins.hpp"

namespace mesowave::dem {

signal::Signal ActuatorForceSensor::signal(double dt_s) const {
  return recorded("force", "N", "actuator " + actuator_.name(), 0.0, dt_s);  // forces of step n act at t_n
}

std::string ActuatorForceSensor::description() const {
  return "force applied by actuator " + actuator_.name() + ", " + every();
}


namespace {

void read_force_sensor(SceneKeys& k, SensorSpec& spec, const std::string&, const std::vector<ActuatorSpec>& actuators) {
  auto actuator = k.text("actuator");
  if (!actuator) throw InputError(k.where() + ": quantity force needs actuator = NAME (the force it applies)");
  bool known = false;
  for (const auto& a : actuators) known = known || a.name == *actuator;
  if (!known) throw InputError(k.where() + ": no actuator named \"" + *actuator + "\"");
  spec.actuator = *actuator;
}

}  // namespace

void register_actuator_force_sensor(Plugins& p) {
  p.sensors.add({
      .name = "force",
      .quantities = {"force"},
      .summary = "the force an actuator applies along its direction (a load cell)",
      .keys = {{"actuator", "", 0, 0, "the actuator's name"}},
      .parse = read_force_sensor,
      .targets = [](const SensorSpec&) { return std::vector<std::pair<const SphereTarget*, std::string>>{}; },
      .make = [](const SensorSite& site, Placement& where) -> std::unique_ptr<Sensor> {
        const Actuator* source = nullptr;
        for (const auto& a : site.actuators)
          if (a->name() == site.spec.actuator) source = a.get();
        where.kind = "force of actuator " + site.spec.actuator;
        return std::make_unique<ActuatorForceSensor>(site.spec.name, *source, site.every);
      },
  });
}

}  // namespace mesowave::dem
