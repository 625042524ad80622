// MLS shape functions (efg/mls.hpp) against closed forms: the weight splines' values, partition of
// unity and exact reproduction of linear (and, with the quadratic basis, quadratic) fields and of
// their first derivatives at every Gauss point of a 2 x 2 background cell grid, on a regular and on
// an irregular node set; derivatives against central differences; support radii by count against
// the grid's neighbour distances; bad input named in the error.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>

#include "mesowave/efg/mls.hpp"
#include "support/efg_fixtures.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::efg;

namespace {

constexpr double kLx = 0.30, kLy = 0.20;  // the body [0, 0.3] x [0, 0.2] m
constexpr double kSpacing = 0.05;         // 7 x 5 nodes

using test::grid_nodes;
std::vector<Vec2> gauss_points(int cx, int cy, int n, double lx = kLx, double ly = kLy) {
  return test::gauss_points(cx, cy, n, lx, ly);
}

// sum_I phi_I f(x_I), and the same with dphi/dx and dphi/dy.
struct Sums {
  double value = 0, dx = 0, dy = 0;
};
Sums apply(const ShapeFunctions& sf, const std::vector<Vec2>& nodes, double (*f)(const Vec2&)) {
  Sums s;
  for (std::size_t k = 0; k < sf.nodes.size(); ++k) {
    const double fi = f(nodes[std::size_t(sf.nodes[k])]);
    s.value += sf.phi[k] * fi;
    s.dx += sf.dphi_dx[k] * fi;
    s.dy += sf.dphi_dy[k] * fi;
  }
  return s;
}

struct Field {
  const char* name;
  double (*f)(const Vec2&);
  double (*fx)(const Vec2&);
  double (*fy)(const Vec2&);
};
const std::vector<Field> kLinearFields = {
    {"1", [](const Vec2&) { return 1.0; }, [](const Vec2&) { return 0.0; }, [](const Vec2&) { return 0.0; }},
    {"x", [](const Vec2& p) { return p.x(); }, [](const Vec2&) { return 1.0; }, [](const Vec2&) { return 0.0; }},
    {"y", [](const Vec2& p) { return p.y(); }, [](const Vec2&) { return 0.0; }, [](const Vec2&) { return 1.0; }},
    {"0.3+2x-5y", [](const Vec2& p) { return 0.3 + 2 * p.x() - 5 * p.y(); }, [](const Vec2&) { return 2.0; },
     [](const Vec2&) { return -5.0; }},
};
const std::vector<Field> kQuadraticFields = {
    {"x^2", [](const Vec2& p) { return p.x() * p.x(); }, [](const Vec2& p) { return 2 * p.x(); },
     [](const Vec2&) { return 0.0; }},
    {"xy", [](const Vec2& p) { return p.x() * p.y(); }, [](const Vec2& p) { return p.y(); },
     [](const Vec2& p) { return p.x(); }},
    {"y^2", [](const Vec2& p) { return p.y() * p.y(); }, [](const Vec2&) { return 0.0; },
     [](const Vec2& p) { return 2 * p.y(); }},
};

// Every field reproduced with its first derivatives to 1e-12 at every Gauss point.
void expect_reproduction(const MlsApproximation& mls, const std::vector<Vec2>& points, const std::vector<Field>& fields) {
  for (std::size_t g = 0; g < points.size(); ++g) {
    const Vec2& x = points[g];
    const ShapeFunctions sf = mls.evaluate(x, "Gauss point " + std::to_string(g));
    ASSERT_GE(sf.nodes.size(), std::size_t(basis_size(mls.options().basis)));
    EXPECT_TRUE(std::is_sorted(sf.nodes.begin(), sf.nodes.end()));
    EXPECT_GE(sf.condition_number, 1.0);
    EXPECT_LT(sf.condition_number, 1e6);
    for (const auto& field : fields) {
      const Sums s = apply(sf, mls.nodes(), field.f);
      EXPECT_NEAR(s.value, field.f(x), 1e-12) << field.name << " at Gauss point " << g;
      EXPECT_NEAR(s.dx, field.fx(x), 1e-12) << "d(" << field.name << ")/dx at Gauss point " << g;
      EXPECT_NEAR(s.dy, field.fy(x), 1e-12) << "d(" << field.name << ")/dy at Gauss point " << g;
    }
  }
}

}  // namespace

