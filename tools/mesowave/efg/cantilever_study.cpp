#include "mesowave/efg/cantilever_study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/efg/material.hpp"
#include "mesowave/fem/plane_static.hpp"

namespace mesowave::efg {

namespace {

constexpr double kMiB = 1024.0 * 1024.0;

double matrix_MiB(std::size_t K_nonzeros, std::size_t factor_nonzeros) {
  return 12.0 * double(K_nonzeros + factor_nonzeros) / kMiB;
}

nlohmann::ordered_json to_json(const CantileverMethodRun& r) {
  nlohmann::ordered_json j;
  j["method"] = r.method;
  j["cells"] = std::to_string(r.cells_x) + " x " + std::to_string(r.cells_y);
  j["nodes"] = r.nodes;
  j["gauss_points"] = r.gauss_points;
  j["dofs"] = r.dofs;
  j["spacing_m"] = r.spacing_m;
  j["displacement_error_L2"] = r.errors.displacement_L2;
  j["energy_error"] = r.errors.energy;
  j["tip_deflection_error"] = r.errors.tip_deflection;
  j["solution_s"] = r.solution_s;
  j["wall_s"] = r.wall_s;
  j["stiffness_nonzeros"] = r.stiffness_nonzeros;
  j["factor_nonzeros"] = r.factor_nonzeros;
  j["matrix_MiB"] = r.matrix_MiB;
  j["solver"] = r.solver;
  return j;
}

}  // namespace

CantileverMethodRun run_fem_cantilever(const CantileverSetup& setup) {
  const auto t0 = std::chrono::steady_clock::now();
  const CantileverBeam& beam = setup.beam;
  ElasticMaterial2D material{beam.E_Pa, beam.nu, beam.t_m, 0, PlaneState::plane_stress};
  material.validate();
  fem::PlaneStaticProblem p;
  p.mesh = fem::structured_plane_mesh({0, -beam.D_m / 2, beam.L_m, beam.D_m, setup.cells_x, setup.cells_y});
  p.D = material.D();
  p.thickness_m = beam.t_m;
  for (auto n : p.mesh.nodes_on_segment({0, -beam.D_m / 2}, {0, beam.D_m / 2})) {
    const Eigen::Vector2d x = p.mesh.nodes[std::size_t(n)], u = beam.at(x).u_m;
    p.constraints.push_back({x, 0, u.x(), "clamp u_x"});
    p.constraints.push_back({x, 1, u.y(), "clamp u_y"});
  }
  p.edge_loads.push_back({{beam.L_m, -beam.D_m / 2}, {beam.L_m, beam.D_m / 2}, [&](const Eigen::Vector2d& x) {
                            const Eigen::Vector3d s = beam.at(x).stress_Pa;
                            return Eigen::Vector2d(s(0), s(2));  // sigma n, n = +x
                          }});
  const fem::PlaneStaticSolution s = fem::solve_plane_static(p);
  const double solution_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  auto u = [&](const Eigen::Vector2d& x) { return fem::plane_displacement(p.mesh, s.u_m, x); };
  auto stress = [&](const Eigen::Vector2d& x) { return fem::plane_stress(p.mesh, p.D, s.u_m, x); };
  CantileverMethodRun r;
  r.method = "Q4 FEM";
  r.solution_s = solution_s;
  r.cells_x = setup.cells_x;
  r.cells_y = setup.cells_y;
  r.errors = cantilever_errors(beam, u, stress, setup.cells_x, setup.cells_y, setup.error_gauss);
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.nodes = p.mesh.nodes.size();
  r.gauss_points = 4 * p.mesh.quads.size();
  r.dofs = p.mesh.dof_count();
  r.spacing_m = std::max(p.mesh.dx_m, p.mesh.dy_m);
  r.stiffness_nonzeros = s.stiffness_nonzeros;
  r.factor_nonzeros = s.factor_nonzeros;
  r.matrix_MiB = matrix_MiB(s.stiffness_nonzeros, s.factor_nonzeros);
  r.solver = s.solver;
  r.snapshot.positions_m = p.mesh.nodes;
  r.snapshot.displacement_m.assign(s.u_m.size() / 2, Eigen::Vector2d::Zero());
  for (std::size_t n = 0; n < p.mesh.nodes.size(); ++n) r.snapshot.displacement_m[n] = s.u_m.segment<2>(2 * Eigen::Index(n));
  r.snapshot.stress_Pa = fem::plane_nodal_stress(p.mesh, p.D, s.u_m);
  return r;
}

CantileverMethodRun run_efg_cantilever(const CantileverSetup& setup) {
  const CantileverRun e = solve_cantilever(setup);
  CantileverMethodRun r;
  r.method = "EFG";
  r.cells_x = setup.cells_x;
  r.cells_y = setup.cells_y;
  r.nodes = e.nodes;
  r.gauss_points = e.gauss_points;
  r.dofs = e.dofs;
  r.spacing_m = e.spacing_m;
  r.errors = e.error;
  r.solution_s = e.shape_s + e.assemble_s + e.factorise_s + e.solve_s;
  r.wall_s = e.wall_s;
  r.stiffness_nonzeros = e.reduced_nonzeros;
  r.factor_nonzeros = e.factor_nonzeros;
  r.matrix_MiB = matrix_MiB(e.reduced_nonzeros, e.factor_nonzeros);
  r.solver = e.solver;
  return r;
}

CantileverStudy run_cantilever_study(const CantileverSetup& setup, bool efg, bool fem, int refinements) {
  if (refinements < 0 || refinements > 6)
    throw InputError("refinements (" + std::to_string(refinements) + ") must lie in [0, 6]: each quadruples the nodes");
  if (!efg && !fem) throw InputError("no method chosen: EFG, FEM or both");
  CantileverStudy study;
  const CantileverBeam& beam = setup.beam;
  study.summary["beam"] = {{"P_N", beam.P_N}, {"L_m", beam.L_m}, {"D_m", beam.D_m}, {"t_m", beam.t_m},
                           {"E_Pa", beam.E_Pa}, {"nu", beam.nu},
                           {"load", "the closed form's traction (sigma_xx, tau_xy) at x = L"},
                           {"clamp", "the closed form's displacements on x = 0 (EFG: " +
                                         std::string(setup.collocated_clamp ? "collocated at the nodes" : "weakly, hat-function averages") +
                                         "; FEM: at the nodes)"}};
  study.summary["options"] = {{"cells", std::to_string(setup.cells_x) + " x " + std::to_string(setup.cells_y)},
                              {"gauss", setup.gauss},
                              {"basis", std::string(to_string(setup.mls.basis))},
                              {"weight", std::string(to_string(setup.mls.weight))},
                              {"support_scale", setup.support_scale},
                              {"error_gauss", setup.error_gauss}};
  study.table_header = {"method", "cells_x", "cells_y", "nodes", "gauss_points", "spacing_m", "displacement_error_L2",
                        "energy_error", "tip_deflection_error", "solution_s", "wall_s", "matrix_MiB"};
  nlohmann::ordered_json runs = nlohmann::ordered_json::array(), orders = nlohmann::ordered_json::object();
  for (int m = 0; m < 2; ++m) {
    if (!(m == 0 ? efg : fem)) continue;
    std::vector<CantileverMethodRun> these;
    for (int k = 0; k <= refinements; ++k) {
      CantileverSetup s = setup;
      s.cells_x <<= k;
      s.cells_y <<= k;
      these.push_back(m == 0 ? run_efg_cantilever(s) : run_fem_cantilever(s));
      const CantileverMethodRun& r = these.back();
      runs.push_back(to_json(r));
      study.table_rows.push_back({r.method, std::to_string(r.cells_x), std::to_string(r.cells_y), std::to_string(r.nodes),
                                  std::to_string(r.gauss_points), format_number(r.spacing_m),
                                  format_number(r.errors.displacement_L2), format_number(r.errors.energy),
                                  format_number(r.errors.tip_deflection), format_number(r.solution_s),
                                  format_number(r.wall_s),
                                  format_number(r.matrix_MiB)});
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
