// Random packings: the porosity reached, every sphere inside, even overlaps,
// isotropy, and determinism (same seed and any thread count: same bits).
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

#include "mesowave/core/error.hpp"
#include "mesowave/dem/engine/neighbour_search.hpp"
#include "mesowave/dem/packing/packing_generator.hpp"
#include "mesowave/dem/packing/packing_stats.hpp"

using namespace mesowave;
using namespace mesowave::dem;

namespace {

PackingOptions concrete(double porosity = 0.07, std::uint64_t seed = 1) {
  PackingOptions o;
  o.porosity = porosity;
  o.sizes = SizeDistribution::uniform(1.6e-3, 2.0e-3);
  o.seed = seed;
  return o;
}

bool same_bits(const Packing& a, const Packing& b) {
  return a.size() == b.size() &&
         std::memcmp(a.centres_m.data(), b.centres_m.data(), a.size() * sizeof(a.centres_m[0])) == 0 &&
         std::memcmp(a.radii_m.data(), b.radii_m.data(), a.size() * sizeof(double)) == 0 && a.ids == b.ids;
}

// A 12 mm cube at p = 7 %, made once for the tests that only look at it.
const Packing& small_cube() {
  static const Packing p = generate_packing(box_container({0, 0, 0}, {12e-3, 12e-3, 12e-3}), concrete());
  return p;
}

}  // namespace

TEST(PackingGenerator, ReachesTheTargetPorosity) {
  // The diameters are drawn until their volume is (1 - p) V and the last gap
  // is closed exactly, so the porosity equals the target to rounding.
  const auto& p = small_cube();
  EXPECT_NEAR(porosity(p), 0.07, 1e-12);
  // The count follows from the volume: (1 - p) V / E[pi d^3 / 6], E[d^3] = (b^4 - a^4) / (4 (b - a)).
  const double mean_volume = std::numbers::pi / 6 * (std::pow(2.0e-3, 4) - std::pow(1.6e-3, 4)) / (4 * 0.4e-3);
  const double expected = 0.93 * 1728e-9 / mean_volume;
  EXPECT_NEAR(double(p.size()), expected, 4 * std::sqrt(expected) * 0.2);  // ~20 % spread of sphere volumes
}

TEST(PackingGenerator, EverySphereLiesInsideTheBox) {
  const auto& p = small_cube();
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int d = 0; d < 3; ++d) {
      EXPECT_GE(p.centres_m[i][d] - p.radii_m[i], -1e-15) << i;
      EXPECT_LE(p.centres_m[i][d] + p.radii_m[i], 12e-3 + 1e-15) << i;
    }
  EXPECT_EQ(packing_stats(p).spheres_outside, 0u);
}

TEST(PackingGenerator, SizesStayInRange) {
  const auto& p = small_cube();
  for (double r : p.radii_m) {
    EXPECT_GE(2 * r, 1.6e-3 * (1 - 1e-12));
    EXPECT_LE(2 * r, 2.0e-3 * (1 + 1e-12));
  }
}

TEST(PackingGenerator, OverlapsAreBalancedAndNoSphereIsBuried) {
  const auto& p = small_cube();
  const auto s = packing_stats(p, 1.1);
  // Far denser than random close packing: every sphere touches about ten others.
  EXPECT_GT(s.coordination_contacts, 8.0);
  EXPECT_GT(s.mean_overlap_ratio, 0.1);
  EXPECT_LT(s.mean_overlap_ratio, 0.3);
  EXPECT_LT(s.max_overlap_ratio, 0.7);  // no centre inside another sphere, none near it
  // Force balance: on every sphere away from the walls the overlap forces
  // dE/d(delta) = xi (1 + Q xi^2) / r_min, xi = delta / r_min, along the
  // centre line, cancel to the tolerance (E = sum 1/2 xi^2 + Q/4 xi^4, Q = 3).
  const auto pairs = find_pairs_within(p.centres_m, p.radii_m, 1.0);
  std::vector<std::array<double, 3>> net(p.size(), {0, 0, 0});
  double sum = 0;
  for (const auto& c : pairs) {
    std::array<double, 3> d;
    for (int k = 0; k < 3; ++k) d[k] = p.centres_m[c.i][k] - p.centres_m[c.j][k];
    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const double r_min = std::min(p.radii_m[c.i], p.radii_m[c.j]);
    const double xi = (p.radii_m[c.i] + p.radii_m[c.j] - len) / r_min;
    const double f = xi * (1 + 3 * xi * xi) / r_min;
    sum += f;
    for (int k = 0; k < 3; ++k) net[c.i][k] += f * d[k] / len, net[c.j][k] -= f * d[k] / len;
  }
  const double mean = sum / double(pairs.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    bool at_wall = false;
    for (int k = 0; k < 3; ++k)
      at_wall = at_wall || p.centres_m[i][k] - p.radii_m[i] < 1e-12 || p.centres_m[i][k] + p.radii_m[i] > 12e-3 - 1e-12;
    if (at_wall) continue;
    EXPECT_LT(std::hypot(net[i][0], net[i][1], net[i][2]) / mean, 1e-3 * 1.0001) << i;
  }
}

