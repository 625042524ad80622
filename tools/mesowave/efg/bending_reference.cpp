#include "mesowave/efg/bending_reference.hpp"

#include <algorithm>
#include <cmath>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/efg/beam_theory.hpp"
#include "mesowave/efg/material.hpp"
#include "mesowave/fem/plane_static.hpp"

namespace mesowave::efg {

namespace {

double fem_stiffness(const ThreePointBendingOptions& o, int cells_x, int cells_y, double notch_m, std::size_t* nodes) {
  fem::PlaneStaticProblem p;
  const double mid = 0.5 * o.span_m;
  p.mesh = fem::structured_plane_mesh({0, 0, o.span_m, o.depth_m, cells_x, cells_y, notch_m > 0 ? o.notch_position_m() : 0, notch_m});
  p.D = ElasticMaterial2D{o.E_Pa, o.nu, o.thickness_m, 0, PlaneState::plane_stress}.D();
  p.thickness_m = o.thickness_m;
  const double half_plate = 0.5 * o.load_width_m;
  p.constraints = {{{0, 0}, 1, 0, "left support u_y"},
                   {{0, 0}, 0, 0, "left support u_x"},
                   {{o.span_m, 0}, 1, 0, "right support u_y"},
                   {{mid - half_plate, o.depth_m}, 1, -1.0, "load point left u_y"},
                   {{mid + half_plate, o.depth_m}, 1, -1.0, "load point right u_y"}};
  const auto s = fem::solve_plane_static(p);
  *nodes = p.mesh.nodes.size();
  return -(s.reactions_N[3] + s.reactions_N[4]) / 1.0;  // the force the plate applies, per metre of deflection
}

}  // namespace

BendingReference three_point_bending_reference(const ThreePointBendingOptions& o, int refinement) {
  o.validate();
  if (refinement < 1) throw InputError("FEM refinement " + std::to_string(refinement) + " must be >= 1");
  // Cells of load_width / (2 refinement): mid-span and the two load points are nodes.
  BendingReference r;
  const double dx = 0.5 * o.load_width_m / refinement;
  r.fem_cells_x = int(std::lround(o.span_m / dx));
  if (std::abs(r.fem_cells_x * dx - o.span_m) > 1e-9 * o.span_m || r.fem_cells_x % 2 != 0)
    throw InputError("the FEM reference needs the span (" + format_number(o.span_m * 1e3) +
                     " mm) to be an even multiple of half the load width (" + format_number(0.5 * o.load_width_m * 1e3) +
                     " mm)");
  const int notch_rows = std::max(1, int(std::lround(o.notch_m / dx)));
  r.fem_cells_y = std::max(2, int(std::lround(o.depth_m / (o.notch_m / notch_rows))));
  std::size_t unnotched_nodes = 0;
  r.fem_notched_N_per_m = fem_stiffness(o, r.fem_cells_x, r.fem_cells_y, o.notch_m, &r.fem_nodes);
  r.fem_unnotched_N_per_m = fem_stiffness(o, r.fem_cells_x, r.fem_cells_y, 0, &unnotched_nodes);
  const double beam = three_point_bending_deflection_m(1.0, o.span_m, o.depth_m, o.thickness_m, o.E_Pa, o.nu);
  r.beam_theory_N_per_m = 1.0 / beam;
  // an eccentric notch: the moment at it over the moment at mid-span, squared (the header)
  const double x = o.notch_position_m(), moment_ratio = std::min(x, o.span_m - x) / (0.5 * o.span_m);
  r.beam_theory_notched_N_per_m =
      1.0 / (beam + moment_ratio * moment_ratio *
                        three_point_bending_notch_deflection_m(1.0, o.span_m, o.depth_m, o.notch_m, o.thickness_m, o.E_Pa));
  return r;
}

}  // namespace mesowave::efg
