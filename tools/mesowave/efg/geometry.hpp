#pragma once
// Plane geometry of the element-free Galerkin solver (mw-efg): points, segments
// and the crossing test every visibility check of Eq. (13) uses.
#include <Eigen/Core>

namespace mesowave::efg {

using Vec2 = Eigen::Vector2d;

/// An axis-aligned rectangle [x0, x1] x [y0, y1]: a body, a background cell.
struct Rect {
  double x0, y0, x1, y1;
};

/// The straight segment from a to b.
struct Segment {
  Vec2 a, b;
};

/// z-component of (b - a) x (c - a): > 0 when c lies left of the line a -> b.
double orientation(const Vec2& a, const Vec2& b, const Vec2& c);

/// True when the open segments p and q cross (touching at an end point counts as crossing when
/// `ends_count`): the test every visibility check uses. Collinear overlapping segments count as
/// crossing when `ends_count` (a crack face seen edge-on hides what lies along it).
bool segments_cross(const Segment& p, const Segment& q, bool ends_count = true);

/// Parameter t in [0, 1] of the point p.a + t (p.b - p.a) where the lines of p and q meet; the
/// caller has checked that they cross and are not parallel.
double crossing_parameter(const Segment& p, const Segment& q);

}  // namespace mesowave::efg
