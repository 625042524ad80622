// The linear checks of the explicit EFG solver on the roller strip (efg/wave_strip, docs/efg.md
// "Explicit dynamics"): uniaxial strain, so a pressure on the end travels at c_p = sqrt(M / rho) with
// sigma_xx = -p(t - x / c_p) and v_x = p(t - x / c_p) / (rho c_p) (the 1D wave equation's d'Alembert
// solution). Against it:
//  - the peak's travel speed and height (triangular pulse);
//  - the phase speed against frequency from the run (the DFT of two sensors' stress) against the
//    stencil's dispersion relation (with the central difference's own), and that relation -> c_p as
//    k h -> 0;
//  - a Hann burst's velocity history against the closed form and against mw-fem's explicit solver
//    (fem::run_explicit) on the same bar: hexahedra of the same size, the lateral displacements
//    held (the same uniaxial strain), the same force per area.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "mesowave/efg/wave_strip.hpp"
#include "mesowave/fem/model.hpp"
#include "mesowave/fem/solver.hpp"
#include "mesowave/signal/hann_burst.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::efg;

namespace {

WaveStripOptions strip() {
  WaveStripOptions o;
  o.length_m = 0.5;
  o.width_m = 0.04;
  o.spacing_m = 5e-3;
  o.sensor_x_m = {0.1, 0.4};
  return o;
}

// sum_i s_i exp(-i w t_i) over t_i < t_max.
std::complex<double> dft(const std::vector<double>& t, const std::vector<double>& s, double omega, double t_max) {
  std::complex<double> x = 0;
  for (std::size_t i = 0; i < t.size() && t[i] < t_max; ++i) x += s[i] * std::exp(std::complex<double>(0, -omega * t[i]));
  return x;
}

}  // namespace

TEST(WaveStrip, PeakTravelsAtThePWaveSpeedWithThePulsesHeight) {
  const WaveStripOptions o = strip();
  const WaveStripResult r = run_wave_strip(o);
  const double c_p = std::sqrt(30e9 * 0.8 / (1.2 * 0.6) / 2400);  // M = E (1 - nu) / ((1 + nu)(1 - 2 nu))
  EXPECT_NEAR(r.c_p_m_s, c_p, 1e-9 * c_p);
  // 10 us rise and fall: the spectrum lies below ~100 kHz (its first zero), k h < 0.85, where the
  // stencil's phase speed is within 0.5 % of c_p (the next test); the peak is a kink, rounded by
  // the high wavenumbers, so its speed is held to 1 %.
  EXPECT_NEAR(r.peak_speed_error, 0.0, 0.01) << "peak speed " << r.peak_speed_m_s << " m/s, c_p " << c_p;
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_NEAR(r.peak_time_s[k], o.sensor_x_m[k] / c_p + 10e-6, 1e-6) << k;
    EXPECT_NEAR(r.peak_stress_Pa[k] / o.triangular.peak_Pa, 1.0, 0.05) << k;
  }
  EXPECT_LT(r.run.energy_drift, 1e-9);
  EXPECT_LE(r.run.max_constraint_violation_m, 1e-12);
}

TEST(WaveStrip, StencilDispersionTendsToTheContinuumAndMatchesTheRun) {
  WaveStripOptions o = strip();
  const WaveStripResult r = run_wave_strip(o);
  const double dt = r.run.dt_first_s;
  const std::vector<DispersionPoint> low = stencil_dispersion(o, {M_PI / 40, M_PI / 20, M_PI / 10}, 0);
  // Second order: the error falls by about 4 when k h halves.
  const double e0 = std::abs(low[0].phase_speed_ratio - 1), e1 = std::abs(low[1].phase_speed_ratio - 1),
               e2 = std::abs(low[2].phase_speed_ratio - 1);
  EXPECT_LT(e2, 5e-3);
  EXPECT_NEAR(e2 / e1, 4.0, 0.5);
  EXPECT_NEAR(e1 / e0, 4.0, 0.5);
  // The run: phase speed between the sensors from the DFT of -sigma_xx, 10 to 60 kHz (the pulse's
  // spectrum above 40 % of its peak), each sensor's window ending before the reflection from x = L.
  const double x1 = o.sensor_x_m[0], x2 = o.sensor_x_m[1], c_p = r.c_p_m_s;
  std::vector<double> s1, s2;
  for (const SensorSample& s : r.run.sensors[0]) s1.push_back(-s.stress_Pa[0]);
  for (const SensorSample& s : r.run.sensors[1]) s2.push_back(-s.stress_Pa[0]);
  for (double f = 10e3; f <= 60e3; f += 10e3) {
    const double w = 2 * M_PI * f;
    const auto X1 = dft(r.run.sample_t_s, s1, w, (2 * o.length_m - x1) / c_p);
    const auto X2 = dft(r.run.sample_t_s, s2, w, (2 * o.length_m - x2) / c_p);
    double phase = -std::arg(X2 / X1);  // w (x2 - x1) / c, modulo 2 pi
    const double expected = w * (x2 - x1) / c_p;
    phase += 2 * M_PI * std::round((expected - phase) / (2 * M_PI));
    const double c_run = w * (x2 - x1) / phase;
    const double kh = w / c_run * o.spacing_m;
    const DispersionPoint d = stencil_dispersion(o, {kh}, dt)[0];
    EXPECT_NEAR(c_run / c_p, d.with_time_step, 2e-3) << f << " Hz: run " << c_run / c_p << ", stencil " << d.with_time_step
                                                     << " (space only " << d.phase_speed_ratio << ")";
  }
}

