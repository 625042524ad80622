// Shock steepening (issue 16 must-show 1, shock paper Section 4.2): the explicit EFG roller strip
// (efg/wave_strip: plane strain, v = 0 on the long sides, so uniaxial strain) with the Y-function
// law (HugoniotElastic without Eq. (27), as the paper's test) under a 2 GPa triangular pulse
// (20 us rise, 20 us fall; lab-data/shock-concrete/shock-steepening.toml), against the
// method-of-characteristics reference of efg/characteristics for the same law:
// - before the characteristics cross (x_b = 63.2 mm, t_b = 37.3 us), the front's width between the
//   levels 0.753 GPa (the dip's minimum, |eps_v| = 0.0475) and 1.9 GPa follows the simple wave,
//   width(x) = (p_hi - p_lo) / p_max t_r + x (1 / c(p_hi) - 1 / c(p_lo));
// - past x_b the simple wave is multivalued (its width negative); the EFG front stays a shock a
//   few steps wide;
// - the shock's speed against the jump condition U^2 = [p] / (rho [s]) between those two levels.
// The figures (h = 1 mm) are in docs/efg.md, "Shock steepening".
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mesowave/efg/characteristics.hpp"
#include "mesowave/efg/wave_strip.hpp"

namespace mesowave::efg {
namespace {

/// The first time -sigma_xx reaches `level` at sensor k, interpolated between samples.
// The 300 x 12 mm plane-strain strip at 1 mm spacing under a 20 us-fall triangular pulse, its
// sensors at 10-200 mm (both laws' runs).
WaveStripOptions strip(double E, double nu, double rho, double peak, double rise) {
  WaveStripOptions o;
  o.length_m = 0.3;
  o.width_m = 0.012;
  o.spacing_m = 1e-3;
  o.E_Pa = E;
  o.nu = nu;
  o.density_kg_m3 = rho;
  o.triangular = {peak, rise, 20e-6, 0};
  o.sensor_x_m = {0.01, 0.03, 0.05, 0.1, 0.15, 0.2};
  return o;
}

double arrival(const WaveStripResult& r, std::size_t k, double level) {
  const auto& t = r.run.sample_t_s;
  const auto& S = r.run.sensors[k];
  for (std::size_t i = 1; i < t.size(); ++i) {
    const double a = -S[i - 1].stress_Pa(0), b = -S[i].stress_Pa(0);
    if (a < level && b >= level) return t[i - 1] + (t[i] - t[i - 1]) * (level - a) / (b - a);
  }
  return -1;
}

TEST(ShockSteepening, YFunctionStripAgainstCharacteristics) {
  const double E = 20e9, nu = 0.2, rho = 2400, peak = 2e9, rise = 20e-6;
  WaveStripOptions o = strip(E, nu, rho, peak, rise);
  o.dynamics.duration_s = 95e-6;  // before the reflection from x = 0.3 m returns to 0.2 m
  HugoniotParameters hp;
  hp.unloading = false;
  const ElasticMaterial2D m{E, nu, 1.0, rho, PlaneState::plane_strain};
  const HugoniotElastic law(m, hp);
  o.material = &law;
  const WaveStripResult r = run_wave_strip(o);

  const HugoniotCompression reference(m.D()(0, 0), hp);
  const ShockFormation f = shock_formation(reference, rho, o.triangular);
  ASSERT_TRUE(f.forms && f.loading);
  const double s_lo = -hugoniot_Y_minimum(hp).eps_v, p_lo = reference.pressure_Pa(s_lo), p_hi = 0.95 * peak;
  const double s_hi = compression_at_pressure(reference, p_hi);
  const double c_lo = wave_speed_m_s(reference, rho, s_lo), c_hi = wave_speed_m_s(reference, rho, s_hi);
  const double U = shock_speed_m_s(reference, rho, s_lo, compression_at_pressure(reference, peak));
  std::printf("x_b = %.4g mm, t_b = %.4g us; steps %lld, dt %.3g..%.3g us, max modulus_scale %.3g, drift %.2g\n",
              f.distance_m * 1e3, f.time_s * 1e6, static_cast<long long>(r.run.steps), r.run.dt_min_s * 1e6,
              r.run.dt_first_s * 1e6, r.run.max_modulus_scale, r.run.energy_drift);
  for (std::size_t k = 0; k < o.sensor_x_m.size(); ++k) {
    const double x = o.sensor_x_m[k];
    const double width = arrival(r, k, p_hi) - arrival(r, k, p_lo);
    const double simple = (p_hi - p_lo) / peak * rise + x * (1 / c_hi - 1 / c_lo);
    std::printf("x = %5.3f m: EFG width %.3g us, simple wave %.3g us, largest -sigma_xx %.3g GPa\n", x, width * 1e6,
                simple * 1e6, r.peak_stress_Pa[k] / 1e9);
    if (x < f.distance_m) {
      EXPECT_NEAR(width, simple, 1.0e-6) << x;  // a sample interval is 0.37-0.51 us
    } else if (x >= 0.1) {
      EXPECT_LT(width, 1.5e-6) << x;  // the linear law would keep (p_hi - p_lo) / p_max t_r = 11.5 us
    }
  }
  // the front between the last two sensors against the jump condition
  const double speed = (o.sensor_x_m[5] - o.sensor_x_m[4]) / (arrival(r, 5, 1.3e9) - arrival(r, 4, 1.3e9));
  std::printf("shock speed %.5g m/s, jump condition U(|eps_v| %.4f -> %.4f) = %.5g m/s, c_0 = %.5g m/s\n", speed,
              s_lo, compression_at_pressure(reference, peak), U, wave_speed_m_s(reference, rho, 0));
  EXPECT_NEAR(speed / U, 1, 0.03);
  EXPECT_LT(r.run.energy_drift, 1e-9);
}


// The smooth law p = M s (1 + beta s), beta = 40, 0.5 GPa, 20/20 us: the front breaks first, at
// x_b = c_0 M t_r / (beta p_max) = 67.6 mm; before it the 10-90 % width follows the simple wave.
TEST(ShockSteepening, QuadraticStripAgainstTheClosedForm) {
  const double E = 20e9, nu = 0.2, rho = 2400, peak = 0.5e9, rise = 20e-6, beta = 40;
  WaveStripOptions o = strip(E, nu, rho, peak, rise);
  o.dynamics.duration_s = 95e-6;
  const ElasticMaterial2D m{E, nu, 1.0, rho, PlaneState::plane_strain};
  const QuadraticStiffeningPoint law(m, beta);
  o.material = &law;
  const WaveStripResult r = run_wave_strip(o);
  const double M = m.D()(0, 0), c0 = std::sqrt(M / rho);
  const QuadraticStiffening reference(M, beta);
  const double x_b = c0 * M * rise / (beta * peak);
  const double p_lo = 0.1 * peak, p_hi = 0.9 * peak;
  const double c_lo = wave_speed_m_s(reference, rho, compression_at_pressure(reference, p_lo));
  const double c_hi = wave_speed_m_s(reference, rho, compression_at_pressure(reference, p_hi));
  std::printf("quadratic: x_b = %.4g mm; steps %lld, max modulus_scale %.3g, drift %.2g\n", x_b * 1e3,
              static_cast<long long>(r.run.steps), r.run.max_modulus_scale, r.run.energy_drift);
  for (std::size_t k = 0; k < o.sensor_x_m.size(); ++k) {
    const double x = o.sensor_x_m[k];
    const double width = arrival(r, k, p_hi) - arrival(r, k, p_lo);
    const double simple = (p_hi - p_lo) / peak * rise + x * (1 / c_hi - 1 / c_lo);
    std::printf("x = %5.3f m: EFG 10-90 %% width %.3g us, simple wave %.3g us, largest -sigma_xx %.3g GPa\n", x,
                width * 1e6, simple * 1e6, r.peak_stress_Pa[k] / 1e9);
    if (x < x_b) {
      EXPECT_NEAR(width, simple, 1.0e-6) << x;
    }
  }
  EXPECT_LT(r.run.energy_drift, 1e-9);
}

}  // namespace
}  // namespace mesowave::efg
