#include "mesowave/dem/motion_sensor.hpp"

#include "mesowave/core/error.hpp"

namespace mesowave::dem {

MotionQuantity parse_motion_quantity(const std::string& text) {
  if (text == "acceleration") return MotionQuantity::acceleration;
  if (text == "velocity") return MotionQuantity::velocity;
  if (text == "displacement") return MotionQuantity::displacement;
  throw InputError("sensor quantity \"" + text + "\" must be acceleration, velocity, displacement or force");
}

std::string to_string(MotionQuantity q) {
  switch (q) {
    case MotionQuantity::acceleration: return "acceleration";
    case MotionQuantity::velocity: return "velocity";
    case MotionQuantity::displacement: return "displacement";
  }
  return "";
}

MotionSensor::MotionSensor(std::string name, std::vector<std::size_t> spheres, MotionQuantity quantity,
                           const Vec3& component, std::string component_name, std::int64_t interval_steps,
                           const Vec3& position_m)
    : name_(std::move(name)), spheres_(std::move(spheres)), quantity_(quantity), component_(component),
      component_name_(std::move(component_name)), interval_(interval_steps), position_(position_m) {}

void MotionSensor::prepare(std::int64_t steps) { samples_.reserve(std::size_t(steps / interval_ + 1)); }

void MotionSensor::record(const Model& model, std::int64_t step) {
  if (step % interval_ != 0) return;
  Vec3 sum{};
  for (std::size_t k : spheres_) {
    switch (quantity_) {
      case MotionQuantity::acceleration: sum += model.acceleration(k); break;
      case MotionQuantity::velocity: sum += model.velocity(k); break;
      case MotionQuantity::displacement: sum += model.displacement(k); break;
    }
  }
  const Vec3 mean = (1.0 / double(spheres_.size())) * sum;
  const bool magnitude = norm2(component_) == 0;
  samples_.push_back(magnitude ? norm(mean) : dot(mean, component_));
}

signal::Signal MotionSensor::signal(double dt_s) const {
  signal::Signal s;
  s.name = name_;
  s.quantity = to_string(quantity_);
  s.unit = quantity_ == MotionQuantity::acceleration ? "m/s^2" : quantity_ == MotionQuantity::velocity ? "m/s" : "m";
  s.component = component_name_;
  s.t0_s = quantity_ == MotionQuantity::acceleration ? 0.0 : quantity_ == MotionQuantity::velocity ? 0.5 * dt_s : dt_s;
  s.dt_s = double(interval_) * dt_s;
  s.samples = samples_;
  s.position_m = std::array<double, 3>{position_.x, position_.y, position_.z};
  return s;
}

std::string MotionSensor::description() const {
  return to_string(quantity_) + " (" + component_name_ + ") averaged over " + std::to_string(spheres_.size()) +
         " spheres, every " + std::to_string(interval_) + " steps";
}

}  // namespace mesowave::dem
