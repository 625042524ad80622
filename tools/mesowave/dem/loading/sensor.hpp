#pragma once
// A sensor samples the model after steps; one class per kind, one file each
// (motion_sensor, actuator_force_sensor, extensometer), each kind registered
// by name with its scene keys and factory (plugins.hpp). The simulation calls
// record(model, n) after step n; a sensor takes a sample every `interval`
// steps and says what one sample is.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "mesowave/dem/engine/model.hpp"
#include "mesowave/signal/signal.hpp"

namespace mesowave::dem {

class Sensor {
public:
  Sensor(std::string name, std::int64_t interval_steps) : name_(std::move(name)), interval_(interval_steps) {}
  virtual ~Sensor() = default;
  const std::string& name() const { return name_; }
  /// Reserves room for `steps` steps (no allocation while running).
  void prepare(std::int64_t steps) { samples_.reserve(std::size_t(steps / interval_ + 1)); }
  void record(const Model& model, std::int64_t step) {
    if (step % interval_ == 0) samples_.push_back(sample(model));
  }
  /// What it has recorded so far (one value per sample).
  const std::vector<double>& samples() const { return samples_; }
  virtual signal::Signal signal(double dt_s) const = 0;
  virtual std::string description() const = 0;
  /// The samples recorded so far (a checkpoint, state_group.hpp); a kind with
  /// state of its own overrides both and calls these.
  virtual void save_state(StateGroup& group) const { group.write("samples", samples_); }
  virtual void load_state(const StateGroup& group) { samples_ = group.read_doubles("samples"); }

protected:
  /// One sample of the model as it is after a step. It reads only the spheres of its
  /// groups (SensorSite::groups): on several MPI ranks every rank holds those, not the
  /// others (docs/mpi.md).
  virtual double sample(const Model& model) const = 0;
  std::int64_t interval() const { return interval_; }
  /// The recorded signal: this sensor's name and samples, one every interval steps from t0.
  signal::Signal recorded(std::string quantity, std::string unit, std::string component, double t0_s, double dt_s,
                          std::optional<std::array<double, 3>> position_m = std::nullopt) const {
    return signal::Signal{.name = name_, .quantity = std::move(quantity), .unit = std::move(unit),
                          .component = std::move(component), .t0_s = t0_s, .dt_s = double(interval_) * dt_s,
                          .samples = samples_, .position_m = position_m};
  }
  std::string every() const { return "every " + std::to_string(interval_) + " steps"; }

private:
  std::string name_;
  std::int64_t interval_;
  std::vector<double> samples_;
};

}  // namespace mesowave::dem
