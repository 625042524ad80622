#pragma once
// The force an actuator applies to the specimen along its direction, sampled
// like any sensor: the load of a force burst, or the reaction of a prescribed
// motion (the platen force of a compression test).
#include "mesowave/dem/loading/actuator.hpp"
#include "mesowave/dem/loading/sensor.hpp"

namespace mesowave::dem {

class ActuatorForceSensor : public Sensor {
public:
  ActuatorForceSensor(std::string name, const Actuator& actuator, std::int64_t interval_steps)
      : Sensor(std::move(name), interval_steps), actuator_(actuator) {}
  signal::Signal signal(double dt_s) const override;
  std::string description() const override;

protected:
  double sample(const Model&) const override { return actuator_.applied_force(); }

private:
  const Actuator& actuator_;
};

}  // namespace mesowave::dem
