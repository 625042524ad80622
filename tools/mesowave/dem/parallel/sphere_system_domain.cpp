// SphereSystem's distributed step (sphere_system.hpp, docs/mpi.md): the split of the
// spheres over the ranks, which contacts each rank computes, the ghosts it receives, and
// what the ranks share after each step so that each holds the single-process state of its
// own spheres, its ghosts and the observed spheres, bit for bit.
//
// Why the bits match. A sphere's force is the sum, in a fixed order, of its contacts'
// results (interior contacts in slot order, then the cross-partition records in slot
// order, then the external load): the order is set by the slot layout, which every rank
// places its contacts in identically (set_contacts: from each rank's counts, each rank giving
// the contacts it detects, spheres_near_own), and a contact's result depends only on its two
// spheres' state and its own history. A rank holds
// and computes only the contacts with an end of its own (stage 3: the whole layout's slots,
// filtered, in their order), and keeps their history
// itself; the other end is its own or a ghost, received from its owner after every step
// (stage 2: only the ghosts, point to point, instead of the whole state). So its own spheres
// get every term in the serial order from the serial inputs.
// The sums over contacts (elastic energy, plastic dissipation) are redone from the
// reporters' per-slot values, per task of the whole layout in its slot order as the single
// process adds them; the strength ratio and the speed bound are maxima, exact in any order;
// the sums over spheres are kept per 256-sphere block, and a block is never split between ranks. The actuators and
// sensors run on every rank, as in one process, on the observed spheres, which every rank
// holds: their sums (sensor averages, wall forces, external work) keep the serial order.
// A contact across two ranks is held and computed on both; its forces on the other rank's
// sphere are cleared after the step, and its energies come from its reporter.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/dem/engine/centre_box.hpp"
#include "mesowave/dem/engine/sphere_system.hpp"
#include "mesowave/dem/engine/state_group.hpp"
#include "mesowave/dem/parallel/domain.hpp"

