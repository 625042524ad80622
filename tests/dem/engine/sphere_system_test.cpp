// The contact layout's partition count (SphereSystem::partition_count): the sizes
// docs/benchmarks.md quotes ("The step near the memory limit", ninth part), and below 20,480
// spheres the rule before it (n / 4,096, at least 1), so that every smaller model - the tests'
// and the quick pipeline's - keeps its bits.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>

#include "mesowave/dem/engine/sphere_system.hpp"

using mesowave::dem::SphereSystem;

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
