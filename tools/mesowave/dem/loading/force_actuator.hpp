#pragma once
// A force F(t) e shared equally by the spheres under an actuator (the PZT of
// both papers pushing normal to the face), F(t) a Hann-windowed sine burst;
// or a force given per step (ForceSeriesActuator: the unit impulse whose
// response superposition.hpp convolves with the bursts).
#include "mesowave/dem/loading/actuator.hpp"
#include "mesowave/signal/hann_burst.hpp"

namespace mesowave::dem {

/// The force a burst actuator applies on the step starting at t_s: the burst
/// inside [delay, end], 0 outside. The step loop and superposition.hpp both
/// sample it here, so that a superposed signal sees the same force samples.
double burst_force_N(const signal::HannBurst& burst, double t_s);

/// What both force actuators share: f(t) e divided equally among the spheres, the last force
/// reported and checkpointed (the load itself is a function of time or step alone).
class SharedForceActuator : public Actuator {
public:
  const std::string& name() const override { return name_; }
  const std::vector<std::size_t>& spheres() const override { return spheres_; }
  double applied_force() const override { return last_force_; }
  void save_state(StateGroup& group) const override { group.write("last_force_N", last_force_); }
  void load_state(const StateGroup& group) override { last_force_ = group.read_double("last_force_N"); }

protected:
  SharedForceActuator(std::string name, std::vector<std::size_t> spheres, const Vec3& direction);
  /// Records f as this step's force and, when `apply`, adds f e / count to every sphere.
  void push(Model& model, double force_N, bool apply);
  /// "along (x, y, z) shared by N spheres"
  std::string sharing_text() const;

private:
  double last_force_ = 0;
  std::string name_;
  std::vector<std::size_t> spheres_;
  Vec3 direction_;
};

class ForceActuator : public SharedForceActuator {
public:
  ForceActuator(std::string name, std::vector<std::size_t> spheres, const Vec3& direction, signal::HannBurst force_N);
  void before_step(Model& model, double t_s, double dt_s) override;
  std::string description() const override;

private:
  signal::HannBurst force_;
};

/// f_n e shared equally by the spheres on step n (t_n = n dt), 0 after the
/// last sample: {1.0} is a unit impulse on step 0, {} pushes nothing.
class ForceSeriesActuator : public SharedForceActuator {
public:
  ForceSeriesActuator(std::string name, std::vector<std::size_t> spheres, const Vec3& direction,
                      std::vector<double> force_N);
  void before_step(Model& model, double t_s, double dt_s) override;
  std::string description() const override;

private:
  std::vector<double> force_;
};

}  // namespace mesowave::dem
