// The elastic validation (efg/cantilever): the EFG and the Q4 FEM on Timoshenko & Goodier's
// cantilever against the closed form as the node spacing halves - the convergence orders measured -
// and the two methods side by side on the same cells.
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
  // The energy error of the EFG with 2 x 2 Gauss points levels off (the integration error of the
  // rational shape functions, the paper's Fig. 4): its order over both halvings.
  EXPECT_GT(0.5 * std::log2(efg[0].errors.energy / efg[2].errors.energy), 0.8);
  // At equal nodes the EFG (linear basis, supports 2.5 spacings) is the more accurate.
  for (std::size_t i = 0; i < efg.size(); ++i) EXPECT_LT(efg[i].errors.displacement_L2, fem[i].errors.displacement_L2);
  EXPECT_EQ(efg[0].nodes, fem[0].nodes);
  EXPECT_EQ(efg[0].nodes, 9u * 3u);
  EXPECT_EQ(efg[0].gauss_points, 8u * 2u * 4u);
}
