// Cell-list neighbour search (efg/node_grid.hpp) against the brute-force answer.
#include <gtest/gtest.h>

#include <algorithm>

#include "mesowave/core/random.hpp"
#include "mesowave/efg/node_grid.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::efg;

TEST(NodeGrid, WithinIsTheBruteForceAnswerAscending) {
  Mt64Random random(11);
  std::vector<Vec2> nodes;
  for (int i = 0; i < 500; ++i) nodes.emplace_back(random.uniform(-0.2, 0.3), random.uniform(0.0, 0.1));
  for (const double cell : {0.004, 0.02, 0.3, 1e-7}) {  // 1e-7: enlarged, not 10^13 cells
    const NodeGrid grid(nodes, cell);
    EXPECT_GE(grid.cell_size(), cell);
    for (int q = 0; q < 50; ++q) {
      const Vec2 x(random.uniform(-0.3, 0.4), random.uniform(-0.1, 0.2));
      const double r = random.uniform(0.0, 0.08);
      std::vector<std::int32_t> expected;
      for (std::size_t i = 0; i < nodes.size(); ++i)
        if ((nodes[i] - x).norm() <= r) expected.push_back(std::int32_t(i));
      EXPECT_EQ(grid.within(x, r), expected) << "cell " << cell << " query " << q;
    }
  }
  const NodeGrid grid(nodes, 0.02);
  EXPECT_EQ(grid.within(Vec2(5, 5), 0.1).size(), 0u);
  EXPECT_EQ(grid.within(Vec2(0, 0), 10).size(), nodes.size());
}

TEST(NodeGrid, BadInputIsNamed) {
  EXPECT_NE(test::input_error_of([] { NodeGrid({Vec2(0, 0)}, 0.0); }).find("cell size (0 m)"), std::string::npos);
  EXPECT_NE(test::input_error_of([] { NodeGrid({Vec2(0, 0), Vec2(NAN, 1)}, 1.0); }).find("node 1"), std::string::npos);
  const NodeGrid empty({}, 1.0);
  EXPECT_TRUE(empty.within(Vec2(0, 0), 1).empty());
}
