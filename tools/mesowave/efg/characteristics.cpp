#include "mesowave/efg/characteristics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "mesowave/core/check.hpp"

namespace mesowave::efg {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

/// One emitted characteristic: its time, level and speed.
struct Ray {
  double tau, s, c;
};

Ray ray(const CompressionLaw& law, double rho, double p_Pa, double tau) {
  const double s = compression_at_pressure(law, p_Pa);
  return {tau, s, wave_speed_m_s(law, rho, s)};
}

/// tau + T(tau) of the envelope formula for the pressure p and its rate dp at tau (inf: no crossing).
double breaking_time(const CompressionLaw& law, double p, double dp, double tau) {
  const double s = compression_at_pressure(law, std::max(0.0, p));  // round-off at the pulse's end
  const double f1 = law.tangent_Pa(s), f2 = law.curvature_Pa(s);
  return f2 * dp > 0 ? tau + 2 * f1 * f1 / (f2 * dp) : inf;
}

void check_pulse(const TriangularPulse& pulse) {
  pulse.validate();
  require_positive("pulse peak", pulse.peak_Pa, "Pa");
  require_positive("pulse rise time", pulse.rise_s, "s");
}

}  // namespace

LinearCompression::LinearCompression(double M_Pa) : M_(require_positive("modulus M", M_Pa, "Pa")) {}

QuadraticStiffening::QuadraticStiffening(double M_Pa, double beta)
    : M_(require_positive("modulus M", M_Pa, "Pa")), beta_(require_positive("stiffening beta", beta)) {}

QuadraticStiffeningPoint::QuadraticStiffeningPoint(const ElasticMaterial2D& material, double beta)
    : material_(material), beta_(require_positive("stiffening beta", beta)), D_(material.D()) {}

Eigen::Vector3d QuadraticStiffeningPoint::update(const Eigen::Vector3d& strain, PointState& state) const {
  // compressions s = max(0, -eps_v) at both ends; g is linear in s, so its mean over the part of the
  // increment in compression is 1 + beta (s_a + s_b), weighted by that part's share of the increment
  const double a = -volumetric_strain(state.strain, material_), b = -volumetric_strain(strain, material_);
  double g = 1 + 2 * beta_ * std::max(0.0, a);
  if (a != b) {
    const double lo = std::min(a, b), hi = std::max(a, b), c_lo = std::max(0.0, lo);
    const double compressed = std::max(0.0, hi - c_lo);  // the length of [lo, hi] with s > 0
    g = 1 + (compressed > 0 ? beta_ * (c_lo + std::max(0.0, hi)) * compressed / (hi - lo) : 0.0);
  }
  state.stress += g * (D_ * (strain - state.strain));
  state.strain = strain;
  state.modulus_scale = 1 + 2 * beta_ * std::max(0.0, b);
  return state.stress;
}

HugoniotCompression::HugoniotCompression(double M_Pa, const HugoniotParameters& parameters)
    : M_(require_positive("modulus M", M_Pa, "Pa")), p_(parameters) {
  p_.validate();
}
double HugoniotCompression::pressure_Pa(double s) const { return M_ * hugoniot_compression_integral(-s, p_); }
double HugoniotCompression::tangent_Pa(double s) const { return M_ * hugoniot_Y(-s, p_); }
double HugoniotCompression::curvature_Pa(double s) const { return M_ * hugoniot_dY_dcompression(-s, p_); }

double wave_speed_m_s(const CompressionLaw& law, double density_kg_m3, double s) {
  require_positive("density", density_kg_m3, "kg/m3");
  return std::sqrt(law.tangent_Pa(s) / density_kg_m3);
}

