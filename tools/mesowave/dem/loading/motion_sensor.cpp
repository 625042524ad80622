#include "mesowave/dem/loading/motion_sensor.hpp"

#include "mesowave/core/error.hpp"
#include "mesowave/dem/scene/plugins.hpp"

namespace mesowave::dem {

MotionSensor::MotionSensor(std::string name, std::vector<std::size_t> spheres, MotionQuantity quantity,
                           const Vec3& component, std::string component_name, std::int64_t interval_steps,
                           const Vec3& position_m)
    : Sensor(std::move(name), interval_steps), spheres_(std::move(spheres)), quantity_(quantity),
      component_(component), component_name_(std::move(component_name)), position_(position_m) {}

double MotionSensor::sample(const Model& model) const {
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
  return magnitude ? norm(mean) : dot(mean, component_);
}

signal::Signal MotionSensor::signal(double dt_s) const {
  const bool a = quantity_ == MotionQuantity::acceleration, v = quantity_ == MotionQuantity::velocity;
  return recorded(to_string(quantity_), si_unit(quantity_), component_name_, a ? 0.0 : v ? 0.5 * dt_s : dt_s,
                  dt_s, std::array<double, 3>{position_.x, position_.y, position_.z});
}

std::string MotionSensor::description() const {
  return to_string(quantity_) + " (" + component_name_ + ") averaged over " + std::to_string(spheres_.size()) +
         " spheres, " + every();
}


namespace {

void read_motion_sensor(SceneKeys& k, SensorSpec& spec, const std::string& quantity, const std::vector<ActuatorSpec>&) {
  spec.quantity = experiment::parse_motion_quantity(quantity, k.where() + ".quantity");
  spec.target = read_target(k);
  spec.component = k.text("component", spec.target.kind == SphereTarget::Kind::patch ? "normal" : "");
  if (spec.component.empty()) throw InputError(k.where() + " needs component (x, -x, ..., magnitude) when it is not on a face");
  if (spec.component == "inward") throw InputError(k.where() + ".component must be normal, an axis or magnitude");
  direction_vector(spec.component, spec.target, k.where(), std::nullopt, true);
}

}  // namespace

void register_motion_sensor(Plugins& p) {
  p.sensors.add({
      .name = "motion",
      .quantities = [] {
        std::vector<std::string> names;
        for (MotionQuantity q : experiment::motion_quantities) names.push_back(to_string(q));
        return names;
      }(),
      .summary = "acceleration, velocity or displacement averaged over the spheres under a patch (or one sphere)",
      .keys = {{"component", "", 0, 0, "normal | line | x | -x | ... | magnitude"},
               {"sample_interval_ns", "ns", 0, 1e12, "time between samples (every step)"}},
      .parse = read_motion_sensor,
      .targets = [](const SensorSpec& spec) {
        return std::vector<std::pair<const SphereTarget*, std::string>>{{&spec.target, ""}};
      },
      .make = [](const SensorSite& site, Placement& where) -> std::unique_ptr<Sensor> {
        const SensorSpec& sensor = site.spec;
        const std::vector<std::size_t>& chosen = site.groups[0];
        const Vec3 component = direction_vector(sensor.component, sensor.target, "sensor " + sensor.name, site.line);
        where.kind = to_string(sensor.quantity);
        where.spheres = packing_indices(site.statics, chosen);
        where.direction = component;
        Vec3 position{};
        for (std::size_t k : chosen) position += site.statics.reference_position(k);
        position = (1.0 / double(chosen.size())) * position;
        return std::make_unique<MotionSensor>(sensor.name, chosen, sensor.quantity, component, sensor.component,
                                              site.every, position);
      },
  });
}

}  // namespace mesowave::dem
