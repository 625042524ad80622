#include "mesowave/efg/geometry.hpp"

#include <algorithm>

namespace mesowave::efg {

double orientation(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

namespace {

// c on the segment a-b, given that the three are collinear.
bool within_box(const Vec2& a, const Vec2& b, const Vec2& c) {
  return std::min(a.x(), b.x()) <= c.x() && c.x() <= std::max(a.x(), b.x()) &&
         std::min(a.y(), b.y()) <= c.y() && c.y() <= std::max(a.y(), b.y());
}

}  // namespace

bool segments_cross(const Segment& p, const Segment& q, bool ends_count) {
  const double o1 = orientation(p.a, p.b, q.a), o2 = orientation(p.a, p.b, q.b);
  const double o3 = orientation(q.a, q.b, p.a), o4 = orientation(q.a, q.b, p.b);
  if (!ends_count) return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
  if (o1 == 0 && within_box(p.a, p.b, q.a)) return true;
  if (o2 == 0 && within_box(p.a, p.b, q.b)) return true;
  if (o3 == 0 && within_box(q.a, q.b, p.a)) return true;
  if (o4 == 0 && within_box(q.a, q.b, p.b)) return true;
  return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

double crossing_parameter(const Segment& p, const Segment& q) {
  const Vec2 r = p.b - p.a, s = q.b - q.a, qp = q.a - p.a;
  const double denom = r.x() * s.y() - r.y() * s.x();
  return std::clamp((qp.x() * s.y() - qp.y() * s.x()) / denom, 0.0, 1.0);
}

}  // namespace mesowave::efg
