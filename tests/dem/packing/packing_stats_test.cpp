// Porosity, coordination and overlaps on configurations with closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesowave/core/error.hpp"
#include "mesowave/dem/packing/packing_generator.hpp"
#include "mesowave/dem/packing/packing_stats.hpp"

using namespace mesowave;
using namespace mesowave::dem;

namespace {

constexpr double pi = std::numbers::pi;

Packing simple_cubic(int n, double r) {
  Packing p;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        p.centres_m.push_back({(2 * i + 1) * r, (2 * j + 1) * r, (2 * k + 1) * r});
        p.radii_m.push_back(r);
        p.ids.push_back(std::int64_t(p.ids.size()));
      }
  p.container = box_container({0, 0, 0}, {2 * n * r, 2 * n * r, 2 * n * r});
  return p;
}

// FCC: integer points (i, j, k) in [0, M]^3 with i + j + k even, scaled by h;
// nearest neighbours at h sqrt(2), next ones at 2h.
Packing fcc_block(int M, double h, double r) {
  Packing p;
  for (int i = 0; i <= M; ++i)
    for (int j = 0; j <= M; ++j)
      for (int k = 0; k <= M; ++k)
        if ((i + j + k) % 2 == 0) {
          p.centres_m.push_back({i * h, j * h, k * h});
          p.radii_m.push_back(r);
          p.ids.push_back(std::int64_t(p.ids.size()));
        }
  p.container = box_container({-r, -r, -r}, {M * h + r, M * h + r, M * h + r});
  return p;
}

}  // namespace

TEST(PackingStats, PorosityOfSimpleCubicIsOneMinusPiOverSix) {
  const auto p = simple_cubic(5, 1e-3);
  EXPECT_NEAR(porosity(p), 1 - pi / 6, 1e-14);
  const auto s = packing_stats(p, 1.1);
  EXPECT_EQ(s.count, 125u);
  EXPECT_NEAR(s.porosity, 1 - pi / 6, 1e-14);
  EXPECT_EQ(s.spheres_outside, 0u);
  // Touching neighbours (grown by 1e-9 so rounding cannot part them):
  // 3 n^2 (n - 1) pairs, no overlap to speak of.
  auto touching = p;
  for (double& r : touching.radii_m) r *= 1 + 1e-9;
  const auto t = packing_stats(touching, 1.0);
  EXPECT_EQ(t.contacts, 3u * 25u * 4u);
  EXPECT_EQ(t.bonds, 3u * 25u * 4u);
  EXPECT_NEAR(t.max_overlap_ratio, 0.0, 1e-8);
  // Diagonal neighbours sit at 2 sqrt(2) r: C_f = 1.5 reaches them (12 more per
  // interior sphere: 6 n (n - 1)^2 pairs), C_f = 1.4 does not.
  EXPECT_EQ(packing_stats(touching, 1.4).bonds, 300u);
  EXPECT_EQ(packing_stats(touching, 1.5).bonds, 300u + 6u * 5u * 16u);
}

TEST(PackingStats, PorosityOfSpheresInACylinder) {
  // n touching spheres of radius r in a cylinder of radius r and length 2 n r:
  // p = 1 - n (4/3) pi r^3 / (pi r^2 2 n r) = 1/3.
  Packing p;
  const double r = 2e-3;
  for (int k = 0; k < 7; ++k) {
    p.centres_m.push_back({0, 0, (2 * k + 1) * r});
    p.radii_m.push_back(r);
    p.ids.push_back(k);
  }
  p.container = cylinder_container(r, 0, 14 * r);
  EXPECT_NEAR(porosity(p), 1.0 / 3.0, 1e-14);
  EXPECT_EQ(packing_stats(p).spheres_outside, 0u);
}

TEST(PackingStats, OverlapsCountInThePorosityAsIfSeparate) {
  // Two spheres overlapping by half a radius: the porosity counts both whole.
  Packing p;
  const double r = 1e-3;
  p.centres_m = {{2e-3, 2e-3, 2e-3}, {2e-3 + 1.5 * r, 2e-3, 2e-3}};
  p.radii_m = {r, r};
  p.ids = {0, 1};
  p.container = box_container({0, 0, 0}, {5e-3, 4e-3, 4e-3});
  EXPECT_NEAR(porosity(p), 1 - 2 * 4.0 / 3.0 * pi * 1e-9 / 80e-9, 1e-14);
  const auto s = packing_stats(p);
  EXPECT_EQ(s.contacts, 1u);
  EXPECT_NEAR(s.mean_overlap_ratio, 0.5, 1e-12);
  EXPECT_NEAR(s.max_overlap_ratio, 0.5, 1e-12);
}

