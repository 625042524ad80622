#pragma once
// A prescribed displacement u(t) e of the spheres under an actuator (Yade: a
// blocked degree of freedom moved at the imposed velocity); components across
// e stay free. u(t) is a Hann-windowed sine burst (a PZT driven in
// displacement) or a constant velocity v t (a platen of a compression test:
// the spheres of a face move together along its normal and slide freely
// across it, i.e. a frictionless wall that also holds them).
#include <functional>

#include "mesowave/dem/loading/actuator.hpp"
#include "mesowave/dem/loading/velocity_ramp.hpp"
#include "mesowave/signal/hann_burst.hpp"

namespace mesowave::dem {

class DisplacementActuator : public Actuator {
public:
  DisplacementActuator(std::string name, std::vector<std::size_t> spheres, const Vec3& direction,
                       std::function<double(double)> displacement_m, std::string what);
  static DisplacementActuator burst(std::string name, std::vector<std::size_t> spheres, const Vec3& direction,
                                    const signal::HannBurst& displacement_m);
  static DisplacementActuator constant_velocity(std::string name, std::vector<std::size_t> spheres,
                                                const Vec3& direction, const VelocityRamp& motion);
  const std::string& name() const override { return name_; }
  void after_step(Model& model, double t_s, double dt_s) override;
  const std::vector<std::size_t>& spheres() const override { return spheres_; }
  std::string description() const override;
  double applied_force() const override { return last_force_; }
  /// Its load is a function of time alone: only the last force carries over.
  void save_state(StateGroup& group) const override { group.write("last_force_N", last_force_); }
  void load_state(const StateGroup& group) override { last_force_ = group.read_double("last_force_N"); }

private:
  std::string name_;
  std::vector<std::size_t> spheres_;
  Vec3 direction_;
  std::function<double(double)> displacement_;
  std::string what_;
  double last_force_ = 0;
};

}  // namespace mesowave::dem
