// Essential boundary conditions by master-slave elimination of collocated (point) and weak (edge)
// rows: the constraints hold exactly for any reduced unknowns and any scale, an edge's rows are the
// hat-weighted averages of the trace (a reproduced linear field meets them), the solution and the
// reactions equal those of the second method (Lagrange multipliers, the saddle-point system solved
// densely), the reactions balance the applied load, and repeated, contradictory or too few
// constraints are refused.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <random>

#include "mesowave/efg/constraints.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::efg;

namespace {

const ElasticMaterial2D kConcrete{20e9, 0.2, 0.1, 2400, PlaneState::plane_stress};

struct Beam {
  Discretisation disc = rectangular_grid({0, 0, 0.3, 0.1}, 12, 4, 2, {Vec2(0.151, 0.049)});
  MlsApproximation mls{disc.nodes, support_radii_by_spacing(disc.nodes, disc.spacing_m, 2.5)};
  ElasticModel model{disc, kConcrete, mls};
};

// A propped beam: pinned at (0, 0), on a roller at (0.3, 0), pushed down at mid-span by 0.1 mm
// (displacement control) and loaded by a shear at x = 0.3 and a point force.
std::vector<PointConstraint> supports() {
  return {{Vec2(0, 0), 0, 0.0, "pin x"},
          {Vec2(0, 0), 1, 0.0, "pin y"},
          {Vec2(0.3, 0), 1, 0.0, "roller"},
          {Vec2(0.15, 0.1), 1, -1e-4, "load point"}};
}

// The saddle point [K C^T; C 0] [u; lambda] = [f; d]: the second method, dense.
std::pair<Eigen::VectorXd, Eigen::VectorXd> lagrange_multipliers(const Eigen::SparseMatrix<double>& K,
                                                                 const Eigen::VectorXd& f, const ConstraintSet& c) {
  const Eigen::Index n = K.rows(), m = c.C().rows();
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(n + m, n + m);
  S.topLeftCorner(n, n) = Eigen::MatrixXd(K);
  S.topRightCorner(n, m) = Eigen::MatrixXd(c.C().transpose());
  S.bottomLeftCorner(m, n) = Eigen::MatrixXd(c.C());
  Eigen::VectorXd rhs(n + m);
  rhs << f, c.d();
  const Eigen::VectorXd x = S.partialPivLu().solve(rhs);
  return {x.head(n), x.tail(m)};
}

}  // namespace

