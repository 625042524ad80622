#pragma once
// Nodes and the background integration cells of the EFG model (shock paper Section 2.5): the
// domain integral of Eq. (18) is a sum over Gauss points of cells that tile a rectangle. The nodes
// are the cells' corners (the paper's first case) plus any extra nodes (its second case: refinement
// around a discontinuity, e.g. ahead of a notch, where the crack will run and a finer support
// resolves the strain localisation); a caller may also move nodes off the corners (the third case) -
// the cells stay where they are. The paper integrates with 2 x 2 points per cell and shows that the
// result depends on that number (Fig. 4): MLS shape functions are rational, no Gauss rule is exact.
#include <cstdint>
#include <functional>
#include <vector>

#include "mesowave/efg/geometry.hpp"

namespace mesowave::efg {

struct GaussPoint {
  Vec2 x;
  double weight_m2;   ///< Gauss weight times the cell's Jacobian (an area; times t it is a volume)
  std::int32_t cell;  ///< index into Discretisation::cells
};

struct Discretisation {
  std::vector<Vec2> nodes;         ///< cell corners first (row by row, x fastest), then extra nodes
  std::vector<GaussPoint> points;  ///< n x n per background cell, cell by cell
  double spacing_m = 0;            ///< nominal nodal spacing (the larger cell edge)
  std::vector<Rect> cells;         ///< the background cells kept (points name them by index)
};

/// Gauss-Legendre rule with n points on [-1, 1] (Golub-Welsch: the eigenvalues of the Jacobi matrix
/// of the Legendre polynomials, weights 2 v_0^2): abscissae ascending. InputError unless 1 <= n <= 64.
struct GaussRule {
  std::vector<double> x, w;
};
GaussRule gauss_legendre(int n);

/// The n-point Gauss-Legendre points along a segment a -> b, as the cohesive integrals along a crack
/// use them (static interface and dynamic faces): position, the length each point stands for (the
/// weights sum to |b - a|), and the unit normal (d.y, -d.x) / |d|, the right of a -> b. Empty for a
/// segment of zero length.
struct SegmentGaussPoint {
  Vec2 x;
  double length_weight_m = 0;
};
struct SegmentGauss {
  Vec2 normal = Vec2::Zero();
  std::vector<SegmentGaussPoint> points;
};
SegmentGauss segment_gauss_points(const Segment& s, int n);

/// Regular cells over `body` (nx x ny), corners as nodes, `gauss` points per direction (default 2,
/// the paper's choice), `extra_nodes` appended. `keep_cell`, when given, drops the cells it returns
/// false for (and the corners no kept cell has): a hole or a re-entrant corner; a notch is better a
/// crack polyline (efg/crack.hpp), which needs no cell removed. InputError for an empty or inverted
/// body, nx or ny < 1, gauss outside [1, 64], an extra node outside the body or on another node.
Discretisation rectangular_grid(const Rect& body, int nx, int ny, int gauss = 2,
                                std::vector<Vec2> extra_nodes = {},
                                const std::function<bool(const Rect& cell)>& keep_cell = {});

}  // namespace mesowave::efg
