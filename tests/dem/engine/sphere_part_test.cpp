// One process's part of the sphere set (dem/engine/sphere_part.hpp): the whole set, whole
// indices are local ones, and each query that combines ranks on several answers as a plain scan
// of the set does here (the scans below are the references; tests/cli/mw_dem_mpi_test.cpp runs
// the same queries on two to four ranks against one process).
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "mesowave/dem/engine/sphere_part.hpp"
#include "dem/test_packings.hpp"

using namespace mesowave::dem;

namespace {

SphereSet lattice() { return make_sphere_set(mesowave::dem::testing::fcc_packing(3, 2.0e-3, 0.7e-3, 0.9e-3, 0.0, 5, 2400), 2400); }

}  // namespace

TEST(SpherePart, TheWholeSetIsOneProcessesPartWithWholeIndicesForLocalOnes) {
  const SphereSet s = lattice();
  const SpherePart part(s);
  EXPECT_EQ(part.domain(), nullptr);
  EXPECT_EQ(part.total(), s.size());
  EXPECT_EQ(part.own_count(), s.size());
  EXPECT_EQ(part.begin(), 0u);
  for (std::size_t k : {std::size_t(0), std::size_t(17), s.size() - 1}) {
    EXPECT_EQ(part.local(k), k);
    EXPECT_EQ(part.whole_index(k), k);
    EXPECT_EQ(part.radius(k), s.radius_m[k]);
    EXPECT_EQ(part.packing_index(k), s.packing_index[k]);
    EXPECT_EQ(part.centre_of(k).x, s.centre_m[k].x);
  }
  EXPECT_FALSE(part.holds(s.size()));
  EXPECT_THROW((void)part.local(s.size()), std::logic_error);
}

TEST(SpherePart, RadiusStatisticsAreTheSetsInOrder) {
  const SphereSet s = lattice();
  const SpherePart part(s);
  EXPECT_EQ(part.radius_min(), *std::min_element(s.radius_m.begin(), s.radius_m.end()));
  EXPECT_EQ(part.radius_max(), *std::max_element(s.radius_m.begin(), s.radius_m.end()));
  double sum = 0;
  for (const double r : s.radius_m) sum += r;
  EXPECT_EQ(part.radius_mean(), sum / double(s.size()));  // the same order of terms: the same bits
}

TEST(SpherePart, ArgMinTakesTheLeastPairAndOnATieTheLowestIndex) {
  const SphereSet s = lattice();  // no jitter: a face of spheres ties in x
  const SpherePart part(s);
  double x_max = -1;
  for (const Vec3& c : s.centre_m) x_max = std::max(x_max, c.x);
  std::size_t first_on_face = s.size();
  for (std::size_t k = 0; k < s.size() && first_on_face == s.size(); ++k)
    if (s.centre_m[k].x == x_max) first_on_face = k;
  EXPECT_EQ(part.arg_min([&](std::size_t k) { return std::pair{-s.centre_m[k].x, 0.0}; }), first_on_face);
  // The second key decides among equal first keys: the face's sphere of the highest packing index.
  std::size_t highest = first_on_face;
  for (std::size_t k = 0; k < s.size(); ++k)
    if (s.centre_m[k].x == x_max && s.packing_index[k] > s.packing_index[highest]) highest = k;
  EXPECT_EQ(part.arg_min([&](std::size_t k) { return std::pair{-s.centre_m[k].x, -double(s.packing_index[k])}; }), highest);
}

TEST(SpherePart, SelectListsTheChosenSpheresAscendingOrByPackingIndex) {
  const SphereSet s = lattice();
  const SpherePart part(s);
  const auto low = [&](std::size_t k) { return s.centre_m[k].z < 2.5e-3; };
  std::vector<std::size_t> expected;
  for (std::size_t k = 0; k < s.size(); ++k)
    if (low(k)) expected.push_back(k);
  ASSERT_GT(expected.size(), 3u);
  EXPECT_EQ(part.select(low), expected);
  std::sort(expected.begin(), expected.end(), [&](std::size_t a, std::size_t b) { return s.packing_index[a] < s.packing_index[b]; });
  EXPECT_EQ(part.select(low, true), expected);
  EXPECT_NE(part.select(low, true), part.select(low));  // Morton order is not the file's here
}

TEST(SpherePart, TheOwnSpheresTakenAreTheSet) {
  const SphereSet s = lattice();
  SpherePart part(s);
  part.fetch({3, 5});  // one process holds every sphere: nothing to fetch
  const SphereSet own = std::move(part).take_own();
  EXPECT_EQ(own.radius_m, s.radius_m);
  EXPECT_EQ(own.packing_index, s.packing_index);
  EXPECT_EQ(own.ids, s.ids);
}
