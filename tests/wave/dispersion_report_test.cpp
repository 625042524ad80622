// What mw-dispersion reports (wave/dispersion_report, bar_echo_velocity): the
// bar-echo uncertainty budget against the GUM quadrature worked by hand, the
// lattice summary against the chain's closed forms, the theory summary against
// c0 = sqrt(E / rho), and a bar-echo record whose delay is known.
#include "mesowave/wave/dispersion_report.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <numbers>

#include "mesowave/core/error.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using namespace mesowave::wave;

namespace {

const prov::MetricRecord* metric(const DispersionReport& r, const std::string& name) {
  for (const auto& m : r.metrics)
    if (m.name == name) return &m;
  return nullptr;
}

}  // namespace

TEST(BarEchoVelocity, MeanOfTheOnsetPickersAndTheQuadratureBudget) {
  // Path 2 m; threshold 400 us (5000 m/s), AIC 392 us (5102.04 m/s); the edges (slower) do not count.
  BarEchoResult r;
  r.picks = {{"edge-0.5", 100e-6, 520e-6, 2.0 / 420e-6},
             {"threshold", 100e-6, 500e-6, 2.0 / 400e-6},
             {"aic", 100e-6, 492e-6, 2.0 / 392e-6},
             {"envelope", 0, 450e-6, 2.0 / 450e-6}};
  const double dt = 80e-9, u_path = 1e-3;
  const auto v = bar_echo_velocity(r, dt, u_path);
  const double c_t = 5000, c_a = 2.0 / 392e-6, mean = (c_t + c_a) / 2;
  EXPECT_DOUBLE_EQ(v.velocity_m_s, mean);
  EXPECT_DOUBLE_EQ(v.relative_uncertainty_method, (c_a - c_t) / 2 / mean);
  // Half a sample on each time: sqrt(2) (dt / 2) over the mean delay of 396 us.
  EXPECT_DOUBLE_EQ(v.relative_uncertainty_sampling, std::sqrt(2.0) * dt / 2 / 396e-6);
  EXPECT_EQ(v.relative_uncertainty_path, u_path);
  const double u = std::hypot(std::hypot((c_a - c_t) / 2 / mean, std::sqrt(2.0) * dt / 2 / 396e-6), u_path);
  EXPECT_NEAR(v.velocity_uncertainty_m_s, mean * u, 1e-9 * mean);
  EXPECT_EQ(v.fitted_c0_uncertainty_m_s, 0);  // no theory fitted

  r.fitted_c0_m_s = 5050;
  r.fitted_c0_relative_spread = 2e-4;
  const auto f = bar_echo_velocity(r, dt, u_path);
  EXPECT_NEAR(f.fitted_c0_uncertainty_m_s,
              5050 * std::hypot(std::hypot(2e-4, std::sqrt(2.0) * dt / 2 / 396e-6), u_path), 1e-9 * 5050);

  BarEchoResult edges_only;
  edges_only.picks = {{"edge-0.5", 0, 1e-3, 2000}};
  EXPECT_THROW(bar_echo_velocity(edges_only, dt, 0), InputError);
}

TEST(DispersionReport, LatticeSummaryIsTheChainsClosedForm) {
  LatticeRequest q;
  q.mass_kg = 1e-3;
  q.stiffness_N_m = 1e6;
  q.spacing_mm = 10;
  q.f_max_kHz = 20;
  q.label = "toy";
  const auto r = lattice_report(q);
  const double w0 = std::sqrt(1e6 / 1e-3);  // sqrt(K / m)
  EXPECT_EQ(r.summary["model"], "toy");
  EXPECT_NEAR(r.summary["long_wave_speed_m_s"].get<double>(), 0.01 * w0, 1e-9);
  const double cutoff_kHz = 2 * w0 / (2 * std::numbers::pi) / 1e3;  // 10.07 kHz
  EXPECT_NEAR(r.summary["cutoff_kHz"].get<double>(), cutoff_kHz, 1e-9);
  // 1, 2, ..., 10 kHz lie below the cut-off; 11 .. 20 kHz do not propagate.
  EXPECT_EQ(r.summary["rows"], 10);
  ASSERT_NE(metric(r, "long-wave speed"), nullptr);
  EXPECT_EQ(metric(r, "lattice cut-off")->unit, "kHz");
  EXPECT_EQ(r.csv.substr(0, r.csv.find('\n')), "model,f_kHz,k_rad_m,kd,c_phase_m_s,c_group_m_s");

  auto both = q;
  both.sphere_radius_mm = 5;
  EXPECT_THROW(lattice_report(both), InputError);
  LatticeRequest dem;
  dem.sphere_radius_mm = 5;
  dem.particle_density_kg_m3 = 7800;
  dem.E_dem_GPa = 600;
  EXPECT_THROW(lattice_report(dem), InputError);  // neither --spacing-mm nor --spacing-R
  dem.spacing_R = 2;
  // m = rho 4/3 pi R^3, K = E_dem R, d = 2 R: c = d sqrt(K / m).
  const double R = 5e-3, m = 7800 * 4.0 / 3 * std::numbers::pi * R * R * R, K = 600e9 * R;
  EXPECT_NEAR(lattice_report(dem).summary["long_wave_speed_m_s"].get<double>(), 2 * R * std::sqrt(K / m), 1e-6);
}

