#pragma once
// Neighbour search for the MLS approximation by cell lists: the nodes are binned into square cells
// once; a query visits only the cells its circle overlaps. Cost O(nodes in the visited cells).
#include <cstdint>
#include <vector>

#include "mesowave/efg/geometry.hpp"

namespace mesowave::efg {

class NodeGrid {
public:
  /// InputError: cell size not > 0, a non-finite node. The cell size is enlarged when the nodes'
  /// bounding box would need more than 4 cells per node (a tiny cell wastes memory, not accuracy).
  NodeGrid(const std::vector<Vec2>& nodes, double cell_size_m);
  /// Indices of the nodes within `radius_m` of x (|x - x_i| <= radius), ascending (deterministic).
  std::vector<std::int32_t> within(const Vec2& x, double radius_m) const;
  /// The same, appended to `out` after clearing it (no allocation once `out` is large enough).
  void within(const Vec2& x, double radius_m, std::vector<std::int32_t>& out) const;
  double cell_size() const { return cell_; }
  std::size_t size() const { return nodes_.size(); }

private:
  std::vector<Vec2> nodes_;
  Vec2 origin_ = Vec2::Zero();
  double cell_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<std::int32_t> start_;  ///< CSR: cell c holds order_[start_[c] .. start_[c + 1])
  std::vector<std::int32_t> order_;
};

}  // namespace mesowave::efg
