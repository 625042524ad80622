// The elastic references of the notched three-point bending beam: the Q4 FEM of the plain and the
// notched beam against Timoshenko beam theory (bending + shear) and against beam theory plus the
// notch's fracture-mechanics compliance (Tada). Beam theory knows no local indentation under the
// point loads and supports: the FEM is softer, and the more so the finer its mesh (the 2D point
// load's log singularity). The notch's own compliance, the difference of the two FEM beams, has no
// such term to first order and is compared directly.
#include <gtest/gtest.h>

#include <cstdio>

#include "mesowave/efg/beam_theory.hpp"
#include "mesowave/efg/bending_reference.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::efg;

TEST(BendingReference, FemAgainstBeamTheoryAndTheNotch) {
  ThreePointBendingOptions o;  // Koermeling and Reinhardt's beam
  o.spacing_m = 0.01;          // the FEM follows the load width (10 mm), not the EFG spacing
  std::vector<BendingReference> r;
  for (int k : {1, 2}) {
    r.push_back(three_point_bending_reference(o, k));
    const auto& b = r.back();
    std::printf("refinement %d (%d x %d, %zu nodes): beam %.4g N/mm, FEM %.4g; notched: beam + LEFM %.4g, FEM %.4g\n", k,
                b.fem_cells_x, b.fem_cells_y, b.fem_nodes, b.beam_theory_N_per_m * 1e-3, b.fem_unnotched_N_per_m * 1e-3,
                b.beam_theory_notched_N_per_m * 1e-3, b.fem_notched_N_per_m * 1e-3);
  }
  EXPECT_EQ(r[0].fem_cells_x, 90);
  EXPECT_EQ(r[0].fem_cells_y, 20);
  EXPECT_EQ(r[1].fem_cells_x, 180);
  for (const auto& b : r) {
    EXPECT_LT(b.fem_unnotched_N_per_m, b.beam_theory_N_per_m);
    EXPECT_GT(b.fem_unnotched_N_per_m, 0.75 * b.beam_theory_N_per_m);
    EXPECT_LT(b.fem_notched_N_per_m, b.beam_theory_notched_N_per_m);
    EXPECT_GT(b.fem_notched_N_per_m, 0.75 * b.beam_theory_notched_N_per_m);
    const double notch_fem = 1 / b.fem_notched_N_per_m - 1 / b.fem_unnotched_N_per_m;
    const double notch_lefm = three_point_bending_notch_deflection_m(1, o.span_m, o.depth_m, o.notch_m, o.thickness_m, o.E_Pa);
    EXPECT_NEAR(notch_fem / notch_lefm, 1.0, 0.12);  // Tada's fit is for S/W = 4, this beam has 4.5
  }
  EXPECT_LT(r[1].fem_notched_N_per_m, r[0].fem_notched_N_per_m);  // the load points' indentation
  EXPECT_GT(r[1].fem_notched_N_per_m, 0.95 * r[0].fem_notched_N_per_m);
  EXPECT_NE(test::input_error_of([&] { three_point_bending_reference(o, 0); }).find("refinement 0"), std::string::npos);
}