namespace mesowave::dem {
namespace {

// Test-only (tests/cli/mw_dem_mpi_test.cpp): MESOWAVE_TEST_GHOST_LAYER_MM keeps as ghosts only
// the partners whose step-0 centre is closer than that to their contact's own end's, on the rank
// MESOWAVE_TEST_GHOST_LAYER_RANK (all if unset), so that the missing-partner check is seen to fire.
double test_ghost_layer_m() {
  const char* v = std::getenv("MESOWAVE_TEST_GHOST_LAYER_MM");
  return v ? std::atof(v) * 1e-3 : std::numeric_limits<double>::infinity();
}
int test_ghost_layer_rank() {
  const char* v = std::getenv("MESOWAVE_TEST_GHOST_LAYER_RANK");
  return v ? std::atoi(v) : -1;
}

// Test-only (tests/cli/mw_dem_mpi_test.cpp): MESOWAVE_TEST_CHECKPOINT_PIECE_ROWS writes a
// distributed checkpoint's arrays in pieces of that many rows (StateGroup::kPieceRows otherwise),
// so that a small model's pieces cut the ranks' ranges and the reporters' runs.
std::size_t checkpoint_piece_rows() {
  const char* v = std::getenv("MESOWAVE_TEST_CHECKPOINT_PIECE_ROWS");
  return v && std::atol(v) > 0 ? std::size_t(std::atol(v)) : StateGroup::kPieceRows;
}

void sort_unique(std::vector<std::uint32_t>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

}  // namespace

void refuse_ranks(const std::string& model) {
  throw InputError("the " + model + " model runs on one process only; on several MPI ranks run --model linear or full");
}

void Model::distribute(Domain& /*domain*/, const std::vector<std::size_t>& /*observed*/) { refuse_ranks(name()); }

std::vector<std::size_t> SphereSystem::rank_starts(std::size_t n, int ranks) {
  const std::size_t blocks = (n + kSphereBlock - 1) / kSphereBlock;
  std::vector<std::size_t> starts(std::size_t(ranks) + 1);
  for (int r = 0; r <= ranks; ++r) starts[std::size_t(r)] = std::min(n, blocks * std::size_t(r) / std::size_t(ranks) * kSphereBlock);
  return starts;
}

// Called by the constructor, before the law lays out its contacts, so that no rank ever holds
// all of them: the owners of the spheres.
void SphereSystem::split(Domain& domain) {
  const std::size_t n = sphere_total_, blocks = (n + kSphereBlock - 1) / kSphereBlock;
  const int ranks = domain.size(), me = domain.rank();
  if (std::size_t(ranks) > blocks)
    throw InputError(std::to_string(ranks) + " MPI ranks for " + std::to_string(n) + " spheres: each rank needs at least one block of " +
                     std::to_string(kSphereBlock) + " spheres; run on at most " + std::to_string(blocks) + " ranks");
  if (3 * n > std::size_t(0x7fffffff))
    throw InputError(std::to_string(n) + " spheres: more than MPI's int counts address in one exchange");
  domain_ = &domain;
  rank_ = me;
  ghost_layer_m_ = test_ghost_layer_m(), ghost_layer_rank_ = test_ghost_layer_rank();
  const std::vector<std::size_t> starts = rank_starts(n, ranks);
  sphere_counts_.assign(std::size_t(ranks), 0), sphere_displs_.assign(std::size_t(ranks), 0);
  block_counts_.assign(std::size_t(ranks), 0), block_displs_.assign(std::size_t(ranks), 0);
  block_owner_.resize(blocks);
  for (int r = 0; r < ranks; ++r) {
    const std::size_t s0 = starts[std::size_t(r)], s1 = starts[std::size_t(r) + 1];
    const std::size_t b0 = s0 / kSphereBlock, b1 = (s1 + kSphereBlock - 1) / kSphereBlock;
    std::fill(block_owner_.begin() + std::ptrdiff_t(b0), block_owner_.begin() + std::ptrdiff_t(b1), r);
    block_displs_[std::size_t(r)] = int(b0), block_counts_[std::size_t(r)] = int(b1 - b0);
    sphere_displs_[std::size_t(r)] = int(3 * s0), sphere_counts_[std::size_t(r)] = int(3 * (s1 - s0));
    if (r == me) own_block_begin_ = b0, own_block_end_ = b1, own_begin_ = s0, own_end_ = s1;
  }
}

void SphereSystem::distribute(Domain& domain, const std::vector<std::size_t>& observed) {
  if (domain_ != &domain)
    throw std::logic_error("SphereSystem::distribute: the system was not made for this domain (LawInput::domain)");
  const int ranks = domain.size();
  // The observed spheres, sorted by id: each rank's are one contiguous run of the list.
  observed_.assign(observed.begin(), observed.end());
  sort_unique(observed_);
  observed_counts_.assign(std::size_t(ranks), 0), observed_displs_.assign(std::size_t(ranks), 0);
  for (int r = 0, k = 0; r < ranks; ++r) {
    observed_displs_[std::size_t(r)] = k;
    const std::uint32_t end = std::uint32_t((sphere_displs_[std::size_t(r)] + sphere_counts_[std::size_t(r)]) / 3);
    while (std::size_t(k) < observed_.size() && observed_[std::size_t(k)] < end) ++k;
    observed_counts_[std::size_t(r)] = k - observed_displs_[std::size_t(r)];
  }
  // Their statics, from their owners (one gather: every rank holds every observed sphere).
  std::vector<int> counts(static_cast<std::size_t>(ranks)), displs(static_cast<std::size_t>(ranks));
  for (int r = 0; r < ranks; ++r)
    counts[std::size_t(r)] = int(kStatics) * observed_counts_[std::size_t(r)], displs[std::size_t(r)] = int(kStatics) * observed_displs_[std::size_t(r)];
  std::vector<double> mine, all(kStatics * observed_.size());
  for (int q = observed_displs_[std::size_t(rank_)], e = q + observed_counts_[std::size_t(rank_)]; q < e; ++q)
    append_statics(own_local(observed_[std::size_t(q)]), mine);
  domain.gather_all(mine.data(), int(mine.size()), all.data(), counts, displs);
  // The observed spheres join the held ones (the contacts' ends are renumbered with them).
  for (auto* ends : {&first_, &second_})
    for (std::uint32_t& k : *ends) k = held_ids_[k];
  std::vector<std::uint32_t> ids(held_ids_);
  ids.insert(ids.end(), observed_.begin(), observed_.end());
  sort_unique(ids);
  hold(std::move(ids), statics_from(all.data(), observed_.size()), observed_);
  number_contacts_locally();
  ghosts_stale_ = false;  // at step 0 every rank holds the same (initial) state of every sphere
  broken_ = std::size_t(domain.sum(kernel_->broken_bonds_in(reported_)));
}

std::size_t SphereSystem::global_task_of(std::size_t s) const {
  if (s >= global_cross_begin_) return partitions_ + (s - global_cross_begin_) / kContactBlock;
  return std::size_t(std::upper_bound(global_interior_start_.begin(), global_interior_start_.end(), std::uint32_t(s)) -
                     global_interior_start_.begin()) - 1;
}

template <class F>
void SphereSystem::for_each_reporter(std::size_t begin, std::size_t end, const F& f) const {
  if (begin >= end) return;
  auto run = std::upper_bound(slot_runs_.begin(), slot_runs_.end(), begin,
                              [](std::size_t s, const std::pair<std::uint32_t, int>& r) { return s < r.first; });
  for (--run; run != slot_runs_.end() && run->first < end; ++run) {
    const std::size_t run_end = run + 1 != slot_runs_.end() ? (run + 1)->first : global_slots_;
    f(run->second, std::max<std::size_t>(begin, run->first), std::min(end, run_end));
  }
}

// Each rank's held contacts (an end of its own) in the whole list's order: bonds, then pairs.
// The whole layout puts, group by group (the partitions' interiors, then the contacts across
// them), the group's bonds before its pairs, and each of these rank after rank (the whole list's
// order, sorted by first sphere, is the reporters' order): so a count a rank, group and part
// places every run, and a reporter counts its slots off its runs. A contact across two ranks
// gets its slot from its reporter, which sends (slot, first, second) in the held order, the
// same on both sides: both detect it, from the same positions.
std::vector<std::uint32_t> SphereSystem::lay_out_held(const std::vector<std::uint32_t>& first,
                                                      const std::vector<std::uint32_t>& second, std::size_t bonds) {
  const int ranks = domain_->size(), me = rank_;
  const std::size_t count = first.size(), groups = partitions_ + 1, parts = 2 * groups;
  const auto part_of = [&](std::size_t c) {
    const std::size_t p = first[c] / sphere_chunk_;
    return (c < bonds ? 0 : groups) + (p == second[c] / sphere_chunk_ ? p : partitions_);
  };
  std::vector<double> mine(parts, 0.0), all(parts * std::size_t(ranks));
  for (std::size_t c = 0; c < count; ++c) {
    if (!is_own(first[c]) && !is_own(second[c]))
      throw std::logic_error("SphereSystem::set_contacts: a contact with no end of this rank's own");
    if (is_own(first[c])) mine[part_of(c)] += 1;  // exact below 2^53
  }
  std::vector<int> counts(static_cast<std::size_t>(ranks), int(parts)), displs(static_cast<std::size_t>(ranks));
  for (int r = 0; r < ranks; ++r) displs[std::size_t(r)] = int(parts) * r;
  domain_->gather_all(mine.data(), int(parts), all.data(), counts, displs);
  std::vector<std::size_t> next(parts);  // this rank's next slot in each part
  global_interior_start_.assign(partitions_ + 1, 0);
  slot_runs_.clear();
  std::size_t slot = 0;
  for (std::size_t g = 0; g < groups; ++g) {
    if (g < partitions_) global_interior_start_[g] = std::uint32_t(slot);
    else global_cross_begin_ = slot;
    for (const std::size_t part : {g, groups + g})
      for (int r = 0; r < ranks; ++r) {
        if (r == me) next[part] = slot;
        const auto n = std::size_t(all[std::size_t(r) * parts + part]);
        if (n > 0 && (slot_runs_.empty() || slot_runs_.back().second != r)) slot_runs_.emplace_back(std::uint32_t(slot), r);
        slot += n;
      }
  }
  global_interior_start_[partitions_] = std::uint32_t(global_cross_begin_);
  global_slots_ = slot;
  if (global_slots_ > std::size_t(0xffffffff))
    throw InputError(std::to_string(global_slots_) + " contacts: more than 32-bit slots address");

  std::vector<std::uint32_t> slot_of(count);
  std::vector<std::vector<double>> out(static_cast<std::size_t>(ranks)), in(static_cast<std::size_t>(ranks));
  std::vector<std::vector<std::uint32_t>> waiting(static_cast<std::size_t>(ranks));  // held contacts reported elsewhere
  // Every contact across two ranks is sent once and expected once (pair_hash; a disagreement is
  // a detection layer that missed a sphere).
  const auto hash = [&](std::size_t c) { return pair_hash(first[c], second[c]); };
  std::uint64_t unmatched = 0;
  for (std::size_t c = 0; c < count; ++c) {
    if (const int oi = owner(first[c]); oi != me) {
      waiting[std::size_t(oi)].push_back(std::uint32_t(c));
      unmatched -= hash(c);
      continue;
    }
    slot_of[c] = std::uint32_t(next[part_of(c)]++);
    if (const int oj = owner(second[c]); oj != me) {
      out[std::size_t(oj)].insert(out[std::size_t(oj)].end(), {double(slot_of[c]), double(first[c]), double(second[c])});
      unmatched += hash(c);
    }
  }
  if (domain_->sum(unmatched) != 0)
    throw std::logic_error("the ranks disagree on the contacts across them: one holds a contact its other end's rank "
                           "does not (contact detection's ghost layer missed a sphere)");
  std::vector<Domain::Message> sends, receives;
  for (int r = 0; r < ranks; ++r) {
    auto& o = out[std::size_t(r)];
    auto& i = in[std::size_t(r)];
    if (!o.empty()) sends.push_back({r, o.data(), int(o.size())});
    if (!waiting[std::size_t(r)].empty()) {
      i.assign(3 * waiting[std::size_t(r)].size(), -1.0);
      receives.push_back({r, i.data(), int(i.size())});
    }
  }
  domain_->exchange(sends, receives);
  for (int r = 0; r < ranks; ++r)
    for (std::size_t k = 0; k < waiting[std::size_t(r)].size(); ++k) {
      const std::uint32_t c = waiting[std::size_t(r)][k];
      const double* t = &in[std::size_t(r)][3 * k];
      if (t[1] != double(first[c]) || t[2] != double(second[c]))
        throw std::logic_error("rank " + std::to_string(me) + ": its contacts with rank " + std::to_string(r) +
                               " are not the ones that rank reports (the contact between spheres " + std::to_string(first[c]) +
                               " and " + std::to_string(second[c]) + ")");
      slot_of[c] = std::uint32_t(t[0]);
    }

  std::vector<std::uint32_t> order(count);
  for (std::size_t c = 0; c < count; ++c) order[c] = std::uint32_t(c);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return slot_of[a] < slot_of[b]; });
  global_slot_.resize(count);
  for (std::size_t s = 0; s < count; ++s) global_slot_[s] = slot_of[order[s]];
  interior_start_.resize(partitions_ + 1);
  for (std::size_t p = 0; p <= partitions_; ++p)
    interior_start_[p] = std::uint32_t(std::lower_bound(global_slot_.begin(), global_slot_.end(), global_interior_start_[p]) -
                                       global_slot_.begin());
  return order;
}

