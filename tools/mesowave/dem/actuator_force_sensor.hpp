#pragma once
// The force an actuator applies to the specimen along its direction, sampled
// like any sensor: the load of a force burst, or the reaction of a prescribed
// motion (the platen force of a compression test).
#include <vector>

#include "mesowave/dem/actuator.hpp"
#include "mesowave/dem/sensor.hpp"

namespace mesowave::dem {

class ActuatorForceSensor : public Sensor {
public:
  ActuatorForceSensor(std::string name, const Actuator& actuator, std::int64_t interval_steps);
  const std::string& name() const override { return name_; }
  void prepare(std::int64_t steps) override { samples_.reserve(std::size_t(steps / interval_ + 1)); }
  void record(const Model& model, std::int64_t step) override;
  signal::Signal signal(double dt_s) const override;
  std::string description() const override;
  const std::vector<double>& samples() const override { return samples_; }

private:
  std::string name_;
  const Actuator& actuator_;
  std::int64_t interval_;
  std::vector<double> samples_;
};

}  // namespace mesowave::dem
