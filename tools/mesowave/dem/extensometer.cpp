#include "mesowave/dem/extensometer.hpp"

#include <algorithm>
#include <cmath>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"

namespace mesowave::dem {
namespace {

Vec3 mean_centre(const Model& model, const std::vector<std::size_t>& group) {
  Vec3 c{};
  for (std::size_t k : group) c += model.reference_position(k);
  return (1.0 / double(group.size())) * c;
}

}  // namespace

Extensometer::Extensometer(std::string name, const Model& model, std::vector<std::size_t> end_a,
                           std::vector<std::size_t> end_b, const Vec3& axis, std::string axis_name,
                           std::int64_t interval_steps)
    : Sensor(std::move(name), interval_steps), axis_name_(std::move(axis_name)), a_(std::move(end_a)),
      b_(std::move(end_b)), axis_(axis) {
  const std::string who = "extensometer " + this->name();
  if (a_.empty() || b_.empty()) throw InputError(who + ": an end holds no sphere");
  for (std::size_t k : a_)
    if (std::find(b_.begin(), b_.end(), k) != b_.end())
      throw InputError(who + ": both ends hold the same sphere; make the gauge length longer or the pads smaller");
  const Vec3 ca = mean_centre(model, a_), cb = mean_centre(model, b_);
  gauge_m_ = dot(cb - ca, axis_);
  midpoint_ = 0.5 * (ca + cb);
  if (!(std::abs(gauge_m_) >= model.radius(a_[0])))
    throw InputError(who + ": the ends are " + format_number(gauge_m_ * 1e3) +
                     " mm apart along the axis; an extensometer needs them at least a sphere radius apart");
}

double Extensometer::mean_displacement(const Model& model, const std::vector<std::size_t>& group) const {
  double sum = 0;
  for (std::size_t k : group) sum += dot(model.displacement(k), axis_);
  return sum / double(group.size());
}

double Extensometer::sample(const Model& model) const {
  return (mean_displacement(model, b_) - mean_displacement(model, a_)) / gauge_m_;
}

signal::Signal Extensometer::signal(double dt_s) const {
  // After step n the displacement is x_{n+1} - x_0: t0 = dt.
  return recorded("strain", "1", axis_name_, dt_s, dt_s, std::array<double, 3>{midpoint_.x, midpoint_.y, midpoint_.z});
}

std::string Extensometer::description() const {
  return "extensometer along " + axis_name_ + ", gauge length " + format_number(std::abs(gauge_m_) * 1e3) +
         " mm between " + std::to_string(a_.size()) + " and " + std::to_string(b_.size()) + " spheres, " + every();
}

signal::Signal BrokenBondCounter::signal(double dt_s) const {
  return recorded("broken_bonds", "1", "count", 0.0, dt_s);  // bonds break while the forces at x_n are computed
}

std::string BrokenBondCounter::description() const {
  return "broken bonds, " + every();
}

}  // namespace mesowave::dem
