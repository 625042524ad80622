#pragma once
// A box of sphere centres as the ranks send them to each other (a block's, a rank's): six
// doubles, low x, y, z then high x, y, z. The setup's layer (SpherePart) and the ghost layer
// (SphereSystem::spheres_near_own) both ask which spheres or blocks come within a reach of
// another rank's boxes; a point is the box whose low and high corners are the point.
#include <algorithm>
#include <limits>

namespace mesowave::dem {

/// The empty box: the first point or box it grows by is the box.
inline void clear_box(double* box) {
  for (int d = 0; d < 3; ++d) box[d] = std::numeric_limits<double>::infinity(), box[3 + d] = -box[d];
}

/// Grow `box` to hold the box `other` (low and high at other[0..2] and other[3..5]).
inline void grow_box(double* box, const double* other) {
  for (int d = 0; d < 3; ++d) box[d] = std::min(box[d], other[d]), box[3 + d] = std::max(box[3 + d], other[3 + d]);
}

/// Grow `box` to hold the point x.
inline void grow_box_by_point(double* box, const double* x) {
  for (int d = 0; d < 3; ++d) box[d] = std::min(box[d], x[d]), box[3 + d] = std::max(box[3 + d], x[d]);
}

/// Whether the gap between boxes a and b (0 where they meet) is at most reach_m.
inline bool boxes_within(const double* a, const double* b, double reach_m) {
  double gap2 = 0;
  for (int d = 0; d < 3; ++d) {
    const double gap = std::max({0.0, b[d] - a[3 + d], a[d] - b[3 + d]});
    gap2 += gap * gap;
  }
  return gap2 <= reach_m * reach_m;
}

}  // namespace mesowave::dem