TEST(DispersionReport, TheorySummaryAndPlot) {
  TheoryRequest q;
  q.rod = {208.72, 0.3, 7850.66, 5.1, {}};
  q.f_max_kHz = 50;
  q.df_kHz = 5;
  const auto r = theory_report(q);
  ASSERT_NE(metric(r, "c0"), nullptr);
  EXPECT_NEAR(metric(r, "c0")->value, std::sqrt(208.72e9 / 7850.66), 1e-6);
  EXPECT_EQ(r.summary["rows"], r.points.size());
  EXPECT_EQ(r.points.size(), 10u);  // L(0,1) alone at 5, 10, ..., 50 kHz (no cut-off below 50 kHz)
  EXPECT_FALSE(r.plot);
  // At 5 kHz the wavelength is 200 radii: the group velocity is c0 to a fraction of a percent.
  EXPECT_NEAR(r.points.front().c_group_m_s / metric(r, "c0")->value, 1.0, 2e-3);

  q.plot = "fig9.png";
  q.plot_key = "inside,bottom,left";
  q.plot_f_range = "5,50";
  const auto p = theory_report(q);
  ASSERT_TRUE(p.plot);
  EXPECT_EQ(p.plot->key, "inside bottom left");
  EXPECT_EQ(p.plot->x_range, (std::pair{5.0, 50.0}));
  q.plot_key = "top; system('x')";
  EXPECT_THROW(theory_report(q), InputError);
  q.plot_key = "top";
  q.plot = "fig9.pdf";
  EXPECT_THROW(theory_report(q), InputError);
  q.plot = "";
  q.overlays = {"=file.csv"};
  EXPECT_THROW(theory_report(q), InputError);
}

TEST(DispersionReport, BarEchoRecordOfKnownDelay) {
  // Two square pulses 400 us apart over a 2 m round trip (5000 m/s), the second inverted
  // (a free end), on 1 % uniform noise; no dispersion, so every picker finds the delay.
  test::TempDir dir;
  const auto path = dir / "bar.csv";
  {
    std::ofstream f(path);
    f << "t_s,gauge\n";
    std::uint64_t state = 7;
    for (int i = 0; i < 12000; ++i) {
      const double t = i * 80e-9;
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      const double noise = 0.01 * (double(state >> 11) / 9007199254740992.0 - 0.5);
      const double x = (t >= 100e-6 && t < 250e-6) ? 1.0 : (t >= 500e-6 && t < 650e-6) ? -0.9 : 0.0;
      f << t << "," << x + noise << "\n";
    }
  }
  BarEchoRequest q;
  q.record = path;
  q.column = "gauge";
  q.path_mm = 2000;
  q.path_uncertainty_mm = 2;
  q.rod.E_GPa = 195;
  q.rod.density_kg_m3 = 7800;
  const auto r = bar_echo_report(q);
  EXPECT_NEAR(r.summary["velocity_m_s"].get<double>(), 5000, 5);
  EXPECT_DOUBLE_EQ(r.summary["relative_uncertainty_path"].get<double>(), 1e-3);
  EXPECT_NEAR(r.summary["c0_m_s"].get<double>(), 5000, 1e-9);
  EXPECT_NEAR(r.summary["echo_over_pulse_amplitude"].get<double>(), -0.9, 0.02);
  EXPECT_FALSE(r.summary.contains("fitted_c0_m_s"));  // no radius and nu: no theory
  EXPECT_EQ(metric(r, "bar velocity")->value, r.summary["velocity_m_s"].get<double>());
  ASSERT_EQ(r.inputs.size(), 1u);
  EXPECT_EQ(r.csv.substr(0, r.csv.find('\n')), "method,t1_us,t2_us,delay_us,c_m_s");
  EXPECT_THROW(bar_echo_signals(r), InputError);
}
