#include "mesowave/dem/contact/bond_network.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/dem/engine/neighbour_search.hpp"
#include "mesowave/dem/engine/sphere_part.hpp"
#include "mesowave/dem/parallel/domain.hpp"

namespace mesowave::dem {
namespace {

// Every pair within `factor` (r_i + r_j) with an end among the part's own spheres, in whole
// indices sorted by (i, j). The search runs over the part's spheres, own and layer: a pair's test
// reads its two spheres alone, so it is found as the whole set's search finds it, provided the
// layer reaches `factor` (2 r_max) beyond the own spheres.
std::vector<SpherePair> pairs_with_an_end_in(const SpherePart& part, double factor) {
  const SphereSet& s = part.spheres();
  std::vector<std::array<double, 3>> centres(s.size());
  for (std::size_t l = 0; l < s.size(); ++l) centres[l] = {s.centre_m[l].x, s.centre_m[l].y, s.centre_m[l].z};
  std::vector<SpherePair> pairs = find_pairs_within(centres, s.radius_m, factor);
  if (part.own_count() == part.total()) return pairs;  // the whole set: local indices are whole ones
  std::erase_if(pairs, [&](const SpherePair& p) { return p.i >= part.own_count() && p.j >= part.own_count(); });
  for (SpherePair& p : pairs) {
    const auto i = std::uint32_t(part.whole_index(p.i)), j = std::uint32_t(part.whole_index(p.j));
    p = {std::min(i, j), std::max(i, j)};
  }
  std::sort(pairs.begin(), pairs.end(), [](const SpherePair& a, const SpherePair& b) { return a.i != b.i ? a.i < b.i : a.j < b.j; });
  return pairs;
}

BondNetwork bonds_of(const SpherePart& part, const std::vector<SpherePair>& pairs) {
  const SphereSet& s = part.spheres();
  BondNetwork net;
  net.first.reserve(pairs.size());
  net.second.reserve(pairs.size());
  net.overlap0_m.reserve(pairs.size());
  net.normal0.reserve(pairs.size());
  for (const auto& p : pairs) {
    const std::size_t i = part.local(p.i), j = part.local(p.j);
    const BondGeometry g = bond_geometry(s.centre_m[i], s.centre_m[j], s.radius_m[i], s.radius_m[j]);
    if (!(g.distance_m > 1e-9 * (s.radius_m[i] + s.radius_m[j])))
      throw InputError("spheres with ids " + std::to_string(s.ids[i]) + " and " + std::to_string(s.ids[j]) +
                       " have coincident centres (distance " + format_number(g.distance_m) +
                       " m): their contact normal is undefined; remove one of them from the packing");
    net.first.push_back(p.i);
    net.second.push_back(p.j);
    net.overlap0_m.push_back(g.overlap_m);
    net.normal0.push_back(g.normal);
  }
  return net;
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

BondNetwork make_bond_network(const SpherePart& part, double bond_factor) {
  require_positive("bond factor C_f", bond_factor);
  BondNetwork net = bonds_of(part, pairs_with_an_end_in(part, bond_factor));
  if (!part.domain()) return net;
  Domain& domain = *part.domain();
  const int ranks = domain.size(), me = domain.rank();
  const std::size_t begin = part.begin();
  net.own_begin = begin, net.own_end = begin + part.own_count();
  // The bonds whose first sphere is a lower rank's come first (sorted by first sphere).
  const std::size_t cross = std::size_t(std::lower_bound(net.first.begin(), net.first.end(), begin) - net.first.begin());
  // The whole network numbers the bonds by first sphere: rank r's own-first bonds after every lower rank's.
  const std::vector<double> counts = gathered_each(domain, double(net.size() - cross));
  std::size_t offset = 0;
  for (int r = 0; r < ranks; ++r) {
    if (r < me) offset += std::size_t(counts[std::size_t(r)]);
    net.whole_size += std::size_t(counts[std::size_t(r)]);
  }
  if (net.whole_size > std::size_t(0xffffffffu))
    throw InputError(std::to_string(net.whole_size) + " bonds: more than 32-bit bond indices address");
  net.ids.resize(net.size());
  for (std::size_t h = cross; h < net.size(); ++h) net.ids[h] = std::uint32_t(offset + h - cross);
  // A bond across two ranks is numbered by its first sphere's rank, which sends the number (with
  // the pair, checked) to the second sphere's. Both found the bond from the same doubles; the
  // ranks check that they agree (pair_hash) before the exchange.
  const auto owner = [&](std::size_t k) { return part.owner(k); };
  const auto hash = [&](std::size_t h) { return pair_hash(net.first[h], net.second[h]); };
  std::vector<std::vector<double>> out(static_cast<std::size_t>(ranks)), in(static_cast<std::size_t>(ranks));
  std::uint64_t unmatched = 0;
  for (std::size_t h = cross; h < net.size(); ++h)
    if (const int t = owner(net.second[h]); t != me) {
      out[std::size_t(t)].insert(out[std::size_t(t)].end(), {double(net.first[h]), double(net.second[h]), double(net.ids[h])});
      unmatched += hash(h);
    }
  for (std::size_t h = 0; h < cross; ++h) {
    auto& from = in[std::size_t(owner(net.first[h]))];
    from.resize(from.size() + 3);
    unmatched -= hash(h);
  }
  if (domain.sum(unmatched) != 0)
    throw std::logic_error("make_bond_network: the ranks disagree on the bonds across them");
  std::vector<Domain::Message> sends, receives;
  for (int r = 0; r < ranks; ++r) {
    if (!out[std::size_t(r)].empty()) sends.push_back({r, out[std::size_t(r)].data(), int(out[std::size_t(r)].size())});
    if (!in[std::size_t(r)].empty()) receives.push_back({r, in[std::size_t(r)].data(), int(in[std::size_t(r)].size())});
  }
  domain.exchange(sends, receives);
  std::vector<std::size_t> read(std::size_t(ranks), 0);
  for (std::size_t h = 0; h < cross; ++h) {
    const auto q = std::size_t(owner(net.first[h]));
    const double* m = &in[q][read[q]];
    read[q] += 3;
    if (m[0] != double(net.first[h]) || m[1] != double(net.second[h]))
      throw std::logic_error("make_bond_network: rank " + std::to_string(q) + " numbered another bond than rank " +
                             std::to_string(me) + "'s bond between spheres " + std::to_string(net.first[h]) + " and " +
                             std::to_string(net.second[h]));
    net.ids[h] = std::uint32_t(m[2]);
  }
  return net;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> unbonded_overlaps(const SpherePart& part, const BondNetwork& net) {
  const SphereSet& s = part.spheres();
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  std::size_t b = 0;  // both lists are sorted by (i, j)
  for (const auto& p : pairs_with_an_end_in(part, 1.0)) {
    if (!part.owns(p.i)) continue;  // its first sphere's rank reports it
    while (b < net.size() && (net.first[b] < p.i || (net.first[b] == p.i && net.second[b] < p.j))) ++b;
    const bool bonded = b < net.size() && net.first[b] == p.i && net.second[b] == p.j;
    const std::size_t i = part.local(p.i), j = part.local(p.j);
    const double u = s.radius_m[i] + s.radius_m[j] - norm(s.centre_m[j] - s.centre_m[i]);
    if (!bonded && u > 0) out.emplace_back(p.i, p.j);
  }
  return out;
}

}  // namespace mesowave::dem
