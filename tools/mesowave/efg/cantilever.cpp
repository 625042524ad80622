#include "mesowave/efg/cantilever.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/efg/constraints.hpp"
#include "mesowave/efg/discretisation.hpp"
#include "mesowave/efg/elastic_model.hpp"
#include "mesowave/efg/material.hpp"
#include "mesowave/fem/plane_static.hpp"

namespace mesowave::efg {

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

constexpr double kMiB = 1024.0 * 1024.0;

void check(const CantileverOptions& o) {
  if (o.cells_x < 1 || o.cells_y < 1)
    throw InputError("cantilever with " + std::to_string(o.cells_x) + " x " + std::to_string(o.cells_y) +
                     " cells: both counts must be >= 1");
}

ElasticMaterial2D material_of(const CantileverBeam& beam) {
  ElasticMaterial2D m{beam.E_Pa, beam.nu, beam.t_m, 0, PlaneState::plane_stress};
  m.validate();
  return m;
}

// The end shear the closed form carries at x = L.
Eigen::Vector2d end_traction(const CantileverBeam& beam, const Eigen::Vector2d& x) {
  return {0.0, beam.at({beam.L_m, x.y()}).stress_Pa(2)};
}

void finish(CantileverRun& run, const CantileverBeam& beam, const CantileverOptions& o,
            const std::function<Eigen::Vector2d(const Eigen::Vector2d&)>& u,
            const std::function<Eigen::Vector3d(const Eigen::Vector2d&)>& stress) {
  run.errors = cantilever_errors(beam, u, stress, o.cells_x, o.cells_y, o.error_gauss);
  run.exact_tip_deflection_m = beam.at({beam.L_m, 0}).u_m.y();
  run.tip_deflection_m = u({beam.L_m, 0}).y();
  for (const auto& x : run.snapshot.positions_m) {
    run.snapshot.displacement_m.push_back(u(x));
    run.snapshot.stress_Pa.push_back(stress(x));
  }
}

}  // namespace

CantileverRun run_efg_cantilever(const CantileverBeam& beam, const CantileverOptions& o) {
  check(o);
  const auto t0 = Clock::now();
  CantileverRun run;
  run.method = "EFG";
  const ElasticMaterial2D material = material_of(beam);
  const Discretisation disc =
      rectangular_grid({0, -beam.D_m / 2, beam.L_m, beam.D_m / 2}, o.cells_x, o.cells_y, o.gauss);
  const auto radii = o.support_count > 0 ? support_radii_by_count(disc.nodes, o.support_count, o.support_factor)
                                         : support_radii_by_spacing(disc.nodes, disc.spacing_m, o.support_scale);
  const MlsApproximation mls(disc.nodes, radii, o.mls);
  ElasticModel model(disc, material, mls);
  run.setup_s = since(t0);

  const auto t1 = Clock::now();
  const Eigen::SparseMatrix<double> K = model.stiffness();
  const Eigen::VectorXd f =
      model.traction_load({{beam.L_m, -beam.D_m / 2}, {beam.L_m, beam.D_m / 2}},
                          [&](const Vec2& x) { return end_traction(beam, x); });
  std::vector<PointConstraint> clamp;
  std::vector<EdgeConstraint> clamp_edge;
  if (o.collocated_clamp) {
    for (const auto& x : disc.nodes)
      if (x.x() == 0.0) {
        const Eigen::Vector2d u = beam.at(x).u_m;
        clamp.push_back({x, 0, u.x(), "clamp u_x"});
        clamp.push_back({x, 1, u.y(), "clamp u_y"});
      }
  } else {
    const Segment edge{{0, -beam.D_m / 2}, {0, beam.D_m / 2}};
    for (int c = 0; c < 2; ++c)
      clamp_edge.push_back({edge, c, [&beam, c](const Vec2& x) { return beam.at(x).u_m[c]; }, c == 0 ? "clamp u_x" : "clamp u_y"});
  }
  const ConstraintSet constraints(model, clamp, clamp_edge);
  run.assembly_s = since(t1);
  const LinearSolution solution = solve_linear(K, f, constraints);
  run.solve_s = solution.wall_s;
  run.wall_s = since(t0);

  run.nodes = disc.nodes.size();
  run.gauss_points = disc.points.size();
  run.dofs = model.dof_count();
  run.spacing_m = disc.spacing_m;
  run.solver = solution.solver;
  run.stiffness_nonzeros = solution.reduced_nonzeros;
  run.factor_nonzeros = solution.factor_nonzeros;
  for (std::size_t k = 0; k < solution.reactions_N.size(); ++k)
    run.clamp_reaction_N[constraints.row_components()[k]] += solution.reactions_N[k];
  for (Eigen::Index i = 0; i < f.size(); ++i) run.applied_N[i % 2] += f[i];
  std::size_t shape_entries = 0;
  for (const auto& sf : model.shape_functions()) {
    shape_entries += sf.nodes.size();
    run.max_condition_number = std::max(run.max_condition_number, sf.condition_number);
  }
  run.memory_estimate_MiB =
      (12.0 * double(K.nonZeros() + Eigen::Index(run.factor_nonzeros)) + 28.0 * double(shape_entries)) / kMiB;
  run.snapshot.positions_m = disc.nodes;
  finish(run, beam, o, [&](const Eigen::Vector2d& x) { return model.displacement(x, solution.u); },
         [&](const Eigen::Vector2d& x) { return model.stress(x, solution.u); });
  return run;
}

