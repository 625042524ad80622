// The linear checks of the explicit EFG solver on the roller strip (efg/wave_strip, docs/efg.md
// "Explicit dynamics"): uniaxial strain, so a pressure on the end travels at c_p = sqrt(M / rho) with
// sigma_xx = -p(t - x / c_p) and v_x = p(t - x / c_p) / (rho c_p) (the 1D wave equation's d'Alembert
// solution). Against it:
//  - the peak's travel speed and height (triangular pulse);
//  - the phase speed against frequency from the run (the DFT of two sensors' stress) against the
//    stencil's dispersion relation (with the central difference's own), and that relation -> c_p as
//    k h -> 0;
//  - a Hann burst's velocity history against the closed form, its error against what the stencil's
//    dispersion predicts, and against mw-fem's explicit solver (fem::run_explicit) on the same bar:
//    one row of hexahedra of the same size, u_y = u_z held (the same uniaxial strain), the same
//    force per area.
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
  WaveStripOptions o = strip();
  o.length_m = 1.0;
  o.sensor_x_m = {0.2, 0.8};
  o.triangular = {100e6, 40e-6, 40e-6, 0};
  const WaveStripResult r = run_wave_strip(o);
  const double c_p = std::sqrt(30e9 * 0.8 / (1.2 * 0.6) / 2400);  // M = E (1 - nu) / ((1 + nu)(1 - 2 nu))
  EXPECT_NEAR(r.c_p_m_s, c_p, 1e-9 * c_p);
  // 40 us rise and fall: the spectrum's first zero at 12.5 kHz, k h = 0.105, where the stencil with
  // the step lags c_p by 0.2 % (e ~ 0.28 (k h)^2 in space, less with the step); the peak is a kink
  // that the higher wavenumbers round. Measured: -0.42 % at 5 mm, -0.43 % at 2.5 mm (so not the
  // dispersion alone: see docs/efg.md); 1 % is held.
  EXPECT_NEAR(r.peak_speed_error, 0.0, 0.01) << "peak speed " << r.peak_speed_m_s << " m/s, c_p " << c_p;
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_NEAR(r.peak_time_s[k], o.sensor_x_m[k] / c_p + 40e-6, 2.5e-6) << k;
    EXPECT_NEAR(r.peak_stress_Pa[k] / o.triangular.peak_Pa, 1.0, 0.08) << k;  // 0.96 and 0.94: the kink rounded
  }
  EXPECT_LT(r.run.energy_drift, 1e-12);
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
  std::cout << "[ info ] phase speed error at kh = pi/40, pi/20, pi/10: " << e0 << " " << e1 << " " << e2 << "\n";
  EXPECT_NEAR(e2 / e1, 4.0, 0.2);  // measured 3.96 and 3.99
  EXPECT_NEAR(e1 / e0, 4.0, 0.2);
  EXPECT_NEAR(e2 / std::pow(M_PI / 10, 2), 0.28, 0.01);  // e = 0.28 (k h)^2: 2.7 % slow at 20 nodes a wavelength
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
    // 3e-3: the strip is 8 spacings wide, its edge rows (weak rollers, the MLS reaching fewer nodes)
    // are not the infinite grid's stencil; measured up to 2.4e-3 (10 kHz, where the 80 us window
    // holds under one period of the difference)
    EXPECT_NEAR(c_run / c_p, d.with_time_step, 3e-3) << f << " Hz: run " << c_run / c_p << ", stencil " << d.with_time_step
                                                     << " (space only " << d.phase_speed_ratio << ")";
  }
}

