#pragma once
// Pressure histories on boundary segments of the explicit EFG model (shock paper Section 4: a blast
// or a contact detonation loads the concrete through a pressure on its surface). A load is a fixed
// spatial distribution times a scalar history: f_ext(t) = p(t) f_1, where f_1 is the consistent
// nodal load of a unit pressure on the segment, int N^T (-n) t ds, integrated with boundary Gauss
// points on pieces no longer than the nodal spacing (ElasticModel::traction_load). The pressure
// pushes INTO the body: n is the segment's outward normal, and the body lies LEFT of a -> b (walk
// the boundary counter-clockwise), so n = (b - a)^perp = (dy, -dx) / |b - a|.
//
// Two histories:
//  - TriangularPulse: linear rise from 0 to p0 in t_r, linear fall back to 0 in t_f, then 0 (the
//    shock paper's Section 4.2 load of the bar that steepens into a shock);
//  - FriedlanderPulse: p(t) = p_s (1 - tau/t_d) exp(-b tau/t_d), tau = t - t_a >= 0, the modified
//    Friedlander equation of a free-air blast wave (F. G. Friedlander 1946, Proc. R. Soc. A 186;
//    W. E. Baker 1973, "Explosions in Air", Ch. 6): peak overpressure p_s at the arrival time t_a, a
//    positive phase of duration t_d, a negative phase after it (p < 0: suction), the decay
//    coefficient b. Its parameters are the caller's (e.g. from Kingery-Bulmash charts for a charge
//    mass and stand-off); none is built in.
// Both start at `start_s` (before it, p = 0).
#include <functional>
#include <string>
#include <vector>

#include "mesowave/efg/elastic_model.hpp"

namespace mesowave::efg {

using PressureHistory = std::function<double(double t_s)>;  ///< p(t) [Pa], > 0 compresses

struct TriangularPulse {
  double peak_Pa = 0, rise_s = 0, fall_s = 0, start_s = 0;
  /// InputError: peak not finite, rise or fall < 0, rise + fall <= 0 (the pulse has no length), start < 0.
  void validate() const;
  double operator()(double t_s) const;
  double duration_s() const { return rise_s + fall_s; }
};

struct FriedlanderPulse {
  double peak_Pa = 0, positive_duration_s = 0, decay = 1, start_s = 0;
  /// InputError: peak not finite, positive duration <= 0, decay < 0, start < 0.
  void validate() const;
  double operator()(double t_s) const;
};

/// A pressure p(t) on the boundary segment a -> b (body on its left).
struct PressureLoad {
  Segment edge;
  PressureHistory pressure;
  std::string name;
};

/// f_1 of a unit pressure (1 Pa) on `edge` (body left of a -> b), consistent with `model`'s MLS.
Eigen::VectorXd unit_pressure_load(const ElasticModel& model, const Segment& edge, int gauss = 4);
/// The outward unit normal of a -> b: (dy, -dx) / |b - a|. InputError for a segment of no length.
Eigen::Vector2d outward_normal(const Segment& edge);

}  // namespace mesowave::efg
