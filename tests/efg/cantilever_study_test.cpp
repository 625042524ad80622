// The cantilever study (efg/cantilever_study): the Q4 FEM converges to the closed form with order 2
// in displacement and 1 in energy on the error measure the EFG uses, the EFG beats it at equal nodes,
// and the study's orders and table are what its runs give.
#include <gtest/gtest.h>

#include <cmath>

#include "mesowave/efg/cantilever_study.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::efg;

TEST(CantileverStudy, FemConvergesAndTheEfgIsMoreAccurateAtEqualNodes) {
  CantileverSetup s;
  s.cells_x = 8;
  s.cells_y = 2;
  const CantileverStudy study = run_cantilever_study(s, true, true, 2);
  ASSERT_EQ(study.runs.size(), 6u);
  ASSERT_EQ(study.table_rows.size(), 6u);
  const auto& fem_orders = study.summary["orders"]["Q4 FEM"];
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_NEAR(fem_orders["displacement_L2"][k].get<double>(), 2.0, 0.2) << k;
    EXPECT_NEAR(fem_orders["energy"][k].get<double>(), 1.0, 0.1) << k;
    const auto& fine = study.runs[4 + k], &coarse = study.runs[3 + k];
    EXPECT_DOUBLE_EQ(fem_orders["displacement_L2"][k].get<double>(),
                     std::log2(coarse.errors.displacement_L2 / fine.errors.displacement_L2));
  }
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(study.runs[k].method, "EFG");
    EXPECT_EQ(study.runs[k + 3].method, "Q4 FEM");
    EXPECT_EQ(study.runs[k].nodes, study.runs[k + 3].nodes);
    EXPECT_LT(study.runs[k].errors.displacement_L2, study.runs[k + 3].errors.displacement_L2);
  }
  EXPECT_EQ(study.runs[5].snapshot.positions_m.size(), 33u * 9u);
  EXPECT_EQ(study.runs[5].snapshot.stress_Pa.size(), 33u * 9u);
  EXPECT_NE(test::input_error_of([&] { run_cantilever_study(s, true, true, 7); }).find("refinements (7)"), std::string::npos);
  EXPECT_NE(test::input_error_of([&] { run_cantilever_study(s, false, false, 0); }).find("no method"), std::string::npos);
}
