#include "mesowave/efg/three_point_bending.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/efg/cohesive_crack.hpp"
#include "mesowave/efg/cohesive_law.hpp"
#include "mesowave/efg/constraints.hpp"
#include "mesowave/efg/crack_growth.hpp"
#include "mesowave/efg/discretisation.hpp"
#include "mesowave/efg/elastic_model.hpp"
#include "mesowave/efg/material.hpp"

namespace mesowave::efg {

namespace {

void positive(double v, const std::string& what) { require_positive("three-point bending: " + what, v); }
std::string text(double v) { return format_number(v); }

}  // namespace

void ThreePointBendingOptions::validate() const {
  positive(span_m, "span_m");
  positive(depth_m, "depth_m");
  positive(thickness_m, "thickness_m");
  positive(notch_m, "notch_m");
  if (!(notch_m < depth_m))
    throw InputError("three-point bending: notch_m (" + text(notch_m) + ") must be less than the depth (" + text(depth_m) + ")");
  if (notch_x_m) require_finite("three-point bending: notch_x_m", *notch_x_m, "m");
  require_crack_inside(notch_polyline(), {0, 0, span_m, depth_m}, BodyFace::bottom, "three-point bending: notch");
  positive(E_Pa, "E_Pa");
  if (!(nu > -1 && nu < 0.5)) throw InputError("three-point bending: nu (" + text(nu) + ") must be in (-1, 0.5)");
  positive(f_t_Pa, "f_t_Pa");
  positive(G_f_J_m2, "G_f_J_m2");
  make_cohesive_law(law, {f_t_Pa, G_f_J_m2, law_keys, f_c_Pa});  // the law checks its name, keys and f_c
  positive(spacing_m, "spacing_m");
  if (!(spacing_m <= 0.5 * (depth_m - notch_m)))
    throw InputError("three-point bending: spacing_m (" + text(spacing_m) + ") must be at most half the ligament (" +
                     text(0.5 * (depth_m - notch_m)) + ")");
  {  // the notch line off the node columns (the cell corners i span / nx)
    const double cell = span_m / cells_along_span(), x = notch_position_m();
    const double column = std::round(x / cell) * cell;
    if (std::abs(x - column) < 0.25 * cell) {
      const double centre = column - 0.5 * cell;
      throw InputError("three-point bending: notch_x_m (" + text(x) + ") lies within a quarter cell (" + text(0.25 * cell) +
                       " m) of the node column at x = " + text(column) +
                       " m, which the notch would hide from both sides: place it between the columns, e.g. at the cell "
                       "centre x = " + text(centre) + " or " + text(centre + cell) + " m");
    }
  }
  positive(max_deflection_m, "max_deflection_m");
  if (!(load_width_m > 0 && load_width_m < 0.5 * span_m))
    throw InputError("three-point bending: load_width_m (" + text(load_width_m) + ") must be in (0, span / 2)");
  if (!(step_ratio >= 1 && step_ratio <= 2))
    throw InputError("three-point bending: step_ratio (" + text(step_ratio) + ") must be in [1, 2]");
  if (steps < 1) throw InputError("three-point bending: steps (" + std::to_string(steps) + ") must be >= 1");
}

int ThreePointBendingOptions::cells_along_span() const {
  int nx = std::max(3, static_cast<int>(std::lround(span_m / spacing_m)));
  return nx % 2 == 0 ? nx + 1 : nx;
}

ThreePointBendingResult run_three_point_bending(const ThreePointBendingOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  o.validate();
  auto law = std::shared_ptr<const CohesiveLaw>(make_cohesive_law(o.law, {o.f_t_Pa, o.G_f_J_m2, o.law_keys, o.f_c_Pa}));

  // nodes: an odd number of cells along the span (mid-span is a line of cell centres)
  const int nx = o.cells_along_span();
  const int ny = std::max(2, static_cast<int>(std::lround(o.depth_m / o.spacing_m)));
  const Discretisation disc = rectangular_grid({0, 0, o.span_m, o.depth_m}, nx, ny, o.gauss);
  const double h = std::max(o.span_m / nx, o.depth_m / ny), mid = 0.5 * o.span_m, notch_x = o.notch_position_m();

  // the notch: a traction-free crack from below the bottom face (so the bottom edge is cut too) to its tip
  CrackSet cracks;
  Crack notch;
  notch.points = {Vec2(notch_x, -h), Vec2(notch_x, o.notch_m)};
  notch.tip_at_start = false;
  notch.tip_at_end = true;
  const std::size_t crack = cracks.add(notch);

  MlsOptions mls_options;
  mls_options.crack_method = o.crack_method;
  const MlsApproximation mls(disc.nodes, support_radii_by_spacing(disc.nodes, h, o.support_scale), mls_options, &cracks);
  ElasticMaterial2D material{o.E_Pa, o.nu, o.thickness_m, 0, PlaneState::plane_stress};
  ElasticModel model(disc, material, mls);

  const double half_plate = 0.5 * o.load_width_m;  // the load points either side of mid-span
  std::vector<PointConstraint> bc = {
      {Vec2(0, 0), 1, 0.0, "left support u_y"},
      {Vec2(0, 0), 0, 0.0, "left support u_x"},
      {Vec2(o.span_m, 0), 1, 0.0, "right support u_y"},
      {Vec2(mid - half_plate, o.depth_m), 1, -1.0, "load point left u_y"},  // both move down by lambda [m]
      {Vec2(mid + half_plate, o.depth_m), 1, -1.0, "load point right u_y"},
  };
  const ConstraintSet notch_constraints(model, bc);
  // The rows of the supports and load points are the MLS shape functions at those points, so they must see the
  // cracks the run has: with the ligament interface its line is cut from the start (below), and the load points,
  // 5 mm either side of it, must not be tied to the nodes across it (that ties the halves together at the top:
  // a shear key the interface does not have). A grown crack stops half a segment below the top face, where the
  // stale rows differ only in the nodes the tip region hides (not rebuilt: ConstraintSet has no update).
  std::optional<ConstraintSet> cut_constraints;
  const ConstraintSet* active = &notch_constraints;

  ThreePointBendingResult result;
  result.law_parameters = law->parameters();
  result.w_max_m = law->w_max_m();
  result.nodes = disc.nodes.size();
  result.gauss_points = disc.points.size();
  result.dofs = model.dof_count();
  auto load_of = [&](const Eigen::VectorXd& full_residual) {
    const auto R = active->reactions(full_residual);
    return -(R[3] + R[4]);
  };
  {
    const auto elastic = solve_linear(model.stiffness(), Eigen::VectorXd::Zero(static_cast<Eigen::Index>(model.dof_count())),
                                      notch_constraints, 1.0);
    result.elastic_stiffness_N_per_m = load_of(model.stiffness() * elastic.u);
  }
  if (o.ligament_interface) {  // the whole ligament's line cut from the start, on beyond the top face
    cracks.extend(crack, Vec2(notch_x, o.depth_m + (o.support_scale + 1) * h));
    model.update_shape_functions();
    active = &cut_constraints.emplace(model, bc);
  }
  const ConstraintSet& constraints = *active;

  CohesiveInterface interface(mls, law, o.thickness_m, 1e-6 * h, o.cohesive_gauss);
  CohesiveCrackProblem problem(model, constraints, interface);

  CrackGrowthOptions growth;
  growth.rule = o.growth;
  growth.prescribed = Vec2::UnitY();
  growth.segment_length_m = h;
  Vec2 tip(notch_x, o.notch_m);
  bool through = false;
  if (o.ligament_interface) {  // the whole ligament cohesive from the start
    const int n = static_cast<int>(std::ceil((o.depth_m - o.notch_m) / h - 1e-9));
    for (int k = 0; k < n; ++k)
      interface.add_segment({Vec2(notch_x, o.notch_m + (o.depth_m - o.notch_m) * k / n),
                             Vec2(notch_x, o.notch_m + (o.depth_m - o.notch_m) * (k + 1) / n)});
    problem.update();
    through = true;
  }
  // the crack tip's height: the grown tip, or on the ligament interface the highest point off its initial secant
  auto tip_height = [&] {
    if (!o.ligament_interface) return tip.y();
    double y = o.notch_m;
    for (const auto& p : interface.points())
      if (p.w_hist_m > interface.w_initial_m()) y = std::max(y, p.x.y());
    return y;
  };
  auto crack_snapshot = [&](const Eigen::VectorXd& u) {
    CrackSnapshot c;
    const Vec2 n = Vec2::UnitX(), m(notch_x, 0.5 * o.notch_m);  // the normal the cohesive segments have (b - a up)
    const double eps = 1e-6 * h;  // off the line on each face, as the cohesive points are
    c.polylines.push_back(o.notch_polyline());
    c.opening_m.push_back((model.displacement(m + eps * n, u) - model.displacement(m - eps * n, u)).dot(n));
    c.traction_Pa.push_back(0);
    c.damage.push_back(1);
    const auto states = interface.point_states(u);
    const auto& points = interface.points();
    std::vector<Vec2> line;
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Segment& seg = interface.segments()[points[k].segment];
      const bool first = k == 0 || points[k - 1].segment != points[k].segment;
      const bool last = k + 1 == points.size() || points[k + 1].segment != points[k].segment;
      if (line.empty()) line.push_back(seg.a);
      // the segments follow each other (a grown segment starts at the last tip), so the pieces do too
      const double t = (first ? 0.0 : (line.back() - seg.a).norm() / (seg.b - seg.a).norm()) +
                       points[k].length_weight_m / (seg.b - seg.a).norm();
      line.push_back(last ? seg.b : Vec2(seg.a + t * (seg.b - seg.a)));
      c.opening_m.push_back(states[k].opening_m);
      c.traction_Pa.push_back(states[k].traction_Pa);
      c.damage.push_back(states[k].damage);
    }
    if (!line.empty()) c.polylines.push_back(std::move(line));
    return c;
  };
  auto snapshot = [&](const Eigen::VectorXd& u) {
    if (!o.node_snapshots) return;
    result.crack_steps.push_back(crack_snapshot(u));
    NodeSnapshot n;
    n.positions_m = disc.nodes;
    for (const auto& x : disc.nodes) {
      n.displacement_m.push_back(model.displacement(x, u));
      n.stress_Pa.push_back(model.stress(x, u));
    }
    result.node_steps.push_back(std::move(n));
  };
  auto inside = [&](const Vec2& x) { return x.x() > 0 && x.x() < o.span_m && x.y() > 0 && x.y() < o.depth_m; };
  AfterConverged grow = [&](const Eigen::VectorXd& v, double lambda) {
    if (through) return false;
    const Eigen::VectorXd u = constraints.expand(v, lambda);
    auto strain_at = [&](const Vec2& x) { return model.strain(x, u); };
    const auto& pts = cracks.cracks()[crack].points;
    const Vec2 heading = (pts.back() - pts[pts.size() - 2]).normalized();
    auto next = grown_tip(tip, heading, o.f_t_Pa, o.E_Pa, growth, strain_at, inside);
    if (!next) return false;
    // the tip stops half a segment below the top face. With the crack through the depth the halves are held only
    // by the crack faces and the right half, on its roller, may slide off them: the fully opened crack is then an
    // equilibrium at zero load (a mechanism), and Newton, started from the shape functions just cut, finds it
    // instead of the closed compression zone - even with its step limited (CohesiveCrackProblem::step_limit).
    // The price: the strip left above the tip, and the MLS coupling across it, is an elastic hinge that keeps a
    // residual load in the tail (it shrinks with the spacing; docs/efg.md).
    if (next->y() >= o.depth_m - 0.5 * h - 1e-12) {
      *next = tip + (o.depth_m - 0.5 * h - tip.y()) / (*next - tip).y() * (*next - tip);
      through = true;
    }
    if (!((*next - tip).norm() > 1e-9 * h)) return through = true, false;
    // the point before the extension: at this deflection the load drops when the crack extends (the curve keeps both)
    result.curve.push_back({lambda, load_of(problem.internal_force(u)), 0, tip.y(), interface.dissipated_energy_J()});
    snapshot(u);
    cracks.extend(crack, *next);
    interface.add_segment({tip, *next});
    tip = *next;
    problem.update();
    return true;
  };

