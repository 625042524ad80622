// Diameter distributions: closed-form moments (uniform), and a sieve curve
// reproduced by number (Kolmogorov-Smirnov) and by mass (the curve itself).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesowave/core/error.hpp"
#include "mesowave/dem/packing/size_distribution.hpp"

using namespace mesowave;
using namespace mesowave::dem;

namespace {

// A sand-like curve (cumulative passing by mass) between 0.5 and 2 mm.
SieveCurve sand() { return parse_sieve_curve("d_mm,passing_pct\n0.5,0\n1,30\n1.6,75\n2,100\n", "sand.csv"); }

// Kolmogorov-Smirnov distance of a sorted sample against a CDF.
template <class Cdf>
double ks_distance(const std::vector<double>& sorted, Cdf cdf) {
  double worst = 0;
  const double n = double(sorted.size());
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    const double f = cdf(sorted[i]);
    worst = std::max({worst, std::abs(f - double(i) / n), std::abs(double(i + 1) / n - f)});
  }
  return worst;
}

}  // namespace

TEST(PackingSizeDistribution, UniformMomentsInClosedForm) {
  const double a = 1.6e-3, b = 2.0e-3;
  const auto s = SizeDistribution::uniform(a, b);
  EXPECT_NEAR(s.mean_power(1), (a + b) / 2, 1e-18);
  EXPECT_NEAR(s.mean_power(3), (std::pow(b, 4) - std::pow(a, 4)) / (4 * (b - a)), 1e-21);
  // Samples: the mean of d^3 within 4 standard errors of the closed form.
  Mt64Random random(11);
  const int n = 200000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    const double d = s.sample_diameter(random);
    ASSERT_GE(d, a);
    ASSERT_LE(d, b);
    sum += d * d * d;
    sum2 += d * d * d * d * d * d;
  }
  const double mean = sum / n, sem = std::sqrt((sum2 / n - mean * mean) / n);
  EXPECT_NEAR(mean, s.mean_power(3), 4 * sem);
  // The concrete cube: N = 0.93 V / (pi/6 E[d^3]) = 37,605.2 for V = (50 mm)^3,
  // E[d^3] = 5.904 mm^3 (Yade made 37,605).
  EXPECT_NEAR(0.93 * 125e-6 / s.mean_sphere_volume(), 116250.0 / (std::numbers::pi / 6 * 5.904), 1e-6);
  EXPECT_NEAR(0.93 * 125e-6 / s.mean_sphere_volume(), 37605, 0.5);
}

TEST(PackingSizeDistribution, UniformVolumeCdf) {
  const auto s = SizeDistribution::uniform(1.0, 2.0);
  // Fraction of volume below d: integral of x^3 from 1 to d over that to 2.
  EXPECT_NEAR(s.volume_cdf(1.5), (std::pow(1.5, 4) - 1) / 15, 1e-15);
  EXPECT_NEAR(s.number_cdf(1.25), 0.25, 1e-15);
  const auto one = SizeDistribution::uniform(1.8e-3, 1.8e-3);
  Mt64Random random(1);
  EXPECT_EQ(one.sample_diameter(random), 1.8e-3);
  EXPECT_THROW(SizeDistribution::uniform(2e-3, 1.6e-3), InputError);
  EXPECT_THROW(SizeDistribution::uniform(-1e-3, 1.6e-3), InputError);
}

TEST(PackingSizeDistribution, SieveNumberCdfMatchesNumericalIntegration) {
  // Independent: integrate n(d) ~ F'(d) / d^3 with a fine midpoint rule.
  const auto s = SizeDistribution::sieve(sand());
  const std::vector<double> x = {0.5e-3, 1e-3, 1.6e-3, 2e-3}, F = {0, 0.3, 0.75, 1};
  auto density = [&](double d) {
    for (std::size_t k = 0; k + 1 < x.size(); ++k)
      if (d <= x[k + 1]) return (F[k + 1] - F[k]) / (x[k + 1] - x[k]) / (d * d * d);
    return 0.0;
  };
  const int steps = 300000;
  const double h = (2e-3 - 0.5e-3) / steps;
  std::vector<double> cumulative(steps + 1, 0);
  double m1 = 0, m3 = 0;
  for (int i = 0; i < steps; ++i) {
    const double d = 0.5e-3 + (i + 0.5) * h;
    cumulative[i + 1] = cumulative[i] + density(d) * h;
    m1 += d * density(d) * h;
    m3 += d * d * d * density(d) * h;
  }
  const double total = cumulative.back();
  for (double d : {0.7e-3, 1e-3, 1.3e-3, 1.6e-3, 1.9e-3}) {
    const int i = int(std::round((d - 0.5e-3) / h));
    EXPECT_NEAR(s.number_cdf(d), cumulative[i] / total, 1e-6) << d;
  }
  EXPECT_NEAR(s.mean_power(1) / (m1 / total), 1.0, 1e-6);
  EXPECT_NEAR(s.mean_power(3) / (m3 / total), 1.0, 1e-6);
  EXPECT_NEAR(s.volume_cdf(1e-3), 0.3, 1e-15);
  EXPECT_NEAR(s.volume_cdf(1.3e-3), 0.3 + 0.45 * 0.5, 1e-15);
}

