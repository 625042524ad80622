// mw-pack's work (dem/packing/packing_request.hpp) against closed forms: the rod
// paper's line of spheres and the particle density that gives the specimen's mass.
#include "mesowave/dem/packing/packing_request.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesowave/core/error.hpp"

using namespace mesowave;
using namespace mesowave::dem;

namespace {
PackingRequest rod_line_request() {
  PackingRequest r;
  r.container = "line";
  r.packing_file = "rod.h5";
  r.sphere_radius_mm = 5.1;
  r.spacing_R = 1.03;
  r.length_mm = 1000;
  r.density_kg_m3 = 7850.66;
  return r;
}
}  // namespace

TEST(PackingRequest, LineOfSpheresWeighsWhatTheRodWeighs) {
  const PackedSpecimen made = make_packing(rod_line_request());
  const double R = 5.1e-3, d = 1.03 * R, L = 1.0;
  const auto n = std::size_t(std::ceil(L / d));  // rod paper Table 1: n = ceil(L / d) = 191
  EXPECT_EQ(n, 191u);
  ASSERT_EQ(made.packing.size(), n);
  // rho_p = m_rod / sum(V_sphere) = rho pi R^2 L / (n 4/3 pi R^3).
  const double rho_p = 7850.66 * std::numbers::pi * R * R * L / (double(n) * 4.0 / 3.0 * std::numbers::pi * R * R * R);
  EXPECT_NEAR(made.packing.particle_density_kg_m3 / rho_p, 1.0, 1e-12);
  ASSERT_TRUE(made.specimen_mass_kg);
  EXPECT_NEAR(*made.specimen_mass_kg, 7850.66 * std::numbers::pi * R * R * L, 1e-12);
  EXPECT_NEAR(made.summary.at("spacing_mm").get<double>(), 1.03 * 5.1, 1e-12);
  EXPECT_EQ(made.summary.at("spheres").get<std::size_t>(), n);
  EXPECT_EQ(made.summary.at("packing_file").get<std::string>(), "rod.h5");
  EXPECT_EQ(made.threads.count, 1);  // nothing to relax
  EXPECT_TRUE(made.inputs.empty());
}

TEST(PackingRequest, SmallRelaxationsRunOnOneThread) {
  PackingRequest r;
  r.container = "box";
  r.cube_side_mm = 8;
  r.porosity_pct = 45;
  r.d_min_mm = 1.6;
  r.d_max_mm = 2;
  r.threads = 2;
  const PackedSpecimen made = make_packing(r);
  ASSERT_LT(made.packing.size(), 4096u);
  EXPECT_EQ(made.threads.count, 1);
  EXPECT_EQ(made.threads.reason, "requested (--threads 2), 1 for " + std::to_string(made.packing.size()) +
                                     " spheres (the relaxation runs on threads from 4096 spheres on)");
  EXPECT_EQ(made.summary.at("threads").get<int>(), 1);
  EXPECT_NEAR(made.stats.porosity, 0.45, 0.02);
  EXPECT_FALSE(made.specimen_mass_kg);
}

TEST(PackingRequest, ContradictoryOrMissingOptionsAreRefused) {
  PackingRequest both = rod_line_request();
  both.specimen_mass_g = 600;
  EXPECT_THROW(make_packing(both), InputError);
  PackingRequest spacing = rod_line_request();
  spacing.spacing_mm = 5;
  EXPECT_THROW(make_packing(spacing), InputError);  // --spacing-mm and --spacing-R
  PackingRequest no_porosity;
  no_porosity.container = "box";
  no_porosity.cube_side_mm = 10;
  EXPECT_THROW(make_packing(no_porosity), InputError);
  PackingRequest unknown;
  unknown.container = "sphere";
  EXPECT_THROW(make_packing(unknown), InputError);
}
