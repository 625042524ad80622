// The nonlinear solver on a problem with a closed-form curve: an elastic bar
// (E, A, L) in series with a cohesive softening spring of the same area. On
// the envelope the load is P = A sigma(w) and the end displacement
// delta = P L / (E A) + w; the curve snaps back (d delta / dP > 0 after the
// peak) when L > E / |sigma'|. Displacement control follows a short bar and
// jumps over the snap-back of a long one; the arc-length method follows it,
// and the work done along the whole path is G_f A plus what is still stored.
#include <gtest/gtest.h>

#include <cmath>

#include "mesowave/efg/cohesive_law.hpp"
#include "mesowave/efg/nonlinear_solver.hpp"

namespace mesowave::efg {
namespace {

constexpr double E = 20e9, A = 0.01, f_t = 2.4e6, G_f = 113;

/// The bar and the spring; `displacement_control`: v = (u1), u2 = lambda delta_ref; else v = (u1, u2), P = lambda f_t A.
class BarWithCohesiveSpring : public NonlinearProblem {
public:
  BarWithCohesiveSpring(double L, bool displacement_control, double delta_ref = 0)
      : law(make_cohesive_law("exponential", {f_t, G_f, {}, std::nullopt})), L(L), disp(displacement_control), delta_ref(delta_ref),
        w0(initial_opening_fraction * law->w_max_m()), w_hist(w0) {}
  std::size_t size() const override { return disp ? 1 : 2; }
  void evaluate(const Eigen::VectorXd& v, double lambda, Eigen::VectorXd& r, Eigen::SparseMatrix<double>* K,
                Eigen::VectorXd* dr) override {
    const double u1 = v[0], u2 = disp ? lambda * delta_ref : v[1], w = u2 - u1;
    const auto c = cohesive_response(*law, w, w_hist, w0);
    const double kb = E * A / L, ks = A * c.tangent_Pa_per_m;
    r.resize(size());
    r[0] = kb * u1 - A * c.traction_Pa;
    if (!disp) r[1] = A * c.traction_Pa - lambda * f_t * A;
    if (K) {
      K->resize(size(), size());
      std::vector<Eigen::Triplet<double>> t{{0, 0, kb + ks}};
      if (!disp) t.insert(t.end(), {{0, 1, -ks}, {1, 0, -ks}, {1, 1, ks}});
      K->setFromTriplets(t.begin(), t.end());
    }
    if (dr) {
      dr->resize(size());
      if (disp) (*dr)[0] = -ks * delta_ref;
      else (*dr) << 0, -f_t * A;
    }
  }
  void commit(const Eigen::VectorXd& v, double lambda) override {
    w_hist = std::max(w_hist, (disp ? lambda * delta_ref : v[1]) - v[0]);
  }
  /// The cohesive response on the envelope, as the closed form sees it (the initial secant below w0).
  double sigma(double w) const { return w < w0 ? law->traction_Pa(w0) / w0 * w : law->traction_Pa(w); }
  /// delta(w) on the loading curve.
  double delta_of(double w) const { return A * sigma(w) * L / (E * A) + w; }

