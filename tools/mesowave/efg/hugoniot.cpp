#include "mesowave/efg/hugoniot.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "mesowave/core/check.hpp"

namespace mesowave::efg {
namespace {

/// Eq. (25) in x = |eps_v| - e_v,th >= 0.
double Y_of_x(double x, const HugoniotParameters& p) {
  const double q = x / (p.b_v * p.e_v);
  return (1 - p.a_v * (1 - std::exp(-x / p.e_v))) * (1 + q * q);
}

double dY_dx(double x, const HugoniotParameters& p) {
  const double E = std::exp(-x / p.e_v), k = 1 / ((p.b_v * p.e_v) * (p.b_v * p.e_v));
  return -(p.a_v / p.e_v) * E * (1 + k * x * x) + (1 - p.a_v * (1 - E)) * 2 * k * x;
}

/// The integral of Eq. (25) from x = 0 to X: (1 - a)(X + k X^3 / 3) + a e (1 - E)
/// + a k (2 e^3 (1 - E) - E (e X^2 + 2 e^2 X)), E = exp(-X / e), k = 1 / (b e)^2.
double integral_of_x(double X, const HugoniotParameters& p) {
  const double e = p.e_v, a = p.a_v, k = 1 / ((p.b_v * e) * (p.b_v * e));
  const double one_minus_E = -std::expm1(-X / e), E = 1 - one_minus_E;
  return (1 - a) * (X + k * X * X * X / 3) + a * e * one_minus_E +
         a * k * (2 * e * e * e * one_minus_E - E * (e * X * X + 2 * e * e * X));
}

}  // namespace

void HugoniotParameters::validate() const {
  if (!std::isfinite(e_v_th) || e_v_th < 0)
    throw InputError("Hugoniot threshold e_v_th (" + format_number(e_v_th) + ") must be >= 0 and finite");
  require_positive("Hugoniot strain scale e_v", e_v);
  if (!std::isfinite(a_v) || a_v < 0 || a_v >= 1)
    throw InputError("Hugoniot softening a_v (" + format_number(a_v) +
                     ") must lie in [0, 1): a_v >= 1 leaves no stiffness far past the threshold");
  require_positive("Hugoniot stiffening scale b_v", b_v);
}

double hugoniot_Y(double eps_v, const HugoniotParameters& p) {
  const double x = -eps_v - p.e_v_th;
  return x > 0 ? Y_of_x(x, p) : 1.0;
}

double hugoniot_dY_dcompression(double eps_v, const HugoniotParameters& p) {
  const double x = -eps_v - p.e_v_th;
  return x >= 0 ? dY_dx(x, p) : 0.0;
}

double hugoniot_compression_integral(double eps_v, const HugoniotParameters& p) {
  const double s = -eps_v, x = s - p.e_v_th;
  return x > 0 ? p.e_v_th + integral_of_x(x, p) : s;
}

double hugoniot_mean_Y(double eps_v_a, double eps_v_b, const HugoniotParameters& p) {
  const double lo = std::min(eps_v_a, eps_v_b), hi = std::max(eps_v_a, eps_v_b);
  if (-lo <= p.e_v_th) return 1.0;  // the whole interval is elastic
  if (hi == lo) return hugoniot_Y(lo, p);
  // x = compression past the threshold over the interval; the elastic part (x < 0) has Y = 1
  const double x_hi = -lo - p.e_v_th, x_lo = std::max(0.0, -hi - p.e_v_th), elastic = (hi - lo) - (x_hi - x_lo);
  double integral;
  if (x_hi - x_lo >= 1e-3) {
    integral = integral_of_x(x_hi, p) - integral_of_x(x_lo, p);
  } else {
    // short: 3-point Gauss-Legendre (error ~ dx^7 Y^(6) / 2e6, below 1e-14 dx here), free of the
    // cancellation of the closed form's difference (1e-16 P / dx)
    const double m = 0.5 * (x_lo + x_hi), r = 0.5 * (x_hi - x_lo), g = 0.7745966692414834;
    integral = r * (5 * Y_of_x(m - g * r, p) + 8 * Y_of_x(m, p) + 5 * Y_of_x(m + g * r, p)) / 9;
  }
  return (std::max(0.0, elastic) + integral) / (hi - lo);
}

HugoniotMinimum hugoniot_Y_minimum(const HugoniotParameters& p) {
  p.validate();
  HugoniotMinimum m;
  m.eps_v = -p.e_v_th;
  m.eps_v_back_at_one = -p.e_v_th;
  if (p.a_v == 0) return m;  // Y rises from the threshold on: no dip
  // dY/dx < 0 at x = 0 and > 0 far out (the quadratic wins): bracket the root by doubling.
  double lo = 0, hi = p.e_v;
  while (dY_dx(hi, p) <= 0) hi *= 2;
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
    const double mid = 0.5 * (lo + hi);
    (dY_dx(mid, p) < 0 ? lo : hi) = mid;
  }
  const double x_min = 0.5 * (lo + hi);
  m.eps_v = -(p.e_v_th + x_min);
  m.Y = Y_of_x(x_min, p);
  // Y rises monotonically past its minimum: the crossing of 1.
  lo = x_min;
  hi = 2 * x_min;
  while (Y_of_x(hi, p) < 1) hi *= 2;
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
    const double mid = 0.5 * (lo + hi);
    (Y_of_x(mid, p) < 1 ? lo : hi) = mid;
  }
  m.eps_v_back_at_one = -(p.e_v_th + 0.5 * (lo + hi));
  return m;
}

