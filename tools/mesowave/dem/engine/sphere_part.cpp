#include "mesowave/dem/engine/sphere_part.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "mesowave/dem/engine/sphere_system.hpp"
#include "mesowave/dem/parallel/domain.hpp"

namespace mesowave::dem {
namespace {

// What travels of a sphere: centre (3), radius, mass, inertia, packing index, packing file id.
constexpr std::size_t kRecord = 8;

void append_record(const SphereSet& s, std::size_t k, std::vector<double>& out) {
  const Vec3& c = s.centre_m[k];
  out.insert(out.end(), {c.x, c.y, c.z, s.radius_m[k], s.mass_kg[k], s.inertia_kg_m2[k], double(s.packing_index[k]),
                         double(s.ids[k])});  // indices and ids exact below 2^53
}

void set_record(SphereSet& s, std::size_t k, const double* r) {
  s.centre_m[k] = {r[0], r[1], r[2]};
  s.radius_m[k] = r[3], s.mass_kg[k] = r[4], s.inertia_kg_m2[k] = r[5];
  s.packing_index[k] = std::uint32_t(r[6]);
  s.ids[k] = std::int64_t(r[7]);
}

SphereSet sized(std::size_t n) {
  SphereSet s;
  s.centre_m.resize(n), s.radius_m.resize(n), s.mass_kg.resize(n), s.inertia_kg_m2.resize(n);
  s.packing_index.resize(n), s.ids.resize(n);
  return s;
}

// Every rank's `mine` (lists of any length), in rank order, on every rank.
std::vector<double> gather_lists(Domain& domain, const std::vector<double>& mine) {
  const int ranks = domain.size();
  std::vector<int> ones(static_cast<std::size_t>(ranks), 1), at(static_cast<std::size_t>(ranks));
  for (int r = 0; r < ranks; ++r) at[std::size_t(r)] = r;
  const double length = double(mine.size());
  std::vector<double> lengths(static_cast<std::size_t>(ranks));
  domain.gather_all(&length, 1, lengths.data(), ones, at);
  std::vector<int> counts(static_cast<std::size_t>(ranks)), displs(static_cast<std::size_t>(ranks));
  std::size_t total = 0;
  for (int r = 0; r < ranks; ++r) {
    counts[std::size_t(r)] = int(lengths[std::size_t(r)]), displs[std::size_t(r)] = int(total);
    total += std::size_t(lengths[std::size_t(r)]);
  }
  std::vector<double> all(total);
  domain.gather_all(mine.data(), int(mine.size()), all.data(), counts, displs);
  return all;
}

}  // namespace

SpherePart::SpherePart(SphereSet whole) : set_(std::move(whole)) {
  own_ = total_ = set_.size();
  if (set_.ids.size() != own_) set_.ids.assign(own_, 0);  // sets made in tests carry none
}

SpherePart::SpherePart(const SphereSet& whole, Domain& domain, double reach_m) : total_(whole.size()), domain_(&domain) {
  const std::vector<std::size_t> starts = SphereSystem::rank_starts(total_, domain.size());
  begin_ = starts[std::size_t(domain.rank())];
  own_ = starts[std::size_t(domain.rank()) + 1] - begin_;
  const double inf = std::numeric_limits<double>::infinity();
  Vec3 lo{inf, inf, inf}, hi{-inf, -inf, -inf};
  for (std::size_t k = begin_; k < begin_ + own_; ++k)
    for (int d = 0; d < 3; ++d) lo[d] = std::min(lo[d], whole.centre_m[k][d]), hi[d] = std::max(hi[d], whole.centre_m[k][d]);
  for (std::size_t k = 0; k < total_; ++k) {
    if (owns(k)) continue;
    double gap2 = 0;
    for (int d = 0; d < 3; ++d) {
      const double gap = std::max({0.0, lo[d] - whole.centre_m[k][d], whole.centre_m[k][d] - hi[d]});
      gap2 += gap * gap;
    }
    if (gap2 <= reach_m * reach_m) layer_index_.push_back(std::uint32_t(k));
  }
  set_ = sized(own_ + layer_index_.size());
  std::vector<double> record;
  for (std::size_t l = 0; l < set_.size(); ++l) {
    record.clear();
    append_record(whole, whole_index(l), record);
    set_record(set_, l, record.data());
  }
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
  const auto all = gather_lists(*domain_, {best, best + 3});
  std::size_t r = 0;  // ranks in whole-index order: the first of equal keys has the lowest index
  for (std::size_t q = 3; q < all.size(); q += 3)
    if (all[q] < all[r] || (all[q] == all[r] && all[q + 1] < all[r + 1])) r = q;
  return std::size_t(all[r + 2]);
}

std::vector<std::size_t> SpherePart::select(const std::function<bool(std::size_t)>& keep, bool by_packing_index) const {
  std::vector<double> mine;  // whole index, packing index
  for (std::size_t k = 0; k < own_; ++k)
    if (keep(k)) mine.insert(mine.end(), {double(begin_ + k), double(set_.packing_index[k])});
  const std::vector<double> all = domain_ ? gather_lists(*domain_, mine) : mine;
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
  return domain_ ? gather_lists(*domain_, mine) : mine;
}

Vec3 SpherePart::centre_of(std::size_t k) const {
  if (!domain_) return set_.centre_m[k];
  const std::vector<std::size_t> starts = SphereSystem::rank_starts(total_, domain_->size());
  const auto owner = std::size_t(std::upper_bound(starts.begin(), starts.end(), k) - starts.begin()) - 1;
  std::vector<int> counts(starts.size() - 1, 0), displs(starts.size() - 1, 0);
  counts[owner] = 3;
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
    if (owns(k)) append_record(set_, k - begin_, mine);
  const std::vector<double> all = gather_lists(*domain_, mine);  // ranks in order: ascending ids
  std::vector<std::uint32_t> arrived;
  for (const std::size_t k : ids)
    if (!holds(k)) arrived.push_back(std::uint32_t(k));
  if (arrived.empty()) return;
  std::vector<std::uint32_t> layer(layer_index_.size() + arrived.size());
  std::merge(layer_index_.begin(), layer_index_.end(), arrived.begin(), arrived.end(), layer.begin());
  SphereSet next = sized(own_ + layer.size());
  std::vector<double> record;
  for (std::size_t l = 0; l < next.size(); ++l) {
    const std::size_t k = l < own_ ? begin_ + l : layer[l - own_];
    if (std::binary_search(arrived.begin(), arrived.end(), std::uint32_t(k))) {
      const auto at = std::size_t(std::lower_bound(ids.begin(), ids.end(), k) - ids.begin());
      set_record(next, l, &all[kRecord * at]);
    } else {
      record.clear();
      append_record(set_, local(k), record);
      set_record(next, l, record.data());
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