  std::unique_ptr<CohesiveLaw> law;
  double L;
  bool disp;
  double delta_ref, w0, w_hist;
};

TEST(NonlinearSolver, NewtonConvergesQuadraticallyOnTheEnvelope) {
  BarWithCohesiveSpring bar(0.05, true, 1e-4);
  Eigen::VectorXd v = Eigen::VectorXd::Zero(1);
  bar.w_hist = 0.3 * bar.law->w_max_m();  // start on the softening branch
  const double lambda = (0.05 * 2.4e6 / E + 0.4 * bar.law->w_max_m()) / 1e-4;
  const auto rep = newton_solve(bar, v, lambda, {});
  ASSERT_TRUE(rep.converged);
  EXPECT_LE(rep.iterations, 8);
  EXPECT_LT(rep.residual_norms.back(), 1e-8 * rep.residual_norms.front());
}

TEST(NonlinearSolver, DisplacementControlFollowsAShortBar) {
  const double L = 0.05;  // far below E / |sigma'(0)| = 0.59 m: no snap-back
  BarWithCohesiveSpring bar(L, true, 1.0);
  const double w_max = bar.law->w_max_m();
  std::vector<double> lambdas;
  for (int i = 1; i <= 200; ++i) lambdas.push_back(i * 0.95 * w_max / 200);
  Eigen::VectorXd v = Eigen::VectorXd::Zero(1);
  std::vector<std::pair<double, double>> curve{{0, 0}};  // (delta, P)
  const auto reports = solve_control_path(bar, v, lambdas, {}, {}, [&](const Eigen::VectorXd& x, double lambda, const StepReport&) {
    curve.push_back({lambda, E * A / L * x[0]});
  });
  ASSERT_TRUE(reports.back().converged);
  for (const auto& r : reports) EXPECT_LE(r.iterations, 25);
  // each point against the closed-form curve: w from delta(w) = delta by bisection
  for (const auto& [delta, P] : curve) {
    double lo = 0, hi = w_max;
    for (int k = 0; k < 200; ++k) ((bar.delta_of(0.5 * (lo + hi)) < delta) ? lo : hi) = 0.5 * (lo + hi);
    EXPECT_NEAR(P, A * bar.sigma(0.5 * (lo + hi)), 1e-6 * f_t * A) << delta;
  }
}

TEST(NonlinearSolver, ArcLengthFollowsTheSnapBackThatDisplacementControlJumps) {
  const double L = 5.0;  // snap-back: L > E / |sigma'(0)| = 0.59 m
  BarWithCohesiveSpring controlled(L, true, 1.0);
  const double w_max = controlled.law->w_max_m(), delta_peak = f_t * L / E;
  // displacement control: no accepted point on the snap-back branch (P between 0.2 and 0.9 f_t A with delta < peak)
  std::vector<double> lambdas;
  for (int i = 1; i <= 100; ++i) lambdas.push_back(i * 1.5 * delta_peak / 100);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(1);
  int on_branch = 0;
  solve_control_path(controlled, u, lambdas, {}, {}, [&](const Eigen::VectorXd& x, double lambda, const StepReport&) {
    const double P = E * A / L * x[0];
    if (P > 0.2 * f_t * A && P < 0.9 * f_t * A && lambda - x[0] > 1e-3 * w_max) ++on_branch;
  });
  EXPECT_EQ(on_branch, 0);

  BarWithCohesiveSpring bar(L, false);
  Eigen::VectorXd v = Eigen::VectorXd::Zero(2);
  double lambda = 0;
  ArcLengthOptions o;
  o.constraint = ArcLengthConstraint::indirect;
  o.control_direction = Eigen::Vector2d(-1, 1);  // the opening w = u2 - u1
  o.first_lambda_increment = 0.05;
  o.max_arc_length = 0.01 * w_max;
  o.lambda_stop = 0.02;
  std::vector<std::array<double, 3>> path{{0, 0, 0}};  // (delta, P, w)
  const auto reports = solve_arc_length(bar, v, lambda, o, {}, [&](const Eigen::VectorXd& x, double lam, const StepReport&) {
    path.push_back({x[1], lam * f_t * A, x[1] - x[0]});
  });
  ASSERT_GT(reports.size(), 20u);
  double work = 0, delta_min_after_peak = 1e9, P_max = 0;
  int points_on_branch = 0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const auto [delta, P, w] = path[i];
    // on the closed-form curve
    EXPECT_NEAR(P, A * bar.sigma(w), 1e-6 * f_t * A) << i;
    EXPECT_NEAR(delta, bar.delta_of(w), 1e-9 * delta_peak + 1e-6 * w_max) << i;
    work += 0.5 * (P + path[i - 1][1]) * (delta - path[i - 1][0]);
    P_max = std::max(P_max, P);
    if (P_max > 0.99 * f_t * A) delta_min_after_peak = std::min(delta_min_after_peak, delta);
    if (P > 0.2 * f_t * A && P < 0.9 * f_t * A) ++points_on_branch;
  }
  EXPECT_GT(points_on_branch, 10);
  // the peak is the corner at w_initial, sigma(w_initial) = f_t (1 - 1e-3)^2: sampled within a step of it
  EXPECT_LE(P_max, A * bar.sigma(bar.w0) * (1 + 1e-9));
  EXPECT_GT(P_max, 0.99 * f_t * A);
  // the path came back: delta fell well below delta at the peak
  EXPECT_LT(delta_min_after_peak, 0.5 * delta_peak);
  // work = energy dissipated in the spring up to w + elastic energy left in the bar (closed forms)
  const auto [delta_end, P_end, w_end] = path.back();
  const double w0 = bar.w0, s0 = bar.law->traction_Pa(w0);
  const double dissipated = A * (s0 * w0 / 2 + f_t * w_max / 3 * (std::pow(1 - w0 / w_max, 3) - std::pow(1 - w_end / w_max, 3)));
  EXPECT_NEAR(work, dissipated + P_end * P_end * L / (2 * E * A), 5e-3 * G_f * A);
  EXPECT_GT(dissipated, 0.99 * G_f * A);
}

TEST(NonlinearSolver, CylindricalArcLengthPassesThePeakOfAShortBar) {
  BarWithCohesiveSpring bar(0.05, false);
  const double w_max = bar.law->w_max_m();
  Eigen::VectorXd v = Eigen::VectorXd::Zero(2);
  double lambda = 0;
  ArcLengthOptions o;
  o.first_lambda_increment = 0.1;
  o.max_arc_length = 0.01 * w_max;
  o.lambda_stop = 0.05;
  double w_last = 0;
  int points = 0;
  const auto reports = solve_arc_length(bar, v, lambda, o, {}, [&](const Eigen::VectorXd& x, double lam, const StepReport&) {
    w_last = x[1] - x[0];
    EXPECT_NEAR(lam * f_t * A, A * bar.sigma(w_last), 1e-6 * f_t * A);
    ++points;
  });
  EXPECT_GT(points, 20);
  EXPECT_GT(w_last, 0.7 * w_max);  // well past the peak, down to 5 % of the load
  EXPECT_LE(lambda, 0.05);
  for (const auto& r : reports) EXPECT_TRUE(r.converged);
}

}  // namespace
}  // namespace mesowave::efg
