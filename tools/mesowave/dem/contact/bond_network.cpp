#include "mesowave/dem/contact/bond_network.hpp"

#include <array>
#include <string>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/dem/engine/neighbour_search.hpp"

namespace mesowave::dem {
namespace {

std::vector<std::array<double, 3>> centres_of(const SphereSet& s) {
  std::vector<std::array<double, 3>> c(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) c[i] = {s.centre_m[i].x, s.centre_m[i].y, s.centre_m[i].z};
  return c;
}

}  // namespace

Incidence make_incidence(std::size_t n, const std::vector<std::uint32_t>& first,
                         const std::vector<std::uint32_t>& second) {
  Incidence inc;
  inc.offset.assign(n + 1, 0);
  for (std::size_t b = 0; b < first.size(); ++b) {
    ++inc.offset[first[b] + 1];
    ++inc.offset[second[b] + 1];
  }
  for (std::size_t k = 0; k < n; ++k) inc.offset[k + 1] += inc.offset[k];
  inc.entry.resize(2 * first.size());
  std::vector<std::uint32_t> fill(inc.offset.begin(), inc.offset.end() - 1);
  // Ascending b, so every sphere's list is in ascending bond order.
  for (std::size_t b = 0; b < first.size(); ++b) {
    inc.entry[fill[first[b]]++] = std::uint32_t(b) << 1;
    inc.entry[fill[second[b]]++] = (std::uint32_t(b) << 1) | 1u;
  }
  return inc;
}

BondNetwork make_bond_network(const SphereSet& s, double bond_factor) {
  require_positive("bond factor C_f", bond_factor);
  const auto centres = centres_of(s);
  const auto pairs = find_pairs_within(centres, s.radius_m, bond_factor);
  BondNetwork net;
  net.first.reserve(pairs.size());
  net.second.reserve(pairs.size());
  net.overlap0_m.reserve(pairs.size());
  net.normal0.reserve(pairs.size());
  for (const auto& p : pairs) {
    const Vec3 d = s.centre_m[p.j] - s.centre_m[p.i];
    const double dist = norm(d);
    const double sum = s.radius_m[p.i] + s.radius_m[p.j];
    if (!(dist > 1e-9 * sum))
      throw InputError("spheres with ids " + std::to_string(s.ids[p.i]) + " and " + std::to_string(s.ids[p.j]) +
                       " have coincident centres (distance " + format_number(dist) +
                       " m): their contact normal is undefined; remove one of them from the packing");
    net.first.push_back(p.i);
    net.second.push_back(p.j);
    net.overlap0_m.push_back(sum - dist);
    net.normal0.push_back((1.0 / dist) * d);
  }
  net.incidence = make_incidence(s.size(), net.first, net.second);
  return net;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> unbonded_overlaps(const SphereSet& s, const BondNetwork& net) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  const auto centres = centres_of(s);
  const auto touching = find_pairs_within(centres, s.radius_m, 1.0);
  std::size_t b = 0;  // both lists are sorted by (i, j)
  for (const auto& p : touching) {
    while (b < net.size() && (net.first[b] < p.i || (net.first[b] == p.i && net.second[b] < p.j))) ++b;
    const bool bonded = b < net.size() && net.first[b] == p.i && net.second[b] == p.j;
    const double u = s.radius_m[p.i] + s.radius_m[p.j] - norm(s.centre_m[p.j] - s.centre_m[p.i]);
    if (!bonded && u > 0) out.emplace_back(p.i, p.j);
  }
  return out;
}

}  // namespace mesowave::dem
