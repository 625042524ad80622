#include "mesowave/efg/node_grid.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "mesowave/core/check.hpp"

namespace mesowave::efg {

NodeGrid::NodeGrid(const std::vector<Vec2>& nodes, double cell_size_m) : nodes_(nodes), cell_(cell_size_m) {
  require_positive("node grid cell size", cell_size_m, "m");
  Vec2 lo = Vec2::Constant(0), hi = Vec2::Constant(0);
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (!nodes_[i].allFinite()) throw InputError("node " + std::to_string(i) + " has a non-finite coordinate");
    lo = i == 0 ? nodes_[i] : Vec2(lo.cwiseMin(nodes_[i]));
    hi = i == 0 ? nodes_[i] : Vec2(hi.cwiseMax(nodes_[i]));
  }
  origin_ = lo;
  const double max_cells = 4.0 * double(std::max<std::size_t>(nodes_.size(), 1)) + 16;
  for (;;) {
    const double cx = std::floor((hi.x() - lo.x()) / cell_) + 1, cy = std::floor((hi.y() - lo.y()) / cell_) + 1;
    if (cx * cy <= max_cells) {
      nx_ = int(cx);
      ny_ = int(cy);
      break;
    }
    cell_ *= 2;
  }
  std::vector<std::int32_t> cell_of(nodes_.size());
  start_.assign(std::size_t(nx_) * std::size_t(ny_) + 1, 0);
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    const int ix = std::min(nx_ - 1, int((nodes_[i].x() - lo.x()) / cell_));
    const int iy = std::min(ny_ - 1, int((nodes_[i].y() - lo.y()) / cell_));
    cell_of[i] = iy * nx_ + ix;
    ++start_[std::size_t(cell_of[i]) + 1];
  }
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  order_.resize(nodes_.size());
  std::vector<std::int32_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < nodes_.size(); ++i) order_[std::size_t(fill[std::size_t(cell_of[i])]++)] = std::int32_t(i);
}

std::vector<std::int32_t> NodeGrid::within(const Vec2& x, double radius_m) const {
  std::vector<std::int32_t> out;
  within(x, radius_m, out);
  return out;
}

void NodeGrid::within(const Vec2& x, double radius_m, std::vector<std::int32_t>& out) const {
  out.clear();
  if (nodes_.empty() || !(radius_m >= 0)) return;
  const auto cell_range = [&](double lo, double hi, int n) {
    const double a = std::floor(lo / cell_), b = std::floor(hi / cell_);
    return std::pair<int, int>(int(std::clamp(a, 0.0, double(n - 1))), int(std::clamp(b, -1.0, double(n - 1))));
  };
  const Vec2 rel = x - origin_;
  if (rel.x() + radius_m < 0 || rel.y() + radius_m < 0) return;
  const auto [x0, x1] = cell_range(rel.x() - radius_m, rel.x() + radius_m, nx_);
  const auto [y0, y1] = cell_range(rel.y() - radius_m, rel.y() + radius_m, ny_);
  const double r2 = radius_m * radius_m;
  for (int iy = y0; iy <= y1; ++iy)
    for (int ix = x0; ix <= x1; ++ix) {
      const std::size_t c = std::size_t(iy) * std::size_t(nx_) + std::size_t(ix);
      for (std::int32_t k = start_[c]; k < start_[c + 1]; ++k) {
        const std::int32_t i = order_[std::size_t(k)];
        if ((nodes_[std::size_t(i)] - x).squaredNorm() <= r2) out.push_back(i);
      }
    }
  std::sort(out.begin(), out.end());
}

}  // namespace mesowave::efg
