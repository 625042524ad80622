#include "mesowave/efg/shock_front.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"

namespace mesowave::efg {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The compression in [0, s_max] where f' is least: a scan (the tangent of the Y-function has one
// minimum, the quadratic's is at 0), refined by golden sections inside the best scan interval.
double least_tangent(const CompressionLaw& law, double s_max) {
  const int n = 2000;
  int best = 0;
  for (int i = 1; i <= n; ++i)
    if (law.tangent_Pa(s_max * i / n) < law.tangent_Pa(s_max * best / n)) best = i;
  double a = s_max * std::max(0, best - 1) / n, b = s_max * std::min(n, best + 1) / n;
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int it = 0; it < 80; ++it) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    if (law.tangent_Pa(c) < law.tangent_Pa(d)) b = d;
    else a = c;
  }
  return 0.5 * (a + b);
}
}  // namespace

double arrival_time(const WaveStripResult& r, std::size_t k, double level) {
  const auto& t = r.run.sample_t_s;
  const auto& S = r.run.sensors.at(k);
  for (std::size_t i = 1; i < t.size(); ++i) {
    const double a = -S[i - 1].stress_Pa(0), b = -S[i].stress_Pa(0);
    if (a < level && b >= level) return t[i - 1] + (t[i] - t[i - 1]) * (level - a) / (b - a);
  }
  return kNaN;
}

double bar_1d_shock_speed(const CompressionLaw& law, double rho, const TriangularPulse& pulse, double length_m,
                          double duration_s, double x_a, double x_b, double level, const BarShockSpeedOptions& bar) {
  const double h = bar.spacing_m;
  if (!(h > 0) || !(length_m >= 4 * h))
    throw InputError("1D bar: cell length " + format_quantity(h, "m") + " must be > 0 and at most a quarter of the length " +
                     format_quantity(length_m, "m"));
  if (!(x_a >= h && x_a < x_b && x_b <= length_m - 2 * h))
    throw InputError("1D bar: stations " + format_quantity(x_a, "m") + ", " + format_quantity(x_b, "m") +
                     " must be ascending and inside the bar");
  bar.viscosity.validate();
  const double M = law.tangent_Pa(0), C0 = bar.viscosity.quadratic, C1 = bar.viscosity.linear;
  const auto n = std::size_t(std::lround(length_m / h));
  std::vector<double> u(n + 1, 0.0), v(n + 1, 0.0), m(n + 1, rho * h), p(n, 0.0);
  m.front() = m.back() = 0.5 * rho * h;
  const auto pressure = [&](double s) { return s > 0 ? law.pressure_Pa(s) : M * s; };
  const auto station = [&](double x) {  // -sigma_xx at x, linear between cell centres
    const double f = x / h - 0.5;
    const auto j = std::size_t(std::floor(f));
    const double w = f - double(j);
    const double sj = -(u[j + 1] - u[j]) / h, sk = -(u[j + 2] - u[j + 1]) / h;
    return (1 - w) * pressure(sj) + w * pressure(sk);
  };
  double t = 0, ta = -1, tb = -1, pa = 0, pb = 0;
  while (t < duration_s && tb < 0) {
    double dt = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < n; ++j) {
      const double s = -(u[j + 1] - u[j]) / h, rate = -(v[j + 1] - v[j]) / h;
      const double c = std::sqrt((s > 0 ? law.tangent_Pa(s) : M) / rho);
      const double Q = rate > 0 ? C1 * c + C0 * h * rate : 0.0;
      dt = std::min(dt, 0.5 * h / (Q + std::sqrt(Q * Q + c * c)));
      p[j] = pressure(s) + (rate > 0 ? rho * h * Q * rate : 0.0);  // q = rho h (C_0 h s_dot + C_1 c) s_dot
    }
    const double load = pulse(t);
    for (std::size_t i = 0; i <= n; ++i) v[i] += dt * ((i == 0 ? load : p[i - 1]) - (i == n ? 0.0 : p[i])) / m[i];
    for (std::size_t i = 0; i <= n; ++i) u[i] += dt * v[i];
    t += dt;
    const double qa = station(x_a), qb = station(x_b);
    if (ta < 0 && qa >= level) ta = t - dt * (qa - level) / (qa - pa);
    if (tb < 0 && qb >= level) tb = t - dt * (qb - level) / (qb - pb);
    pa = qa, pb = qb;
  }
  return ta >= 0 && tb > ta ? (x_b - x_a) / (tb - ta) : kNaN;
}