// After every new slot layout (set_contacts; first_/second_ in global ids):
// the reporters, the ghost lists and who adds which task's elastic sum; then the held spheres
// (hold: own, ghosts, observed) and the contacts' local ids.
void SphereSystem::lay_out_domain() {
  const std::size_t count = first_.size();
  const int ranks = domain_->size(), me = domain_->rank();
  reported_.clear();
  std::vector<std::vector<std::uint32_t>> sends(static_cast<std::size_t>(ranks)), receives(static_cast<std::size_t>(ranks));
  for (std::size_t s = 0; s < count; ++s) {
    const std::uint32_t i = first_[s], j = second_[s];
    const int oi = owner(i), oj = owner(j);
    if (oi == me) reported_.push_back(std::uint32_t(s));
    if (oi == oj) continue;
    // A contact across two ranks: each needs the other's end. Both sides list it from the same layout.
    const std::uint32_t mine = oi == me ? i : j, theirs = oi == me ? j : i;
    const int other = oi == me ? oj : oi;
    sends[std::size_t(other)].push_back(mine);
    receives[std::size_t(other)].push_back(theirs);
  }
  ghost_sends_.clear(), ghost_receives_.clear();
  std::vector<std::uint32_t> ghosts;  // every rank's in rank order, so sorted by id
  for (int r = 0; r < ranks; ++r) {
    auto& out = sends[std::size_t(r)];
    auto& in = receives[std::size_t(r)];
    sort_unique(out), sort_unique(in);
    if (!out.empty()) ghost_sends_.push_back({r, std::move(out), {}});
    if (!in.empty()) {
      ghosts.insert(ghosts.end(), in.begin(), in.end());
      ghost_receives_.push_back({r, std::move(in), {}});
    }
  }
  ghosts_ = ghosts.size();
  const SphereSet arrived = ghost_statics();  // every ghost's, in `ghosts` order
  const auto ghost_at = [&](std::uint32_t k) {
    const auto at = std::lower_bound(ghosts.begin(), ghosts.end(), k);
    return at != ghosts.end() && *at == k ? std::size_t(at - ghosts.begin()) : kNotHeld;
  };
  const auto centre = [&](std::uint32_t k) { return is_own(k) ? spheres_.centre_m[own_local(k)] : arrived.centre_m[ghost_at(k)]; };
  // The test's thinned layer (test_ghost_layer_m) keeps a ghost only if one of its contacts
  // here spans at most that at step 0.
  std::vector<std::uint8_t> kept(ghosts.size(), 1);
  if (std::isfinite(ghost_layer_m_) && (ghost_layer_rank_ < 0 || ghost_layer_rank_ == me)) {
    std::fill(kept.begin(), kept.end(), std::uint8_t(0));
    for (std::size_t s = 0; s < count; ++s) {
      const std::uint32_t i = first_[s], j = second_[s];
      if (owner(i) == owner(j)) continue;
      const std::uint32_t theirs = is_own(i) ? j : i;
      if (norm(centre(j) - centre(i)) <= ghost_layer_m_) kept[ghost_at(theirs)] = 1;
    }
  }
  // Never silently lost: every contact of this rank's spheres must find its other end here.
  const auto here = [&](std::uint32_t k) {
    if (is_own(k)) return true;
    const std::size_t g = ghost_at(k);
    return g != kNotHeld && kept[g] != 0;
  };
  for (std::size_t s = 0; s < count; ++s) {
    if (here(first_[s]) && here(second_[s])) continue;
    const std::uint32_t i = first_[s], j = second_[s], missing = here(i) ? j : i;
    const auto at = std::lower_bound(bonds_.first.begin(), bonds_.first.end(), i);
    std::size_t bond = bonds_.size();
    for (auto b = std::size_t(at - bonds_.first.begin()); b < bonds_.size() && bonds_.first[b] == i; ++b)
      if (bonds_.second[b] == j) bond = b;
    const bool known = is_own(missing) || ghost_at(missing) != kNotHeld;  // a ghost the thinned layer dropped
    const auto name = [&](std::uint32_t k) {
      if (is_own(k)) return std::to_string(spheres_.packing_index[own_local(k)]) + " (packing id)";
      if (const std::size_t g = ghost_at(k); g != kNotHeld) return std::to_string(arrived.packing_index[g]) + " (packing id)";
      return std::to_string(k) + " (Morton order)";
    };
    throw InputError("rank " + std::to_string(me) + " of " + std::to_string(ranks) + ": " +
                     (bond < bonds_.size() ? "bond " + std::to_string(held_bond_id(bond)) : std::string("the contact")) +
                     " between spheres " + name(i) + " and " + name(j) + " has lost its partner: sphere " + name(missing) +
                     " is neither held nor a ghost on this rank (ghost layer " + format_number(ghost_layer_m_ * 1e3) + " mm" +
                     (known ? ", the spheres " + format_number(norm(centre(j) - centre(i)) * 1e3) + " mm apart at step 0" : "") +
                     "): the layer must reach at least the longest bond plus the motion between exchanges");
  }
  // The per-slot values are written by every step before they are read; they (and the owned
  // tasks' values) are allocated by the first step that needs them, not here: at setup the
  // critical step's Lanczos vectors would be held beside them (the peak, docs/mpi.md).
  for (auto* values : {&slot_elastic_, &slot_plastic_, &owned_values_}) std::vector<double>().swap(*values);

  // The elastic sum of each task of the whole layout is taken, in slot order, by the rank that
  // reports most of its slots (ties: the lowest); the reporters of its other slots send it
  // their values (point to point), in slot order on both sides.
  const std::size_t tasks = partitions_ + global_cross_blocks_, slots = global_slots_;
  const auto task_range = [&](std::size_t task) {
    const bool interior = task < partitions_;
    const std::size_t begin =
        interior ? global_interior_start_[task] : global_cross_begin_ + (task - partitions_) * kContactBlock;
    return std::pair{begin, interior ? std::size_t(global_interior_start_[task + 1]) : std::min(slots, begin + kContactBlock)};
  };
  task_owner_.assign(tasks, 0);
  task_counts_.assign(std::size_t(ranks), 0);
  std::vector<std::size_t> tally(static_cast<std::size_t>(ranks));
  for (std::size_t task = 0; task < tasks; ++task) {
    const auto [begin, end] = task_range(task);
    std::fill(tally.begin(), tally.end(), 0);
    for_each_reporter(begin, end, [&](int r, std::size_t lo, std::size_t hi) { tally[std::size_t(r)] += hi - lo; });
    task_owner_[task] = int(std::max_element(tally.begin(), tally.end()) - tally.begin());
    ++task_counts_[std::size_t(task_owner_[task])];
  }
  // This rank's tasks' places (the values in slot order), and who fills each place.
  owned_tasks_.clear(), owned_start_.assign(1, 0);
  std::vector<std::vector<std::uint32_t>> from(static_cast<std::size_t>(ranks));
  for (std::size_t task = 0; task < tasks; ++task) {
    if (task_owner_[task] != me) continue;
    const auto [begin, end] = task_range(task);
    for_each_reporter(begin, end, [&](int r, std::size_t lo, std::size_t hi) {
      if (r != me)
        for (std::size_t s = lo; s < hi; ++s) from[std::size_t(r)].push_back(std::uint32_t(owned_start_.back() + s - begin));
    });
    owned_tasks_.push_back(std::uint32_t(task));
    owned_start_.push_back(std::uint32_t(owned_start_.back() + end - begin));
  }
  std::vector<std::vector<std::uint32_t>> to(static_cast<std::size_t>(ranks));
  own_elastic_.clear();
  for (const std::uint32_t s : reported_) {
    const std::size_t g = global_slot(s), task = global_task_of(g);
    const int q = task_owner_[task];
    if (q != me) {
      to[std::size_t(q)].push_back(s);
      continue;
    }
    const std::size_t k = std::size_t(std::lower_bound(owned_tasks_.begin(), owned_tasks_.end(), std::uint32_t(task)) - owned_tasks_.begin());
    own_elastic_.emplace_back(s, std::uint32_t(owned_start_[k] + g - task_range(task).first));
  }
  elastic_sends_.clear(), elastic_receives_.clear();
  for (int r = 0; r < ranks; ++r) {
    if (!to[std::size_t(r)].empty()) elastic_sends_.push_back({r, std::move(to[std::size_t(r)]), {}});
    if (!from[std::size_t(r)].empty()) elastic_receives_.push_back({r, std::move(from[std::size_t(r)]), {}});
  }
  std::vector<std::uint32_t> ids(observed_);
  for (std::size_t k = own_begin_; k < own_end_; ++k) ids.push_back(std::uint32_t(k));
  ids.insert(ids.end(), ghosts.begin(), ghosts.end());
  sort_unique(ids);
  hold(std::move(ids), arrived, ghosts);
  number_contacts_locally();
  ghosts_stale_ = true;
}