TEST(WaveStrip, HannBurstErrorIsTheDispersionsPhaseLag) {
  // 20 kHz, 3 cycles: a wavelength of 186 mm = 37 spacings of 5 mm.
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

  double peak = 0, rms_exact = 0, e_efg = 0;
  std::size_t n = 0;
  for (double t = 0; t < duration; t += 0.5e-6) peak = std::max(peak, std::abs(exact(t)));
  for (std::size_t i = 0; i < efg.run.sample_t_s.size(); ++i) {
    const double t = efg.run.sample_t_s[i], v = efg.run.sensors[0][i].velocity_m_s[0];
    e_efg += std::pow(v - exact(t), 2), rms_exact += std::pow(exact(t), 2);
    ++n;
  }
  ASSERT_GT(n, 100u);  // the EFG step is 2.1 us here: 120 samples
  e_efg = std::sqrt(e_efg / double(n)) / peak, rms_exact = std::sqrt(rms_exact / double(n)) / peak;
  // The dispersion predicts it: at 20 kHz (k h = 0.17) the stencil with the step lags by 1 - ratio,
  // a phase lag phi = w x (1 / ratio - 1) / c_p at the sensor, and a burst shifted by phi differs
  // from itself by about phi times its rms.
  const double w = 2 * M_PI * f, kh = w / efg.c_p_m_s * h;
  const double ratio = stencil_dispersion(o, {kh}, efg.run.dt_first_s)[0].with_time_step;
  const double predicted = w * x * (1 / ratio - 1) / efg.c_p_m_s * rms_exact;
  std::cout << "[ info ] velocity rms error / peak: EFG " << e_efg << ", predicted by the dispersion " << predicted << "\n";
  // The estimate takes the centre frequency only; a 3-cycle burst spreads to ~33 kHz, where the lag
  // is 2.7 times larger (e ~ k^2): the measured error lies above the estimate, not 1.6 times above.
  EXPECT_GT(e_efg, 0.9 * predicted);  // measured 1.31 x
  EXPECT_LT(e_efg, 1.6 * predicted);
}

TEST(WaveStrip, HannBurstAgreesWithTheFemOnTheSameBar) {
  const double f = 20e3, cycles = 3, p0 = 1e6, h = 5e-3, L = 0.8, x = 0.3, duration = 250e-6;
  const signal::HannBurst burst(f, cycles, p0);
  WaveStripOptions o;
  o.length_m = L, o.width_m = 0.04, o.spacing_m = h, o.sensor_x_m = {x};
  o.custom = [&](double t) { return burst(t); };
  o.dynamics.duration_s = duration;
  const WaveStripResult efg = run_wave_strip(o);
  const auto exact = [&](double t) { return burst(t - x / efg.c_p_m_s) / (2400 * efg.c_p_m_s); };
  fem::FemModel m = fem::box_hexahedra({30e9, 0.2, 2400}, {L, h, h}, h);
  for (std::size_t d = 0; d < m.dof_count(); ++d)
    if (d % 3 != 0) m.fixed[d] = 1;
  fem::BurstLoad load{{}, signal::HannBurst(f, cycles, p0 * h * h)};
  for (const auto& [node, w] : fem::surface_patch(m, 0, 0.0, {0, h / 2, h / 2}, INFINITY))
    load.dof_weights.emplace_back(node * 3, w);  // the x dof of each face node
  const std::size_t node = m.nearest_node({x, 0, 0});
  ASSERT_NEAR(m.position(node)[0], x, 1e-9);
  fem::ExplicitOptions fo;
  fo.dt_s = 0.9 * m.stable_dt();
  fo.steps = std::int64_t(duration / fo.dt_s);
  const auto fr = fem::run_explicit(m, load, {{"x", node * 3, fem::MotionQuantity::velocity, "x", 1.0}}, fo);
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
  ASSERT_GT(n, 100u);
  e_efg = std::sqrt(e_efg / double(n)) / peak, e_fem = std::sqrt(e_fem / double(n)) / peak;
  e_between = std::sqrt(e_between / double(n)) / peak;
  std::cout << "[ info ] velocity rms / peak: EFG " << e_efg << ", FEM " << e_fem << ", EFG - FEM " << e_between << "\n";
  // The Q1 bar with a lumped mass lags by 1 - sin(kh/2)/(kh/2) = 1.2e-3 at k h = 0.17 and its step
  // (Courant 0.9 of its bound) cancels part of it: the FEM is the closer of the two; the EFG lags
  // by its stencil's 0.5-0.8 % (the test above); their difference is the EFG's error.
  EXPECT_LT(e_fem, 0.5 * e_efg);
  EXPECT_NEAR(e_between / e_efg, 1.0, 0.3);
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
