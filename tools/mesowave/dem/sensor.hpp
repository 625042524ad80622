#pragma once
// A sensor samples the model after steps; one class per kind, one file each
// (motion_sensor). The simulation calls record(model, n) after step n.
#include <cstdint>
#include <string>
#include <vector>

#include "mesowave/dem/model.hpp"
#include "mesowave/signal/signal.hpp"

namespace mesowave::dem {

class Sensor {
public:
  virtual ~Sensor() = default;
  virtual const std::string& name() const = 0;
  /// Reserves room for `steps` steps (no allocation while running).
  virtual void prepare(std::int64_t steps) = 0;
  virtual void record(const Model& model, std::int64_t step) = 0;
  virtual signal::Signal signal(double dt_s) const = 0;
  /// What it has recorded so far (one value per sample).
  virtual const std::vector<double>& samples() const = 0;
  virtual std::string description() const = 0;
};

}  // namespace mesowave::dem
