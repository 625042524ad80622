// Group velocity from signals: envelope-peak arrivals (two stations, echo,
// source), the 2D FFT ridge of a space-time record, and the RSS of rod Table 2,
// on synthetic records whose propagation is known exactly.
#include "mesowave/wave/group_velocity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesowave/core/error.hpp"
#include "mesowave/signal/fft.hpp"
#include "mesowave/signal/hann_burst.hpp"
#include "mesowave/wave/lattice.hpp"
#include "mesowave/wave/pochhammer_chree.hpp"

using namespace mesowave;
using namespace mesowave::wave;

namespace {

signal::Signal burst_signal(const std::string& name, double f, double cycles, double delay, double amplitude,
                            double dt, std::size_t n) {
  signal::Signal s;
  s.name = name;
  s.quantity = "velocity";
  s.unit = "m/s";
  s.dt_s = dt;
  s.samples = signal::HannBurst(f, cycles, amplitude, delay).sample(dt, n);
  return s;
}

// x carried over a distance dz by the L(0,1) mode of the rod: X(f) exp(-i k(f) dz).
signal::Signal propagate(const signal::Signal& x, double dz, const PochhammerChree& pc, const DispersionTrace& tr,
                         double f_cut) {
  const std::size_t n = 2 * x.size();
  auto X = signal::rfft(x.samples, n);
  std::vector<double> f;
  for (std::size_t j = 1; j < X.size(); ++j)
    if (double(j) / (double(n) * x.dt_s) < f_cut) f.push_back(double(j) / (double(n) * x.dt_s));
  const auto pts = sample_at_frequencies(pc, tr, f);
  X[0] = 0;
  for (std::size_t j = 1; j < X.size(); ++j) X[j] = j <= pts.size() ? X[j] * std::polar(1.0, -pts[j - 1].k_rad_m * dz) : 0.0;
  signal::Signal y = x;
  y.samples = signal::irfft(X, n);
  y.samples.resize(x.size());
  return y;
}

}  // namespace

TEST(GroupVelocity, NonDispersiveDelaysGiveTheVelocityExactly) {
  const double c = 5000, d = 0.4, f = 100e3, dt = 0.1e-6;
  const auto a = burst_signal("A", f, 5, 20e-6, 1.0, dt, 3000);
  const auto b = burst_signal("B", f, 5, 20e-6 + d / c, 0.6, dt, 3000);
  const auto p = two_station_velocity(a, b, d, f, 5 / f);
  EXPECT_NEAR(p.c_group_m_s / c, 1.0, 1e-5);
  EXPECT_NEAR(p.t1_s, 20e-6 + 25e-6, 1e-8);  // the envelope of a Hann burst peaks at its centre
  // Echo: the same burst and a weaker copy after a round trip of 2 m.
  auto e = burst_signal("S", f, 5, 10e-6, 1.0, dt, 8000);
  const auto echo = burst_signal("S", f, 5, 10e-6 + 2.0 / c, -0.5, dt, 8000);
  for (std::size_t i = 0; i < e.size(); ++i) e.samples[i] += echo.samples[i];
  EXPECT_NEAR(echo_velocity(e, 2.0, f, 5 / f).c_group_m_s / c, 1.0, 1e-5);
  // Source: from the burst centre of the first station (45 us) to the packet at B.
  const auto ps = source_velocity(b, d, 45e-6, f, 5 / f);
  EXPECT_NEAR(ps.c_group_m_s / c, 1.0, 1e-5);
  // measure_run finds the stations by name and reports a missing one.
  EXPECT_NEAR(measure_run({a, b}, f, {"two-stations", {"A", "B"}, d, 5}).c_group_m_s / c, 1.0, 1e-5);
  EXPECT_THROW(measure_run({a, b}, f, {"two-stations", {"A", "C"}, d, 5}), InputError);
  EXPECT_THROW(echo_velocity(a, 2.0, f, 5 / f), InputError);  // one packet only
}