void SphereSystem::append_statics(std::size_t l, std::vector<double>& out) const {
  const Vec3& c = spheres_.centre_m[l];
  out.insert(out.end(), {c.x, c.y, c.z, spheres_.radius_m[l], spheres_.mass_kg[l], spheres_.inertia_kg_m2[l],
                         double(spheres_.packing_index[l])});  // exact below 2^53
}

SphereSet SphereSystem::statics_from(const double* values, std::size_t count) {
  SphereSet s;
  for (std::size_t q = 0; q < count; ++q) {
    const double* v = values + kStatics * q;
    s.centre_m.push_back({v[0], v[1], v[2]});
    s.radius_m.push_back(v[3]);
    s.mass_kg.push_back(v[4]);
    s.inertia_kg_m2.push_back(v[5]);
    s.packing_index.push_back(std::uint32_t(v[6]));
  }
  return s;
}

// Point to point, as the motion goes (exchange_ghosts). Only a new ghost needs them, but only its
// receiver knows which are new; a layout is rare beside the steps (docs/mpi.md).
SphereSet SphereSystem::ghost_statics() {
  std::vector<Domain::Message> sends, receives;
  std::vector<std::vector<double>> out(ghost_sends_.size());
  for (std::size_t g = 0; g < ghost_sends_.size(); ++g) {
    for (const std::uint32_t k : ghost_sends_[g].spheres) append_statics(own_local(k), out[g]);
    sends.push_back({ghost_sends_[g].rank, out[g].data(), int(out[g].size())});
  }
  std::size_t count = 0;
  for (const auto& g : ghost_receives_) count += g.spheres.size();
  std::vector<double> in(kStatics * count);
  count = 0;
  for (const auto& g : ghost_receives_) {
    receives.push_back({g.rank, in.data() + kStatics * count, int(kStatics * g.spheres.size())});
    count += g.spheres.size();
  }
  domain_->exchange(sends, receives);
  return statics_from(in.data(), count);
}

// Energy steps: the elastic parts to each task's owner, which adds them in slot order; the task
// sums then to every rank (in owner then task order), so every rank holds every task's sum.
void SphereSystem::share_elastic() {
  owned_values_.resize(owned_start_.back());  // every place is filled below
  std::vector<Domain::Message> sends, receives;
  for (auto& g : elastic_sends_) {
    g.buffer.resize(g.spheres.size());
    for (std::size_t k = 0; k < g.spheres.size(); ++k) g.buffer[k] = slot_elastic_[g.spheres[k]];
    sends.push_back({g.rank, g.buffer.data(), int(g.buffer.size())});
  }
  for (auto& g : elastic_receives_) {
    g.buffer.resize(g.spheres.size());
    receives.push_back({g.rank, g.buffer.data(), int(g.buffer.size())});
    shared_doubles_ += g.buffer.size();
  }
  domain_->exchange(sends, receives);
  for (const auto& g : elastic_receives_)
    for (std::size_t k = 0; k < g.spheres.size(); ++k) owned_values_[g.spheres[k]] = g.buffer[k];
  for (const auto& [slot, place] : own_elastic_) owned_values_[place] = slot_elastic_[slot];
  std::vector<double> mine;
  for (std::size_t k = 0; k < owned_tasks_.size(); ++k) {
    double elastic = 0;
    for (std::size_t v = owned_start_[k]; v < owned_start_[k + 1]; ++v) elastic += owned_values_[v];
    mine.push_back(elastic);
  }
  const int ranks = domain_->size();
  std::vector<int> displs(static_cast<std::size_t>(ranks));
  for (int r = 1; r < ranks; ++r) displs[std::size_t(r)] = displs[std::size_t(r - 1)] + task_counts_[std::size_t(r - 1)];
  std::vector<double> all(task_owner_.size());
  domain_->gather_all(mine.data(), int(mine.size()), all.data(), task_counts_, displs);
  shared_doubles_ += all.size() - mine.size();
  std::vector<int> next(displs);
  for (std::size_t task = 0; task < task_owner_.size(); ++task)
    task_elastic_[task] = all[std::size_t(next[std::size_t(task_owner_[task])]++)];
}

