#include "mesowave/efg/cantilever.hpp"

#include <chrono>
#include <cmath>

#include "mesowave/efg/constraints.hpp"
#include "mesowave/efg/discretisation.hpp"
#include "mesowave/efg/elastic_model.hpp"

namespace mesowave::efg {

CantileverRun solve_cantilever(const CantileverSetup& s) {
  using clock = std::chrono::steady_clock;
  const auto seconds = [](clock::time_point a) { return std::chrono::duration<double>(clock::now() - a).count(); };
  const auto start = clock::now();
  const CantileverBeam& beam = s.beam;
  const Rect body{0, -beam.D_m / 2, beam.L_m, beam.D_m / 2};
  const Discretisation disc = rectangular_grid(body, s.cells_x, s.cells_y, s.gauss);
  const MlsApproximation mls(disc.nodes, support_radii_by_spacing(disc.nodes, disc.spacing_m, s.support_scale), s.mls);
  const ElasticModel model(disc, {beam.E_Pa, beam.nu, beam.t_m, 0, PlaneState::plane_stress}, mls);
  CantileverRun run;
  run.shape_s = seconds(start);

  auto t = clock::now();
  const Eigen::SparseMatrix<double> K = model.stiffness();
  run.assemble_s = seconds(t);
  std::vector<PointConstraint> clamp;
  std::vector<EdgeConstraint> clamp_edge;
  if (s.collocated_clamp) {
    for (std::size_t i = 0; i < disc.nodes.size(); ++i)
      if (disc.nodes[i].x() == body.x0) {
        const Eigen::Vector2d u = beam.at(disc.nodes[i]).u_m;
        clamp.push_back({disc.nodes[i], 0, u.x(), "clamp x, node " + std::to_string(i)});
        clamp.push_back({disc.nodes[i], 1, u.y(), "clamp y, node " + std::to_string(i)});
      }
  } else {
    const Segment edge{Vec2(body.x0, body.y0), Vec2(body.x0, body.y1)};
    for (int c = 0; c < 2; ++c)
      clamp_edge.push_back({edge, c, [&beam, c](const Vec2& x) { return beam.at(x).u_m[c]; }, c == 0 ? "clamp x" : "clamp y"});
  }
  const Eigen::VectorXd f = model.traction_load({Vec2(body.x1, body.y0), Vec2(body.x1, body.y1)}, [&](const Vec2& x) {
    const Eigen::Vector3d stress = beam.at(x).stress_Pa;
    return Eigen::Vector2d(stress[0], stress[2]);  // sigma n with n = +x
  });
  t = clock::now();
  const ConstraintSet constraints(model, clamp, clamp_edge);
  const LinearSolution solution = solve_linear(K, f, constraints);
  run.solve_s = seconds(t) - solution.factorise_s;
  run.factorise_s = solution.factorise_s;

  run.nodes = disc.nodes.size();
  run.gauss_points = disc.points.size();
  run.dofs = model.dof_count();
  run.constraints = constraints.row_names().size();
  run.spacing_m = disc.spacing_m;
  for (std::size_t k = 0; k < solution.reactions_N.size(); ++k)
    run.reaction_N[constraints.row_components()[k]] += solution.reactions_N[k];
  for (Eigen::Index i = 0; i < f.size(); ++i) run.applied_N[i % 2] += f[i];
  run.solver = solution.solver;
  run.reduced_nonzeros = solution.reduced_nonzeros;
  run.factor_nonzeros = solution.factor_nonzeros;
  run.error = cantilever_errors(
      beam, [&](const Vec2& x) { return model.displacement(x, solution.u); },
      [&](const Vec2& x) { return model.stress(x, solution.u); }, s.cells_x, s.cells_y, s.error_gauss);
  run.wall_s = seconds(start);
  return run;
}

}  // namespace mesowave::efg
