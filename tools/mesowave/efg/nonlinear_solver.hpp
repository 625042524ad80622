#pragma once
// The nonlinear static solver of the cohesive crack (issue 15, "static
// solution"): a problem in the unknowns v and one control parameter lambda
// (a load factor, or the factor on the prescribed displacements under
// displacement control), r(v, lambda) = 0, solved
//  - by Newton-Raphson with a backtracking line search at each lambda of a
//    list (load or displacement control), and
//  - by Crisfield's cylindrical arc-length method (Crisfield 1981, "A fast
//    incremental/iterative solution procedure that handles snap-through"),
//    which treats lambda as an unknown under |Delta v| = Delta l, so it follows
//    a curve that turns back in lambda (snap-back) where control of lambda
//    has no solution or jumps.
// Linear systems: Eigen's SimplicialLDLT (the tangent is symmetric; LDL^T
// without pivoting also factorises the indefinite tangent of a softening
// crack unless a pivot vanishes), SparseLU when it fails. Each step reports its
// iterations and the residual norm of each iteration.
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

namespace mesowave::efg {

class NonlinearProblem {
public:
  virtual ~NonlinearProblem() = default;
  virtual std::size_t size() const = 0;
  /// r(v, lambda); dr/dv into `tangent` and dr/dlambda into `load_derivative` when they are not null.
  /// Must not change the problem's committed state (the solver calls it at trial points).
  virtual void evaluate(const Eigen::VectorXd& v, double lambda, Eigen::VectorXd& residual,
                        Eigen::SparseMatrix<double>* tangent, Eigen::VectorXd* load_derivative) = 0;
  /// A step converged at (v, lambda): history variables (the largest crack openings) move on.
  virtual void commit(const Eigen::VectorXd& /*v*/, double /*lambda*/) {}
  /// The largest fraction (0, 1] of the Newton step dv from v that the problem accepts (default 1): a cohesive
  /// crack limits the change of any opening per iteration, so that Newton cannot leap to a far-away solution (the
  /// fully opened crack, a mechanism at zero load) when a tangent softens.
  virtual double step_limit(const Eigen::VectorXd& /*v*/, const Eigen::VectorXd& /*dv*/, double /*lambda*/) { return 1.0; }
  /// The force scale convergence is measured against (default: |dr/dlambda| |lambda|, the norm of the load or of
  /// the forces the prescribed displacements raise; 1 where that is 0).
  virtual double residual_scale(const Eigen::VectorXd& v, double lambda);
};

struct NewtonOptions {
  int max_iterations = 40;
  double tolerance = 1e-8;           ///< converged when |r| <= tolerance * residual_scale
  double absolute_tolerance = 0;     ///< or when |r| <= this
  int max_line_search_cuts = 8;      ///< halvings of the step when |r| does not fall
  double armijo = 1e-4;              ///< sufficient decrease: |r(s)| <= (1 - armijo s) |r(0)|
};

/// One converged (or failed) step.
struct StepReport {
  double lambda = 0;
  int iterations = 0;
  std::vector<double> residual_norms;  ///< |r| before each iteration and after the last
  int line_search_cuts = 0;
  bool converged = false;
  double arc_length = 0;  ///< arc-length steps: the Delta l used
  int re_solves = 0;      ///< times the step was solved again after the problem changed (a crack grew)
};

/// Newton-Raphson with line search at fixed lambda, from v (updated in place; on failure v is the last iterate).
StepReport newton_solve(NonlinearProblem& problem, Eigen::VectorXd& v, double lambda, const NewtonOptions& options = {});

/// After a converged step: return true when the problem changed (a crack grew) and the step must be solved
/// again at the same lambda; `commit` is called only once this returns false.
using AfterConverged = std::function<bool(const Eigen::VectorXd& v, double lambda)>;
/// Each accepted point of a path.
using OnPoint = std::function<void(const Eigen::VectorXd& v, double lambda, const StepReport&)>;

struct ControlOptions {
  NewtonOptions newton;
  int max_re_solves = 50;  ///< per step
  int max_bisections = 6;  ///< a step that fails is split in two, down to this depth
};

/// Load / displacement control: lambda runs through `lambdas` (each from the previous solution, starting at v);
/// stops at the first step that fails even when bisected. Returns the reports of the accepted steps (the
/// bisected ones included) and the failed one last, if any.
/// `lambda_start`: the lambda of the starting v (the first step's bisection runs from it).
std::vector<StepReport> solve_control_path(NonlinearProblem& problem, Eigen::VectorXd& v, const std::vector<double>& lambdas,
                                           const ControlOptions& options = {}, const AfterConverged& after = {},
                                           const OnPoint& on_point = {}, double lambda_start = 0);

/// The arc-length constraint: Crisfield's cylindrical |Delta v| = Delta l, or the indirect displacement control
/// of de Borst (1987) c . Delta v = Delta l, where c picks a quantity that grows monotonically along the path (a
/// crack opening, the CMOD). The cylindrical constraint cycles at a corner of the cohesive law (the stiff initial
/// secant meeting the softening envelope at the peak: Newton's tangent jumps from +f_t/w_initial to the softening
/// slope); the indirect one fixes the opening in the first iteration, so the corner is met only once.
enum class ArcLengthConstraint { cylindrical, indirect };

struct ArcLengthOptions {
  NewtonOptions newton;
  ArcLengthConstraint constraint = ArcLengthConstraint::cylindrical;
  Eigen::VectorXd control_direction;  ///< c of the indirect constraint (size: the problem's)
  double first_lambda_increment = 0;  ///< sets the first Delta l from the tangent: Delta l = |dv/dlambda| dlambda
  double max_arc_length = 0;          ///< 0: 10 x the first
  double min_arc_length = 0;          ///< 0: 1e-4 x the first; below it the path stops
  int desired_iterations = 5;         ///< Delta l scales by sqrt(desired / used) after each step
  int max_steps = 500;
  double lambda_stop = 0;             ///< the path stops when lambda falls to it after rising (0: no stop)
  int max_re_solves = 50;
  /// The path stops when this returns true for an accepted point (e.g. the crack is through).
  std::function<bool(const Eigen::VectorXd& v, double lambda)> stop;
};

/// Arc-length from (v, lambda) (both updated): the predictor along the tangent (cylindrical: with the sign of the
/// previous increment), corrector iterations dv = dv_r + dlambda dv_t with dlambda from the constraint (cylindrical:
/// the quadratic |Delta v + dv|^2 = Delta l^2, the root closest to the previous increment, with backtracking; indirect:
/// linear); a step that does not converge is retried with half the Delta l.
std::vector<StepReport> solve_arc_length(NonlinearProblem& problem, Eigen::VectorXd& v, double& lambda,
                                         const ArcLengthOptions& options, const AfterConverged& after = {},
                                         const OnPoint& on_point = {});

}  // namespace mesowave::efg