double volumetric_strain(const Eigen::Vector3d& strain, const ElasticMaterial2D& material) {
  const double in_plane = strain(0) + strain(1);
  return material.state == PlaneState::plane_strain ? in_plane
                                                    : in_plane * (1 - 2 * material.nu) / (1 - material.nu);
}

HugoniotElastic::HugoniotElastic(const ElasticMaterial2D& material, const HugoniotParameters& parameters)
    : material_(material), p_(parameters), D_(material.D()) {
  p_.validate();
}

Eigen::Vector3d HugoniotElastic::update(const Eigen::Vector3d& strain, PointState& state) const {
  const double ev_old = volumetric_strain(state.strain, material_);
  const double ev_new = volumetric_strain(strain, material_);
  double Y_step;  // the mean tangent ratio over this increment
  if (!p_.unloading) {
    Y_step = hugoniot_mean_Y(ev_old, ev_new, p_);
  } else {
    // Eq. (27): inside the history (eps_v >= min_eps_v) Y = max(1, max_Y); beyond it the envelope.
    const double Y_un = std::max(1.0, state.max_Y);
    const double hist = state.min_eps_v;
    const double inside = std::max(ev_new, hist) - std::max(ev_old, hist);  // part of the path above hist
    const double beyond = std::min(ev_new, hist) - std::min(ev_old, hist);  // part below hist (new ground)
    const double total = ev_new - ev_old;
    if (total == 0)
      Y_step = ev_old > hist ? Y_un : hugoniot_Y(ev_old, p_);
    else
      // a convex combination (inside and beyond have total's sign): no cancellation for small steps
      Y_step = (inside * Y_un + beyond * hugoniot_mean_Y(std::min(ev_old, hist), std::min(ev_new, hist), p_)) / total;
  }
  // the loading record, kept with or without Eq. (27) (an output either way)
  if (ev_new < state.min_eps_v) {
    state.min_eps_v = ev_new;
    // Y has a single minimum: its largest value on [ev_new, hist] is at an end, and max_Y holds hist's
    state.max_Y = std::max(state.max_Y, hugoniot_Y(ev_new, p_));
  }
  state.stress += Y_step * (D_ * (strain - state.strain));
  state.strain = strain;
  state.modulus_scale = p_.unloading ? std::max(1.0, state.max_Y) : hugoniot_Y(ev_new, p_);
  return state.stress;
}

}  // namespace mesowave::efg
