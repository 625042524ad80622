// SphereSystem's distributed step (sphere_system.hpp, docs/mpi.md): the split of the
// spheres over the ranks, which contacts each rank computes, and what the ranks share
// after each step so that every one holds the single-process state, bit for bit.
//
// Why the bits match. A sphere's force is the sum, in a fixed order, of its contacts'
// results (interior contacts in slot order, then the cross-partition records in slot
// order, then the external load): the order is set by the slot layout, which every rank
// builds identically from the same (shared) positions, and a contact's result depends
// only on its two spheres' state and its own history, which the ranks holding it compute
// identically. A rank computes every contact with an end of its own (and so keeps those
// contacts' history itself), so its own spheres get every term in the serial order.
// The sums over contacts (elastic energy, plastic dissipation) are redone after the
// gather, per task in slot order as the single process adds them; the strength ratio is
// a max, exact in any order; the sums over spheres are kept per 256-sphere block, and a
// block is never split between ranks.
#include <algorithm>
#include <string>

#include "mesowave/core/error.hpp"
#include "mesowave/dem/engine/sphere_system.hpp"
#include "mesowave/dem/parallel/domain.hpp"

namespace mesowave::dem {

void Model::distribute(Domain& /*domain*/) {
  throw InputError("the " + name() + " model runs on one process only; on several MPI ranks run --model linear or full");
}

void SphereSystem::distribute(Domain& domain) {
  const std::size_t n = spheres_.size(), blocks = (n + kSphereBlock - 1) / kSphereBlock;
  const int ranks = domain.size(), me = domain.rank();
  if (std::size_t(ranks) > blocks)
    throw InputError(std::to_string(ranks) + " MPI ranks for " + std::to_string(n) + " spheres: each rank needs at least one block of " +
                     std::to_string(kSphereBlock) + " spheres; run on at most " + std::to_string(blocks) + " ranks");
  if (3 * n > std::size_t(0x7fffffff))
    throw InputError(std::to_string(n) + " spheres: more than MPI's int counts address in one exchange");
  domain_ = &domain;
  // Whole blocks in Morton order: rank r holds blocks [B r / N, B (r + 1) / N).
  sphere_counts_.assign(std::size_t(ranks), 0), sphere_displs_.assign(std::size_t(ranks), 0);
  block_counts_.assign(std::size_t(ranks), 0), block_displs_.assign(std::size_t(ranks), 0);
  for (int r = 0; r < ranks; ++r) {
    const std::size_t b0 = blocks * std::size_t(r) / std::size_t(ranks), b1 = blocks * std::size_t(r + 1) / std::size_t(ranks);
    const std::size_t s0 = b0 * kSphereBlock, s1 = std::min(n, b1 * kSphereBlock);
    block_displs_[std::size_t(r)] = int(b0), block_counts_[std::size_t(r)] = int(b1 - b0);
    sphere_displs_[std::size_t(r)] = int(3 * s0), sphere_counts_[std::size_t(r)] = int(3 * (s1 - s0));
    if (r == me) own_block_begin_ = b0, own_block_end_ = b1, own_begin_ = s0, own_end_ = s1;
  }
  lay_out_domain();
  broken_ = std::size_t(domain.sum(kernel_->broken_bonds_in(reported_)));
}

// After every new slot layout: the contacts this rank computes and the reporters.
void SphereSystem::lay_out_domain() {
  const std::size_t count = first_.size(), n = spheres_.size();
  const int ranks = domain_->size(), me = domain_->rank();
  const auto own = [&](std::uint32_t k) { return k >= own_begin_ && k < own_end_; };
  // The rank owning sphere k: the block's, by the same rule as distribute().
  const std::size_t blocks = (n + kSphereBlock - 1) / kSphereBlock;
  std::vector<int> block_owner(blocks);
  for (int r = 0; r < ranks; ++r)
    for (int b = 0; b < block_counts_[std::size_t(r)]; ++b) block_owner[std::size_t(block_displs_[std::size_t(r)] + b)] = r;
  slot_needed_.assign(count, 0);
  std::vector<std::uint8_t> ghost(n, 0);
  std::vector<std::vector<std::uint32_t>> by_rank(static_cast<std::size_t>(ranks));
  for (std::size_t s = 0; s < count; ++s) {
    const std::uint32_t i = first_[s], j = second_[s];
    slot_needed_[s] = own(i) || own(j);
    if (slot_needed_[s]) ghost[own(i) ? j : i] |= !own(own(i) ? j : i);
    by_rank[std::size_t(block_owner[i / kSphereBlock])].push_back(std::uint32_t(s));
  }
  ghosts_ = std::size_t(std::count(ghost.begin(), ghost.end(), 1));
  reported_ = by_rank[std::size_t(me)];
  reported_all_.clear();
  reported_counts_.assign(std::size_t(ranks), 0), reported_displs_.assign(std::size_t(ranks), 0);
  for (int r = 0; r < ranks; ++r) {
    reported_displs_[std::size_t(r)] = int(reported_all_.size());
    reported_counts_[std::size_t(r)] = int(by_rank[std::size_t(r)].size());
    reported_all_.insert(reported_all_.end(), by_rank[std::size_t(r)].begin(), by_rank[std::size_t(r)].end());
  }
  slot_elastic_.assign(count, 0), slot_plastic_.assign(count, 0), slot_ratio2_.assign(count, 0);
}

// One message a step: each rank's part - its spheres' motion, its blocks' sums, its reported
// contacts' plastic (and on energy steps elastic) parts, its largest strength ratio and its
// broken bonds - gathered to every rank, which then adds the task sums in slot order, as
// for_each_contact adds them in one process.
void SphereSystem::share_step(bool evaluate_energy) {
  const std::size_t count = first_.size();
  // Other ranks' spheres got this rank's share of their contacts: not theirs to keep.
  std::fill(f_acc_.begin(), f_acc_.begin() + std::ptrdiff_t(own_begin_), Vec3{});
  std::fill(t_acc_.begin(), t_acc_.begin() + std::ptrdiff_t(own_begin_), Vec3{});
  std::fill(f_acc_.begin() + std::ptrdiff_t(own_end_), f_acc_.end(), Vec3{});
  std::fill(t_acc_.begin() + std::ptrdiff_t(own_end_), t_acc_.end(), Vec3{});

  std::vector<Vec3>* motion[] = {&x_, &v_, &w_, &a_, &a_undamped_, &theta_};
  std::vector<double>* block_sums[] = {&sphere_block_kinetic_, &sphere_block_damping_, &sphere_block_vmax2_};
  const std::size_t vectors = track_rotation_ ? 6 : 5, per_contact = evaluate_energy ? 2 : 1;
  const int ranks = domain_->size(), me = domain_->rank();
  // Rank r's part: `vectors` x its spheres (3 doubles each), 3 x its blocks, per_contact x its reported contacts, 2.
  const auto part = [&](int r) {
    const std::size_t i = std::size_t(r);
    return vectors * std::size_t(sphere_counts_[i]) + 3 * std::size_t(block_counts_[i]) +
           per_contact * std::size_t(reported_counts_[i]) + 2;
  };
  std::vector<int> counts(static_cast<std::size_t>(ranks)), displs(static_cast<std::size_t>(ranks));
  std::size_t total = 0;
  for (int r = 0; r < ranks; ++r) {
    counts[std::size_t(r)] = int(part(r));
    displs[std::size_t(r)] = int(total);
    total += part(r);
  }
  if (total > std::size_t(0x7fffffff)) throw InputError("a distributed step's exchange exceeds MPI's int counts");
  send_.resize(part(me));
  {
    double* o = send_.data();
    const std::size_t s0 = own_begin_, s1 = own_end_;
    for (std::size_t v = 0; v < vectors; ++v) o = std::copy(&(*motion[v])[s0].x, &(*motion[v])[s0].x + 3 * (s1 - s0), o);
    for (auto* b : block_sums)
      o = std::copy(b->begin() + std::ptrdiff_t(own_block_begin_), b->begin() + std::ptrdiff_t(own_block_end_), o);
    double peak2 = 0;
    for (const std::uint32_t s : reported_) *o++ = slot_plastic_[s], peak2 = std::max(peak2, slot_ratio2_[s]);
    if (evaluate_energy)
      for (const std::uint32_t s : reported_) *o++ = slot_elastic_[s];
    *o++ = peak2;
    *o++ = double(kernel_->broken_bonds_in(reported_));  // exact: a count below 2^53
  }
  recv_.resize(total);
  domain_->gather_all(send_.data(), int(send_.size()), recv_.data(), counts, displs);

  double peak2 = 0;
  std::size_t broken = 0;
  for (int r = 0; r < ranks; ++r) {
    const std::size_t i = std::size_t(r);
    const double* in = recv_.data() + displs[i];
    const std::size_t s0 = std::size_t(sphere_displs_[i]) / 3, doubles = std::size_t(sphere_counts_[i]);
    for (std::size_t v = 0; v < vectors; ++v, in += doubles) std::copy(in, in + doubles, &(*motion[v])[s0].x);
    for (auto* b : block_sums) {
      std::copy(in, in + block_counts_[i], b->begin() + block_displs_[i]);
      in += block_counts_[i];
    }
    const std::size_t c = std::size_t(reported_counts_[i]), d = std::size_t(reported_displs_[i]);
    for (std::size_t k = 0; k < c; ++k) slot_plastic_[reported_all_[d + k]] = *in++;
    if (evaluate_energy)
      for (std::size_t k = 0; k < c; ++k) slot_elastic_[reported_all_[d + k]] = *in++;
    peak2 = std::max(peak2, *in++);
    broken += std::size_t(*in++);
  }
  broken_ = broken;

  const std::size_t tasks = partitions_ + cross_blocks_;
  for (std::size_t task = 0; task < tasks; ++task) {
    const bool interior = task < partitions_;
    const std::size_t begin = interior ? interior_start_[task] : cross_begin_ + (task - partitions_) * kContactBlock;
    const std::size_t end = interior ? interior_start_[task + 1] : std::min(count, begin + kContactBlock);
    double elastic = 0, plastic = 0;
    for (std::size_t s = begin; s < end; ++s) plastic += slot_plastic_[s];
    task_plastic_[task] += plastic;
    if (evaluate_energy) {
      for (std::size_t s = begin; s < end; ++s) elastic += slot_elastic_[s];
      task_elastic_[task] = elastic;
    }
    task_peak2_[task] = 0;
  }
  if (tasks > 0) task_peak2_[0] = peak2;  // a max: exact in any order
}

std::size_t SphereSystem::broken_bond_count() const { return domain_ ? broken_ : kernel_->broken_bond_count(); }

std::string SphereSystem::distribution() const {
  if (!domain_) return {};
  return "rank " + std::to_string(domain_->rank()) + " of " + std::to_string(domain_->size()) + ": spheres " +
         std::to_string(own_begin_) + "-" + std::to_string(own_end_) + " of " + std::to_string(spheres_.size()) +
         " (Morton order), " + std::to_string(ghosts_) + " ghosts, " +
         std::to_string(std::count(slot_needed_.begin(), slot_needed_.end(), 1)) + " of " +
         std::to_string(first_.size()) + " contacts computed here";
}

}  // namespace mesowave::dem