TEST(PackingStats, FccCoordinationAtDetectionFactor) {
  // Bonds of the block, counted per direction: 6 directions, M^2 (M+1)/2
  // pairs each (M even), so B = 3 M^2 (M+1); N = ((M+1)^3 + 1)/2; an
  // interior sphere has 12. C_f = 1.1 reaches 2.2 r < 2h = 2.83 r, so only
  // the 12 nearest count, also with a 1 % gap.
  const int M = 10;
  const double h = 1e-3, r_touch = h * std::sqrt(2.0) / 2;
  for (double r : {r_touch, r_touch / 1.01}) {
    const auto s = packing_stats(fcc_block(M, h, r), 1.1);
    EXPECT_EQ(s.count, std::size_t(((M + 1) * (M + 1) * (M + 1) + 1) / 2));
    EXPECT_EQ(s.bonds, std::size_t(3 * M * M * (M + 1)));
    EXPECT_DOUBLE_EQ(s.coordination, 12.0 * M * M * (M + 1) / (((M + 1) * (M + 1) * (M + 1) + 1) / 2.0) / 2.0);
    EXPECT_NEAR(s.fabric_min, 1.0 / 3.0, 0.01);  // cubic symmetry: isotropic fabric
    EXPECT_NEAR(s.fabric_max, 1.0 / 3.0, 0.01);
  }
  // Far from the faces the coordination tends to 12: B/N -> 6 as M grows.
  const auto big = packing_stats(fcc_block(40, h, r_touch), 1.1);
  EXPECT_NEAR(big.coordination, 12.0 * 40 * 40 * 41 / ((41.0 * 41 * 41 + 1) / 2) / 2, 1e-12);
  EXPECT_GT(big.coordination, 11.0);
}

TEST(PackingStats, CubeParticleDensityIsDensityOverSolidFraction) {
  // sum(V) = (1 - p) V_container, so rho_p = rho / (1 - p) exactly.
  const auto p = simple_cubic(4, 0.5e-3);
  const double rho = 2129.56;
  EXPECT_NEAR(particle_density_for_mass(specimen_mass(rho, p.container), p), rho / (pi / 6), 1e-9);
  EXPECT_THROW(particle_density_for_mass(-1.0, p), InputError);
  EXPECT_THROW(specimen_mass(0.0, p.container), InputError);
}

TEST(PackingStats, SphereInsideRules) {
  const auto box = box_container({0, 0, 0}, {10e-3, 10e-3, 10e-3});
  EXPECT_TRUE(sphere_inside(box, {1e-3, 1e-3, 1e-3}, 1e-3));
  EXPECT_FALSE(sphere_inside(box, {0.9e-3, 5e-3, 5e-3}, 1e-3));
  const auto cyl = cylinder_container(5e-3, 0, 10e-3, 5e-3, 5e-3);
  EXPECT_TRUE(sphere_inside(cyl, {5e-3 + 3.9e-3, 5e-3, 5e-3}, 1e-3));
  EXPECT_FALSE(sphere_inside(cyl, {5e-3 + 3e-3, 5e-3 + 3e-3, 5e-3}, 1e-3));  // 4.24 + 1 > 5
}

TEST(PackingStats, ContainerChecks) {
  EXPECT_THROW(box_container({0, 0, 0}, {1e-3, -1e-3, 1e-3}), InputError);
  EXPECT_THROW(cylinder_container(-1e-3, 0, 1e-3), InputError);
  Container bad = cylinder_container(1e-3, 0, 1e-3);
  bad.upper_m[0] += 1e-3;  // bounding box no longer 2R wide
  EXPECT_THROW(container_volume(bad), InputError);
  EXPECT_NEAR(container_volume(cylinder_container(2e-3, 0, 3e-3)), pi * 4e-6 * 3e-3, 1e-20);
}
