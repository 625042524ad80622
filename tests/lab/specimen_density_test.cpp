// Step 1: density and its resolution-propagated uncertainty.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "mesowave/core/error.hpp"
#include "mesowave/lab/specimen_density.hpp"

using namespace mesowave;
using namespace mesowave::lab;

TEST(SpecimenDensity, PaperCubeFromItsDerivedMass) {
  // Concrete paper Section 3.1: rho = 2129.56 kg/m3; a nominal 150 mm cube then weighs 7.187265 kg.
  SpecimenGeometry cube{SpecimenShape::Cube, 0.150};
  const auto d = specimen_density(7.187265, cube, {});
  EXPECT_NEAR(d.density_kg_m3, 2129.56, 1e-9);
  EXPECT_DOUBLE_EQ(d.u_density_kg_m3, 0.0);
}

TEST(SpecimenDensity, VolumesOfTheThreeShapes) {
  SpecimenGeometry prism{SpecimenShape::Prism};
  prism.length_m = 0.4;
  prism.width_m = 0.1;
  prism.height_m = 0.1;
  EXPECT_NEAR(specimen_volume(prism), 0.004, 1e-15);
  SpecimenGeometry cyl{SpecimenShape::Cylinder};
  cyl.diameter_m = 0.15;
  cyl.height_m = 0.3;
  EXPECT_NEAR(specimen_volume(cyl), std::numbers::pi * 0.075 * 0.075 * 0.3, 1e-15);
}

TEST(SpecimenDensity, UncertaintyMatchesHandPropagation) {
  // GUM: u = res/sqrt(12); for a cube V = a^3 so u_V/V = 3 u_a/a.
  SpecimenGeometry cube{SpecimenShape::Cube, 0.1};
  const auto d = specimen_density(2.4, cube, {1e-3, 1e-4});
  const double rel = std::sqrt(std::pow(1e-3 / std::sqrt(12.0) / 2.4, 2) + std::pow(3 * 1e-4 / std::sqrt(12.0) / 0.1, 2));
  EXPECT_NEAR(d.u_density_kg_m3, 2400 * rel, 1e-9);
  // Finite-difference check of the cube's sensitivity: d rho / d a = -3 rho / a.
  const double h = 1e-7;
  SpecimenGeometry bigger{SpecimenShape::Cube, 0.1 + h};
  const double slope = (specimen_density(2.4, bigger, {}).density_kg_m3 - 2400.0) / h;
  EXPECT_NEAR(slope, -3 * 2400 / 0.1, 1e-3 * 72000);
}

TEST(SpecimenDensity, CylinderDiameterCountsTwice) {
  SpecimenGeometry cyl{SpecimenShape::Cylinder};
  cyl.diameter_m = 0.1;
  cyl.height_m = 0.2;
  const auto d = specimen_density(3.7, cyl, {0, 1e-4});
  const double u = 1e-4 / std::sqrt(12.0);
  EXPECT_NEAR(d.u_density_kg_m3 / d.density_kg_m3, std::hypot(2 * u / 0.1, u / 0.2), 1e-12);
}

TEST(SpecimenDensity, BatchStatistics) {
  std::vector<SpecimenDensity> batch = {{0, 2100, 1}, {0, 2130, 2}, {0, 2160, 3}};
  const auto s = summarize_densities(batch);
  EXPECT_EQ(s.count, 3u);
  EXPECT_DOUBLE_EQ(s.mean_kg_m3, 2130);
  EXPECT_DOUBLE_EQ(s.std_kg_m3, 30);  // sample standard deviation of 2100, 2130, 2160
  EXPECT_NEAR(s.sem_kg_m3, 30 / std::sqrt(3.0), 1e-12);
  EXPECT_DOUBLE_EQ(s.u_resolution_kg_m3, 2);
  EXPECT_NEAR(s.u_mean_kg_m3, std::hypot(30 / std::sqrt(3.0), 2.0), 1e-12);
  EXPECT_DOUBLE_EQ(s.min_kg_m3, 2100);
  EXPECT_DOUBLE_EQ(s.max_kg_m3, 2160);
}

TEST(SpecimenDensity, RejectsBadInput) {
  SpecimenGeometry cube{SpecimenShape::Cube, 0.15};
  EXPECT_THROW(specimen_density(0, cube, {}), InputError);
  EXPECT_THROW(specimen_density(-1, cube, {}), InputError);
  EXPECT_THROW(specimen_density(INFINITY, cube, {}), InputError);
  EXPECT_THROW(specimen_density(7, SpecimenGeometry{SpecimenShape::Cube, 0}, {}), InputError);
  EXPECT_THROW(specimen_density(7, cube, {-1, 0}), InputError);
  EXPECT_THROW(parse_specimen_shape("sphere"), InputError);
  EXPECT_THROW(summarize_densities({}), InputError);
}
