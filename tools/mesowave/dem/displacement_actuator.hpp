#pragma once
// A prescribed displacement u(t) e of the spheres under an actuator, u(t) a
// Hann-windowed sine burst (Yade: a blocked degree of freedom moved at the
// imposed velocity). Components across e stay free.
#include "mesowave/dem/actuator.hpp"
#include "mesowave/signal/hann_burst.hpp"

namespace mesowave::dem {

class DisplacementActuator : public Actuator {
public:
  DisplacementActuator(std::string name, std::vector<std::size_t> spheres, const Vec3& direction,
                       signal::HannBurst displacement_m);
  const std::string& name() const override { return name_; }
  void after_step(Model& model, double t_s, double dt_s) override;
  const std::vector<std::size_t>& spheres() const override { return spheres_; }
  std::string description() const override;

private:
  std::string name_;
  std::vector<std::size_t> spheres_;
  Vec3 direction_;
  signal::HannBurst displacement_;
};

}  // namespace mesowave::dem
