// core/random.hpp against the engines' published reference outputs, and its
// distributions against their moments and ranges.
#include "mesowave/core/random.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>

using namespace mesowave;

namespace {

// The C++ standard fixes std::mt19937_64 ([rand.predef]): the 10000th
// consecutive invocation of a default-constructed object (seed 5489)
// produces 9981545732273789042.
TEST(Random, Mt64StreamIsTheStandardsMt19937_64) {
  Mt64Random random(5489);
  std::uint64_t v = 0;
  for (int i = 0; i < 10000; ++i) v = random.bits();
  EXPECT_EQ(v, 9981545732273789042ull);
}

// Reference values of Vigna's splitmix64.c for this seed (as quoted by the
// rand_xoshiro crate's reference test).
constexpr std::uint64_t splitmix_seed = 1477776061723855037ull;
constexpr std::array<std::uint64_t, 10> splitmix_reference = {
    1985237415132408290ull,  2979275885539914483ull,  13511426838097143398ull, 8488337342461049707ull,
    15141737807933549159ull, 17093170987380407015ull, 16389528042912955399ull, 13177319091862933652ull,
    10841969400225389492ull, 17094824097954834098ull};

TEST(Random, SplitMix64MatchesTheReferenceImplementation) {
  SplitMix64 s(splitmix_seed);
  for (auto expected : splitmix_reference) EXPECT_EQ(s(), expected);
}

// Reference values of xoshiro256starstar.c from the state {1, 2, 3, 4}.
TEST(Random, Xoshiro256StarStarMatchesTheReferenceImplementation) {
  auto x = Xoshiro256StarStar::from_state({1, 2, 3, 4});
  const std::array<std::uint64_t, 10> expected = {11520ull,
                                                  0ull,
                                                  1509978240ull,
                                                  1215971899390074240ull,
                                                  1216172134540287360ull,
                                                  607988272756665600ull,
                                                  16172922978634559625ull,
                                                  8476171486693032832ull,
                                                  10595114339597558777ull,
                                                  2904607092377533576ull};
  for (auto e : expected) EXPECT_EQ(x(), e);
}

TEST(Random, XoshiroIsSeededWithTheFirstFourSplitMix64Outputs) {
  const Xoshiro256StarStar x(splitmix_seed);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(x.state()[i], splitmix_reference[i]);
}

TEST(Random, UniformsTakeTheTop53BitsOfOneDraw) {
  Mt64Random a(42), b(42);
  for (int i = 0; i < 1000; ++i) {
    const std::uint64_t bits = a.bits();
    const double u = b.uniform01();
    EXPECT_EQ(u, std::ldexp(double(bits >> 11), -53));
    EXPECT_GE(u, 0.0);
    EXPECT_LT(u, 1.0);
  }
  // The open uniform is the midpoint of the same cell: never 0.
  Mt64Random c(42), d(42);
  for (int i = 0; i < 1000; ++i) EXPECT_EQ(c.uniform_open01(), d.uniform01() + 0x1.0p-54);
  XoshiroRandom e(7);
  for (int i = 0; i < 1000; ++i) {
    const double v = e.uniform(-2.5, 4.0);
    EXPECT_GE(v, -2.5);
    EXPECT_LT(v, 4.0);
  }
}

// Irwin-Hall of 12: mean 0, variance 12 * (1/12) = 1, support [-6, 6]; the
// sample mean of n draws has standard error 1/sqrt(n).
TEST(Random, IrwinHallNormalHasUnitVarianceAndBoundedTails) {
  XoshiroRandom random(11);
  const int n = 200000;
  double sum = 0, sum2 = 0, lo = 0, hi = 0;
  for (int i = 0; i < n; ++i) {
    const double z = random.normal();
    sum += z, sum2 += z * z;
    lo = std::min(lo, z), hi = std::max(hi, z);
  }
  EXPECT_NEAR(sum / n, 0.0, 5.0 / std::sqrt(n));
  EXPECT_NEAR(sum2 / n, 1.0, 0.02);
  EXPECT_GE(lo, -6.0);
  EXPECT_LE(hi, 6.0);
  XoshiroRandom a(3), b(3);
  EXPECT_EQ(a.normal(2.0, 0.5), 2.0 + 0.5 * b.normal());
}

// Box-Muller pairs: each deviate N(0, sd^2), the two uncorrelated, and a
// fourth moment of 3 sd^4 (Gaussian tails, unlike Irwin-Hall's 2.9).
TEST(Random, GaussianPairsHaveTheGaussianMoments) {
  Mt64Random random(5);
  const int n = 200000;
  const double sd = 0.3;
  double s1 = 0, s2 = 0, s4 = 0, cross = 0;
  for (int i = 0; i < n; ++i) {
    const auto [a, b] = random.gaussian_pair(sd);
    s1 += a + b, s2 += a * a + b * b, s4 += std::pow(a, 4) + std::pow(b, 4), cross += a * b;
  }
  const double m = 2.0 * n;
  EXPECT_NEAR(s1 / m, 0.0, 5.0 * sd / std::sqrt(m));
  EXPECT_NEAR(s2 / m, sd * sd, 0.01 * sd * sd);
  EXPECT_NEAR(s4 / m / std::pow(sd, 4), 3.0, 0.06);
  EXPECT_NEAR(cross / n / (sd * sd), 0.0, 0.015);
}

}  // namespace
