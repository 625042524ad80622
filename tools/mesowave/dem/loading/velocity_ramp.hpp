#pragma once
// How far a platen has travelled by time t when it starts at `delay` and
// reaches its velocity V over `ramp` with a half-cosine,
//   v(t) = V (1 - cos(pi s / ramp)) / 2 for s = t - delay < ramp, V after,
// so that the specimen is not hit by a velocity step (a step sends a stress
// wave rho c V through it; a lab machine ramps its crosshead too).
#include <cmath>
#include <numbers>

namespace mesowave::dem {

struct VelocityRamp {
  double velocity_m_s = 0, delay_s = 0, ramp_s = 0;

  double travel_m(double t_s) const {
    const double s = t_s - delay_s;
    if (s <= 0) return 0;
    if (s >= ramp_s) return velocity_m_s * (s - 0.5 * ramp_s);
    const double w = std::numbers::pi / ramp_s;
    return 0.5 * velocity_m_s * (s - std::sin(w * s) / w);
  }
};

}  // namespace mesowave::dem