std::vector<double> SphereSystem::ghost_rows(const double* x, std::vector<std::uint32_t>& ghost_ids) const {
  std::vector<std::vector<double>> out(ghost_sends_.size());
  std::vector<Domain::Message> sends, receives;
  for (std::size_t g = 0; g < ghost_sends_.size(); ++g) {
    for (const std::uint32_t k : ghost_sends_[g].spheres)
      out[g].insert(out[g].end(), x + 6 * (k - own_begin_), x + 6 * (k - own_begin_ + 1));
    sends.push_back({ghost_sends_[g].rank, out[g].data(), int(out[g].size())});
  }
  ghost_ids.clear();
  for (const auto& g : ghost_receives_) ghost_ids.insert(ghost_ids.end(), g.spheres.begin(), g.spheres.end());
  std::vector<double> rows(6 * ghost_ids.size());
  std::size_t at = 0;
  for (const auto& g : ghost_receives_) {
    receives.push_back({g.rank, rows.data() + at, int(6 * g.spheres.size())});
    at += 6 * g.spheres.size();
  }
  domain_->exchange(sends, receives);
  return rows;
}

// Point to point: each neighbour gets the motion the contact law reads of the spheres it
// holds as ghosts (positions; velocities and angular velocities unless the law reads none;
// rotations where they are integrated).
void SphereSystem::exchange_ghosts() {
  std::vector<Vec3>* motion[4];
  std::size_t vectors = 0;
  motion[vectors++] = &x_;
  if (kernel_->reads_velocities()) motion[vectors++] = &v_, motion[vectors++] = &w_;
  if (track_rotation_) motion[vectors++] = &theta_;
  std::vector<Domain::Message> sends, receives;
  for (auto& g : ghost_sends_) {
    g.buffer.resize(3 * vectors * g.spheres.size());
    double* o = g.buffer.data();
    for (const std::uint32_t k : g.local)
      for (std::size_t v = 0; v < vectors; ++v) {
        const Vec3& q = (*motion[v])[k];
        *o++ = q.x, *o++ = q.y, *o++ = q.z;
      }
    sends.push_back({g.rank, g.buffer.data(), int(g.buffer.size())});
  }
  for (auto& g : ghost_receives_) {
    g.buffer.resize(3 * vectors * g.spheres.size());
    receives.push_back({g.rank, g.buffer.data(), int(g.buffer.size())});
    ghost_doubles_ += g.buffer.size();
  }
  ghost_messages_ += receives.size();
  domain_->exchange(sends, receives);
  for (const auto& g : ghost_receives_) {
    const double* in = g.buffer.data();
    for (const std::uint32_t k : g.local)
      for (std::size_t v = 0; v < vectors; ++v) {
        Vec3& q = (*motion[v])[k];
        q.x = in[0], q.y = in[1], q.z = in[2];
        in += 3;
      }
  }
  ghosts_stale_ = false;
}