ShockFrontComparison compare_front_with_characteristics(const WaveStripOptions& o, const WaveStripResult& r,
                                                        const CompressionLaw& law, const BarShockSpeedOptions* bar) {
  if (o.pulse != "triangular" || o.custom)
    throw InputError("the characteristics' reference needs the triangular pulse (--pulse triangular)");
  const TriangularPulse& pulse = o.triangular;
  if (pulse.start_s != 0) throw InputError("the characteristics' reference needs the pulse to start at t = 0 (--start-us 0)");
  const double rho = o.density_kg_m3, p_max = pulse.peak_Pa, t_r = pulse.rise_s;
  ShockFrontComparison c;
  c.formation = shock_formation(law, rho, pulse);
  c.c_0_m_s = wave_speed_m_s(law, rho, 0);
  const double s_max = compression_at_pressure(law, p_max);
  c.p_hi_Pa = 0.9 * p_max;
  c.p_lo_Pa = std::max(0.1 * p_max, law.pressure_Pa(least_tangent(law, s_max)));
  c.s_lo = compression_at_pressure(law, c.p_lo_Pa), c.s_hi = compression_at_pressure(law, c.p_hi_Pa);
  c.c_lo_m_s = wave_speed_m_s(law, rho, c.s_lo), c.c_hi_m_s = wave_speed_m_s(law, rho, c.s_hi);
  const double w0 = (c.p_hi_Pa - c.p_lo_Pa) / p_max * t_r, slowness = 1 / c.c_hi_m_s - 1 / c.c_lo_m_s;
  c.meet_distance_m = slowness < 0 ? -w0 / slowness : kNaN;
  c.meet_time_s = c.p_hi_Pa / p_max * t_r + c.meet_distance_m / c.c_hi_m_s;
  // least squares lines width(x) and arrival_hi(x) over the sensors before x_b
  double n = 0, sx = 0, sxx = 0, sw = 0, sxw = 0, sa = 0, sxa = 0;
  for (std::size_t k = 0; k < r.sensors.size(); ++k) {
    FrontWidth f;
    f.x_m = r.sensors[k].x.x();
    const double hi = arrival_time(r, k, c.p_hi_Pa);
    f.width_s = hi - arrival_time(r, k, c.p_lo_Pa);
    f.simple_wave_width_s = w0 + f.x_m * slowness;
    f.before_breaking = !c.formation.forms || f.x_m < c.formation.distance_m;
    if (f.before_breaking && std::isfinite(f.width_s))
      n += 1, sx += f.x_m, sxx += f.x_m * f.x_m, sw += f.width_s, sxw += f.x_m * f.width_s, sa += hi, sxa += f.x_m * hi;
    c.fronts.push_back(f);
  }
  c.fitted_sensors = int(n);
  c.measured_meet_distance_m = c.measured_meet_time_s = kNaN;
  if (n >= 2 && n * sxx - sx * sx > 0) {
    const double det = n * sxx - sx * sx;
    const double w_slope = (n * sxw - sx * sw) / det, w_icpt = (sw - w_slope * sx) / n;
    const double a_slope = (n * sxa - sx * sa) / det, a_icpt = (sa - a_slope * sx) / n;
    if (w_slope < 0) {
      c.measured_meet_distance_m = -w_icpt / w_slope;
      c.measured_meet_time_s = a_icpt + a_slope * c.measured_meet_distance_m;
    }
  }
  c.speed_level_Pa = 0.5 * (c.p_lo_Pa + c.p_hi_Pa);
  c.shock_speed_m_s = kNaN;
  const std::size_t m = r.sensors.size();
  // a shock only past the levels' meeting: before it the front is still the simple wave's ramp
  if (m >= 2 && r.sensors[m - 2].x.x() > c.meet_distance_m) {
    const double dt = arrival_time(r, m - 1, c.speed_level_Pa) - arrival_time(r, m - 2, c.speed_level_Pa);
    if (dt > 0) c.shock_speed_m_s = (r.sensors[m - 1].x.x() - r.sensors[m - 2].x.x()) / dt;
  }
  c.jump_speed_m_s = shock_speed_m_s(law, rho, c.s_lo, c.s_hi);
  c.bar_speed_m_s = kNaN;
  if (bar && std::isfinite(c.shock_speed_m_s)) {
    c.bar_spacing_m = bar->spacing_m;
    c.bar_speed_m_s = bar_1d_shock_speed(law, rho, pulse, o.length_m, o.dynamics.duration_s, r.sensors[m - 2].x.x(),
                                         r.sensors[m - 1].x.x(), c.speed_level_Pa, *bar);
  }
  return c;
}

}  // namespace mesowave::efg
