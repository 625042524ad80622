// The rod paper's line of spheres: sphere counts and particle densities of
// its Table 1 (rod paper, Section 3; lab-data/steel-rod/paper/table1.csv).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesowave/core/error.hpp"
#include "mesowave/dem/packing/packing_generator.hpp"
#include "mesowave/dem/packing/packing_stats.hpp"

using namespace mesowave;
using namespace mesowave::dem;

namespace {

struct TableRow {
  double spacing_R;
  std::size_t spheres;
  double rho_p_kg_m3;  // as printed
};

// Rod paper, Table 1: R = 5.1 mm, L = 1000 mm, rod of D = 10.2 mm and rho = 7850.66 kg/m3.
constexpr TableRow kTable1[] = {{0.95, 207, 5577.17}, {1.03, 191, 6044.37}, {1.05, 187, 6173.66}, {1.15, 171, 6751.31}};

RodLine rod(double spacing_R) {
  RodLine line;
  line.sphere_radius_m = 5.1e-3;
  line.spacing_m = spacing_R * 5.1e-3;
  line.length_m = 1.0;
  line.rod_radius_m = 10.2e-3 / 2;
  return line;
}

}  // namespace

TEST(PackingRod, SphereCountsOfTable1) {
  for (const auto& row : kTable1) {
    EXPECT_EQ(rod_sphere_count(1.0, row.spacing_R * 5.1e-3), row.spheres) << row.spacing_R << "R";
    EXPECT_EQ(line_of_spheres(rod(row.spacing_R)).size(), row.spheres) << row.spacing_R << "R";
  }
}

TEST(PackingRod, ParticleDensityOfTable1) {
  // The printed values sit 3e-5 below the rod mass / sphere volume (paper-values.md): 1e-4 relative.
  for (const auto& row : kTable1) {
    const auto p = line_of_spheres(rod(row.spacing_R));
    const double mass = specimen_mass(7850.66, p.container);
    EXPECT_NEAR(mass, 7850.66 * std::numbers::pi * 5.1e-3 * 5.1e-3 * 1.0, 1e-12);
    const double rho_p = particle_density_for_mass(mass, p);
    EXPECT_NEAR(rho_p / row.rho_p_kg_m3, 1.0, 1e-4) << row.spacing_R << "R";
  }
}

TEST(PackingRod, LineGeometry) {
  const auto p = line_of_spheres(rod(1.03));
  const double d = 1.03 * 5.1e-3;
  ASSERT_EQ(p.size(), 191u);
  EXPECT_EQ(p.container.shape, "line");
  for (std::size_t k = 0; k < p.size(); ++k) {
    EXPECT_EQ(p.ids[k], std::int64_t(k));
    EXPECT_EQ(p.centres_m[k][0], 0.0);
    EXPECT_EQ(p.centres_m[k][1], 0.0);
    EXPECT_DOUBLE_EQ(p.radii_m[k], 5.1e-3);
    if (k) {
      EXPECT_NEAR(p.centres_m[k][2] - p.centres_m[k - 1][2], d, 1e-15);
    }
  }
  // Centred on the rod: the overhang is the same at both ends.
  EXPECT_NEAR(p.centres_m.front()[2], 1.0 - p.centres_m.back()[2], 1e-12);
}

TEST(PackingRod, NearestNeighboursOnlyUnlessSpacingBelowR) {
  // At C_f = 1 a sphere touches its second neighbour only when 2d < 2R, i.e.
  // d < R: the 0.95R model (rod paper: unstable, second neighbours overlap).
  const auto wide = packing_stats(line_of_spheres(rod(1.03)), 1.0);
  EXPECT_EQ(wide.bonds, 190u);
  const auto tight = packing_stats(line_of_spheres(rod(0.95)), 1.0);
  EXPECT_EQ(tight.bonds, 206u + 205u);
}

TEST(PackingRod, CountRuleAtExactMultiples) {
  EXPECT_EQ(rod_sphere_count(1.0, 0.005), 200u);  // 1/0.005 is 200 up to rounding
  EXPECT_EQ(rod_sphere_count(1.0, 0.0049), 205u);  // ceil(204.08)
  EXPECT_THROW(rod_sphere_count(1.0, 0.0), InputError);
  EXPECT_THROW(rod_sphere_count(1.0, -1e-3), InputError);
  EXPECT_THROW(rod_sphere_count(-1.0, 1e-3), InputError);
}
