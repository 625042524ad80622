// The segment crossing test behind every visibility check (efg/geometry.hpp), case by case.
#include <gtest/gtest.h>

#include "mesowave/efg/geometry.hpp"

using namespace mesowave::efg;

TEST(Geometry, SegmentsCrossCaseByCase) {
  const Segment horizontal{{0, 0}, {2, 0}};
  EXPECT_TRUE(segments_cross(horizontal, {{1, -1}, {1, 1}}));          // X
  EXPECT_TRUE(segments_cross(horizontal, {{1, -1}, {1, 1}}, false));
  EXPECT_FALSE(segments_cross(horizontal, {{3, -1}, {3, 1}}));         // beyond the end
  EXPECT_FALSE(segments_cross(horizontal, {{1, 0.5}, {1, 1}}));        // above
  EXPECT_TRUE(segments_cross(horizontal, {{1, 0}, {1, 1}}));           // T: touches the inside
  EXPECT_FALSE(segments_cross(horizontal, {{1, 0}, {1, 1}}, false));
  EXPECT_TRUE(segments_cross(horizontal, {{2, -1}, {2, 1}}));          // through the end point
  EXPECT_FALSE(segments_cross(horizontal, {{2, -1}, {2, 1}}, false));
  EXPECT_TRUE(segments_cross(horizontal, {{1, 0}, {3, 0}}));           // collinear overlap
  EXPECT_FALSE(segments_cross(horizontal, {{1, 0}, {3, 0}}, false));
  EXPECT_FALSE(segments_cross(horizontal, {{2.5, 0}, {3, 0}}));        // collinear, apart
  EXPECT_FALSE(segments_cross(horizontal, {{0, 1}, {2, 1}}));          // parallel
  EXPECT_TRUE(segments_cross({{0, 0}, {1, 1}}, {{0, 1}, {1, 0}}));     // diagonals
  EXPECT_GT(orientation({0, 0}, {1, 0}, {0.5, 1}), 0);                 // left of a -> b
}

TEST(Geometry, CrossingParameterIsWhereTheLinesMeet) {
  EXPECT_DOUBLE_EQ(crossing_parameter({{0, 0}, {4, 0}}, {{1, -1}, {1, 3}}), 0.25);
  EXPECT_DOUBLE_EQ(crossing_parameter({{0, 0}, {2, 2}}, {{0, 2}, {2, 0}}), 0.5);
}