double compression_at_pressure(const CompressionLaw& law, double p_Pa) {
  if (!std::isfinite(p_Pa) || p_Pa < 0)
    throw InputError("pressure (" + format_quantity(p_Pa, "Pa") + ") must be >= 0 and finite");
  if (p_Pa == 0) return 0;
  double lo = 0, hi = p_Pa / law.tangent_Pa(0);
  while (law.pressure_Pa(hi) < p_Pa) {
    lo = hi;
    hi *= 2;
  }
  while (hi - lo > 1e-15 * hi) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (law.pressure_Pa(mid) < p_Pa ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

ShockFormation shock_formation(const CompressionLaw& law, double rho, const TriangularPulse& pulse, int samples) {
  check_pulse(pulse);
  require_positive("density", rho, "kg/m3");
  if (samples < 2) throw InputError("shock_formation samples (" + std::to_string(samples) + ") must be >= 2");
  ShockFormation best;
  double best_t = inf;
  // Each phase on its own: p linear in tau with the rate dp, over [a, b].
  struct Phase {
    double a, b, p_a, dp;
    bool loading;
  };
  const double t0 = pulse.start_s, t1 = t0 + pulse.rise_s, t2 = t1 + pulse.fall_s;
  const Phase phases[2] = {{t0, t1, 0, pulse.peak_Pa / pulse.rise_s, true},
                           {t1, t2, pulse.peak_Pa, pulse.fall_s > 0 ? -pulse.peak_Pa / pulse.fall_s : 0, false}};
  for (const Phase& ph : phases) {
    if (ph.b <= ph.a) continue;  // an instant drop: its levels leave together and fan out
    const auto t_of = [&](double tau) { return breaking_time(law, ph.p_a + ph.dp * (tau - ph.a), ph.dp, tau); };
    const double h = (ph.b - ph.a) / samples;
    int i_min = -1;
    double t_min = inf;
    for (int i = 0; i <= samples; ++i) {
      const double t = t_of(ph.a + h * i);
      if (t < t_min) t_min = t, i_min = i;
    }
    if (i_min < 0) continue;
    // golden-section search between the neighbours of the best sample (T is smooth there)
    double lo = ph.a + h * std::max(0, i_min - 1), hi = ph.a + h * std::min(samples, i_min + 1);
    const double g = 0.5 * (std::sqrt(5.0) - 1);
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = t_of(x1), f2 = t_of(x2);
    for (int it = 0; it < 200 && hi - lo > 1e-12 * (ph.b - ph.a); ++it) {
      if (f1 < f2) {
        hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo), f1 = t_of(x1);
      } else {
        lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo), f2 = t_of(x2);
      }
    }
    double tau = 0.5 * (lo + hi), t = t_of(tau);
    if (t_min < t) tau = ph.a + h * i_min, t = t_min;  // a minimum at the phase's end stays there
    if (t < best_t) {
      best_t = t;
      const double s = compression_at_pressure(law, std::max(0.0, ph.p_a + ph.dp * (tau - ph.a)));
      best.forms = true;
      best.time_s = t;
      best.emitted_at_s = tau;
      best.compression = s;
      best.wave_speed_m_s = wave_speed_m_s(law, rho, s);
      best.distance_m = best.wave_speed_m_s * (t - tau);
      best.loading = ph.loading;
    }
  }
  return best;
}

ShockFormation traced_first_crossing(const CompressionLaw& law, double rho, const TriangularPulse& pulse, int count,
                                     bool all_pairs) {
  check_pulse(pulse);
  require_positive("density", rho, "kg/m3");
  if (count < 2) throw InputError("characteristic count (" + std::to_string(count) + ") must be >= 2");
  std::vector<Ray> rays;
  rays.reserve(count + 1);
  for (int i = 0; i <= count; ++i) {
    const double tau = pulse.start_s + pulse.duration_s() * i / count;
    rays.push_back(ray(law, rho, std::max(0.0, pulse(tau)), tau));
  }
  ShockFormation best;
  double best_t = inf;
  const auto consider = [&](const Ray& a, const Ray& b) {  // a emitted before b
    if (b.c <= a.c) return;                                 // b never catches a
    const double t = (b.c * b.tau - a.c * a.tau) / (b.c - a.c);
    if (t < best_t) {
      best_t = t;
      best.forms = true;
      best.time_s = t;
      best.distance_m = a.c * (t - a.tau);
      best.emitted_at_s = a.tau;
      best.compression = a.s;
      best.wave_speed_m_s = a.c;
      best.loading = a.tau < pulse.start_s + pulse.rise_s;
    }
  };
  for (std::size_t i = 0; i + 1 < rays.size(); ++i) {
    if (all_pairs)
      for (std::size_t j = i + 1; j < rays.size(); ++j) consider(rays[i], rays[j]);
    else
      consider(rays[i], rays[i + 1]);
  }
  return best;
}

double shock_speed_m_s(const CompressionLaw& law, double rho, double s_ahead, double s_behind) {
  require_positive("density", rho, "kg/m3");
  if (!std::isfinite(s_ahead) || !std::isfinite(s_behind) || s_ahead < 0 || s_behind < 0 || s_ahead == s_behind)
    throw InputError("shock states (s = " + format_number(s_ahead) + ", " + format_number(s_behind) +
                     ") must be two different compressions >= 0");
  return std::sqrt((law.pressure_Pa(s_behind) - law.pressure_Pa(s_ahead)) / (rho * (s_behind - s_ahead)));
}

}  // namespace mesowave::efg