TEST(GroupVelocity, DispersiveRodRecordMeetsPochhammerChree) {
  // A 20-cycle burst carried 1 m along the rod paper's rod by the exact L(0,1)
  // propagator: the envelope delay gives the group velocity at the centre frequency.
  const PochhammerChree pc({208.72e9, 0.3, 7850.66}, 5.1e-3);
  TraceOptions opt;
  opt.f_max_Hz = 400e3;
  const auto tr = trace_longitudinal_modes(pc, opt);
  for (double f : {50e3, 100e3, 150e3}) {
    const auto a = burst_signal("A", f, 20, 0, 1.0, 0.1e-6, 6000);
    const auto b = propagate(a, 1.0, pc, tr, 340e3);
    const auto p = two_station_velocity(a, b, 1.0, f, 20 / f);
    const double cg = sample_at_frequencies(pc, tr, {f}).at(0).c_group_m_s;
    EXPECT_NEAR(p.c_group_m_s / cg, 1.0, 2e-3) << f;
  }
}

TEST(GroupVelocity, SpaceTimeRidgeRecoversTheLatticeDispersion) {
  // u(t, x) = sum_q cos(2 pi f_q t - k(f_q) x) with the DEM chain's dispersion, f_q on
  // the DFT grid of the record (no leakage in time).
  const MassSpringChain chain{3.358e-3, 3.366e9, 5.253e-3};
  SpaceTimeRecord r;
  r.times = 1000;
  r.positions = 48;
  r.dt_s = 0.2e-6;
  r.dx_m = chain.spacing_m;
  r.samples.assign(r.times * r.positions, 0.0);
  const double df = 1 / (double(r.times) * r.dt_s);
  std::vector<std::pair<double, double>> fk;
  for (int q = 5; q <= 50; ++q) {
    const double f = q * df;
    const auto p = lattice_at_frequency(chain, 2 * std::numbers::pi * f);
    ASSERT_TRUE(p);
    fk.emplace_back(f, p->k_rad_m);
    for (std::size_t i = 0; i < r.times; ++i)
      for (std::size_t j = 0; j < r.positions; ++j)
        r.samples[i * r.positions + j] +=
            std::cos(2 * std::numbers::pi * f * double(i) * r.dt_s - p->k_rad_m * double(j) * r.dx_m);
  }
  const auto ridge = spacetime_ridge(r, fk.front().first, fk.back().first, 16, 0.05);
  ASSERT_GE(ridge.size(), 40u);
  const double k_resolution = 2 * std::numbers::pi / (double(r.positions) * r.dx_m);
  for (const auto& p : ridge) {
    double k_true = 0;
    for (const auto& [f, k] : fk)
      if (std::abs(f - p.f_Hz) < 1e-6 * f) k_true = k;
    ASSERT_GT(k_true, 0);
    EXPECT_NEAR(p.k_rad_m, k_true, 0.05 * k_resolution) << p.f_Hz;
    const auto exact = lattice_at_frequency(chain, 2 * std::numbers::pi * p.f_Hz);
    EXPECT_NEAR(p.c_phase_m_s / exact->c_phase_m_s, 1.0, 0.01);
    EXPECT_NEAR(p.c_group_m_s / exact->c_group_m_s, 1.0, 0.02) << p.f_Hz;
  }
}

TEST(GroupVelocity, ResidualSumOfSquaresOverABand) {
  std::vector<GroupVelocityPoint> pts;
  for (double f : {40e3, 50e3, 100e3, 150e3, 160e3}) {
    GroupVelocityPoint p;
    p.f_Hz = f;
    p.c_group_m_s = 5000 + f / 1e3;  // residual f / 1 kHz against a flat 5000 m/s
    pts.push_back(p);
  }
  const auto r = residual_sum_of_squares(pts, [](double) { return 5000.0; }, 50e3, 150e3);
  EXPECT_EQ(r.points, 3u);
  EXPECT_DOUBLE_EQ(r.rss_m2_s2, 50.0 * 50 + 100.0 * 100 + 150.0 * 150);
  EXPECT_DOUBLE_EQ(r.max_abs_m_s, 150.0);
  EXPECT_FALSE(r.in_band[0]);
  EXPECT_TRUE(r.in_band[3]);
  EXPECT_THROW(residual_sum_of_squares(pts, [](double) { return 0.0; }, 200e3, 300e3), InputError);
}
