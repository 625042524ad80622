// The contact layout's partition count (SphereSystem::partition_count): the sizes
// docs/benchmarks.md quotes ("The step near the memory limit", ninth part), and below 20,480
// spheres the rule before it (n / 4,096, at least 1), so that every smaller model - the tests'
// and the quick pipeline's - keeps its bits. And the observed spheres (observe): keeping only
// their accelerations changes no bit of the motion or the energies (tenth part).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "dem/test_packings.hpp"
#include "dem/test_systems.hpp"
#include "mesowave/dem/engine/sphere_system.hpp"

using namespace mesowave::dem;
using mesowave::dem::testing::bonded_system;
using mesowave::dem::testing::concrete_material;
using mesowave::dem::testing::expect_same_motion;
using mesowave::dem::testing::fcc_packing;

TEST(SphereSystem, PartitionsOfTheBenchmarkedCubes) {
  EXPECT_EQ(SphereSystem::partition_count(9'847), 2u);      // 32 mm
  EXPECT_EQ(SphereSystem::partition_count(37'580), 4u);     // 50 mm: the floor of four
  EXPECT_EQ(SphereSystem::partition_count(126'844), 7u);    // 75 mm: 16,384 spheres each
  EXPECT_EQ(SphereSystem::partition_count(1'015'355), 61u); // 150 mm
  EXPECT_EQ(SphereSystem::partition_count(50'000'000), 64u);
  // The comparison's old layout (bench_dem_sizes --compare-spheres-per-partition 4096).
  EXPECT_EQ(SphereSystem::partition_count(37'580, 4'096), 9u);
  EXPECT_EQ(SphereSystem::partition_count(126'844, 4'096), 30u);
  EXPECT_EQ(SphereSystem::partition_count(1'015'355, 4'096), 64u);
}

TEST(SphereSystem, SmallModelsKeepTheEarlierPartitions) {
  for (std::size_t n = 0; n < 20'480; ++n)
    ASSERT_EQ(SphereSystem::partition_count(n), std::clamp<std::size_t>(n / 4'096, 1, 64)) << n << " spheres";
  EXPECT_NE(SphereSystem::partition_count(20'480), std::size_t(20'480 / 4'096));
}

// 864 spheres, four blocks of 256: spheres 0-39 pushed and sphere 700 moved by an imposed
// displacement (the third block) are observed, the second and fourth blocks not. Both laws, with
// local damping: the motion, the energies and the observed accelerations are those of a model
// that keeps every acceleration, to the bit, and the kept ones the last step's change of velocity;
// an unobserved sphere's acceleration is refused.
TEST(SphereSystem, KeepingTheObservedAccelerationsOnlyChangesNoBit) {
  const Packing p = fcc_packing(6, 2.5e-3, 0.8e-3, 1.0e-3, 0.03, 5, 2290);
  CohesiveFrictionalMaterial material = concrete_material();
  material.damping = 0.05;
  const Vec3 e{1, 0, 0};
  const double dt = 5e-8;
  const std::vector<std::size_t> checked = {0, 39, 255, 300};  // 300: every acceleration kept only
  std::vector<Vec3> v_before[2] = {std::vector<Vec3>(checked.size()), std::vector<Vec3>(checked.size())};
  std::vector<std::size_t> observed(40);
  std::iota(observed.begin(), observed.end(), std::size_t(0));
  observed.push_back(700);
  for (const bool full : {false, true}) {
    std::unique_ptr<SphereSystem> systems[2];  // every acceleration kept, the observed spheres' only
    for (int which = 0; which < 2; ++which) {
      auto& s = systems[which] = bonded_system(p, material, full);
      ASSERT_EQ(s->sphere_count(), 864u);
      if (which == 1) s->observe(observed);
      for (int i = 0; i < 120; ++i) {
        for (std::size_t k = 0; k < 40; ++k) s->add_external_force(k, {1e-2 * std::sin(0.1 * i), 2e-3, 0});
        if (i == 119)
          for (std::size_t q = 0; q < checked.size(); ++q) v_before[which][q] = s->velocity(checked[q]);
        s->step(dt, i % 40 == 39);
        s->impose_displacement(700, e, 1e-9 * std::sin(0.05 * i), 1e-9 * std::sin(0.05 * (i + 1)), dt);
      }
    }
    // The kept accelerations are the last step's: (v_{n+1/2} - v_{n-1/2}) / dt to round-off, that
    // of v_{n+1/2} = v_{n-1/2} + dt a and of the difference: a few eps (|v_{n-1/2}| + |v_{n+1/2}|) / dt
    // (measured: 0.4-1.6e-15 |a|, with |v| / (dt |a|) 9-30). Not sphere 700: the constraint set its velocity.
    const char* law = full ? "full" : "linear";
    for (int which = 0; which < 2; ++which)
      for (std::size_t q = 0; q < checked.size(); ++q) {
        const std::size_t k = checked[q];
        if (which == 1 && k == 300) continue;  // not observed
        const Vec3 v_after = systems[which]->velocity(k), a = systems[which]->acceleration(k);
        const Vec3 dv = (1.0 / dt) * (v_after - v_before[which][q]);
        const double round_off = 4 * std::numeric_limits<double>::epsilon() * (norm(v_before[which][q]) + norm(v_after)) / dt;
        EXPECT_GT(norm(a), 0.0) << law << ", sphere " << k;
        EXPECT_LE(norm(a - dv), round_off) << law << ", sphere " << k;
      }
    const SphereSystem &every = *systems[0], &some = *systems[1];
    expect_same_motion(some, every, law);
    EXPECT_GT(every.energy().damping_J, 0.0) << law;
    for (const std::size_t k : {std::size_t(0), std::size_t(39), std::size_t(255), std::size_t(700)}) {
      const Vec3 a = some.acceleration(k), reference = every.acceleration(k);
      EXPECT_EQ(std::memcmp(&a, &reference, sizeof(Vec3)), 0) << law << ", sphere " << k;
    }
    EXPECT_GT(norm(every.acceleration(700)), 0.0) << law;
    EXPECT_THROW(some.acceleration(256), std::logic_error) << law;
    EXPECT_THROW(some.acceleration(863), std::logic_error) << law;
    EXPECT_THROW(systems[1]->impose_displacement(300, e, 0, 0, dt), std::logic_error) << law;
  }
}
