// St. Venant initiation and the growth direction against hand-computed
// principal strains (Mohr's circle) and rotated uniaxial states.
#include <gtest/gtest.h>

#include <cmath>

#include "mesowave/efg/crack_growth.hpp"
#include "support/input_error.hpp"

namespace mesowave::efg {
namespace {

/// Voigt strain of a uniaxial strain e along the unit vector n: e n n^T.
Eigen::Vector3d uniaxial(double e, const Vec2& n) { return {e * n.x() * n.x(), e * n.y() * n.y(), 2 * e * n.x() * n.y()}; }

TEST(CrackGrowth, PrincipalStrainsOfRotatedStates) {
  for (double deg : {0.0, 17.0, 45.0, 90.0, 133.0}) {
    const double a = deg * M_PI / 180;
    const Vec2 n(std::cos(a), std::sin(a)), m(-n.y(), n.x());
    const Eigen::Vector3d e = uniaxial(3e-4, n) + uniaxial(-1e-4, m);
    const auto p = principal_strain(e);
    EXPECT_NEAR(p.largest, 3e-4, 1e-15);
    EXPECT_NEAR(p.smallest, -1e-4, 1e-15);
    EXPECT_NEAR(std::abs(p.direction.dot(n)), 1, 1e-12) << deg;
  }
  // pure shear gamma: principal +-gamma/2 at 45 degrees
  const auto p = principal_strain({0, 0, 2e-4});
  EXPECT_NEAR(p.largest, 1e-4, 1e-16);
  EXPECT_NEAR(std::abs(p.direction.dot(Vec2(1, 1).normalized())), 1, 1e-12);
}

TEST(CrackGrowth, StVenantAgainstTheStrengthOverE) {
  const double f_t = 2.4e6, E = 20e9;  // f_t / E = 1.2e-4
  EXPECT_FALSE(st_venant_exceeded(uniaxial(1.19e-4, Vec2::UnitX()), f_t, E));
  EXPECT_TRUE(st_venant_exceeded(uniaxial(1.21e-4, Vec2(1, 1).normalized()), f_t, E));
  EXPECT_FALSE(st_venant_exceeded(uniaxial(-5e-4, Vec2::UnitX()), f_t, E));  // compression never
}

TEST(CrackGrowth, DirectionOrthogonalToThePrincipalStrainOrPrescribed) {
  CrackGrowthOptions o;
  o.segment_length_m = 0.005;
  // bending at the bottom fibre: largest strain along x, the crack goes up (heading +y)
  const Eigen::Vector3d e = uniaxial(2e-4, Vec2::UnitX());
  EXPECT_NEAR((growth_direction(e, Vec2::UnitY(), o) - Vec2::UnitY()).norm(), 0, 1e-12);
  EXPECT_NEAR((growth_direction(e, -Vec2::UnitY(), o) + Vec2::UnitY()).norm(), 0, 1e-12);
  // principal strain at 30 degrees: the crack at 120 degrees
  const double a = 30 * M_PI / 180;
  const Vec2 d = growth_direction(uniaxial(2e-4, Vec2(std::cos(a), std::sin(a))), Vec2(-0.2, 1).normalized(), o);
  EXPECT_NEAR(d.x(), std::cos(a + M_PI / 2), 1e-12);
  EXPECT_NEAR(d.y(), std::sin(a + M_PI / 2), 1e-12);
  o.rule = GrowthDirectionRule::prescribed;
  EXPECT_NEAR((growth_direction(uniaxial(2e-4, Vec2(1, 1).normalized()), Vec2(0.1, 1).normalized(), o) - Vec2::UnitY()).norm(), 0, 1e-12);
}

TEST(CrackGrowth, GrownTipStopsAtTheBoundary) {
  CrackGrowthOptions o;
  o.segment_length_m = 0.01;
  o.rule = GrowthDirectionRule::prescribed;
  auto inside = [](const Vec2& x) { return x.y() < 0.1 && x.y() > 0; };
  auto strained = [](const Vec2&) { return uniaxial(2e-4, Vec2::UnitX()); };
  auto relaxed = [](const Vec2&) { return uniaxial(1e-4, Vec2::UnitX()); };
  const auto next = grown_tip(Vec2(0.225, 0.05), Vec2::UnitY(), 2.4e6, 20e9, o, strained, inside);
  ASSERT_TRUE(next);
  EXPECT_NEAR((*next - Vec2(0.225, 0.06)).norm(), 0, 1e-15);
  EXPECT_FALSE(grown_tip(Vec2(0.225, 0.05), Vec2::UnitY(), 2.4e6, 20e9, o, relaxed, inside));
  const auto near_top = grown_tip(Vec2(0.225, 0.095), Vec2::UnitY(), 2.4e6, 20e9, o, strained, inside);
  ASSERT_TRUE(near_top);
  EXPECT_LT(near_top->y(), 0.1);
  EXPECT_NEAR(near_top->y(), 0.095 + 0.01 / 4, 1e-12);  // the first halving inside
  o.segment_length_m = 0;
  EXPECT_EQ(test::input_error_of([&] { grown_tip(Vec2(0, 0), Vec2::UnitY(), 1, 1, o, strained, inside); }),
            "crack growth: segment length (0 m) must be > 0");
}

}  // namespace
}  // namespace mesowave::efg