  result.curve.push_back({0, 0, 0, tip_height(), 0});
  snapshot(Eigen::VectorXd::Zero(static_cast<Eigen::Index>(model.dof_count())));
  Eigen::VectorXd v = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(constraints.reduced_size()));
  ControlOptions control;
  control.newton = o.newton;
  control.max_re_solves = 4 * (ny + 2);
  std::vector<double> lambdas;
  for (int i = 1; i <= o.steps; ++i)  // equal steps, or growing geometrically by step_ratio
    lambdas.push_back(o.step_ratio == 1 ? o.max_deflection_m * i / o.steps
                                        : o.max_deflection_m * (std::pow(o.step_ratio, i) - 1) / (std::pow(o.step_ratio, o.steps) - 1));
  auto on_point = [&](const Eigen::VectorXd& x, double lam, const StepReport& rep) {
    const Eigen::VectorXd u = constraints.expand(x, lam);
    const double P = load_of(problem.internal_force(u));
    result.curve.push_back({lam, P, rep.iterations, tip_height(), interface.dissipated_energy_J()});
    snapshot(u);
    result.steps.push_back(rep);
    result.newton_iterations += rep.iterations;
    result.re_solves += rep.re_solves;
    result.line_search_cuts += rep.line_search_cuts;
    if (P > result.peak_load_N) result.peak_load_N = P, result.deflection_at_peak_m = lam;
  };
  double previous = 0;
  bool failed = false;
  for (double lambda : lambdas) {
    const auto reports = solve_control_path(problem, v, {lambda}, control, grow, on_point, previous);
    previous = lambda;
    if (reports.empty() || !reports.back().converged) {
      failed = true;
      result.stop_reason = "step to deflection " + text(lambda * 1e3) + " mm did not converge";
      break;
    }
    if (through && result.curve.back().load_N < o.stop_load_fraction * result.peak_load_N) {
      result.stop_reason = "crack tip at its highest and the load below " + text(100 * o.stop_load_fraction) + " % of the peak";
      break;
    }
  }
  result.completed = !failed;
  if (result.stop_reason.empty()) result.stop_reason = "maximum deflection reached";
  for (std::size_t i = 1; i < result.curve.size(); ++i) {
    const auto& a = result.curve[i - 1];
    const auto& b = result.curve[i];
    result.work_of_fracture_J += 0.5 * (a.load_N + b.load_N) * (b.deflection_m - a.deflection_m);
  }
  result.dissipated_J = interface.dissipated_energy_J();
  result.final_load_N = result.curve.back().load_N;
  result.final_deflection_m = result.curve.back().deflection_m;
  result.stored_J = problem.stored_energy_J(constraints.expand(v, result.final_deflection_m));
  result.cohesive_points = interface.points().size();
  result.crack_path = cracks.cracks()[crack].points;
  result.crack_path.front() = Vec2(notch_x, 0);  // the notch mouth on the bottom face (the polyline starts below it)
  if (o.ligament_interface) result.crack_path.back() = Vec2(notch_x, o.depth_m);  // the line runs on beyond the top face
  result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace mesowave::efg