TEST(PackingGenerator, IsotropicAndHomogeneous) {
  // A 16 mm cube: bond directions equally spread (fabric eigenvalues near
  // 1/3), and the same number of sphere centres in each half along every axis.
  const auto p = generate_packing(box_container({0, 0, 0}, {16e-3, 16e-3, 16e-3}), concrete(0.07, 3));
  const auto s = packing_stats(p, 1.1);
  EXPECT_GT(s.fabric_min, 0.32);
  EXPECT_LT(s.fabric_max, 0.347);
  for (int d = 0; d < 3; ++d) {
    double lower = 0;
    for (const auto& c : p.centres_m) lower += c[d] < 8e-3 ? 1 : 0;
    const double n = double(p.size());
    EXPECT_NEAR(lower / n, 0.5, 3 * 0.5 / std::sqrt(n)) << "axis " << d;  // binomial, 3 sigma
  }
}

TEST(PackingGenerator, SameSeedSameBitsOtherSeedOtherPacking) {
  const auto box = box_container({0, 0, 0}, {8e-3, 8e-3, 8e-3});
  const auto a = generate_packing(box, concrete(0.07, 42));
  const auto b = generate_packing(box, concrete(0.07, 42));
  const auto c = generate_packing(box, concrete(0.07, 43));
  EXPECT_TRUE(same_bits(a, b));
  EXPECT_FALSE(same_bits(a, c));
}

TEST(PackingGenerator, SameBitsForOneAndTwoThreads) {
  // Several 256-sphere reduction blocks, threads forced on from 1 sphere.
  auto o = concrete(0.07, 7);
  o.sizes = SizeDistribution::uniform(0.8e-3, 1.0e-3);
  o.parallel_from = 1;
  const auto box = box_container({0, 0, 0}, {5e-3, 5e-3, 5e-3});
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const auto one = generate_packing(box, o);
  omp_set_num_threads(2);
  const auto two = generate_packing(box, o);
  omp_set_num_threads(threads);
  ASSERT_GT(one.size(), 256u);
  EXPECT_TRUE(same_bits(one, two));
}

TEST(PackingGenerator, Cylinder) {
  const auto cyl = cylinder_container(6e-3, 0, 10e-3, 6e-3, 6e-3);
  PackingRun run;
  const auto p = generate_packing(cyl, concrete(0.10, 5), &run);
  EXPECT_TRUE(run.converged);
  EXPECT_NEAR(porosity(p), 0.10, 1e-12);
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_LE(std::hypot(p.centres_m[i][0] - 6e-3, p.centres_m[i][1] - 6e-3) + p.radii_m[i], 6e-3 * (1 + 1e-12));
    EXPECT_GE(p.centres_m[i][2] - p.radii_m[i], -1e-15);
    EXPECT_LE(p.centres_m[i][2] + p.radii_m[i], 10e-3 + 1e-15);
  }
}

TEST(PackingGenerator, WideSieveCurveAtSevenPercentBuriesNoSphere) {
  // A 0.5-2 mm sand (size ratio 4) at p = 7 %: the radius growth and the
  // quartic term keep every small sphere out of the large ones' centres, and
  // the packing's mass passing 1 mm is the curve's (27/65 of the kept range).
  auto o = concrete(0.07, 4);
  o.sizes = SizeDistribution::sieve(
      parse_sieve_curve("d_mm,passing_pct\n0.25,12\n0.5,35\n1,62\n1.6,88\n2,100\n", "sand"), 0.5e-3);
  const auto p = generate_packing(box_container({0, 0, 0}, {8e-3, 8e-3, 8e-3}), o);
  EXPECT_NEAR(porosity(p), 0.07, 1e-12);
  const auto s = packing_stats(p);
  EXPECT_LT(s.max_overlap_ratio, 1.0);
  EXPECT_EQ(s.spheres_outside, 0u);
  double below = 0, total = 0;
  for (double r : p.radii_m) (2 * r <= 1e-3 ? below : total) += r * r * r;
  EXPECT_NEAR(below / (below + total), 27.0 / 65.0, 0.05);
}

TEST(PackingGenerator, LoosePackingsNeedNoOverlap) {
  // p = 80 % is far looser than random close packing: the spheres separate.
  const auto p = generate_packing(box_container({0, 0, 0}, {10e-3, 10e-3, 10e-3}), concrete(0.80, 2));
  EXPECT_NEAR(porosity(p), 0.80, 1e-12);
  EXPECT_LT(packing_stats(p).max_overlap_ratio, 1e-2);
}

TEST(PackingGenerator, BadRequests) {
  const auto box = box_container({0, 0, 0}, {10e-3, 10e-3, 10e-3});
  for (double p : {0.0, 1.0, -0.1, 1.5, std::nan("")}) EXPECT_THROW(generate_packing(box, concrete(p)), InputError) << p;
  // Too small for one sphere of d_max; too porous to hold one sphere.
  EXPECT_THROW(generate_packing(box_container({0, 0, 0}, {1.5e-3, 10e-3, 10e-3}), concrete()), InputError);
  EXPECT_THROW(generate_packing(box_container({0, 0, 0}, {2e-3, 2e-3, 2e-3}), concrete(0.9999)), InputError);
  EXPECT_THROW(generate_packing(rod_container(5e-3, 0, 1), concrete()), InputError);
}
