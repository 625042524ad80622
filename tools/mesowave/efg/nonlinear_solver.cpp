#include "mesowave/efg/nonlinear_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

namespace mesowave::efg {

double NonlinearProblem::residual_scale(const Eigen::VectorXd& v, double lambda) {
  Eigen::VectorXd r, dr_dlambda;
  evaluate(v, lambda, r, nullptr, &dr_dlambda);
  const double scale = dr_dlambda.norm() * std::abs(lambda);
  return scale > 0 ? scale : 1.0;
}

namespace {

/// The tangent factorised: sparse LDL^T first (the cohesive tangent is symmetric; LDL^T without pivoting also
/// takes the indefinite matrices of a softening crack as long as no pivot vanishes), LU when that fails.
class Factorised {
public:
  bool factor(const Eigen::SparseMatrix<double>& K) {
    ldlt_.compute(K);
    use_lu_ = ldlt_.info() != Eigen::Success || !(ldlt_.vectorD().array().abs() > 0).all();
    if (!use_lu_) return true;
    lu_.analyzePattern(K);
    lu_.factorize(K);
    return lu_.info() == Eigen::Success;
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) { return use_lu_ ? Eigen::VectorXd(lu_.solve(b)) : Eigen::VectorXd(ldlt_.solve(b)); }

private:
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu_;
  bool use_lu_ = false;
};

bool finite(const Eigen::VectorXd& x) { return x.allFinite(); }

}  // namespace

StepReport newton_solve(NonlinearProblem& problem, Eigen::VectorXd& v, double lambda, const NewtonOptions& o) {
  StepReport rep;
  rep.lambda = lambda;
  const double scale = problem.residual_scale(v, lambda);
  const double tol = std::max(o.tolerance * scale, o.absolute_tolerance);
  Eigen::VectorXd r, r_trial;
  Eigen::SparseMatrix<double> K;
  Factorised lu;
  problem.evaluate(v, lambda, r, &K, nullptr);
  double norm = r.norm();
  rep.residual_norms.push_back(norm);
  while (true) {
    if (norm <= tol) {
      rep.converged = true;
      return rep;
    }
    if (rep.iterations >= o.max_iterations || !std::isfinite(norm) || !lu.factor(K)) return rep;
    const Eigen::VectorXd dv = lu.solve(-r);
    if (!finite(dv)) return rep;
    ++rep.iterations;
    // backtracking on |r|: halve the step while the residual does not fall enough; keep the best
    const double s_max = std::clamp(problem.step_limit(v, dv, lambda), 1e-6, 1.0);
    double s = s_max, best_s = s_max, best_norm = std::numeric_limits<double>::infinity();
    for (int cut = 0;; ++cut) {
      problem.evaluate(v + s * dv, lambda, r_trial, nullptr, nullptr);
      const double n = r_trial.norm();
      if (n < best_norm) best_norm = n, best_s = s;
      if (n <= (1 - o.armijo * s) * norm || cut >= o.max_line_search_cuts) break;
      s *= 0.5;
      ++rep.line_search_cuts;
    }
    if (!std::isfinite(best_norm)) return rep;
    v += best_s * dv;
    problem.evaluate(v, lambda, r, &K, nullptr);
    norm = r.norm();
    rep.residual_norms.push_back(norm);
  }
}

namespace {

/// Newton at lambda, then the AfterConverged loop, then commit.
StepReport solve_step(NonlinearProblem& problem, Eigen::VectorXd& v, double lambda, const NewtonOptions& newton,
                      int max_re_solves, const AfterConverged& after) {
  StepReport rep = newton_solve(problem, v, lambda, newton);
  int re_solves = 0;
  while (rep.converged && after && after(v, lambda)) {
    if (++re_solves > max_re_solves) {
      rep.converged = false;
      break;
    }
    StepReport again = newton_solve(problem, v, lambda, newton);
    again.iterations += rep.iterations;
    again.line_search_cuts += rep.line_search_cuts;
    again.residual_norms.insert(again.residual_norms.begin(), rep.residual_norms.begin(), rep.residual_norms.end());
    rep = std::move(again);
  }
  rep.re_solves = re_solves;
  if (rep.converged) problem.commit(v, lambda);
  return rep;
}

/// One control step from lambda_from to lambda_to, split in two on failure (depth-limited).
bool control_step(NonlinearProblem& problem, Eigen::VectorXd& v, double lambda_from, double lambda_to, int depth,
                  const ControlOptions& o, const AfterConverged& after, const OnPoint& on_point,
                  std::vector<StepReport>& reports) {
  Eigen::VectorXd trial = v;
  StepReport rep = solve_step(problem, trial, lambda_to, o.newton, o.max_re_solves, after);
  if (rep.converged) {
    v = trial;
    if (on_point) on_point(v, lambda_to, rep);
    reports.push_back(std::move(rep));
    return true;
  }
  if (depth >= o.max_bisections) {
    reports.push_back(std::move(rep));
    return false;
  }
  const double mid = 0.5 * (lambda_from + lambda_to);
  return control_step(problem, v, lambda_from, mid, depth + 1, o, after, on_point, reports) &&
         control_step(problem, v, mid, lambda_to, depth + 1, o, after, on_point, reports);
}

}  // namespace

std::vector<StepReport> solve_control_path(NonlinearProblem& problem, Eigen::VectorXd& v, const std::vector<double>& lambdas,
                                           const ControlOptions& o, const AfterConverged& after, const OnPoint& on_point,
                                           double lambda_start) {
  std::vector<StepReport> reports;
  double previous = lambda_start;
  for (double lambda : lambdas) {
    if (!control_step(problem, v, previous, lambda, 0, o, after, on_point, reports)) break;
    previous = lambda;
  }
  return reports;
}

std::vector<StepReport> solve_arc_length(NonlinearProblem& problem, Eigen::VectorXd& v, double& lambda,
                                         const ArcLengthOptions& o, const AfterConverged& after, const OnPoint& on_point) {
  std::vector<StepReport> reports;
  const std::size_t n = problem.size();
  Eigen::VectorXd r, dr_dlambda;
  Eigen::SparseMatrix<double> K;
  Factorised lu;

  // the first Delta l from the tangent at the start
  problem.evaluate(v, lambda, r, &K, &dr_dlambda);
  if (!lu.factor(K)) return reports;
  const Eigen::VectorXd t0 = lu.solve(-dr_dlambda);
  const Eigen::VectorXd& c = o.control_direction;
  const bool indirect = o.constraint == ArcLengthConstraint::indirect;
  if (indirect && c.size() != static_cast<Eigen::Index>(n)) return reports;
  double dl = (indirect ? std::abs(c.dot(t0)) : t0.norm()) * o.first_lambda_increment;
  const double dl_max = o.max_arc_length > 0 ? o.max_arc_length : 10 * dl;
  const double dl_min = o.min_arc_length > 0 ? o.min_arc_length : 1e-4 * dl;
  Eigen::VectorXd previous_dv = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n));
  double previous_dlambda = o.first_lambda_increment;
  double lambda_peak = lambda;

  for (int step = 0; step < o.max_steps && dl >= dl_min; ++step) {
    StepReport rep;
    rep.arc_length = dl;
    Eigen::VectorXd v_new = v;
    double lambda_new = lambda;
    // predictor along the tangent, continuing in the direction of the previous increment
    problem.evaluate(v, lambda, r, &K, &dr_dlambda);
    if (!lu.factor(K)) break;
    Eigen::VectorXd dv_t = lu.solve(-dr_dlambda);
    double dlam;
    if (indirect) {  // c . Delta v = Delta l: the controlled opening grows by Delta l
      dlam = dl / c.dot(dv_t);
    } else {
      const double sign = previous_dv.squaredNorm() > 0 ? (previous_dv.dot(dv_t) >= 0 ? 1 : -1) : (previous_dlambda >= 0 ? 1 : -1);
      dlam = sign * dl / std::max(dv_t.norm(), std::numeric_limits<double>::min());
    }
    if (!std::isfinite(dlam)) break;
    Eigen::VectorXd Dv = dlam * dv_t;
    double Dlam = dlam;
    v_new = v + Dv;
    lambda_new = lambda + Dlam;
    const double scale = problem.residual_scale(v_new, lambda_new);
    const double tol = std::max(o.newton.tolerance * scale, o.newton.absolute_tolerance);
    problem.evaluate(v_new, lambda_new, r, &K, &dr_dlambda);
    rep.residual_norms.push_back(r.norm());
    // the new iterate (v + Dv, lambda + Dlam): residual and tangent there; false when they are not finite
    auto accept = [&] {
      v_new = v + Dv;
      lambda_new = lambda + Dlam;
      ++rep.iterations;
      problem.evaluate(v_new, lambda_new, r, &K, &dr_dlambda);
      rep.residual_norms.push_back(r.norm());
      return std::isfinite(rep.residual_norms.back());
    };
    while (rep.residual_norms.back() > tol && rep.iterations < o.newton.max_iterations) {
      if (!lu.factor(K)) break;
      const Eigen::VectorXd dv_r = lu.solve(-r);
      dv_t = lu.solve(-dr_dlambda);
      // |Dv + dv_r + dlam dv_t|^2 = dl^2
      const Eigen::VectorXd base = Dv + dv_r;
      if (indirect) {
        const double d = (dl - c.dot(base)) / c.dot(dv_t);
        if (!std::isfinite(d)) break;
        Dv = base + d * dv_t;
        Dlam += d;
        if (!accept()) break;
        continue;
      }
      const double a = dv_t.squaredNorm(), b = 2 * dv_t.dot(base), c = base.squaredNorm() - dl * dl;
      const double disc = b * b - 4 * a * c;
      if (!(disc >= 0) || a <= 0) break;
      const double q = std::sqrt(disc);
      const double roots[2] = {(-b + q) / (2 * a), (-b - q) / (2 * a)};
      // the root whose new increment makes the smallest angle with the current one
      double best = roots[0], best_cos = -std::numeric_limits<double>::infinity();
      for (double root : roots) {
        const double cosine = (base + root * dv_t).dot(Dv);
        if (cosine > best_cos) best_cos = cosine, best = root;
      }
      // backtracking between the last iterate and the full correction: a corner of the cohesive law (where the
      // secant meets the envelope) makes the full Newton step cycle across it; a shortened step breaks the cycle
      // and the next iteration restores |Delta v| = Delta l
      const Eigen::VectorXd Dv_full = base + best * dv_t;
      const double Dlam_full = Dlam + best, norm_before = rep.residual_norms.back();
      double s = 1;
      for (int cut = 0;; ++cut) {
        problem.evaluate(v + Dv + s * (Dv_full - Dv), lambda + Dlam + s * (Dlam_full - Dlam), r, nullptr, nullptr);
        if (r.norm() <= (1 - o.newton.armijo * s) * norm_before || cut >= o.newton.max_line_search_cuts) break;
        s *= 0.5;
        ++rep.line_search_cuts;
      }
      Dv += s * (Dv_full - Dv);
      Dlam += s * (Dlam_full - Dlam);
      if (!accept()) break;
    }
    rep.converged = rep.residual_norms.back() <= tol && std::abs((indirect ? c.dot(Dv) : Dv.norm()) - dl) <= 1e-6 * dl;
    if (rep.converged && after) {  // a crack grew: re-solve at the reached lambda
      StepReport fixed = solve_step(problem, v_new, lambda_new, o.newton, o.max_re_solves, after);
      rep.re_solves = fixed.re_solves;
      rep.iterations += fixed.iterations;
      rep.residual_norms.insert(rep.residual_norms.end(), fixed.residual_norms.begin(), fixed.residual_norms.end());
      rep.converged = fixed.converged;  // solve_step committed
    } else if (rep.converged) {
      problem.commit(v_new, lambda_new);
    }
    if (!rep.converged) {
      dl *= 0.5;
      continue;
    }
    previous_dv = v_new - v;
    previous_dlambda = lambda_new - lambda;
    v = v_new;
    lambda = lambda_new;
    rep.lambda = lambda;
    if (on_point) on_point(v, lambda, rep);
    const int used = std::max(rep.iterations, 1);
    reports.push_back(std::move(rep));
    lambda_peak = std::max(lambda_peak, lambda);
    if (o.stop && o.stop(v, lambda)) break;
    if (o.lambda_stop != 0 && lambda_peak > o.lambda_stop && lambda <= o.lambda_stop) break;
    dl = std::clamp(dl * std::sqrt(static_cast<double>(o.desired_iterations) / used), dl_min, dl_max);
  }
  return reports;
}

}  // namespace mesowave::efg
