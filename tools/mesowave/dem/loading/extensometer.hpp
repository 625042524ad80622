#pragma once
// A virtual extensometer: the strain between two groups of spheres along one
// axis, as a lab reads it between two pads glued on the specimen (concrete
// paper, Section 4.2: "vertical and horizontal virtual extensometers"):
//     eps(t) = [mean_B u.e - mean_A u.e] / L0,   L0 = (c_B - c_A).e,
// u the spheres' displacements, c_A, c_B the groups' mean centres at step 0.
// Positive in extension. Sampled like a motion sensor: after step n the
// displacement is x_{n+1} - x_0, so the signal's t0 is dt.
#include <vector>

#include "mesowave/dem/loading/sensor.hpp"

namespace mesowave::dem {

class Extensometer : public Sensor {
public:
  /// `axis`: unit vector e; InputError naming the sensor if the groups are
  /// empty, share a sphere, or lie less than a sphere radius apart along e.
  Extensometer(std::string name, const SphereStatics& statics, std::vector<std::size_t> end_a, std::vector<std::size_t> end_b,
               const Vec3& axis, std::string axis_name, std::int64_t interval_steps);
  signal::Signal signal(double dt_s) const override;
  std::string description() const override;
  double gauge_length_m() const { return gauge_m_; }

protected:
  double sample(const Model& model) const override;

private:
  double mean_displacement(const Model& model, const std::vector<std::size_t>& group) const;

  std::string axis_name_;
  std::vector<std::size_t> a_, b_;
  Vec3 axis_;
  double gauge_m_ = 0;
  Vec3 midpoint_;
};

/// The number of bonds broken so far (tension or Mohr-Coulomb), sampled every
/// `interval` steps: the damage history of a test to failure.
class BrokenBondCounter : public Sensor {
public:
  BrokenBondCounter(std::string name, std::int64_t interval_steps) : Sensor(std::move(name), interval_steps) {}
  signal::Signal signal(double dt_s) const override;
  std::string description() const override;

protected:
  double sample(const Model& model) const override { return double(model.broken_bond_count()); }
};

}  // namespace mesowave::dem