// After every step: the ghosts (point to point), then one small fixed gather (each rank's
// largest strength ratio and speed bound, broken bonds and count of sliding contacts) and one
// gather of each rank's part of what every rank reads: the observed spheres' motion, its
// reported contacts' nonzero plastic parts as (slot, value), on energy steps its blocks'
// damping and kinetic sums. Every rank then adds the plastic task sums in slot order, as
// for_each_contact adds them in one process; the elastic ones come from share_elastic.
void SphereSystem::share_step(bool evaluate_energy) {
  // The ghosts got this rank's share of their contacts' forces (every other end of a held contact
  // is a ghost, lay_out_domain checks): not this rank's to keep.
  for (const auto& g : ghost_receives_)
    for (const std::uint32_t k : g.local) f_acc_[k] = {}, t_acc_[k] = {};
  exchange_ghosts();

  const int ranks = domain_->size(), me = domain_->rank();
  const auto at = [](const std::vector<int>& v, int r) { return std::size_t(v[std::size_t(r)]); };
  double peak2 = 0, vmax2 = 0;
  std::size_t sliding = 0;
  for (std::size_t t = 0; t < partitions_ + cross_blocks_; ++t) peak2 = std::max(peak2, task_peak2_[t]);
  for (const std::uint32_t s : reported_) sliding += slot_plastic_[s] != 0;
  for (std::size_t b = own_block_begin_; b < own_block_end_; ++b) vmax2 = std::max(vmax2, sphere_block_vmax2_[b]);
  constexpr int kFixed = 4;
  const double fixed[kFixed] = {peak2, vmax2, double(kernel_->broken_bonds_in(reported_)), double(sliding)};  // counts exact below 2^53
  std::vector<double> all_fixed(static_cast<std::size_t>(kFixed * ranks));
  std::vector<int> fixed_counts(static_cast<std::size_t>(ranks), kFixed), fixed_displs(static_cast<std::size_t>(ranks));
  for (int r = 0; r < ranks; ++r) fixed_displs[std::size_t(r)] = kFixed * r;
  domain_->gather_all(fixed, kFixed, all_fixed.data(), fixed_counts, fixed_displs);
  peak2 = 0, vmax2 = 0;
  std::size_t broken = 0;
  std::vector<std::size_t> sliding_on(static_cast<std::size_t>(ranks));
  for (int r = 0; r < ranks; ++r) {
    const double* f = &all_fixed[std::size_t(kFixed * r)];
    peak2 = std::max(peak2, f[0]), vmax2 = std::max(vmax2, f[1]);
    broken += std::size_t(f[2]), sliding_on[std::size_t(r)] = std::size_t(f[3]);
  }
  broken_ = broken, vmax2_all_ = vmax2;

  // Rank r's part: 12 doubles an observed sphere (x, v, a, a undamped), 2 a sliding contact; on
  // energy steps also 2 a block (damping, kinetic). The blocks' damping sums are read only with
  // the energies (energy steps, and collect_energy after the last step).
  const std::size_t per_block = evaluate_energy ? 2 : 0;
  const auto part = [&](int r) {
    return 12 * at(observed_counts_, r) + per_block * at(block_counts_, r) + 2 * sliding_on[std::size_t(r)];
  };
  std::vector<int> counts(static_cast<std::size_t>(ranks)), displs(static_cast<std::size_t>(ranks));
  std::size_t total = 0;
  for (int r = 0; r < ranks; ++r) {
    counts[std::size_t(r)] = int(part(r));
    displs[std::size_t(r)] = int(total);
    total += part(r);
  }
  if (total > std::size_t(0x7fffffff)) throw InputError("a distributed step's exchange exceeds MPI's int counts");
  std::vector<Vec3>* observed_motion[] = {&x_, &v_, &a_, &a_undamped_};
  send_.resize(part(me));
  {
    double* o = send_.data();
    for (std::size_t q = at(observed_displs_, me), e = q + at(observed_counts_, me); q < e; ++q)
      for (auto* m : observed_motion) {
        const Vec3& p = (*m)[observed_local_[q]];
        *o++ = p.x, *o++ = p.y, *o++ = p.z;
      }
    if (evaluate_energy)
      for (auto* b : {&sphere_block_damping_, &sphere_block_kinetic_})
        o = std::copy(b->begin() + std::ptrdiff_t(own_block_begin_), b->begin() + std::ptrdiff_t(own_block_end_), o);
    for (const std::uint32_t s : reported_)
      if (slot_plastic_[s] != 0) *o++ = double(global_slot(s)), *o++ = slot_plastic_[s];  // exact below 2^53
  }
  recv_.resize(total);
  domain_->gather_all(send_.data(), int(send_.size()), recv_.data(), counts, displs);
  shared_doubles_ += total - send_.size() + std::size_t(kFixed * (ranks - 1));
  ++shared_steps_;

  std::vector<std::pair<std::uint32_t, double>> plastic;  // (slot of the whole layout, value), every rank's
  for (int r = 0; r < ranks; ++r) {
    const double* in = recv_.data() + displs[std::size_t(r)];
    const bool mine = r == me;
    for (std::size_t q = at(observed_displs_, r), e = q + at(observed_counts_, r); q < e; ++q)
      for (auto* m : observed_motion) {
        if (!mine) (*m)[observed_local_[q]] = {in[0], in[1], in[2]};
        in += 3;
      }
    const std::size_t b0 = at(block_displs_, r), nb = at(block_counts_, r);
    if (evaluate_energy)
      for (auto* b : {&sphere_block_damping_, &sphere_block_kinetic_}) {
        std::copy(in, in + nb, b->begin() + std::ptrdiff_t(b0));
        in += nb;
      }
    for (std::size_t k = 0; k < sliding_on[std::size_t(r)]; ++k, in += 2) plastic.emplace_back(std::uint32_t(in[0]), in[1]);
  }

  // The task sums in slot order. The plastic parts left out are zeros, and adding a zero
  // changes no sum that starts at +0, so these are the bits of the sum over every slot.
  std::sort(plastic.begin(), plastic.end());
  const std::size_t tasks = partitions_ + global_cross_blocks_;
  for (std::size_t k = 0; k < plastic.size();) {
    const std::size_t task = global_task_of(plastic[k].first);
    double sum = 0;
    for (; k < plastic.size() && global_task_of(plastic[k].first) == task; ++k) sum += plastic[k].second;
    task_plastic_[task] += sum;
  }
  if (evaluate_energy) share_elastic();
  std::fill(task_peak2_.begin(), task_peak2_.end(), 0.0);
  if (tasks > 0) task_peak2_[0] = peak2;  // a max: exact in any order
}

std::size_t SphereSystem::sum_over_ranks(std::size_t count) const {
  return domain_ ? std::size_t(domain_->sum(count)) : count;
}

double SphereSystem::max_over_ranks(double value) const { return domain_ ? domain_->max(value) : value; }

SphereSystem::Nearby SphereSystem::spheres_near_own(double reach_m) {
  Nearby near;
  const auto add = [&](std::size_t k, const Vec3& x, double r) {
    near.ids.push_back(std::uint32_t(k));
    near.centres.push_back({x.x, x.y, x.z});
    near.radii.push_back(r);
  };
  if (!domain_) {
    for (std::size_t k = 0; k < x_.size(); ++k) add(k, x_[k], spheres_.radius_m[k]);
    return near;
  }
  // Each block's bounding box of centres (low x, y, z, high x, y, z), every rank's, and each
  // rank's box around its blocks'.
  const int ranks = domain_->size(), me = rank_;
  const std::size_t n = sphere_total_, blocks = block_owner_.size();
  const auto block_end = [&](std::size_t b) { return std::min(n, (b + 1) * kSphereBlock); };
  std::vector<double> box(6 * blocks);
  for (std::size_t b = own_block_begin_; b < own_block_end_; ++b) {
    double* q = &box[6 * b];
    clear_box(q);
    for (std::size_t k = b * kSphereBlock; k < block_end(b); ++k) {
      const Vec3& x = x_[own_local(k)];
      const double c[3] = {x.x, x.y, x.z};
      grow_box_by_point(q, c);
    }
  }
  std::vector<int> counts(static_cast<std::size_t>(ranks)), displs(static_cast<std::size_t>(ranks));
  for (int r = 0; r < ranks; ++r)
    counts[std::size_t(r)] = 6 * block_counts_[std::size_t(r)], displs[std::size_t(r)] = 6 * block_displs_[std::size_t(r)];
  domain_->share(box.data(), counts, displs);
  const auto blocks_of = [&](int r) {
    const auto b0 = std::size_t(block_displs_[std::size_t(r)]);
    return std::pair{b0, b0 + std::size_t(block_counts_[std::size_t(r)])};
  };
  const auto near_boxes = [&](const double* a, const double* b) { return boxes_within(a, b, reach_m); };
  std::vector<double> rank_box(6 * std::size_t(ranks));
  for (int r = 0; r < ranks; ++r) {
    double* q = &rank_box[6 * std::size_t(r)];
    clear_box(q);
    for (auto [b, e] = blocks_of(r); b < e; ++b) grow_box(q, &box[6 * b]);
  }
  // Rank r's blocks that come within reach of one of rank t's: what r sends t, worked out alike
  // on both (the same call on the same boxes).
  const auto blocks_near = [&](int r, int t) {
    std::vector<std::size_t> list;
    if (!near_boxes(&rank_box[6 * std::size_t(r)], &rank_box[6 * std::size_t(t)])) return list;
    const auto [t0, t1] = blocks_of(t);
    for (auto [b, e] = blocks_of(r); b < e; ++b)
      for (std::size_t a = t0; a < t1; ++a)
        if (near_boxes(&box[6 * b], &box[6 * a])) {
          list.push_back(b);
          break;
        }
    return list;
  };
  std::vector<std::vector<double>> out(static_cast<std::size_t>(ranks)), in(static_cast<std::size_t>(ranks));
  std::vector<std::vector<std::size_t>> incoming(static_cast<std::size_t>(ranks));
  std::vector<Domain::Message> sends, receives;
  for (int r = 0; r < ranks; ++r) {
    if (r == me) continue;
    auto& o = out[std::size_t(r)];
    for (const std::size_t b : blocks_near(me, r))
      for (std::size_t k = b * kSphereBlock; k < block_end(b); ++k) {  // a layer sphere's position and radius
        const Vec3& x = x_[own_local(k)];
        o.insert(o.end(), {x.x, x.y, x.z, spheres_.radius_m[own_local(k)]});
      }
    if (!o.empty()) sends.push_back({r, o.data(), int(o.size())});
    incoming[std::size_t(r)] = blocks_near(r, me);
    std::size_t spheres = 0;
    for (const std::size_t b : incoming[std::size_t(r)]) spheres += block_end(b) - b * kSphereBlock;
    if (spheres > 0) {
      in[std::size_t(r)].resize(4 * spheres);
      receives.push_back({r, in[std::size_t(r)].data(), int(4 * spheres)});
    }
  }
  domain_->exchange(sends, receives);
  layer_spheres_ = 0;
  for (int r = 0; r < ranks; ++r) {  // by rank, so by id
    if (r == me) {
      for (std::size_t k = own_begin_; k < own_end_; ++k) add(k, x_[own_local(k)], spheres_.radius_m[own_local(k)]);
      continue;
    }
    const double* x = in[std::size_t(r)].data();
    for (const std::size_t b : incoming[std::size_t(r)])
      for (std::size_t k = b * kSphereBlock; k < block_end(b); ++k, x += 4) add(k, {x[0], x[1], x[2]}, x[3]);
    layer_spheres_ += in[std::size_t(r)].size() / 4;
  }
  return near;
}

