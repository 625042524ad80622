// Bar velocity from a pulse-echo record: a synthetic split-Hopkinson-bar record
// whose echo is the pulse carried over the path by exact Pochhammer-Chree
// dispersion, and the CSV import with a coarsely printed time column.
#include "mesowave/wave/bar_echo.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>

#include "mesowave/core/error.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using namespace mesowave::wave;

namespace {

// A trapezoid: 8 us rise, 200 us plateau, 8 us fall, starting at t_start.
double trapezoid(double t, double t_start) {
  const double r = 8e-6, p = 200e-6, x = t - t_start;
  if (x <= 0 || x >= 2 * r + p) return 0;
  if (x < r) return x / r;
  if (x < r + p) return 1;
  return (2 * r + p - x) / r;
}

}  // namespace

TEST(BarEcho, SyntheticRecordWithTheoryEcho) {
  const PochhammerChree pc({210e9, 0.3, 7800}, 10e-3);  // the 20 mm bar of the real record
  const double path = 2.036, dt = 80e-9;
  signal::Signal pulse;
  pulse.name = "pulse";
  pulse.dt_s = dt;
  pulse.t0_s = -50e-6;
  for (int i = 0; i < 4000; ++i) pulse.samples.push_back(-trapezoid(pulse.time(std::size_t(i)), 0.0));
  const auto echo = propagate_l01(pulse, pc, path, 500e3);
  signal::Signal record = pulse;
  record.name = "incident";
  record.samples.assign(echo.size(), 0.0);
  // Reflection -1, and gauge noise of 2 % RMS of the pulse (uniform, fixed seed), about
  // the level of the real record in ../shared/realdata/shpb-steel-bar.
  std::uint64_t state = 12345;
  for (std::size_t i = 0; i < echo.size(); ++i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    const double noise = 0.02 * std::sqrt(12.0) * (double(state >> 11) / 9007199254740992.0 - 0.5);
    record.samples[i] = (i < pulse.size() ? pulse.samples[i] : 0.0) - echo.samples[i] + noise;
  }
  BarEchoOptions opt;
  opt.path_m = path;
  opt.theory = &pc;
  const auto r = analyse_bar_echo(record, opt);
  // Opposite sign; larger, as dispersion rings the front of the echo (the overshoot behind
  // a dispersed step front, Pochhammer-Chree ringing).
  EXPECT_LT(r.second_pulse_extreme / r.first_pulse_extreme, -1.0);
  const auto pick = [&](const std::string& m) {
    for (const auto& p : r.picks)
      if (p.method == m) return p;
    ADD_FAILURE() << "no pick " << m;
    return BarEchoPick{};
  };
  // The echo is the theory's: its edges are found where the theory puts them.
  for (const std::string level : {"0.25", "0.5", "0.75"})
    EXPECT_NEAR(pick("edge-" + level).t2_s, pick("theory-edge-" + level).t2_s, 0.5e-6) << level;  // noise jitter
  EXPECT_NEAR(r.fitted_c0_m_s / pc.speeds().c0, 1.0, 1e-3);
  EXPECT_LT(r.fitted_c0_relative_spread, 1e-3);
  // Onset pickers: near c0 but early on the echo, whose dispersed front rises ahead of
  // z / c0 (up to ~1 % fast at 2 % noise); edges lag as the front widens, so higher
  // levels give lower apparent velocities.
  const double c0 = pc.speeds().c0;
  EXPECT_NEAR(pick("aic").velocity_m_s / c0, 1.0, 0.015);
  EXPECT_NEAR(pick("threshold").velocity_m_s / c0, 1.0, 0.015);
  EXPECT_GT(pick("aic").velocity_m_s, c0);
  EXPECT_GT(pick("edge-0.25").velocity_m_s, pick("edge-0.75").velocity_m_s);
  EXPECT_LT(r.f90_Hz, 20e3);
}

TEST(BarEcho, CsvWithCoarseTimeColumn) {
  test::TempDir dir;
  const auto path = dir / "r.csv";
  {
    std::ofstream f(path);
    f << "Time/s,incident/e\n";
    for (int i = 0; i < 2000; ++i) {
      char t[32];
      std::snprintf(t, sizeof t, "%.2E", -20e-6 + i * 80e-9);  // 3 significant digits
      f << t << "," << (i > 500 && i < 900 ? 1.0 : 0.0) << "\n";
    }
  }
  const auto s = signal_from_csv(path.string(), "incident");
  EXPECT_NEAR(s.dt_s, 80e-9, 1e-12);
  EXPECT_NEAR(s.t0_s, -20e-6, 0.05e-6);
  EXPECT_EQ(s.size(), 2000u);
  EXPECT_EQ(s.samples[600], 1.0);
  EXPECT_THROW(signal_from_csv(path.string(), "reflected"), InputError);
  const auto bad = dir / "bad.csv";
  {
    std::ofstream f(bad);
    f << "t,x\n";
    for (int i = 0; i < 100; ++i) f << (i < 50 ? i : 3 * i) * 1e-6 << ",0\n";
  }
  EXPECT_THROW(signal_from_csv(bad.string(), "x"), InputError);
  // A record with a single pulse cannot give an echo velocity.
  signal::Signal one;
  one.name = "one";
  one.dt_s = 80e-9;
  for (int i = 0; i < 5000; ++i) one.samples.push_back(trapezoid(i * 80e-9, 20e-6));
  BarEchoOptions opt;
  opt.path_m = 2.0;
  EXPECT_THROW(analyse_bar_echo(one, opt), InputError);
}
