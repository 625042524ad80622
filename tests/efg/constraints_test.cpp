// Essential boundary conditions by collocation and master-slave elimination: the constraints hold
// exactly for any reduced unknowns and any scale, the solution and the reactions equal those of the
// second method (Lagrange multipliers, the saddle-point system solved densely), the reactions
// balance the applied load, and repeated, contradictory or too few constraints are refused.
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

  // the saddle point [K C^T; C 0] [u; lambda] = [f; d], dense
  const Eigen::Index n = K.rows(), m = c.C().rows();
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(n + m, n + m);
  S.topLeftCorner(n, n) = Eigen::MatrixXd(K);
  S.topRightCorner(n, m) = Eigen::MatrixXd(c.C().transpose());
  S.bottomLeftCorner(m, n) = Eigen::MatrixXd(c.C());
  Eigen::VectorXd rhs(n + m);
  rhs << f, Eigen::Vector4d(0, 0, 0, -1e-4);
  const Eigen::VectorXd x = S.partialPivLu().solve(rhs);
  EXPECT_LE((s.u - x.head(n)).norm(), 1e-9 * x.head(n).norm());
  for (Eigen::Index k = 0; k < m; ++k)  // R = -lambda
    EXPECT_NEAR(s.reactions_N[std::size_t(k)], -x[n + k], 1e-7 * x.tail(m).cwiseAbs().maxCoeff()) << k;

  // the reactions balance the applied load: sum R + sum f = 0 in each direction
  double fx = 0, fy = 0;
  for (Eigen::Index i = 0; i < n; i += 2) fx += f[i], fy += f[i + 1];
  const double Rx = s.reactions_N[0], Ry = s.reactions_N[1] + s.reactions_N[2] + s.reactions_N[3];
  const double scale = std::abs(s.reactions_N[3]);
  EXPECT_LE(std::abs(Rx + fx), 1e-9 * scale);
  EXPECT_LE(std::abs(Ry + fy), 1e-9 * scale);
  EXPECT_EQ(s.solver, "Eigen::SimplicialLDLT (AMD ordering) on the reduced T^T K T");
  EXPECT_GT(s.factor_nonzeros, 0u);
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
