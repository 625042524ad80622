#include "mesowave/efg/crater.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/efg/node_grid.hpp"

namespace mesowave::efg {

namespace {

struct UnionFind {
  std::vector<std::size_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t(0)); }
  std::size_t find(std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(std::size_t a, std::size_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);  // the root is the piece's lowest index
  }
};

struct Box {
  double x0, y0, x1, y1;
};
Box box_of(const Segment& s) {
  return {std::min(s.a.x(), s.b.x()), std::min(s.a.y(), s.b.y()), std::max(s.a.x(), s.b.x()), std::max(s.a.y(), s.b.y())};
}
bool boxes_meet(const Box& p, const Box& q) { return p.x0 <= q.x1 && q.x0 <= p.x1 && p.y0 <= q.y1 && q.y0 <= p.y1; }

}  // namespace

void CraterInput::validate() const {
  if (area_m2.size() != x.size() || min_eps_v.size() != x.size())
    throw InputError("crater: " + std::to_string(x.size()) + " points but " + std::to_string(area_m2.size()) + " areas and " +
                     std::to_string(min_eps_v.size()) + " strains");
  require_positive("crater link radius", link_radius_m, "m");
  require_positive("crushing volumetric strain", crushing_eps_v);
}

double default_crushing_eps_v(const HugoniotParameters& p) { return std::abs(hugoniot_Y_minimum(p).eps_v); }

CraterMeasure measure_crater(const CraterInput& in) {
  in.validate();
  const std::size_t n = in.x.size();
  CraterMeasure m;
  m.label.assign(n, CraterLabel::intact);
  if (n == 0) return m;

  // the links: pairs within the link radius that no open segment separates
  std::vector<Box> cut_boxes;
  for (const Segment& s : in.open_segments) cut_boxes.push_back(box_of(s));
  const NodeGrid grid(in.x, in.link_radius_m);
  std::vector<std::vector<std::size_t>> links(n);
  std::vector<std::int32_t> near;
  for (std::size_t i = 0; i < n; ++i) {
    grid.within(in.x[i], in.link_radius_m, near);
    for (const std::int32_t j32 : near) {
      const std::size_t j = std::size_t(j32);
      if (j <= i) continue;
      const Segment link{in.x[i], in.x[j]};
      const Box lb = box_of(link);
      bool cut = false;
      for (std::size_t c = 0; c < in.open_segments.size() && !cut; ++c)
        cut = boxes_meet(lb, cut_boxes[c]) && segments_cross(link, in.open_segments[c]);
      if (cut) continue;
      links[i].push_back(j);
      links[j].push_back(i);
    }
  }

  UnionFind pieces(n);
  for (std::size_t i = 0; i < n; ++i)
    for (const std::size_t j : links[i]) pieces.join(i, j);
  std::vector<double> piece_area(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) piece_area[pieces.find(i)] += in.area_m2[i];
  std::size_t slab = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (pieces.find(i) != i) continue;
    ++m.pieces;
    if (piece_area[i] > piece_area[slab]) slab = i;  // ascending: ties stay with the lowest index
  }

  const double face_band = 0.5 * in.link_radius_m;
  auto on_loaded_face = [&](std::size_t i) { return in.body.y1 - in.x[i].y() <= face_band; };
  auto on_far_face = [&](std::size_t i) { return in.x[i].y() - in.body.y0 <= face_band; };
  auto crushed = [&](std::size_t i) { return -in.min_eps_v[i] >= in.crushing_eps_v; };

  // (a) crushed points joined to the loaded face through crushed points (breadth first from the face)
  std::vector<char> in_crushed(n, 0);
  std::vector<std::size_t> queue;
  for (std::size_t i = 0; i < n; ++i)
    if (crushed(i) && on_loaded_face(i)) in_crushed[i] = 1, queue.push_back(i);
  for (std::size_t q = 0; q < queue.size(); ++q)
    for (const std::size_t j : links[queue[q]])
      if (!in_crushed[j] && crushed(j)) in_crushed[j] = 1, queue.push_back(j);

  // (b) the loose pieces: in the crater when they touch the loaded face or hold a crushed crater point
  std::vector<char> touches_top(n, 0), touches_bottom(n, 0), holds_crushed(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t p = pieces.find(i);
    touches_top[p] |= on_loaded_face(i) ? 1 : 0;
    touches_bottom[p] |= on_far_face(i) ? 1 : 0;
    holds_crushed[p] |= in_crushed[i];
  }
  std::vector<char> counted(n, 0);
  double x_min = INFINITY, x_max = -INFINITY, y_min = INFINITY, spall_y_max = -INFINITY;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t p = pieces.find(i);
    const bool loose = p != pieces.find(slab);
    if (loose && (touches_top[p] || holds_crushed[p])) {
      m.label[i] = CraterLabel::crater_fragment;
      ++m.crater_fragment_points;
      m.fragment_area_m2 += in.area_m2[i];
      if (!counted[p]) counted[p] = 1, ++m.crater_fragments;
    } else if (in_crushed[i]) {
      m.label[i] = CraterLabel::crushed;
    } else if (loose && touches_bottom[p]) {
      m.label[i] = CraterLabel::spall;
      ++m.spall_points;
      m.spall_area_m2 += in.area_m2[i];
      spall_y_max = std::max(spall_y_max, in.x[i].y());
      if (!counted[p]) counted[p] = 1, ++m.spall_fragments;
      continue;
    } else if (loose) {
      m.label[i] = CraterLabel::loose_inside;
      ++m.loose_inside_points;
      continue;
    } else {
      continue;
    }
    if (in_crushed[i]) ++m.crushed_points, m.crushed_area_m2 += in.area_m2[i];
    m.area_m2 += in.area_m2[i];
    x_min = std::min(x_min, in.x[i].x()), x_max = std::max(x_max, in.x[i].x()), y_min = std::min(y_min, in.x[i].y());
  }
  if (m.area_m2 > 0) {
    m.x_min_m = x_min, m.x_max_m = x_max;
    m.width_m = x_max - x_min;
    m.depth_m = in.body.y1 - y_min;
  }
  if (m.spall_points > 0) m.spall_depth_m = spall_y_max - in.body.y0;
  return m;
}

}  // namespace mesowave::efg
