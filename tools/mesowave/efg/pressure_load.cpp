#include "mesowave/efg/pressure_load.hpp"

#include <cmath>

#include "mesowave/core/check.hpp"

namespace mesowave::efg {

void TriangularPulse::validate() const {
  require_finite("pulse peak pressure", peak_Pa, "Pa");
  if (!std::isfinite(rise_s) || rise_s < 0) throw InputError("pulse rise time (" + format_quantity(rise_s, "s") + ") must be >= 0 and finite");
  if (!std::isfinite(fall_s) || fall_s < 0) throw InputError("pulse fall time (" + format_quantity(fall_s, "s") + ") must be >= 0 and finite");
  if (!(rise_s + fall_s > 0))
    throw InputError("pulse length (rise + fall = " + format_quantity(rise_s + fall_s, "s") + ") must be positive");
  if (!std::isfinite(start_s) || start_s < 0) throw InputError("pulse start (" + format_quantity(start_s, "s") + ") must be >= 0 and finite");
}

double TriangularPulse::operator()(double t_s) const {
  const double t = t_s - start_s;
  if (t <= 0 || t >= rise_s + fall_s) return 0.0;
  return t < rise_s ? peak_Pa * t / rise_s : peak_Pa * (rise_s + fall_s - t) / fall_s;
}

void FriedlanderPulse::validate() const {
  require_finite("Friedlander peak overpressure", peak_Pa, "Pa");
  require_positive("Friedlander positive-phase duration", positive_duration_s, "s");
  if (!std::isfinite(decay) || decay < 0)
    throw InputError("Friedlander decay coefficient (" + format_number(decay) + ") must be >= 0 and finite");
  if (!std::isfinite(start_s) || start_s < 0) throw InputError("Friedlander arrival time (" + format_quantity(start_s, "s") + ") must be >= 0 and finite");
}

double FriedlanderPulse::operator()(double t_s) const {
  const double tau = t_s - start_s;
  if (tau < 0) return 0.0;
  const double r = tau / positive_duration_s;
  return peak_Pa * (1.0 - r) * std::exp(-decay * r);
}

Eigen::Vector2d outward_normal(const Segment& edge) {
  const Eigen::Vector2d d = edge.b - edge.a;
  const double length = d.norm();
  if (!std::isfinite(length) || length <= 0)
    throw InputError("pressure segment (" + format_number(edge.a.x()) + ", " + format_number(edge.a.y()) + ") - (" +
                     format_number(edge.b.x()) + ", " + format_number(edge.b.y()) + ") m has no length");
  return Eigen::Vector2d(d.y(), -d.x()) / length;
}

Eigen::VectorXd unit_pressure_load(const ElasticModel& model, const Segment& edge, int gauss) {
  const Eigen::Vector2d traction = -outward_normal(edge);  // 1 Pa pushing into the body
  return model.traction_load(edge, [&](const Vec2&) { return traction; }, gauss);
}

}  // namespace mesowave::efg
