#include "mesowave/dem/engine/sphere_part.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/dem/engine/centre_box.hpp"
#include "mesowave/dem/engine/sphere_system.hpp"
#include "mesowave/dem/parallel/domain.hpp"

namespace mesowave::dem {
namespace {

// A sphere as it travels between ranks: centre (3), radius, packing index, id (exact below
// 2^53); the receiver makes its mass and inertia (set_row), as make_sphere_set does.
constexpr std::size_t kRow = 6;

void append_row(const Packing& rows, std::size_t i, std::vector<double>& out) {
  const auto& c = rows.centres_m[i];
  out.insert(out.end(), {c[0], c[1], c[2], rows.radii_m[i], double(rows.first_row + i), double(rows.ids[i])});
}

void append_row(const SphereSet& s, std::size_t k, std::vector<double>& out) {
  const Vec3& c = s.centre_m[k];
  out.insert(out.end(), {c.x, c.y, c.z, s.radius_m[k], double(s.packing_index[k]), double(s.ids[k])});
}

void set_row(SphereSet& s, std::size_t k, const double* row, double density) {
  set_sphere(s, k, {row[0], row[1], row[2]}, row[3], density, std::uint32_t(row[4]), std::int64_t(row[5]));
}

// A sphere's place in the Morton order: its code, then its packing index (morton_order's stable
// sort keeps the packing's order among equal codes).
__extension__ typedef unsigned __int128 Key;
Key key_of(std::uint64_t code, std::size_t packing_index) { return (Key(code) << 32) | Key(packing_index); }

// The key at whole position starts[r] of every rank r (first[0] = 0; past the last key, and
// first[ranks], the largest key): for each, the least bound with more than starts[r] keys of all
// ranks at most it, bisected with one sum of the ranks' counts a step (integers: exact).
std::vector<Key> first_keys(Domain& domain, const std::vector<std::pair<Key, std::uint32_t>>& keys,
                            const std::vector<std::size_t>& starts) {
  const std::size_t ranks = starts.size() - 1, total = starts.back();
  const Key none = ~Key(0);
  std::vector<Key> lo(ranks + 1, 0), hi(ranks + 1, Key(1) << 95);  // codes have 63 bits, indices 32
  for (std::size_t r = 1; r < ranks; ++r)
    if (starts[r] >= total) lo[r] = hi[r] = none;
  lo[ranks] = hi[ranks] = none;
  const auto at_most = [&](Key bound) {
    return std::uint64_t(std::upper_bound(keys.begin(), keys.end(), std::pair{bound, ~std::uint32_t(0)}) - keys.begin());
  };
  while (true) {
    std::vector<std::uint64_t> counts(ranks, 0);
    bool open = false;
    for (std::size_t r = 1; r < ranks; ++r)
      if (lo[r] < hi[r]) counts[r] = at_most(lo[r] + (hi[r] - lo[r]) / 2), open = true;
    if (!open) break;  // every rank reads the same bounds: they stop together
    domain.sum_each(counts);
    for (std::size_t r = 1; r < ranks; ++r) {
      if (!(lo[r] < hi[r])) continue;
      const Key mid = lo[r] + (hi[r] - lo[r]) / 2;
      if (counts[r] > starts[r]) hi[r] = mid;
      else lo[r] = mid + 1;
    }
  }
  return lo;
}

}  // namespace

SpherePart::SpherePart(SphereSet whole) : set_(std::move(whole)) {
  own_ = total_ = set_.size();
  if (set_.ids.size() != own_) set_.ids.assign(own_, 0);  // sets made in tests carry none
}

SpherePart::SpherePart(const Packing& rows, double density, Domain& domain, double reach_radii)
    : total_(rows.file_rows), density_(density), domain_(&domain) {
  if (!rows.is_piece()) throw std::logic_error("SpherePart: the rows are not a part of a packing file (read_packing_file)");
  if (total_ == 0) throw InputError("the packing has no spheres");
  require_positive("particle density", density, "kg/m3");
  // The file's first bad row names the error on every rank, as one process's check does: each
  // rank's first (centre, radius, row), gathered in row order.
  std::vector<double> bad;
  for (std::size_t i = 0; i < rows.size() && bad.empty(); ++i)
    if (!is_sound_sphere(rows.centres_m[i], rows.radii_m[i])) {
      const auto& c = rows.centres_m[i];
      bad = {c[0], c[1], c[2], rows.radii_m[i], double(rows.first_row + i)};
    }
  bad = gathered_lists(domain, bad);
  if (!bad.empty()) check_sphere({bad[0], bad[1], bad[2]}, bad[3], std::size_t(bad[4]));
  const int ranks = domain.size(), me = domain.rank();
  const double inf = std::numeric_limits<double>::infinity();

  // The Morton frame of every centre's box (a min and a max: exact in any order), each row's key.
  std::array<double, 3> lo{inf, inf, inf}, hi{-inf, -inf, -inf};
  for (const auto& c : rows.centres_m)
    for (std::size_t d = 0; d < 3; ++d) lo[d] = std::min(lo[d], c[d]), hi[d] = std::max(hi[d], c[d]);
  for (std::size_t d = 0; d < 3; ++d) lo[d] = -domain.max(-lo[d]), hi[d] = domain.max(hi[d]);
  const MortonFrame frame = MortonFrame::of(lo, hi);
  std::vector<std::pair<Key, std::uint32_t>> keys(rows.size());  // key, row
  for (std::size_t i = 0; i < rows.size(); ++i) keys[i] = {key_of(frame.code(rows.centres_m[i]), rows.first_row + i), std::uint32_t(i)};
  std::sort(keys.begin(), keys.end());

  // Each rank's first key: the key at whole position starts_[r], bisected on the count of keys up to a bound.
  starts_ = SphereSystem::rank_starts(total_, ranks);
  begin_ = starts_[std::size_t(me)], own_ = starts_[std::size_t(me) + 1] - begin_;
  const std::vector<Key> first = first_keys(domain, keys, starts_);
  std::vector<std::vector<double>> out(static_cast<std::size_t>(ranks));
  for (const auto& [key, i] : keys) {
    const auto r = std::size_t(std::upper_bound(first.begin() + 1, first.end(), key) - first.begin()) - 1;
    append_row(rows, i, out[r]);
  }
  const std::vector<double> arrived = exchanged_lists(domain, std::move(out));
  if (arrived.size() != kRow * own_) throw std::logic_error("SpherePart: the Morton sort gave this rank another count than its range");
  keys.resize(own_);
  for (std::size_t k = 0; k < own_; ++k) {
    const double* row = &arrived[kRow * k];
    keys[k] = {key_of(frame.code({row[0], row[1], row[2]}), std::uint32_t(row[4])), std::uint32_t(k)};
  }
  std::sort(keys.begin(), keys.end());

  // The layer: each rank's own spheres within reach of one of another rank's blocks (its own
  // spheres in runs of kSphereBlock, compact pieces of space: their boxes of centres), from their
  // owner. A sphere is tested against a rank's blocks only if it comes within reach of their box.
  constexpr std::size_t block = SphereSystem::kSphereBlock;
  std::vector<double> boxes(6 * ((own_ + block - 1) / block));
  double r_max = 0;
  for (std::size_t k = 0; k < own_; ++k) {
    double* box = &boxes[6 * (k / block)];
    const double* row = &arrived[kRow * keys[k].second];
    if (k % block == 0) clear_box(box);
    grow_box_by_point(box, row);
    r_max = std::max(r_max, row[3]);
  }
  const double reach = reach_radii * domain.max(r_max);
  boxes = gathered_lists(domain, boxes);  // every rank's, in rank order (its blocks from starts_[r] / block)
  out.assign(static_cast<std::size_t>(ranks), {});
  for (int t = 0; t < ranks; ++t) {
    const std::size_t b0 = starts_[std::size_t(t)] / block, b1 = (starts_[std::size_t(t) + 1] + block - 1) / block;
    if (t == me || b0 == b1) continue;
    double all[6];  // the box of rank t's blocks
    clear_box(all);
    for (std::size_t b = b0; b < b1; ++b) grow_box(all, &boxes[6 * b]);
    for (std::size_t k = 0; k < own_; ++k) {
      const double* row = &arrived[kRow * keys[k].second];
      const double point[6] = {row[0], row[1], row[2], row[0], row[1], row[2]};
      if (!boxes_within(point, all, reach)) continue;
      bool any = false;
      for (std::size_t b = b0; b < b1 && !any; ++b) any = boxes_within(point, &boxes[6 * b], reach);
      if (!any) continue;
      out[std::size_t(t)].insert(out[std::size_t(t)].end(), row, row + kRow);
      out[std::size_t(t)].push_back(double(begin_ + k));
    }
  }
  const std::vector<double> layer = exchanged_lists(domain, std::move(out));  // ranks in order, each ascending: ascending whole index
  const std::size_t layers = layer.size() / (kRow + 1);
  set_ = sphere_set_of_size(own_ + layers, true);
  for (std::size_t k = 0; k < own_; ++k) set_row(set_, k, &arrived[kRow * keys[k].second], density);
  layer_index_.resize(layers);
  for (std::size_t i = 0; i < layers; ++i) {
    set_row(set_, own_ + i, &layer[(kRow + 1) * i], density);
    layer_index_[i] = std::uint32_t(layer[(kRow + 1) * i + kRow]);
  }
}

int SpherePart::owner(std::size_t k) const {
  if (!domain_) return 0;
  return int(std::upper_bound(starts_.begin(), starts_.end(), k) - starts_.begin()) - 1;
}

bool SpherePart::holds(std::size_t k) const {
  return owns(k) || std::binary_search(layer_index_.begin(), layer_index_.end(), std::uint32_t(k));
}

std::size_t SpherePart::local(std::size_t k) const {
  if (owns(k)) return k - begin_;
  const auto at = std::lower_bound(layer_index_.begin(), layer_index_.end(), std::uint32_t(k));
  if (at == layer_index_.end() || *at != k)
    throw std::logic_error("SpherePart: sphere " + std::to_string(k) + " is neither this rank's nor in its layer");
  return own_ + std::size_t(at - layer_index_.begin());
}

double SpherePart::radius_min() const {
  double r = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < own_; ++k) r = std::min(r, set_.radius_m[k]);
  return domain_ ? -domain_->max(-r) : r;  // exact in any order
}