template <class T>
std::vector<T> SphereSystem::gathered_spheres(const std::vector<T>& held) const {
  static_assert(sizeof(T) % sizeof(double) == 0);
  constexpr int per = int(sizeof(T) / sizeof(double));  // sphere_counts_ and displs count 3 a sphere
  const int ranks = domain_->size();
  std::vector<int> counts(static_cast<std::size_t>(ranks)), displs(static_cast<std::size_t>(ranks));
  for (int r = 0; r < ranks; ++r)
    counts[std::size_t(r)] = sphere_counts_[std::size_t(r)] / 3 * per, displs[std::size_t(r)] = sphere_displs_[std::size_t(r)] / 3 * per;
  std::vector<T> whole(domain_->rank() == 0 ? sphere_total_ : 0);
  domain_->gather(reinterpret_cast<const double*>(&held[own_local_]), per * int(own_end_ - own_begin_),
                  reinterpret_cast<double*>(whole.data()), counts, displs);
  return whole;
}
template std::vector<Vec3> SphereSystem::gathered_spheres(const std::vector<Vec3>&) const;
template std::vector<double> SphereSystem::gathered_spheres(const std::vector<double>&) const;

// To rank 0 only, into a whole copy kept until the next step: it alone writes snapshots, through
// the Model interface, which reads the copy for the spheres it does not hold.
void SphereSystem::collect_state() {
  if (!domain_) return;
  collected_.x = gathered_spheres(x_);
  collected_.v = gathered_spheres(v_);
  collected_.centre = gathered_spheres(spheres_.centre_m);
  collected_.radius = gathered_spheres(spheres_.radius_m);
  const std::vector<double> index(spheres_.packing_index.begin(), spheres_.packing_index.end());  // exact below 2^53
  const std::vector<double> whole_index = gathered_spheres(index);
  collected_.packing_index.assign(whole_index.begin(), whole_index.end());
}

void SphereSystem::collect_energy() {
  if (domain_) domain_->share(sphere_block_damping_.data(), block_counts_, block_displs_);
}

std::size_t SphereSystem::broken_bond_count() const { return domain_ ? broken_ : kernel_->broken_bond_count(); }

// A checkpoint's per-slot array: rank 0 writes the whole layout's slots a piece at a time
// (checkpoint_piece_rows). The reporters' runs (slot_runs_, the same on every rank) say how many
// of a piece's slots each rank reports and where they go; a rank's reported slots ascend in the
// layout (its held slots are in the layout's order), so each sends its next ones. Rank 0 holds a
// piece, never the array.
void SphereSystem::write_reported_slots(StateGroup& group, const std::string& name, bool indices,
                                        const std::function<double(std::uint32_t)>& value) const {
  const auto ranks = static_cast<std::size_t>(domain_->size()), me = static_cast<std::size_t>(rank_);
  const bool root = me == 0;
  StateGroup::Rows rows = group.write_rows(name, global_slots_, 0, indices);
  std::vector<int> counts(ranks), displs(ranks), next(ranks);
  std::vector<double> send, arrived, piece;
  std::size_t sent = 0;  // this rank's reported slots sent so far
  const std::size_t piece_rows = checkpoint_piece_rows();
  for (std::size_t begin = 0; begin < global_slots_; begin += piece_rows) {
    const std::size_t end = std::min(global_slots_, begin + piece_rows);
    std::fill(counts.begin(), counts.end(), 0);
    for_each_reporter(begin, end, [&](int r, std::size_t b, std::size_t e) { counts[std::size_t(r)] += int(e - b); });
    for (std::size_t r = 1; r < ranks; ++r) displs[r] = displs[r - 1] + counts[r - 1];
    send.resize(std::size_t(counts[me]));
    for (double& v : send) v = value(reported_[sent++]);
    arrived.resize(root ? end - begin : 0);
    domain_->gather(send.data(), int(send.size()), arrived.data(), counts, displs);
    if (!root) continue;
    piece.resize(end - begin);
    next = displs;
    for_each_reporter(begin, end, [&](int r, std::size_t b, std::size_t e) {
      for (std::size_t s = b; s < e; ++s) piece[s - begin] = arrived[std::size_t(next[std::size_t(r)]++)];
    });
    rows.write(begin, piece);
  }
  if (sent != reported_.size()) throw std::logic_error("SphereSystem::write_slots: the reporters' runs do not cover the layout");
}

void SphereSystem::write_slots(StateGroup& group, const std::string& name, const std::vector<double>& held) const {
  if (!domain_) return group.write(name, held);
  write_reported_slots(group, name, false, [&](std::uint32_t s) { return held[s]; });  // the other ranks' group writes nowhere
}

void SphereSystem::write_slots(StateGroup& group, const std::string& name, const std::vector<std::uint32_t>& held) const {
  if (!domain_) return group.write(name, held);
  write_reported_slots(group, name, true, [&](std::uint32_t s) { return double(held[s]); });  // exact
}

