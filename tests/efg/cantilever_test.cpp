// The elastic validation (efg/cantilever): the EFG and the Q4 FEM on Timoshenko & Goodier's
// cantilever against the closed form as the node spacing halves - the convergence orders measured -
// and the two methods side by side on the same cells. With a linear basis the EFG's displacement
// error falls as h^2 and its energy-norm (stress) error as h once the clamp is held weakly along the
// edge; collocated at the edge's nodes it loses both orders. The clamp's reactions balance the load.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mesowave/efg/cantilever.hpp"

using namespace mesowave::efg;

TEST(Cantilever, EfgAndFemConvergeToTheClosedForm) {
  const CantileverBeam beam;
  std::vector<CantileverRun> efg, fem;
  for (int k : {1, 2, 4}) {
    CantileverOptions o;
    o.cells_x = 8 * k;
    o.cells_y = 2 * k;
    efg.push_back(run_efg_cantilever(beam, o));
    fem.push_back(run_fem_cantilever(beam, o));
  }
  for (std::size_t i = 0; i < efg.size(); ++i)
    std::printf("%zu nodes: EFG u %.3e energy %.3e tip %.2e | FEM u %.3e energy %.3e tip %.2e | cond %.1e\n",
                efg[i].nodes, efg[i].errors.displacement_L2, efg[i].errors.energy, efg[i].errors.tip_deflection,
                fem[i].errors.displacement_L2, fem[i].errors.energy, fem[i].errors.tip_deflection,
                efg[i].max_condition_number);
  for (std::size_t i = 1; i < efg.size(); ++i) {
    EXPECT_GT(std::log2(efg[i - 1].errors.displacement_L2 / efg[i].errors.displacement_L2), 1.5);
    EXPECT_GT(std::log2(fem[i - 1].errors.displacement_L2 / fem[i].errors.displacement_L2), 1.8);
  }
  // The energy error's order over both halvings (still pre-asymptotic on these coarse cells).
  EXPECT_GT(0.5 * std::log2(efg[0].errors.energy / efg[2].errors.energy), 0.8);
  // At equal nodes the EFG (linear basis, supports 2.5 spacings) is the more accurate.
  for (std::size_t i = 0; i < efg.size(); ++i) EXPECT_LT(efg[i].errors.displacement_L2, fem[i].errors.displacement_L2);
  EXPECT_EQ(efg[0].nodes, fem[0].nodes);
  EXPECT_EQ(efg[0].nodes, 9u * 3u);
  EXPECT_EQ(efg[0].gauss_points, 8u * 2u * 4u);
}

namespace {

CantileverRun efg_at_level(int level, bool collocated_clamp = false) {
  CantileverOptions o;
  o.cells_x = 16 << level;
  o.cells_y = 4 << level;
  o.collocated_clamp = collocated_clamp;
  return run_efg_cantilever(CantileverBeam{}, o);
}

}  // namespace

TEST(Cantilever, EfgConvergesAtOrderTwoInDisplacementAndOneInStress) {
  // 16 x 4, 32 x 8, 64 x 16 cells (85, 297, 1105 nodes), 2 x 2 Gauss points, supports 2.5 h
  std::vector<CantileverRun> runs;
  for (int level = 0; level < 3; ++level) {
    runs.push_back(efg_at_level(level));
    std::printf("h = %5.3f  nodes %5zu  L2(u) %.3e  energy %.3e  tip %+.3e\n", runs.back().spacing_m, runs.back().nodes,
                runs.back().errors.displacement_L2, runs.back().errors.energy, runs.back().errors.tip_deflection);
  }
  for (std::size_t k = 1; k < runs.size(); ++k) {
    const double order_u = std::log2(runs[k - 1].errors.displacement_L2 / runs[k].errors.displacement_L2);
    const double order_e = std::log2(runs[k - 1].errors.energy / runs[k].errors.energy);
    std::printf("orders %zu -> %zu: displacement %.2f, energy %.2f\n", k - 1, k, order_u, order_e);
    EXPECT_GT(order_u, 1.8) << k;
    EXPECT_GT(order_e, 0.9) << k;
  }
  EXPECT_LT(runs.back().errors.displacement_L2, 1e-4);
  EXPECT_LT(runs.back().errors.energy, 1e-2);
  EXPECT_LT(std::abs(runs.back().errors.tip_deflection), 1e-4);
  // collocated at the clamp's nodes the same run is worse in both norms
  const CantileverRun collocated = efg_at_level(2, true);
  EXPECT_GT(collocated.errors.energy, 1.5 * runs.back().errors.energy);
}

TEST(Cantilever, ClampReactionsBalanceTheEndLoad) {
  for (bool collocated : {false, true}) {
    const CantileverRun r = efg_at_level(1, collocated);
    const double P = CantileverBeam{}.P_N;
    EXPECT_NEAR(r.applied_N[1], P, 1e-9 * P);  // the parabola integrates exactly
    EXPECT_NEAR(r.applied_N[0], 0, 1e-9 * P);
    EXPECT_LE(std::abs(r.clamp_reaction_N[0] + r.applied_N[0]), 1e-9 * P);
    EXPECT_LE(std::abs(r.clamp_reaction_N[1] + r.applied_N[1]), 1e-9 * P);
  }
}
