#pragma once
// Acceleration, velocity or displacement of the spheres under a patch (or of
// one sphere), averaged over them, one component: x, y, z, the outward normal
// of the sensor's face, or the magnitude of the averaged vector. Sampled
// every `interval` steps. Leapfrog staggers the three quantities: after step
// n the acceleration is a_n (t_n), the velocity v_{n+1/2} (t_n + dt/2) and
// the displacement x_{n+1} - x_0 (t_n + dt); each signal's t0 says which.
#include <vector>

#include "mesowave/dem/loading/sensor.hpp"
#include "mesowave/experiment/motion_quantity.hpp"

namespace mesowave::dem {

/// The lab's quantity (experiment/motion_quantity.hpp: its one parser, names and units).
using experiment::MotionQuantity;

class MotionSensor : public Sensor {
public:
  /// `component`: a unit vector, or a zero vector for the magnitude;
  /// `component_name` as written in the signal file (x, normal, magnitude...).
  MotionSensor(std::string name, std::vector<std::size_t> spheres, MotionQuantity quantity, const Vec3& component,
               std::string component_name, std::int64_t interval_steps, const Vec3& position_m);
  signal::Signal signal(double dt_s) const override;
  std::string description() const override;
  const std::vector<std::size_t>& spheres() const { return spheres_; }

protected:
  double sample(const Model& model) const override;

private:
  std::vector<std::size_t> spheres_;
  MotionQuantity quantity_;
  Vec3 component_;
  std::string component_name_;
  Vec3 position_;
};

}  // namespace mesowave::dem