// A checkpoint's sphere array: rank 0 writes it a piece at a time, each piece the own spheres of
// the ranks whose ranges meet it, in rank order (the ranges ascend).
void SphereSystem::write_spheres(StateGroup& group, const std::string& name, const std::vector<Vec3>& held) const {
  if (!domain_) return group.write(name, held);
  constexpr std::size_t per = 3;  // doubles a row
  const auto ranks = static_cast<std::size_t>(domain_->size());
  const bool root = rank_ == 0;
  StateGroup::Rows rows = group.write_rows(name, sphere_total_, per, false);
  std::vector<int> counts(ranks), displs(ranks);
  std::vector<double> piece;
  const std::size_t piece_rows = checkpoint_piece_rows();
  for (std::size_t begin = 0; begin < sphere_total_; begin += piece_rows) {
    const std::size_t end = std::min(sphere_total_, begin + piece_rows);
    for (std::size_t r = 0; r < ranks; ++r) {  // rank r's spheres [first, last) (sphere_counts_ count 3 a sphere)
      const std::size_t first = std::size_t(sphere_displs_[r]) / 3, last = first + std::size_t(sphere_counts_[r]) / 3;
      const std::size_t from = std::max(first, begin), to = std::min(last, end);
      counts[r] = from < to ? int(per * (to - from)) : 0;
      displs[r] = from < to ? int(per * (from - begin)) : 0;
    }
    const std::size_t from = std::max(own_begin_, begin);
    const double* mine = counts[std::size_t(rank_)] ? reinterpret_cast<const double*>(&held[own_local(from)]) : nullptr;
    piece.resize(root ? per * (end - begin) : 0);
    domain_->gather(mine, counts[std::size_t(rank_)], piece.data(), counts, displs);
    rows.write(begin, piece);
  }
}

// Round k reads rows [k P N, (k + 1) P N) (P a piece's rows, N ranks), rank r its piece
// [k P N + r P, k P N + (r + 1) P): what arrives, rank after rank and round after round, is in row
// order, so the held contacts need no sort (and no more than their 12 B each). One process reads
// every piece in order and keeps every contact.
bool SphereSystem::read_held_contacts(const StateGroup& group, std::size_t rows, std::vector<std::uint32_t>& rows_held,
                                      std::vector<std::uint32_t>& first, std::vector<std::uint32_t>& second) const {
  const auto ranks = static_cast<std::size_t>(domain_ ? domain_->size() : 1), me = static_cast<std::size_t>(rank_);
  const std::size_t piece_rows = checkpoint_piece_rows();
  bool fits = true;
  rows_held.clear(), first.clear(), second.clear();
  if (!domain_) first.reserve(rows), second.reserve(rows);
  std::vector<std::vector<double>> out(ranks);  // a round's, kept from round to round (no churn of the heap)
  std::vector<double> in;
  // The first value that is not an index, as one process meets it (the pieces in row order, in
  // each `first` before `second`): {its piece's first row, the array (0 first, 1 second), its row}.
  // Every rank reads on (the exchanges are collective), and the ranks agree on the file's first,
  // so that every rank refuses the checkpoint with the line one process prints.
  std::vector<double> bad;
  const auto find_bad = [&](const std::vector<std::int64_t>& values, std::size_t start, int array) {
    for (std::size_t q = 0; q < values.size() && bad.empty(); ++q)
      if (!StateGroup::is_index(values[q])) bad = {double(start), double(array), double(start + q)};
  };
  for (std::size_t round = 0; round * piece_rows * ranks < rows && (domain_ || bad.empty()); ++round) {
    const std::size_t start = std::min(rows, (round * ranks + me) * piece_rows);
    const std::size_t count = std::min(rows, start + piece_rows) - start;
    const auto f = group.read_int64s("first", start, count), g = group.read_int64s("second", start, count);
    find_bad(f, start, 0), find_bad(g, start, 1);
    for (auto& o : out) o.clear();
    for (std::size_t q = 0; q < count; ++q) {
      if (!(0 <= f[q] && f[q] < g[q] && g[q] < std::int64_t(sphere_total_))) {
        fits = false;  // not sent: its ends may be no rank's
        continue;
      }
      if (!domain_) {
        first.push_back(f[q]), second.push_back(g[q]);
        continue;
      }
      const auto a = std::size_t(owner(f[q])), b = std::size_t(owner(g[q]));
      out[a].insert(out[a].end(), {double(start + q), double(f[q]), double(g[q])});
      if (b != a) out[b].insert(out[b].end(), {double(start + q), double(f[q]), double(g[q])});
    }
    if (!domain_) continue;
    exchange_lists(*domain_, out, in);
    for (std::size_t c = 0; c < in.size(); c += 3)
      rows_held.push_back(std::uint32_t(in[c])), first.push_back(std::uint32_t(in[c + 1])), second.push_back(std::uint32_t(in[c + 2]));
  }
  if (domain_) bad = gathered_lists(*domain_, bad);  // each rank's first, in rank order
  std::size_t earliest = bad.size();
  for (std::size_t k = 0; k < bad.size(); k += 3)
    if (earliest == bad.size() || bad[k] < bad[earliest]) earliest = k;  // the ranks read distinct pieces
  if (earliest < bad.size()) {  // every rank reads the value back, for the message
    const std::string array = bad[earliest + 1] == 0 ? "first" : "second";
    throw group.not_an_index(array, group.read_int64s(array, std::size_t(bad[earliest + 2]), 1)[0]);
  }
  return domain_ ? domain_->sum(fits ? 0 : 1) == 0 : fits;
}

std::string SphereSystem::distribution() const {
  if (!domain_) return {};
  const std::size_t steps = std::max<std::uint64_t>(shared_steps_, 1);
  // What the stage-1 exchange (the whole motion of every sphere, each rank's blocks' sums, each
  // reported contact's plastic part, on every step) would have brought into this rank.
  const std::size_t replicated = ((track_rotation_ ? 18 : 15) * (sphere_total_ - (own_end_ - own_begin_)) +
                                  3 * ((sphere_total_ + kSphereBlock - 1) / kSphereBlock) + global_slots_ - reported_.size()) * 8;
  return "rank " + std::to_string(domain_->rank()) + " of " + std::to_string(domain_->size()) + ": spheres " +
         std::to_string(own_begin_) + "-" + std::to_string(own_end_) + " of " + std::to_string(sphere_total_) +
         " (Morton order), " + std::to_string(held_sphere_count()) + " held, " + std::to_string(ghosts_) +
         " ghosts from " + std::to_string(ghost_receives_.size()) + " ranks, " + std::to_string(observed_.size()) + " observed spheres, " +
         std::to_string(first_.size()) + " of " + std::to_string(global_slots_) + " contacts and " + std::to_string(bonds_.size()) +
         " of " + std::to_string(bond_count_) + " bonds held here; received per step: " + std::to_string(ghost_doubles_ * 8 / steps) + " B of ghosts in " +
         format_number(double(ghost_messages_) / double(steps)) + " messages, " +
         std::to_string(shared_doubles_ * 8 / steps) + " B gathered (the replicated state of stage 1: " +
         std::to_string(replicated) + " B)" +
         (layer_spheres_ ? "; contact detection's ghost layer: " + std::to_string(layer_spheres_) + " spheres" : "");
}

}  // namespace mesowave::dem