CantileverRun run_fem_cantilever(const CantileverBeam& beam, const CantileverOptions& o) {
  check(o);
  const auto t0 = Clock::now();
  CantileverRun run;
  run.method = "Q4 FEM";
  const ElasticMaterial2D material = material_of(beam);
  fem::PlaneStaticProblem p;
  p.mesh = fem::structured_plane_mesh({0, -beam.D_m / 2, beam.L_m, beam.D_m, o.cells_x, o.cells_y});
  p.D = material.D();
  p.thickness_m = beam.t_m;
  for (auto n : p.mesh.nodes_on_segment({0, -beam.D_m / 2}, {0, beam.D_m / 2})) {
    const Eigen::Vector2d x = p.mesh.nodes[std::size_t(n)], u = beam.at(x).u_m;
    p.constraints.push_back({x, 0, u.x(), "clamp u_x"});
    p.constraints.push_back({x, 1, u.y(), "clamp u_y"});
  }
  p.edge_loads.push_back({{beam.L_m, -beam.D_m / 2}, {beam.L_m, beam.D_m / 2},
                          [&](const Eigen::Vector2d& x) { return end_traction(beam, x); }});
  run.setup_s = since(t0);
  const fem::PlaneStaticSolution s = fem::solve_plane_static(p);
  run.wall_s = since(t0);
  run.assembly_s = s.assembly_s;
  run.solve_s = s.solve_s;
  run.nodes = p.mesh.nodes.size();
  run.gauss_points = 4 * p.mesh.quads.size();
  run.dofs = p.mesh.dof_count();
  run.spacing_m = std::max(p.mesh.dx_m, p.mesh.dy_m);
  run.solver = s.solver;
  run.stiffness_nonzeros = s.stiffness_nonzeros;
  run.factor_nonzeros = s.factor_nonzeros;
  run.memory_estimate_MiB = 12.0 * double(s.stiffness_nonzeros + s.factor_nonzeros) / kMiB;
  run.snapshot.positions_m = p.mesh.nodes;
  finish(run, beam, o, [&](const Eigen::Vector2d& x) { return fem::plane_displacement(p.mesh, s.u_m, x); },
         [&](const Eigen::Vector2d& x) { return fem::plane_stress(p.mesh, p.D, s.u_m, x); });
  return run;
}

nlohmann::ordered_json to_json(const CantileverBeam& beam) {
  nlohmann::ordered_json j;
  j["P_N"] = beam.P_N;
  j["L_m"] = beam.L_m;
  j["D_m"] = beam.D_m;
  j["t_m"] = beam.t_m;
  j["E_Pa"] = beam.E_Pa;
  j["nu"] = beam.nu;
  j["clamp"] = "closed-form displacements on x = 0 (chord_vertical: Belytschko, Lu & Gu 1994): the FEM at its nodes, "
               "the EFG weakly along the edge (hat-function averages, efg/constraints.hpp)";
  j["load"] = "parabolic end shear tau_xy = P / (2 I) (D^2/4 - y^2) at x = L";
  return j;
}