TEST(PackingSizeDistribution, SieveSamplesPassKolmogorovSmirnov) {
  const auto s = SizeDistribution::sieve(sand());
  Mt64Random random(5);
  std::vector<double> d(20000);
  for (double& v : d) v = s.sample_diameter(random);
  std::sort(d.begin(), d.end());
  // 1 % critical value of the one-sample KS statistic: 1.63 / sqrt(n).
  EXPECT_LT(ks_distance(d, [&](double x) { return s.number_cdf(x); }), 1.63 / std::sqrt(double(d.size())));
}

TEST(PackingSizeDistribution, PackingFilledByVolumeReproducesTheSieveCurve) {
  // Spheres drawn until their volume reaches a target: the mass fraction
  // passing each sieve is the curve's (by mass), within sampling noise.
  const auto s = SizeDistribution::sieve(sand());
  Mt64Random random(9);
  const auto d = draw_diameters_for_volume(s, 2e-6, random);  // 2 cm^3 of sand, ~ 3000 grains
  double total = 0;
  for (double v : d) total += v * v * v;
  EXPECT_NEAR(std::numbers::pi / 6 * total, 2e-6, 1e-18);  // the volume is met exactly
  for (auto [sieve, passing] : {std::pair{1e-3, 0.30}, {1.6e-3, 0.75}}) {
    double below = 0;
    for (double v : d)
      if (v <= sieve) below += v * v * v;
    EXPECT_NEAR(below / total, passing, 0.02) << sieve;
  }
}

TEST(PackingSizeDistribution, SieveCutToRange) {
  // Cutting to [1, 1.6] mm keeps 45 % of the mass, renormalised.
  const auto s = SizeDistribution::sieve(sand(), 1e-3, 1.6e-3);
  EXPECT_NEAR(s.represented_fraction(), 0.45, 1e-15);
  EXPECT_EQ(s.d_min(), 1e-3);
  EXPECT_EQ(s.d_max(), 1.6e-3);
  EXPECT_NEAR(s.volume_cdf(1.3e-3), 0.5, 1e-15);
  // Within one interval with linear F, n(d) ~ d^-3: number CDF in closed form.
  EXPECT_NEAR(s.number_cdf(1.3e-3), (1 / 1e-6 - 1 / 1.69e-6) / (1 / 1e-6 - 1 / 2.56e-6), 1e-12);
  EXPECT_THROW(SizeDistribution::sieve(sand(), 0.1e-3, 1e-3), InputError);  // outside the curve
  EXPECT_THROW(SizeDistribution::sieve(sand(), 1.6e-3, 1e-3), InputError);
}

TEST(PackingSizeDistribution, MalformedSieveCurves) {
  EXPECT_THROW(parse_sieve_curve("size,passing_pct\n1,0\n2,100\n", "x"), InputError);          // no unit
  EXPECT_THROW(parse_sieve_curve("d_mm,passing\n1,0\n2,100\n", "x"), InputError);              // no unit
  EXPECT_THROW(parse_sieve_curve("d_mm,passing_pct\n1,0\n", "x"), InputError);                 // one row
  EXPECT_THROW(parse_sieve_curve("d_mm,passing_pct\n2,0\n1,100\n", "x"), InputError);          // sizes decrease
  EXPECT_THROW(parse_sieve_curve("d_mm,passing_pct\n1,50\n2,40\n", "x"), InputError);          // passing decreases
  EXPECT_THROW(parse_sieve_curve("d_mm,passing_fraction\n1,0\n2,1.5\n", "x"), InputError);     // above 1
  EXPECT_THROW(parse_sieve_curve("d_mm,passing_pct\n0,0\n2,100\n", "x"), InputError);          // size 0
  EXPECT_THROW(parse_sieve_curve("d_mm,passing_pct\n1,20\n2,20\n", "x"), InputError);          // no mass
  EXPECT_THROW(parse_sieve_curve("d_mm,passing_pct\n1,abc\n2,20\n", "x"), InputError);
  const auto ok = parse_sieve_curve("# sand\nsize_um,passing_fraction\n500,0.1\n2000,1\n", "x");
  EXPECT_EQ(ok.d_m.front(), 500e-6);
  EXPECT_EQ(ok.passing.front(), 0.1);
}
