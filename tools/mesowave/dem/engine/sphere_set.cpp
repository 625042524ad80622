#include "mesowave/dem/engine/sphere_set.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <string>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"

namespace mesowave::dem {
namespace {

// Spreads the low 21 bits of v so that two zero bits follow each one.
std::uint64_t spread_bits(std::uint64_t v) {
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffffULL;
  v = (v | v << 16) & 0x1f0000ff0000ffULL;
  v = (v | v << 8) & 0x100f00f00f00f00fULL;
  v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
  v = (v | v << 2) & 0x1249249249249249ULL;
  return v;
}

}  // namespace

MortonFrame MortonFrame::of(const std::array<double, 3>& lo, const std::array<double, 3>& hi) {
  const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-300});
  return {lo, double((1u << 21) - 1) / extent};
}

std::uint64_t MortonFrame::code(const std::array<double, 3>& x) const {
  std::uint64_t c = 0;
  for (int d = 0; d < 3; ++d) c |= spread_bits(std::uint64_t((x[std::size_t(d)] - lower[std::size_t(d)]) * scale)) << d;
  return c;
}

std::vector<std::uint32_t> morton_order(std::span<const std::array<double, 3>> x) {
  const std::size_t n = x.size();
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  if (n < 2) return order;
  std::array<double, 3> lo = x[0], hi = x[0];
  for (const auto& p : x)
    for (int d = 0; d < 3; ++d) lo[d] = std::min(lo[d], p[d]), hi[d] = std::max(hi[d], p[d]);
  const MortonFrame frame = MortonFrame::of(lo, hi);
  std::vector<std::uint64_t> code(n);
  for (std::size_t i = 0; i < n; ++i) code[i] = frame.code(x[i]);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return code[a] < code[b]; });
  return order;
}

SphereSet sphere_set_of_size(std::size_t n, bool with_ids) {
  SphereSet s;
  s.centre_m.resize(n), s.radius_m.resize(n), s.mass_kg.resize(n), s.inertia_kg_m2.resize(n), s.packing_index.resize(n);
  if (with_ids) s.ids.resize(n);
  return s;
}

void set_sphere(SphereSet& s, std::size_t k, const std::array<double, 3>& c, double r, double density,
                std::uint32_t packing_index, std::int64_t id) {
  constexpr double pi = std::numbers::pi;
  s.centre_m[k] = {c[0], c[1], c[2]};
  s.radius_m[k] = r;
  s.mass_kg[k] = density * 4.0 / 3.0 * pi * r * r * r;
  s.inertia_kg_m2[k] = 0.4 * s.mass_kg[k] * r * r;
  s.packing_index[k] = packing_index;
  s.ids[k] = id;
}

bool is_sound_sphere(const std::array<double, 3>& centre, double r) {
  return std::isfinite(r) && r > 0 && std::isfinite(centre[0]) && std::isfinite(centre[1]) && std::isfinite(centre[2]);
}

void check_sphere(const std::array<double, 3>& centre, double r, std::size_t i) {
  if (!std::isfinite(r) || r <= 0)
    throw InputError("sphere " + std::to_string(i) + " has radius " + format_number(r) + " m; radii must be positive");
  for (double c : centre)
    if (!std::isfinite(c)) throw InputError("sphere " + std::to_string(i) + " has a non-finite centre coordinate");
}

SphereSet make_sphere_set(const Packing& packing, double density, bool renumber) {
  const std::size_t n = packing.size();
  if (n == 0) throw InputError("the packing has no spheres");
  if (packing.centres_m.size() != n) throw InputError("the packing has " + std::to_string(packing.centres_m.size()) +
                                                      " centres but " + std::to_string(n) + " radii");
  require_positive("particle density", density, "kg/m3");
  for (std::size_t i = 0; i < n; ++i) check_sphere(packing.centres_m[i], packing.radii_m[i], i);
  std::vector<std::uint32_t> order;
  if (renumber) order = morton_order(packing.centres_m);
  else {
    order.resize(n);
    std::iota(order.begin(), order.end(), 0u);
  }
  SphereSet s = sphere_set_of_size(n, true);
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t p = order[k];
    set_sphere(s, k, packing.centres_m[p], packing.radii_m[p], density, p, p < packing.ids.size() ? packing.ids[p] : std::int64_t(p));
  }
  return s;
}

}  // namespace mesowave::dem