TEST(WaveStrip, HannBurstAgreesWithTheClosedFormAndWithTheFem) {
  // 20 kHz, 3 cycles: a wavelength of 186 mm = 37 spacings of 5 mm, both models.
  const double f = 20e3, cycles = 3, p0 = 1e6, h = 5e-3, L = 0.8, x = 0.3, duration = 250e-6;
  const signal::HannBurst burst(f, cycles, p0);
  WaveStripOptions o;
  o.length_m = L;
  o.width_m = 0.04;
  o.spacing_m = h;
  o.sensor_x_m = {x};
  o.custom = [&](double t) { return burst(t); };
  o.dynamics.duration_s = duration;
  const WaveStripResult efg = run_wave_strip(o);
  const double rho_c = 2400 * efg.c_p_m_s;
  const auto exact = [&](double t) { return burst(t - x / efg.c_p_m_s) / rho_c; };

  // The FEM: one row of hexahedra, u_y = u_z = 0 everywhere, the force p0 h^2 on the end face.
  fem::FemModel m = fem::box_hexahedra({30e9, 0.2, 2400}, {L, h, h}, h);
  for (std::size_t d = 0; d < m.dof_count(); ++d)
    if (d % 3 != 0) m.fixed[d] = 1;
  fem::BurstLoad load{fem::surface_patch(m, 0, 0.0, {0, h / 2, h / 2}, INFINITY), signal::HannBurst(f, cycles, p0 * h * h)};
  const std::size_t node = m.nearest_node({x, 0, 0});
  ASSERT_NEAR(m.position(node)[0], x, 1e-9);
  fem::ExplicitOptions fo;
  fo.dt_s = 0.9 * m.stable_dt();
  fo.steps = std::int64_t(duration / fo.dt_s);
  const auto fr = fem::run_explicit(m, load, {{"x", node * 3, fem::Quantity::Velocity, "x", 1.0}}, fo);
  const auto& fv = fr.signals[0].samples;

  double peak = 0, e_efg = 0, e_fem = 0, e_between = 0;
  for (double t = 0; t < duration; t += 0.5e-6) peak = std::max(peak, std::abs(exact(t)));
  std::size_t n = 0;
  for (std::size_t i = 0; i < efg.run.sample_t_s.size(); ++i) {
    const double t = efg.run.sample_t_s[i], v = efg.run.sensors[0][i].velocity_m_s[0];
    const double k = t / fo.dt_s;  // the FEM's samples at k dt, linearly between them
    const auto k0 = std::size_t(k);
    if (k0 + 1 >= fv.size()) break;
    const double vf = fv[k0] + (k - double(k0)) * (fv[k0 + 1] - fv[k0]);
    e_efg += std::pow(v - exact(t), 2), e_fem += std::pow(vf - exact(t), 2), e_between += std::pow(v - vf, 2);
    ++n;
  }
  ASSERT_GT(n, 400u);
  e_efg = std::sqrt(e_efg / double(n)) / peak, e_fem = std::sqrt(e_fem / double(n)) / peak;
  e_between = std::sqrt(e_between / double(n)) / peak;
  // 37 nodes a wavelength: a phase error of order 1e-3 over the 80 us path shifts the burst by
  // ~0.1 us of its 50 us period, ~1 % of the peak in rms; 2 % is held for each.
  EXPECT_LT(e_efg, 0.02) << "EFG rms error / peak";
  EXPECT_LT(e_fem, 0.02) << "FEM rms error / peak";
  EXPECT_LT(e_between, 0.02) << "EFG - FEM rms / peak";
  std::cout << "[ info ] rms / peak: EFG " << e_efg << ", FEM " << e_fem << ", EFG - FEM " << e_between << "\n";
}

TEST(WaveStrip, BadInputIsOneLineEach) {
  WaveStripOptions o = strip();
  o.width_m = 0.004;
  EXPECT_NE(test::input_error_of([&] { run_wave_strip(o); }).find("at least 2 node spacings"), std::string::npos);
  o = strip();
  o.pulse = "square";
  EXPECT_NE(test::input_error_of([&] { run_wave_strip(o); }).find("triangular or friedlander"), std::string::npos);
  o = strip();
  o.triangular.fall_s = o.triangular.rise_s = 0;
  EXPECT_NE(test::input_error_of([&] { run_wave_strip(o); }).find("pulse length"), std::string::npos);
  o = strip();
  o.sensor_x_m = {0.7};
  EXPECT_NE(test::input_error_of([&] { run_wave_strip(o); }).find("sensor x"), std::string::npos);
  o = strip();
  o.dynamics.dt_s = 1e-3;
  EXPECT_NE(test::input_error_of([&] { run_wave_strip(o); }).find("exceeds the stable step"), std::string::npos);
}
