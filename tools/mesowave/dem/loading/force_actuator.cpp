#include "mesowave/dem/loading/force_actuator.hpp"

#include <cmath>

#include "mesowave/core/format.hpp"
#include "mesowave/dem/scene/plugins.hpp"

namespace mesowave::dem {

SharedForceActuator::SharedForceActuator(std::string name, std::vector<std::size_t> spheres, const Vec3& direction)
    : name_(std::move(name)), spheres_(std::move(spheres)), direction_((1.0 / norm(direction)) * direction) {}

void SharedForceActuator::push(Model& model, double force_N, bool apply) {
  last_force_ = force_N;
  if (!apply) return;
  const Vec3 share = (force_N / double(spheres_.size())) * direction_;
  for (std::size_t k : spheres_) model.add_external_force(k, share);
}

std::string SharedForceActuator::sharing_text() const {
  return "along (" + format_number(direction_.x + 0.0) + ", " + format_number(direction_.y + 0.0) + ", " +
         format_number(direction_.z + 0.0) + ") shared by " + std::to_string(spheres_.size()) + " spheres";
}

ForceActuator::ForceActuator(std::string name, std::vector<std::size_t> spheres, const Vec3& direction,
                             signal::HannBurst force_N)
    : SharedForceActuator(std::move(name), std::move(spheres), direction), force_(force_N) {}

double burst_force_N(const signal::HannBurst& burst, double t_s) {
  if (t_s < burst.delay_s() || t_s > burst.end_s()) return 0.0;
  return burst(t_s);
}

void ForceActuator::before_step(Model& model, double t_s, double /*dt_s*/) {
  push(model, burst_force_N(force_, t_s), t_s >= force_.delay_s() && t_s <= force_.end_s());
}

std::string ForceActuator::description() const {
  return "force " + format_number(force_.amplitude()) + " N, " + format_number(force_.centre_frequency_hz() / 1e3) +
         " kHz " + format_number(force_.cycles()) + "-cycle Hann burst " + sharing_text();
}

ForceSeriesActuator::ForceSeriesActuator(std::string name, std::vector<std::size_t> spheres, const Vec3& direction,
                                         std::vector<double> force_N)
    : SharedForceActuator(std::move(name), std::move(spheres), direction), force_(std::move(force_N)) {}

void ForceSeriesActuator::before_step(Model& model, double t_s, double dt_s) {
  const auto n = std::llround(t_s / dt_s);  // t_s = n dt_s exactly (the step loop's time)
  const double f = n >= 0 && std::size_t(n) < force_.size() ? force_[std::size_t(n)] : 0.0;
  push(model, f, f != 0);
}

std::string ForceSeriesActuator::description() const {
  const std::string what = force_.empty()       ? "no force"
                           : force_.size() == 1 ? "force " + format_number(force_[0]) + " N on step 0 (an impulse)"
                                                : "force given on " + std::to_string(force_.size()) + " steps";
  return what + " " + sharing_text();
}

}  // namespace mesowave::dem

namespace mesowave::dem {

void register_force_actuator(Plugins& p) {
  p.actuators.add({
      .name = "force",
      .summary = "a Hann-windowed force burst shared by the spheres under a patch (a PZT driven in force)",
      .keys = {{"amplitude_N", "N", -1e12, 1e12, "peak force"},
               {"frequency_kHz", "kHz", 0, 1e9, "centre frequency"},
               {"cycles", "", 0, 1e9, "cycles of the burst (5)"},
               {"delay_us", "us", 0, 1e9, "start"}},
      .parse = [](SceneKeys& k, ActuatorSpec& spec) { read_actuator_load(k, spec, 1.0, true); },
      .make = [](const ActuatorSite& site) -> std::unique_ptr<Actuator> {
        const ActuatorSpec& a = site.spec;
        return std::make_unique<ForceActuator>(a.name, site.spheres, site.direction,
                                               signal::HannBurst(a.frequency_hz, a.cycles, a.amplitude, a.delay_s));
      },
      .peak_sphere_force = [](const ActuatorSpec& a, std::size_t spheres, double, double) {
        return std::abs(a.amplitude) / double(spheres);
      },
      .amplitude_key = "amplitude_N",
      .report_key = "amplitude_N",
  });
}

}  // namespace mesowave::dem