double SpherePart::radius_max() const {
  double r = 0;
  for (std::size_t k = 0; k < own_; ++k) r = std::max(r, set_.radius_m[k]);
  return domain_ ? domain_->max(r) : r;
}

double SpherePart::radius_mean() const {
  const auto add_own = [&](double sum) {
    for (std::size_t k = 0; k < own_; ++k) sum += set_.radius_m[k];
    return sum;
  };
  return (domain_ ? chained_sum(*domain_, add_own) : add_own(0.0)) / double(total_);
}

std::size_t SpherePart::arg_min(const std::function<std::pair<double, double>(std::size_t)>& key) const {
  const double inf = std::numeric_limits<double>::infinity();
  double best[3] = {inf, inf, inf};  // the key and the whole index
  for (std::size_t k = 0; k < own_; ++k) {
    const auto [a, b] = key(k);
    if (a < best[0] || (a == best[0] && b < best[1])) best[0] = a, best[1] = b, best[2] = double(begin_ + k);
  }
  if (!domain_) return std::size_t(best[2]);
  const auto all = gathered_lists(*domain_, {best, best + 3});
  std::size_t r = 0;  // ranks in whole-index order: the first of equal keys has the lowest index
  for (std::size_t q = 3; q < all.size(); q += 3)
    if (all[q] < all[r] || (all[q] == all[r] && all[q + 1] < all[r + 1])) r = q;
  return std::size_t(all[r + 2]);
}