TEST(Constraints, HoldExactlyForAnyReducedUnknownsAndScale) {
  Beam b;
  const ConstraintSet c(b.model, supports());
  EXPECT_EQ(c.reduced_size(), b.model.dof_count() - 4);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uniform(-1e-3, 1e-3);
  Eigen::VectorXd v(Eigen::Index(c.reduced_size()));
  for (Eigen::Index i = 0; i < v.size(); ++i) v[i] = uniform(rng);
  for (double scale : {0.0, 1.0, -2.5}) {
    const Eigen::VectorXd u = c.expand(v, scale);
    EXPECT_LE(c.violation(u, scale).cwiseAbs().maxCoeff(), 1e-17);
    // read back through the model: u^h at the constraint points
    EXPECT_NEAR(b.model.displacement(Vec2(0.15, 0.1), u).y(), -1e-4 * scale, 1e-17);
    EXPECT_NEAR(b.model.displacement(Vec2(0, 0), u).norm(), 0, 1e-17);
  }
  EXPECT_LE(Eigen::MatrixXd(c.C() * c.T()).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(Constraints, SolutionAndReactionsEqualLagrangeMultipliers) {
  Beam b;
  const ConstraintSet c(b.model, supports());
  const Eigen::SparseMatrix<double> K = b.model.stiffness();
  const Eigen::VectorXd f =
      b.model.traction_load({Vec2(0.3, 0), Vec2(0.3, 0.1)}, [](const Vec2&) { return Eigen::Vector2d(0, -2e4); }) +
      b.model.point_load(Vec2(0.07, 0.1), Eigen::Vector2d(150, -300));
  const LinearSolution s = solve_linear(K, f, c);

  const auto [u_lm, lambda] = lagrange_multipliers(K, f, c);
  EXPECT_LE((s.u - u_lm).norm(), 1e-9 * u_lm.norm());
  for (std::size_t k = 0; k < s.reactions_N.size(); ++k)  // R = -lambda
    EXPECT_NEAR(s.reactions_N[k], -lambda[Eigen::Index(k)], 1e-7 * lambda.cwiseAbs().maxCoeff()) << k;

  // the reactions balance the applied load: sum R + sum f = 0 in each direction
  double fx = 0, fy = 0;
  for (Eigen::Index i = 0; i < f.size(); i += 2) fx += f[i], fy += f[i + 1];
  const double Rx = s.reactions_N[0], Ry = s.reactions_N[1] + s.reactions_N[2] + s.reactions_N[3];
  const double scale = std::abs(s.reactions_N[3]);
  EXPECT_LE(std::abs(Rx + fx), 1e-9 * scale);
  EXPECT_LE(std::abs(Ry + fy), 1e-9 * scale);
  EXPECT_EQ(s.solver, "Eigen::SimplicialLDLT (AMD ordering) on the reduced T^T K T");
  EXPECT_GT(s.factor_nonzeros, 0u);
}

TEST(Constraints, EdgeRowsAreWeakAveragesOfTheTrace) {
  Beam b;
  // the left edge held to a linear field, the right edge's u_y to a constant
  Eigen::Matrix2d G;
  G << 1e-3, 4e-4, -2e-4, -3e-4;
  const auto field = [&](const Vec2& x) { return Eigen::Vector2d(Eigen::Vector2d(1e-5, -2e-5) + G * x); };
  const Segment left{Vec2(0, 0), Vec2(0, 0.1)}, right{Vec2(0.3, 0), Vec2(0.3, 0.1)};
  const ConstraintSet c(b.model, {},
                        {{left, 0, [&](const Vec2& x) { return field(x).x(); }, "clamp x"},
                         {left, 1, [&](const Vec2& x) { return field(x).y(); }, "clamp y"},
                         {right, 1, [&](const Vec2& x) { return field(x).y(); }, "end y", 2}});
  EXPECT_EQ(c.edge_rows(0), std::make_pair(std::size_t(0), std::size_t(5)));  // 4 pieces of the spacing
  EXPECT_EQ(c.edge_rows(2), std::make_pair(std::size_t(10), std::size_t(13)));
  EXPECT_EQ(c.row_names()[12], "edge constraint 2 'end y' (u_y on (0.3, 0) - (0.3, 0.1) m) hat 2");
  EXPECT_EQ(c.reduced_size(), b.model.dof_count() - 13);
  // every row's coefficients sum to 1: an average
  for (Eigen::Index k = 0; k < c.C().rows(); ++k) EXPECT_NEAR(Eigen::VectorXd(c.C().row(k).transpose()).sum(), 1, 1e-14);
  // the linear field, reproduced exactly by MLS, meets the rows
  Eigen::VectorXd u(Eigen::Index(b.model.dof_count()));
  for (std::size_t i = 0; i < b.disc.nodes.size(); ++i) u.segment<2>(2 * Eigen::Index(i)) = field(b.disc.nodes[i]);
  EXPECT_LE(c.violation(u).cwiseAbs().maxCoeff(), 1e-15);
  // and every expanded u does too
  const Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(Eigen::Index(c.reduced_size()), -1e-3, 1e-3);
  EXPECT_LE(c.violation(c.expand(v, 0.7), 0.7).cwiseAbs().maxCoeff(), 1e-17);

  // solved with an end shear and a point force: the same u and reactions as the multipliers
  const Eigen::SparseMatrix<double> K = b.model.stiffness();
  const Eigen::VectorXd f =
      b.model.traction_load(right, [](const Vec2&) { return Eigen::Vector2d(3e4, 0); }) +
      b.model.point_load(Vec2(0.2, 0.1), Eigen::Vector2d(150, -300));
  const LinearSolution s = solve_linear(K, f, c);
  const auto [u_lm, lambda] = lagrange_multipliers(K, f, c);
  EXPECT_LE((s.u - u_lm).norm(), 1e-9 * u_lm.norm());
  double R[2] = {0, 0}, F[2] = {0, 0};
  for (std::size_t k = 0; k < s.reactions_N.size(); ++k) {
    EXPECT_NEAR(s.reactions_N[k], -lambda[Eigen::Index(k)], 1e-7 * lambda.cwiseAbs().maxCoeff()) << k;
    R[c.row_components()[k]] += s.reactions_N[k];
  }
  for (Eigen::Index i = 0; i < f.size(); ++i) F[i % 2] += f[i];
  EXPECT_LE(std::abs(R[0] + F[0]), 1e-9 * std::abs(F[0]));
  EXPECT_LE(std::abs(R[1] + F[1]), 1e-9 * std::abs(F[0]));
}

TEST(Constraints, ScaleIsDisplacementControl) {
  Beam b;
  const ConstraintSet c(b.model, supports());
  const Eigen::SparseMatrix<double> K = b.model.stiffness();
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(K.rows());
  const LinearSolution one = solve_linear(K, zero, c, 1.0), half = solve_linear(K, zero, c, 0.5);
  EXPECT_LE((one.u - 2 * half.u).norm(), 1e-12 * one.u.norm());
  EXPECT_NEAR(one.reactions_N[3], 2 * half.reactions_N[3], 1e-9 * std::abs(one.reactions_N[3]));
  EXPECT_LT(one.reactions_N[3], 0);  // pushing down: the constraint pushes the body down
  // and reactions from the residual of an unconverged u are the least-squares ones, not garbage
  EXPECT_EQ(c.reactions(Eigen::VectorXd::Zero(K.rows())), std::vector<double>(4, 0.0));
}

TEST(Constraints, BadConstraintsAreRefusedByName) {
  Beam b;
  auto repeated = supports();
  repeated.push_back({Vec2(0, 0), 1, 0.0, "pin y again"});
  EXPECT_NE(test::input_error_of([&] { ConstraintSet(b.model, repeated); }).find("'pin y again' (u_y at (0, 0) m) repeats"),
            std::string::npos);
  auto bad_component = supports();
  bad_component[1].component = 2;
  EXPECT_NE(test::input_error_of([&] { ConstraintSet(b.model, bad_component); }).find("'pin y'"), std::string::npos);
  auto outside = supports();
  outside[2].x = Vec2(5, 5);
  EXPECT_NE(test::input_error_of([&] { ConstraintSet(b.model, outside); }).find("'roller'"), std::string::npos);
  // without the pin's x the beam slides: the reduced stiffness is singular
  auto sliding = supports();
  sliding.erase(sliding.begin());
  const ConstraintSet c(b.model, sliding);
  EXPECT_NE(test::input_error_of([&] {
              solve_linear(b.model.stiffness(), Eigen::VectorXd::Zero(Eigen::Index(b.model.dof_count())), c);
            }).find("not positive definite"),
            std::string::npos);
}
