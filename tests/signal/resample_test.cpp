// Resampling against closed forms: linear interpolation is exact on a line,
// the natural cubic spline on sin over [0, pi] (where sin'' = 0 at both ends,
// as the natural end conditions assume) errs by at most (5/384) h^4 max|f''''|.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesowave/core/error.hpp"
#include "mesowave/signal/resample.hpp"

using namespace mesowave;
using namespace mesowave::signal;

TEST(Resample, LinearIsExactOnALine) {
  Signal s{"B", "displacement", "m", "", 1e-6, 2e-7, {}, std::nullopt};
  for (int i = 0; i < 50; ++i) s.samples.push_back(0.5 - 3e4 * s.time(std::size_t(i)));
  const TimeBase target{1.03e-6, 0.7e-7, 130};
  const auto r = resample(s, target, Interpolation::linear);
  ASSERT_EQ(r.size(), 130u);
  EXPECT_EQ(r.name, "B");
  for (std::size_t i = 0; i < r.size(); ++i) EXPECT_NEAR(r.samples[i], 0.5 - 3e4 * r.time(i), 1e-14) << i;
}

TEST(Resample, NaturalCubicSplineOnSineWithinTheFourthOrderBound) {
  const std::size_t n = 101;
  const double h = std::numbers::pi / double(n - 1);
  Signal s{"S", "", "", "", 0.0, h, std::vector<double>(n), std::nullopt};
  for (std::size_t i = 0; i < n; ++i) s.samples[i] = std::sin(double(i) * h);
  const TimeBase target{0.0, h / 7.0, 7 * (n - 1) + 1};
  const auto r = resample(s, target, Interpolation::cubic_spline);
  double worst = 0;
  for (std::size_t i = 0; i < r.size(); ++i) worst = std::max(worst, std::abs(r.samples[i] - std::sin(r.time(i))));
  EXPECT_LT(worst, 5.0 / 384.0 * std::pow(h, 4));
  // Linear interpolation is second order: h^2/8 max|f''| bounds it and is nearly reached.
  const auto l = resample(s, target, Interpolation::linear);
  double worst_linear = 0;
  for (std::size_t i = 0; i < l.size(); ++i) worst_linear = std::max(worst_linear, std::abs(l.samples[i] - std::sin(l.time(i))));
  EXPECT_LT(worst_linear, h * h / 8.0);
  EXPECT_GT(worst_linear, 0.9 * h * h / 8.0);
}

TEST(Resample, RefusesToExtrapolate) {
  Signal s{"B", "", "", "", 0.0, 1e-7, std::vector<double>(100, 1.0), std::nullopt};
  EXPECT_THROW(resample(s, TimeBase{-1e-7, 1e-7, 10}, Interpolation::linear), InputError);
  EXPECT_THROW(resample(s, TimeBase{0.0, 1e-7, 101}, Interpolation::linear), InputError);
  EXPECT_NO_THROW(resample(s, TimeBase{0.0, 1e-7, 100}, Interpolation::cubic_spline));
  Signal one{"C", "", "", "", 0.0, 1e-7, {1.0}, std::nullopt};
  EXPECT_THROW(resample(one, TimeBase{0.0, 1e-7, 1}, Interpolation::linear), InputError);
}

TEST(Resample, TimeBasesAndWindows) {
  const TimeBase a{0.0, 1e-7, 100};
  EXPECT_TRUE(same_time_base(a, TimeBase{1e-14, 1e-7 * (1 + 1e-12), 100}));
  EXPECT_FALSE(same_time_base(a, TimeBase{0.0, 1e-7, 99}));
  EXPECT_FALSE(same_time_base(a, TimeBase{0.0, 1.001e-7, 100}));
  EXPECT_FALSE(same_time_base(a, TimeBase{1e-8, 1e-7, 100}));
  const auto w = restrict_time_base(a, 1.05e-6, 2e-6, "test");
  EXPECT_EQ(w.count, 10u);  // samples 11 .. 20
  EXPECT_NEAR(w.t0_s, 1.1e-6, 1e-18);
  EXPECT_THROW(restrict_time_base(a, 1e-3, 2e-3, "test"), InputError);
  EXPECT_EQ(parse_interpolation("cubic"), Interpolation::cubic_spline);
  EXPECT_THROW(parse_interpolation("nearest"), InputError);
}