std::vector<std::size_t> SpherePart::select(const std::function<bool(std::size_t)>& keep, bool by_packing_index) const {
  std::vector<double> mine;  // whole index, packing index
  for (std::size_t k = 0; k < own_; ++k)
    if (keep(k)) mine.insert(mine.end(), {double(begin_ + k), double(set_.packing_index[k])});
  const std::vector<double> all = domain_ ? gathered_lists(*domain_, mine) : mine;
  std::vector<std::size_t> order(all.size() / 2);
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  if (by_packing_index) std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return all[2 * i + 1] < all[2 * j + 1]; });
  std::vector<std::size_t> chosen(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) chosen[i] = std::size_t(all[2 * order[i]]);
  return chosen;
}

std::vector<double> SpherePart::gathered(const std::function<double(std::size_t)>& value) const {
  std::vector<double> mine(own_);
  for (std::size_t k = 0; k < own_; ++k) mine[k] = value(k);
  return domain_ ? gathered_lists(*domain_, mine) : mine;
}

Vec3 SpherePart::centre_of(std::size_t k) const {
  if (!domain_) return set_.centre_m[k];
  std::vector<int> counts(starts_.size() - 1, 0), displs(starts_.size() - 1, 0);
  counts[std::size_t(owner(k))] = 3;
  Vec3 c = owns(k) ? set_.centre_m[k - begin_] : Vec3{};
  double x[3] = {c.x, c.y, c.z};
  domain_->share(x, counts, displs);
  return {x[0], x[1], x[2]};
}

void SpherePart::fetch(std::vector<std::size_t> ids) {
  if (!domain_) return;
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  std::vector<double> mine;
  for (const std::size_t k : ids)
    if (owns(k)) append_row(set_, k - begin_, mine);
  const std::vector<double> all = gathered_lists(*domain_, mine);  // ranks in order: ascending ids
  std::vector<std::uint32_t> arrived;
  for (const std::size_t k : ids)
    if (!holds(k)) arrived.push_back(std::uint32_t(k));
  if (arrived.empty()) return;
  std::vector<std::uint32_t> layer(layer_index_.size() + arrived.size());
  std::merge(layer_index_.begin(), layer_index_.end(), arrived.begin(), arrived.end(), layer.begin());
  SphereSet next = sphere_set_of_size(own_ + layer.size(), true);
  std::vector<double> row;
  for (std::size_t l = 0; l < next.size(); ++l) {
    const std::size_t k = l < own_ ? begin_ + l : layer[l - own_];
    if (std::binary_search(arrived.begin(), arrived.end(), std::uint32_t(k))) {
      const auto at = std::size_t(std::lower_bound(ids.begin(), ids.end(), k) - ids.begin());
      set_row(next, l, &all[kRow * at], density_);
    } else {
      row.clear();
      append_row(set_, local(k), row);
      set_row(next, l, row.data(), density_);
    }
  }
  set_ = std::move(next);
  layer_index_ = std::move(layer);
}

SphereSet SpherePart::take_own() && {
  for (auto* v : {&set_.radius_m, &set_.mass_kg, &set_.inertia_kg_m2}) v->resize(own_), v->shrink_to_fit();
  set_.centre_m.resize(own_), set_.centre_m.shrink_to_fit();
  set_.packing_index.resize(own_), set_.packing_index.shrink_to_fit();
  set_.ids.resize(own_), set_.ids.shrink_to_fit();
  layer_index_.clear();
  return std::move(set_);
}

}  // namespace mesowave::dem
