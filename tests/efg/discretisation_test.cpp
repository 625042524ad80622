// Background cells and nodes of Section 2.5: the Gauss rule integrates polynomials of degree 2n-1
// exactly (against their closed-form integrals), the points tile the body (weights sum to its area),
// corners come first, dropped cells take their lone corners with them, and bad input is refused.
#include <gtest/gtest.h>

#include <cmath>

#include "mesowave/efg/discretisation.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::efg;

TEST(GaussLegendre, IntegratesDegree2nMinus1Exactly) {
  for (int n = 1; n <= 10; ++n) {
    const GaussRule r = gauss_legendre(n);
    ASSERT_EQ(r.x.size(), std::size_t(n));
    for (int k = 0; k <= 2 * n - 1; ++k) {
      double sum = 0;
      for (int i = 0; i < n; ++i) sum += r.w[std::size_t(i)] * std::pow(r.x[std::size_t(i)], k);
      const double exact = k % 2 == 0 ? 2.0 / (k + 1) : 0.0;  // integral of x^k over [-1, 1]
      EXPECT_NEAR(sum, exact, 1e-14) << "n = " << n << ", x^" << k;
    }
    // and not degree 2n: the rule is Gaussian, not better
    double sum = 0;
    for (int i = 0; i < n; ++i) sum += r.w[std::size_t(i)] * std::pow(r.x[std::size_t(i)], 2 * n);
    EXPECT_GT(std::abs(sum - 2.0 / (2 * n + 1)), 1e-6) << n;
  }
  EXPECT_NEAR(gauss_legendre(2).x[1], 1 / std::sqrt(3.0), 1e-15);
  EXPECT_NE(test::input_error_of([] { gauss_legendre(0); }).find("(0)"), std::string::npos);
}

TEST(RectangularGrid, CornersFirstAndPointsTileTheBody) {
  const Rect body{0.0, -0.05, 0.45, 0.05};
  const Discretisation d = rectangular_grid(body, 9, 2, 3, {Vec2(0.2251, 0.0)});
  EXPECT_EQ(d.nodes.size(), 10u * 3u + 1u);
  EXPECT_EQ(d.cells.size(), 18u);
  EXPECT_EQ(d.points.size(), 18u * 9u);
  EXPECT_DOUBLE_EQ(d.spacing_m, 0.05);
  EXPECT_EQ(d.nodes[0], Vec2(0.0, -0.05));
  EXPECT_EQ(d.nodes[10], Vec2(0.0, 0.0));  // second row starts at x0
  EXPECT_EQ(d.nodes[29], Vec2(0.45, 0.05));
  EXPECT_EQ(d.nodes[30], Vec2(0.2251, 0.0));
  double area = 0, moment = 0;
  for (const GaussPoint& p : d.points) {
    const Rect& c = d.cells[std::size_t(p.cell)];
    EXPECT_TRUE(p.x.x() > c.x0 && p.x.x() < c.x1 && p.x.y() > c.y0 && p.x.y() < c.y1);
    area += p.weight_m2;
    moment += p.weight_m2 * p.x.x() * p.x.x() * p.x.y() * p.x.y();
  }
  EXPECT_NEAR(area, 0.45 * 0.1, 1e-15);
  // integral of x^2 y^2 = (0.45^3 / 3) (2 0.05^3 / 3), exact for 3 points
  EXPECT_NEAR(moment, std::pow(0.45, 3) / 3 * 2 * std::pow(0.05, 3) / 3, 1e-18);
}

TEST(RectangularGrid, DroppedCellsTakeTheirLoneCorners) {
  // an L-shape: the upper-right cell of 2 x 2 dropped; its outer corner (1, 1) has no cell left
  const auto keep = [](const Rect& c) { return !(c.x0 >= 0.5 && c.y0 >= 0.5); };
  const Discretisation d = rectangular_grid({0, 0, 1, 1}, 2, 2, 2, {}, keep);
  EXPECT_EQ(d.cells.size(), 3u);
  EXPECT_EQ(d.points.size(), 12u);
  EXPECT_EQ(d.nodes.size(), 8u);
  for (const Vec2& x : d.nodes) EXPECT_FALSE(x == Vec2(1, 1));
  for (const GaussPoint& p : d.points) EXPECT_FALSE(p.x.x() > 0.5 && p.x.y() > 0.5);
}

TEST(RectangularGrid, BadInputIsOneLineNamingTheValue) {
  EXPECT_NE(test::input_error_of([] { rectangular_grid({1, 0, 0, 1}, 2, 2); }).find("x1 > x0"), std::string::npos);
  EXPECT_NE(test::input_error_of([] { rectangular_grid({0, 0, 1, 1}, 0, 2); }).find("0 x 2"), std::string::npos);
  EXPECT_NE(test::input_error_of([] { rectangular_grid({0, 0, 1, 1}, 2, 2, 65); }).find("(65)"), std::string::npos);
  EXPECT_NE(test::input_error_of([] { rectangular_grid({0, 0, 1, 1}, 2, 2, 2, {Vec2(2, 0.5)}); })
                .find("extra node (2, 0.5) m lies outside"),
            std::string::npos);
  EXPECT_NE(test::input_error_of([] { rectangular_grid({0, 0, 1, 1}, 2, 2, 2, {Vec2(0.5, 0.5)}); })
                .find("on another node"),
            std::string::npos);
  EXPECT_NE(test::input_error_of([] { rectangular_grid({0, 0, 1, 1}, 2, 2, 2, {}, [](const Rect&) { return false; }); })
                .find("no cell"),
            std::string::npos);
}
