#include "mesowave/dem/engine/neighbour_search.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mesowave/core/check.hpp"

namespace mesowave::dem {

std::vector<SpherePair> find_pairs_within(std::span<const std::array<double, 3>> x, std::span<const double> r,
                                          double factor) {
  require_positive("interaction factor", factor);
  if (x.size() != r.size()) throw std::logic_error("centres and radii differ in length");
  const std::size_t n = x.size();
  if (n < 2) return {};

  std::array<double, 3> lo = x[0], hi = x[0];
  double r_max = 0;
  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], x[i][d]);
      hi[d] = std::max(hi[d], x[i][d]);
    }
    r_max = std::max(r_max, r[i]);
  }
  // A cell as wide as the longest possible interaction: partners are in the
  // 27 cells around. Cap the grid so a stray far sphere cannot explode memory.
  double cell = std::max(factor * 2.0 * r_max, 1e-300);
  std::array<std::int64_t, 3> dims{};
  for (;;) {
    std::int64_t total = 1;
    for (int d = 0; d < 3; ++d) {
      dims[d] = std::max<std::int64_t>(1, std::int64_t((hi[d] - lo[d]) / cell) + 1);
      total *= dims[d];
    }
    if (total <= std::int64_t(8 * n) + 64) break;
    cell *= 1.5;
  }
  auto cell_of = [&](const std::array<double, 3>& p) {
    std::array<std::int64_t, 3> c;
    for (int d = 0; d < 3; ++d) c[d] = std::min(dims[d] - 1, std::int64_t((p[d] - lo[d]) / cell));
    return c;
  };
  auto linear = [&](const std::array<std::int64_t, 3>& c) { return (c[2] * dims[1] + c[1]) * dims[0] + c[0]; };

  // Counting sort of the spheres by cell (stable: ascending index in a cell).
  const std::size_t cells = std::size_t(dims[0] * dims[1] * dims[2]);
  std::vector<std::uint32_t> start(cells + 1, 0), order(n);
  std::vector<std::size_t> home(n);
  for (std::size_t i = 0; i < n; ++i) ++start[(home[i] = std::size_t(linear(cell_of(x[i])))) + 1];
  for (std::size_t c = 0; c < cells; ++c) start[c + 1] += start[c];
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) order[fill[home[i]]++] = std::uint32_t(i);
  }

  std::vector<SpherePair> pairs;
  std::vector<std::uint32_t> partners;
  for (std::size_t i = 0; i < n; ++i) {
    partners.clear();
    const auto c = cell_of(x[i]);
    for (std::int64_t dz = -1; dz <= 1; ++dz)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
          const std::array<std::int64_t, 3> nc = {c[0] + dx, c[1] + dy, c[2] + dz};
          if (nc[0] < 0 || nc[1] < 0 || nc[2] < 0 || nc[0] >= dims[0] || nc[1] >= dims[1] || nc[2] >= dims[2]) continue;
          const auto k = std::size_t(linear(nc));
          for (std::uint32_t s = start[k]; s < start[k + 1]; ++s) {
            const std::uint32_t j = order[s];
            if (j <= i) continue;
            const double ddx = x[j][0] - x[i][0], ddy = x[j][1] - x[i][1], ddz = x[j][2] - x[i][2];
            const double reach = factor * (r[i] + r[j]);
            if (ddx * ddx + ddy * ddy + ddz * ddz <= reach * reach) partners.push_back(j);
          }
        }
    std::sort(partners.begin(), partners.end());
    for (std::uint32_t j : partners) pairs.push_back({std::uint32_t(i), j});
  }
  return pairs;
}

double coordination_number(std::size_t pair_count, std::size_t sphere_count) {
  return sphere_count == 0 ? 0.0 : 2.0 * double(pair_count) / double(sphere_count);
}

}  // namespace mesowave::dem