TEST(Weight, SplinesMatchTheirClosedForms) {
  // Eq. (12): w(1/2) = 1 - 6/4 + 8/8 - 3/16 = 5/16; the scaled cubic spline: w(1/2) = 1/4.
  EXPECT_DOUBLE_EQ(weight(WeightKind::quartic_spline, 0).first, 1.0);
  EXPECT_DOUBLE_EQ(weight(WeightKind::quartic_spline, 0.5).first, 5.0 / 16);
  EXPECT_DOUBLE_EQ(weight(WeightKind::quartic_spline, 0.5).second, -12 * 0.5 * 0.25);
  EXPECT_DOUBLE_EQ(weight(WeightKind::cubic_spline, 0).first, 1.0);
  EXPECT_DOUBLE_EQ(weight(WeightKind::cubic_spline, 0.5).first, 0.25);
  for (const auto kind : {WeightKind::quartic_spline, WeightKind::cubic_spline}) {
    EXPECT_EQ(weight(kind, 1.0).first, 0.0);
    EXPECT_EQ(weight(kind, 1.5).second, 0.0);
    EXPECT_NEAR(weight(kind, 1 - 1e-9).first, 0.0, 1e-20);
    for (const double s : {0.1, 0.3, 0.49, 0.51, 0.7, 0.95}) {
      const double d = 1e-6;  // central difference, error ~ d^2 w''' / 6 < 1e-10
      const double fd = (weight(kind, s + d).first - weight(kind, s - d).first) / (2 * d);
      EXPECT_NEAR(weight(kind, s).second, fd, 1e-8) << to_string(kind) << " s = " << s;
      EXPECT_GT(weight(kind, s).first, 0.0);
      EXPECT_LT(weight(kind, s).second, 0.0);  // monotone falling, Eq. (11)
    }
  }
  EXPECT_EQ(parse_weight_kind("cubic-spline"), WeightKind::cubic_spline);
  EXPECT_EQ(parse_basis("quadratic"), Basis::quadratic);
  EXPECT_NE(test::input_error_of([] { parse_basis("cubic"); }).find("'cubic'"), std::string::npos);
}

TEST(Mls, LinearBasisReproducesLinearFieldsOnARegularGrid) {
  const auto nodes = grid_nodes(6, 4, kLx, kLy);
  for (const auto kind : {WeightKind::quartic_spline, WeightKind::cubic_spline}) {
    MlsOptions options;
    options.weight = kind;
    const MlsApproximation by_spacing(nodes, support_radii_by_spacing(nodes, kSpacing, 2.5), options);
    expect_reproduction(by_spacing, gauss_points(2, 2, 2), kLinearFields);
    expect_reproduction(by_spacing, gauss_points(2, 2, 4), kLinearFields);
    const MlsApproximation by_count(nodes, support_radii_by_count(nodes, 8, 1.5), options);
    expect_reproduction(by_count, gauss_points(2, 2, 2), kLinearFields);
  }
}

TEST(Mls, LinearBasisReproducesLinearFieldsOnAnIrregularSet) {
  const auto nodes = grid_nodes(6, 4, kLx, kLy, 0.3);
  EXPECT_NE(nodes[8], Vec2(kSpacing, kSpacing));  // moved
  const MlsApproximation by_count(nodes, support_radii_by_count(nodes, 8, 1.6));
  expect_reproduction(by_count, gauss_points(2, 2, 2), kLinearFields);
  expect_reproduction(by_count, gauss_points(2, 2, 4), kLinearFields);
  const MlsApproximation by_spacing(nodes, support_radii_by_spacing(nodes, kSpacing, 2.5));
  expect_reproduction(by_spacing, gauss_points(2, 2, 2), kLinearFields);
}

TEST(Mls, QuadraticBasisReproducesQuadraticFields) {
  MlsOptions options;
  options.basis = Basis::quadratic;
  for (const double jitter : {0.0, 0.3}) {
    const auto nodes = grid_nodes(6, 4, kLx, kLy, jitter);
    const MlsApproximation mls(nodes, support_radii_by_spacing(nodes, kSpacing, 3.2), options);
    expect_reproduction(mls, gauss_points(2, 2, 2), kLinearFields);
    expect_reproduction(mls, gauss_points(2, 2, 2), kQuadraticFields);
    expect_reproduction(mls, gauss_points(2, 2, 4), kQuadraticFields);
  }
  // The linear basis does not reproduce x^2 (the test above is not empty).
  const auto nodes = grid_nodes(6, 4, kLx, kLy, 0.3);
  const MlsApproximation linear(nodes, support_radii_by_spacing(nodes, kSpacing, 3.2));
  const Vec2 x(0.11, 0.07);
  EXPECT_GT(std::abs(apply(linear.evaluate(x), nodes, kQuadraticFields[0].f).value - x.x() * x.x()), 1e-5);
}

