#pragma once
// Node sets and Gauss points for the EFG approximation tests (tests/efg/): a regular grid of nodes,
// optionally perturbed by a deterministic generator, and the Gauss points of a background cell
// grid, written out here so the MLS tests do not depend on the discretisation they serve; and the
// derivative check against central differences.
#include <cmath>
#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "mesowave/core/random.hpp"
#include "mesowave/efg/geometry.hpp"
#include "mesowave/efg/mls.hpp"

namespace mesowave::test {

/// (nx + 1) x (ny + 1) nodes on [0, lx] x [0, ly], row by row from (0, 0); interior nodes moved by
/// up to +-`jitter` spacings in each direction (Mt64Random with `seed`).
inline std::vector<efg::Vec2> grid_nodes(int nx, int ny, double lx, double ly, double jitter = 0,
                                         std::uint64_t seed = 7) {
  Mt64Random random(seed);
  std::vector<efg::Vec2> nodes;
  const double dx = lx / nx, dy = ly / ny;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      efg::Vec2 p(i * dx, j * dy);
      if (jitter > 0 && i > 0 && i < nx && j > 0 && j < ny)
        p += efg::Vec2(random.uniform(-jitter, jitter) * dx, random.uniform(-jitter, jitter) * dy);
      nodes.push_back(p);
    }
  return nodes;
}

/// The Gauss points (n x n Gauss-Legendre, n = 2 or 4) of a cx x cy background cell grid over
/// [0, lx] x [0, ly], cell by cell.
inline std::vector<efg::Vec2> gauss_points(int cx, int cy, int n, double lx, double ly) {
  const double a = std::sqrt(3.0 / 7 - 2.0 / 7 * std::sqrt(6.0 / 5)), b = std::sqrt(3.0 / 7 + 2.0 / 7 * std::sqrt(6.0 / 5));
  const std::vector<double> xi = n == 2 ? std::vector<double>{-1 / std::sqrt(3.0), 1 / std::sqrt(3.0)}
                                        : std::vector<double>{-b, -a, a, b};
  std::vector<efg::Vec2> points;
  for (int j = 0; j < cy; ++j)
    for (int i = 0; i < cx; ++i)
      for (const double gy : xi)
        for (const double gx : xi) points.emplace_back((i + 0.5 * (1 + gx)) * lx / cx, (j + 0.5 * (1 + gy)) * ly / cy);
  return points;
}

/// The MLS derivatives at x against central differences of phi with step `delta`.
struct DerivativeCheck {
  double error = std::numeric_limits<double>::infinity();  ///< largest |dphi - difference|; inf: node sets differ
  double largest = 0;                                      ///< largest |dphi| (the check is not between zeros)
};
inline DerivativeCheck check_derivatives(const efg::MlsApproximation& mls, const efg::Vec2& x, double delta) {
  const auto sf = mls.evaluate(x);
  const auto px = mls.evaluate(x + efg::Vec2(delta, 0)), mx = mls.evaluate(x - efg::Vec2(delta, 0));
  const auto py = mls.evaluate(x + efg::Vec2(0, delta)), my = mls.evaluate(x - efg::Vec2(0, delta));
  DerivativeCheck check;
  if (px.nodes != sf.nodes || mx.nodes != sf.nodes || py.nodes != sf.nodes || my.nodes != sf.nodes) return check;
  check.error = 0;
  for (std::size_t k = 0; k < sf.nodes.size(); ++k) {
    check.error = std::max(check.error, std::abs(sf.dphi_dx[k] - (px.phi[k] - mx.phi[k]) / (2 * delta)));
    check.error = std::max(check.error, std::abs(sf.dphi_dy[k] - (py.phi[k] - my.phi[k]) / (2 * delta)));
    check.largest = std::max({check.largest, std::abs(sf.dphi_dx[k]), std::abs(sf.dphi_dy[k])});
  }
  return check;
}

}  // namespace mesowave::test
