// Timoshenko & Goodier's cantilever under a parabolic end shear (plane stress, Belytschko, Lu & Gu's
// beam L = 48, D = 12): the EFG solution against the closed form (efg/beam_theory.hpp) as the node
// spacing halves three times. With a linear basis the displacement error falls as h^2 and the
// energy-norm (stress) error as h: the measured orders are asserted, and the clamp's reactions
// balance the end load.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mesowave/efg/cantilever.hpp"

using namespace mesowave;
using namespace mesowave::efg;

namespace {

CantileverRun at_level(int level, int gauss = 2) {
  CantileverSetup s;
  s.cells_x = 16 << level;
  s.cells_y = 4 << level;
  s.gauss = gauss;
  return solve_cantilever(s);
}

void print(const char* label, const CantileverRun& r) {
  std::printf("%s h = %5.3f  nodes %5zu  points %6zu  L2(u) %.3e  energy %.3e  tip %+.3e  factor nnz %zu  %.3f s\n",
              label, r.spacing_m, r.nodes, r.gauss_points, r.error.displacement_L2, r.error.energy,
              r.error.tip_deflection, r.factor_nonzeros, r.wall_s);
}

}  // namespace

TEST(Cantilever, ConvergesAtOrderTwoInDisplacementAndOneInStress) {
  std::vector<CantileverRun> runs;
  for (int level = 0; level < 3; ++level) {
    runs.push_back(at_level(level));
    print("2x2", runs.back());
  }
  for (std::size_t k = 1; k < runs.size(); ++k) {
    const double order_u = std::log2(runs[k - 1].error.displacement_L2 / runs[k].error.displacement_L2);
    const double order_e = std::log2(runs[k - 1].error.energy / runs[k].error.energy);
    std::printf("orders %zu -> %zu: displacement %.2f, energy %.2f\n", k - 1, k, order_u, order_e);
    EXPECT_GT(order_u, 1.8) << k;
    EXPECT_GT(order_e, 0.9) << k;
  }
  EXPECT_LT(runs.back().error.displacement_L2, 1e-4);
  EXPECT_LT(runs.back().error.energy, 1e-2);
  EXPECT_LT(std::abs(runs.back().error.tip_deflection), 1e-4);
}

TEST(Cantilever, ClampReactionsBalanceTheEndLoad) {
  const CantileverRun r = at_level(1);
  const double P = CantileverBeam{}.P_N;
  EXPECT_NEAR(r.applied_N[1], P, 1e-9 * P);  // the parabola integrates exactly
  EXPECT_NEAR(r.applied_N[0], 0, 1e-9 * P);
  EXPECT_LE(std::abs(r.reaction_N[0] + r.applied_N[0]), 1e-9 * P);
  EXPECT_LE(std::abs(r.reaction_N[1] + r.applied_N[1]), 1e-9 * P);
}