TEST(Mls, ShiftedScaledBasisMakesTheResultIndependentOfTheOrigin) {
  // The same nodes 10 km from the origin: phi the same to rounding of the coordinates (1e4 m * eps /
  // h ~ 1e-11) and the condition number the same - an unshifted basis (1, x, y) would have A's
  // entries spread over 8 orders of magnitude there and its condition number above 1e16.
  const auto nodes = grid_nodes(6, 4, kLx, kLy, 0.3);
  const Vec2 far(1e4, -5e3);
  std::vector<Vec2> moved;
  for (const auto& p : nodes) moved.push_back(p + far);
  for (const auto basis : {Basis::linear, Basis::quadratic}) {
    MlsOptions options;
    options.basis = basis;
    const MlsApproximation here(nodes, support_radii_by_spacing(nodes, kSpacing, 3.2), options);
    const MlsApproximation there(moved, support_radii_by_spacing(moved, kSpacing, 3.2), options);
    const Vec2 x(0.11, 0.07);
    const auto a = here.evaluate(x), b = there.evaluate(x + far);
    ASSERT_EQ(a.nodes, b.nodes);
    for (std::size_t k = 0; k < a.nodes.size(); ++k) {
      EXPECT_NEAR(a.phi[k], b.phi[k], 1e-9);
      EXPECT_NEAR(a.dphi_dx[k], b.dphi_dx[k], 1e-7);
    }
    EXPECT_NEAR(a.condition_number, b.condition_number, 1e-6 * a.condition_number);
    EXPECT_LT(a.condition_number, 1e4);
  }
}

TEST(Mls, DerivativesMatchCentralDifferences) {
  // delta = 1e-6 m against h = 0.125 m: truncation ~ delta^2 phi''' / 6 ~ 1e-12 * 10^3, rounding
  // ~ eps phi / delta ~ 1e-10; 1e-7 on derivatives of order 10 per metre is far above both and far
  // below any formula error (a wrong term is O(1/h) = 8).
  const auto nodes = grid_nodes(6, 4, kLx, kLy, 0.3);
  for (const auto basis : {Basis::linear, Basis::quadratic}) {
    MlsOptions options;
    options.basis = basis;
    const MlsApproximation mls(nodes, support_radii_by_spacing(nodes, kSpacing, basis == Basis::linear ? 2.5 : 3.2), options);
    for (const Vec2& x : {Vec2(0.11, 0.07), Vec2(0.013, 0.188), Vec2(0.2437, 0.1021)}) {
      const auto check = test::check_derivatives(mls, x, 1e-6);
      EXPECT_LT(check.error, 1e-7) << "at (" << x.x() << ", " << x.y() << ")";
      EXPECT_GT(check.largest, 1.0);  // the comparison is not between zeros
    }
  }
}

TEST(Mls, SupportRadiiByCountAreTheGridsNeighbourDistances) {
  const auto nodes = grid_nodes(6, 4, kLx, kLy);
  const auto four = support_radii_by_count(nodes, 4);  // interior node: 4 neighbours at one spacing
  const auto eight = support_radii_by_count(nodes, 8, 1.5);  // ... then 4 at sqrt(2) spacings
  const std::size_t interior = 7 * 2 + 3, corner = 0;
  EXPECT_NEAR(four[interior], kSpacing, 1e-15);
  EXPECT_NEAR(eight[interior], 1.5 * std::sqrt(2.0) * kSpacing, 1e-15);
  // The corner's 4th nearest: (1,0), (0,1), (1,1) at 1, 1, sqrt 2, then (2,0), (0,2) at 2 spacings.
  EXPECT_NEAR(four[corner], 2 * kSpacing, 1e-15);
  EXPECT_NE(test::input_error_of([&] { support_radii_by_count(nodes, 0); }).find("count 0"), std::string::npos);
  EXPECT_NE(test::input_error_of([&] { support_radii_by_count(nodes, 35); }).find("count 35"), std::string::npos);
  EXPECT_NE(test::input_error_of([&] { support_radii_by_spacing(nodes, 0.0, 2); }).find("spacing (0 m)"), std::string::npos);
}

