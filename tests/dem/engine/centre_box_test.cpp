// Boxes of centres (dem/engine/centre_box.hpp): growth against the extremes of the points put
// in, and the reach test against the closed-form Euclidean gap between boxes (a 3-4-5 triangle
// between corners, a face-to-face gap, overlapping boxes) on either side of the reach.
#include <gtest/gtest.h>

#include <cmath>

#include "mesowave/dem/engine/centre_box.hpp"

using namespace mesowave::dem;

TEST(CentreBox, AGrownBoxSpansItsPointsAndBoxes) {
  double box[6];
  clear_box(box);
  const double a[3] = {1.0, -2.0, 0.5}, b[3] = {-1.0, 3.0, 0.25};
  grow_box_by_point(box, a);
  for (int d = 0; d < 3; ++d) {  // one point: itself
    EXPECT_EQ(box[d], a[d]);
    EXPECT_EQ(box[3 + d], a[d]);
  }
  grow_box_by_point(box, b);
  const double spanned[6] = {-1.0, -2.0, 0.25, 1.0, 3.0, 0.5};
  for (int d = 0; d < 6; ++d) EXPECT_EQ(box[d], spanned[d]);
  double all[6];
  clear_box(all);
  const double other[6] = {0.0, 0.0, -4.0, 0.0, 7.0, 0.0};
  grow_box(all, box);
  grow_box(all, other);
  const double both[6] = {-1.0, -2.0, -4.0, 1.0, 7.0, 0.5};
  for (int d = 0; d < 6; ++d) EXPECT_EQ(all[d], both[d]);
}

TEST(CentreBox, BoxesAreWithinReachByTheirEuclideanGap) {
  const double unit[6] = {0, 0, 0, 1, 1, 1};
  const double corner[6] = {4, 5, 0.5, 4, 5, 0.5};  // from the corner (1, 1, z): 3 along x, 4 along y, gap 5
  EXPECT_TRUE(boxes_within(corner, unit, 5.0));
  EXPECT_TRUE(boxes_within(unit, corner, 5.0));
  EXPECT_FALSE(boxes_within(corner, unit, std::nextafter(5.0, 0.0)));
  const double beside[6] = {-2.5, 0.2, 0.2, -2.0, 0.8, 0.8};  // a face 2 from the unit box's x = 0
  EXPECT_TRUE(boxes_within(beside, unit, 2.0));
  EXPECT_FALSE(boxes_within(beside, unit, 1.99));
  const double overlapping[6] = {0.5, 0.5, 0.5, 3, 3, 3};
  EXPECT_TRUE(boxes_within(overlapping, unit, 0.0));
}