nlohmann::ordered_json to_json(const CantileverRun& r) {
  nlohmann::ordered_json j;
  j["method"] = r.method;
  j["nodes"] = r.nodes;
  j["gauss_points"] = r.gauss_points;
  j["dofs"] = r.dofs;
  j["spacing_m"] = r.spacing_m;
  j["displacement_error_L2"] = r.errors.displacement_L2;
  j["energy_error"] = r.errors.energy;
  j["tip_deflection_m"] = r.tip_deflection_m;
  j["exact_tip_deflection_m"] = r.exact_tip_deflection_m;
  j["tip_deflection_error"] = r.errors.tip_deflection;
  if (r.method == "EFG") j["max_condition_number"] = r.max_condition_number;
  j["setup_s"] = r.setup_s;
  j["assembly_s"] = r.assembly_s;
  j["solve_s"] = r.solve_s;
  j["wall_s"] = r.wall_s;
  j["stiffness_nonzeros"] = r.stiffness_nonzeros;
  j["factor_nonzeros"] = r.factor_nonzeros;
  j["memory_estimate_MiB"] = r.memory_estimate_MiB;
  j["solver"] = r.solver;
  if (r.method == "EFG") {
    j["clamp_reaction_N"] = {r.clamp_reaction_N[0], r.clamp_reaction_N[1]};
    j["applied_load_N"] = {r.applied_N[0], r.applied_N[1]};
  }
  return j;
}

CantileverStudy run_cantilever_study(const CantileverBeam& beam, const CantileverOptions& options, bool efg, bool fem,
                                     int refinements) {
  if (refinements < 0 || refinements > 6)
    throw InputError("refinements = " + std::to_string(refinements) + " must lie in [0, 6] (each one quadruples the nodes)");
  if (!efg && !fem) throw InputError("no method chosen: EFG, FEM or both");
  CantileverStudy study;
  study.summary["beam"] = to_json(beam);
  nlohmann::ordered_json opt;
  opt["cells_x"] = options.cells_x;
  opt["cells_y"] = options.cells_y;
  opt["gauss"] = options.gauss;
  opt["efg_clamp"] = options.collocated_clamp ? "collocated at the nodes" : "weak along the edge";
  opt["basis"] = std::string(to_string(options.mls.basis));
  opt["weight"] = std::string(to_string(options.mls.weight));
  if (options.support_count > 0) {
    opt["support_count"] = options.support_count;
    opt["support_factor"] = options.support_factor;
  } else {
    opt["support_scale"] = options.support_scale;
  }
  opt["error_gauss"] = options.error_gauss;
  study.summary["options"] = opt;
  study.table_header = {"method", "cells_x", "cells_y", "nodes", "gauss_points", "spacing_m", "displacement_error_L2",
                        "energy_error", "tip_deflection_error", "wall_s", "memory_estimate_MiB"};
  nlohmann::ordered_json runs = nlohmann::ordered_json::array(), orders = nlohmann::ordered_json::object();
  for (int m = 0; m < 2; ++m) {
    if (!(m == 0 ? efg : fem)) continue;
    std::vector<CantileverRun> these;
    for (int k = 0; k <= refinements; ++k) {
      CantileverOptions o = options;
      o.cells_x <<= k;
      o.cells_y <<= k;
      these.push_back(m == 0 ? run_efg_cantilever(beam, o) : run_fem_cantilever(beam, o));
      const CantileverRun& r = these.back();
      runs.push_back(to_json(r));
      study.table_rows.push_back({r.method, std::to_string(o.cells_x), std::to_string(o.cells_y), std::to_string(r.nodes),
                                  std::to_string(r.gauss_points), format_number(r.spacing_m),
                                  format_number(r.errors.displacement_L2), format_number(r.errors.energy),
                                  format_number(r.errors.tip_deflection), format_number(r.wall_s),
                                  format_number(r.memory_estimate_MiB)});
    }
    nlohmann::ordered_json u = nlohmann::ordered_json::array(), e = nlohmann::ordered_json::array();
    for (std::size_t k = 1; k < these.size(); ++k) {
      u.push_back(std::log2(these[k - 1].errors.displacement_L2 / these[k].errors.displacement_L2));
      e.push_back(std::log2(these[k - 1].errors.energy / these[k].errors.energy));
    }
    orders[these.front().method] = {{"displacement_L2", u}, {"energy", e}};
    study.runs.insert(study.runs.end(), these.begin(), these.end());
  }
  study.summary["runs"] = runs;
  study.summary["orders"] = orders;
  return study;
}

}  // namespace mesowave::efg