TEST(Mls, TooFewNodesNamesThePoint) {
  // A support of half a spacing near the body's corner: one node reaches (0.01, 0.01).
  const auto nodes = grid_nodes(6, 4, kLx, kLy);
  const MlsApproximation mls(nodes, support_radii_by_spacing(nodes, kSpacing, 0.5));
  const std::string message = test::input_error_of([&] { mls.evaluate(Vec2(0.01, 0.01), "Gauss point 3 of cell 0"); });
  EXPECT_NE(message.find("x = (0.01, 0.01) m"), std::string::npos) << message;
  EXPECT_NE(message.find("Gauss point 3 of cell 0"), std::string::npos) << message;
  EXPECT_NE(message.find("1 nodes reach the point"), std::string::npos) << message;
  EXPECT_NE(message.find("at least 3"), std::string::npos) << message;
  // The quadratic basis needs 6: four reach the centre of a cell with a support of 0.8 spacings.
  MlsOptions quadratic;
  quadratic.basis = Basis::quadratic;
  const MlsApproximation q(nodes, support_radii_by_spacing(nodes, kSpacing, 0.8), quadratic);
  const std::string few = test::input_error_of([&] { q.evaluate(Vec2(0.075, 0.075)); });
  EXPECT_NE(few.find("4 nodes reach the point, the quadratic basis needs at least 6"), std::string::npos) << few;
}

TEST(Mls, SingularMomentMatrixNamesThePoint) {
  // Collinear nodes: the linear basis' A has rank 2 whatever the support.
  std::vector<Vec2> line;
  for (int i = 0; i < 10; ++i) line.emplace_back(0.01 * i, 0.02 * i);
  const MlsApproximation mls(line, support_radii_by_spacing(line, 0.02, 3.0));
  const std::string message = test::input_error_of([&] { mls.evaluate(Vec2(0.041, 0.08), "node check"); });
  EXPECT_NE(message.find("x = (0.041, 0.08) m (node check)"), std::string::npos) << message;
  EXPECT_NE(message.find("singular or ill-conditioned"), std::string::npos) << message;
  // Nearly collinear: refused by the condition limit, accepted when the limit allows it.
  line[4].x() += 1e-9;
  const MlsApproximation nearly(line, support_radii_by_spacing(line, 0.02, 3.0));
  EXPECT_NE(test::input_error_of([&] { nearly.evaluate(Vec2(0.041, 0.08)); }).find("condition number"), std::string::npos);
  MlsOptions loose;
  loose.max_condition_number = 1e30;
  const MlsApproximation accepted(line, support_radii_by_spacing(line, 0.02, 3.0), loose);
  EXPECT_GT(accepted.evaluate(Vec2(0.041, 0.08)).condition_number, 1e12);
}

TEST(Mls, BadConstructionIsNamed) {
  const auto nodes = grid_nodes(2, 2, 1, 1);
  EXPECT_NE(test::input_error_of([&] { MlsApproximation(nodes, std::vector<double>(3, 1.0)); }).find("9 nodes but 3"),
            std::string::npos);
  auto radii = std::vector<double>(9, 1.0);
  radii[4] = -1;
  EXPECT_NE(test::input_error_of([&] { MlsApproximation(nodes, radii); }).find("of node 4"), std::string::npos);
  const MlsApproximation mls(nodes, std::vector<double>(9, 1.0));
  EXPECT_NE(test::input_error_of([&] { mls.evaluate(Vec2(NAN, 0)); }).find("not finite"), std::string::npos);
}

TEST(Mls, SpeedOnAHundredByTwentyGrid) {
  // No timing assertion: the rate is printed for the report (2 x 2 Gauss points of 99 x 19 cells).
  const double s = 0.01;
  const auto nodes = grid_nodes(99, 19, 99 * s, 19 * s);
  const MlsApproximation mls(nodes, support_radii_by_spacing(nodes, s, 2.5));
  const auto points = gauss_points(99, 19, 2, 99 * s, 19 * s);
  const auto start = std::chrono::steady_clock::now();
  double check = 0;
  for (const auto& x : points) check += apply(mls.evaluate(x), nodes, kLinearFields[1].f).value - x.x();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_NEAR(check, 0.0, 1e-9);
  std::cout << "MLS speed: " << points.size() << " evaluations on " << nodes.size() << " nodes in " << wall
            << " s = " << points.size() / wall << " per second\n";
}
