#include "mesowave/dem/contact/cohesive_frictional_contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <tuple>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/kernel_clones.hpp"
#include "mesowave/dem/contact/axial_chain.hpp"
#include "mesowave/dem/contact/linear_bonded_network.hpp"
#include "mesowave/dem/engine/neighbour_search.hpp"
#include "mesowave/dem/parallel/domain.hpp"
#include "mesowave/dem/scene/plugins.hpp"

namespace mesowave::dem {

void refuse_unbonded_overlaps(const SpherePart& spheres, const BondNetwork& bonds, double bond_factor) {
  Domain* domain = spheres.domain();
  const auto stray = unbonded_overlaps(spheres, bonds);
  // Distributed, each rank finds the pairs whose first sphere is its own: all ranks report them.
  const std::size_t count = domain ? std::size_t(domain->sum(stray.size())) : stray.size();
  if (count == 0) return;
  double worst = 0;
  for (auto [i, j] : stray)
    worst = std::max(worst, spheres.radius(i) + spheres.radius(j) - norm(spheres.reference_position(j) - spheres.reference_position(i)));
  if (domain) worst = domain->max(worst);
  throw InputError(std::to_string(count) + " pairs of spheres overlap at step 0 without a bond (bond factor C_f " +
                   format_number(bond_factor) + " < 1; largest overlap " + format_number(worst) +
                   " m): the full law would start them as contacts pushing with K_n u; raise C_f to bond them, or "
                   "run --model linear/chain, which never adds contacts");
}

void CohesiveFrictionalContact::attach(SphereSystem& system) {
  margin_ = 0.1 * system.radius_min();
  detect_contacts(system);
}

CohesiveFrictionalContact::Slot CohesiveFrictionalContact::slot(std::size_t s) const {
  return {{nx_[s], ny_[s], nz_[s]}, {sx_[s], sy_[s], sz_[s]}, overlap0_[s], bond_[s],
          cohesive_[s] != 0 ? kCohesive : kFrictional};
}

template <class SlotAt>
void CohesiveFrictionalContact::set_slots(std::size_t m, const SlotAt& slot_at) {
  std::vector<double> nx(m), ny(m), nz(m), sx(m), sy(m), sz(m), overlap0(m), cohesive(m);
  std::vector<std::uint32_t> bond(m);
  for (std::size_t s = 0; s < m; ++s) {
    const Slot q = slot_at(s);
    nx[s] = q.normal.x, ny[s] = q.normal.y, nz[s] = q.normal.z;
    sx[s] = q.shear.x, sy[s] = q.shear.y, sz[s] = q.shear.z;
    overlap0[s] = q.overlap0;
    bond[s] = q.bond;
    cohesive[s] = q.status == kCohesive ? 1.0 : 0.0;
  }
  nx_ = std::move(nx), ny_ = std::move(ny), nz_ = std::move(nz), sx_ = std::move(sx), sy_ = std::move(sy), sz_ = std::move(sz);
  overlap0_ = std::move(overlap0), bond_ = std::move(bond), cohesive_ = std::move(cohesive);
}

std::size_t CohesiveFrictionalContact::broken_bond_count() const {
  std::size_t broken = 0;
  for (std::size_t s = 0; s < bond_.size(); ++s) broken += bond_[s] != kNoBond && cohesive_[s] == 0;
  return broken;
}

std::size_t CohesiveFrictionalContact::broken_bonds_in(const std::vector<std::uint32_t>& slots) const {
  std::size_t broken = 0;
  for (const std::uint32_t s : slots) broken += bond_[s] != kNoBond && cohesive_[s] == 0;
  return broken;
}

// In the whole layout's slot order (SphereSystem::write_slots), so that a checkpoint does not
// depend on the rank count that wrote it, nor binds the one that reads it.
void CohesiveFrictionalContact::save_state(const SphereSystem& system, StateGroup& group) const {
  const std::size_t m = bond_.size();
  std::vector<std::uint32_t> first(m), second(m);  // the spheres' global ids
  for (std::size_t s = 0; s < m; ++s) first[s] = system.global_id(system.first(s)), second[s] = system.global_id(system.second(s));
  system.write_slots(group, "first", first);
  system.write_slots(group, "second", second);
  system.write_slots(group, "normal_x", nx_), system.write_slots(group, "normal_y", ny_);
  system.write_slots(group, "normal_z", nz_);
  system.write_slots(group, "shear_x_N", sx_), system.write_slots(group, "shear_y_N", sy_);
  system.write_slots(group, "shear_z_N", sz_);
  system.write_slots(group, "overlap0_m", overlap0_);
  system.write_slots(group, "bond", bond_);
  system.write_slots(group, "cohesive", cohesive_);
  group.write("travelled_m", travelled_);
  group.write("detection_passes", std::int64_t(detection_passes_));
}

void CohesiveFrictionalContact::load_state(SphereSystem& system, const StateGroup& group) {
  // The checkpoint replaces the per-slot arrays the law laid out at attach: gone first, so that
  // they are not held beside the checkpoint's whole arrays (the restart's peak).
  for (auto* array : {&nx_, &ny_, &nz_, &sx_, &sy_, &sz_, &overlap0_, &cohesive_}) std::vector<double>().swap(*array);
  std::vector<std::uint32_t>().swap(bond_);
  // The contact list, checked to fit the packing: one process keeps every slot (so no list of
  // them); several ranks share the reading, and each gets its held slots (an end of its own),
  // ascending, with their spheres (read_held_contacts). The lengths are the same on every rank.
  const std::size_t n = system.sphere_count(), nb = system.bond_count();
  std::size_t m = 0, m_second = 0;
  group.read_uint32s("first", 0, 0, &m);
  group.read_uint32s("second", 0, 0, &m_second);
  std::vector<std::uint32_t> slots, first, second;
  const bool fits = m == m_second && m >= nb && system.read_held_contacts(group, m, slots, first, second);
  if (!fits) throw InputError("checkpoint " + group.where() + ": its contacts do not fit this packing's " +
                              std::to_string(n) + " spheres: the checkpoint is not from this run");
  std::vector<double> cohesive;
  if (system.distributed()) {
    bond_ = group.read_uint32s_at("bond", m, slots);
    cohesive = group.read_at("cohesive", m, slots);
  } else {
    bond_ = group.read_uint32s("bond");
    cohesive.resize(m);
    group.read_into("cohesive", cohesive);
  }
  const auto row = [&](std::size_t c) { return system.distributed() ? slots[c] : std::uint32_t(c); };
  // Each bond once, in the slot of its own pair; cohesion only where a bond is (0 or 1). A rank
  // checks the bonds it holds (an end of its own; each bond is some rank's, all in one process):
  // a held slot holds one of those or none.
  std::vector<std::uint32_t> held_of(system.held_bond_network().size(), kNoBond);  // each held bond's held row
  std::size_t bonded = 0;
  bool valid = bond_.size() == first.size();
  for (std::size_t c = 0; valid && c < first.size(); ++c) {
    const std::uint32_t b = bond_[c];
    valid = cohesive[c] == 0.0 || (b != kNoBond && cohesive[c] == 1.0);
    if (b == kNoBond || !valid) continue;
    valid = b < nb && system.holds_bond(b);
    if (!valid) continue;
    const std::size_t h = system.held_bond(b);
    valid = held_of[h] == kNoBond && system.bond_first(b) == first[c] && system.bond_second(b) == second[c];
    held_of[h] = std::uint32_t(c), ++bonded;
  }
  if (system.sum_over_ranks(valid && bonded == held_of.size() ? 0 : 1) != 0)
    throw InputError("checkpoint " + group.where() + ": its bonds are not this packing's " + std::to_string(nb));
  // The held slots as detection lists them: the bonds by index, then the pairs by (first,
  // second). Laid out, each must come back to its own slot, on every rank: so the checkpoint's
  // layout is the one detection makes.
  std::vector<std::uint32_t> listed = std::move(held_of);
  const std::size_t held_bonds = listed.size();
  for (std::size_t c = 0; c < bond_.size(); ++c)
    if (bond_[c] == kNoBond) listed.push_back(std::uint32_t(c));
  std::sort(listed.begin() + std::ptrdiff_t(held_bonds), listed.end(), [&](std::uint32_t a, std::uint32_t b) {
    return std::tie(first[a], second[a]) < std::tie(first[b], second[b]);
  });
  std::vector<std::uint32_t> held_first(listed.size()), held_second(listed.size());
  for (std::size_t c = 0; c < listed.size(); ++c) held_first[c] = first[listed[c]], held_second[c] = second[listed[c]];
  std::vector<std::uint32_t>().swap(first), std::vector<std::uint32_t>().swap(second);
  const auto order = system.set_contacts(held_first, held_second, held_bonds, moments());
  std::size_t misplaced = 0;
  for (std::size_t s = 0; s < order.size(); ++s) misplaced += system.global_slot(s) != row(listed[order[s]]);
  if (system.sum_over_ranks(misplaced) != 0)
    throw InputError("checkpoint " + group.where() + ": its contact layout is not this packing's");
  // Each held slot in its place: the layout's held slots are `slots`, in the same ascending order.
  cohesive_ = std::move(cohesive);
  nx_ = system.read_slots(group, "normal_x"), ny_ = system.read_slots(group, "normal_y");
  nz_ = system.read_slots(group, "normal_z");
  sx_ = system.read_slots(group, "shear_x_N"), sy_ = system.read_slots(group, "shear_y_N");
  sz_ = system.read_slots(group, "shear_z_N");
  overlap0_ = system.read_slots(group, "overlap0_m");
  travelled_ = group.read_double("travelled_m");
  detection_passes_ = std::size_t(group.read_int64("detection_passes"));
}

void CohesiveFrictionalContact::contact_forces(SphereSystem& system, double dt, bool evaluate_energy) {
  kernel(system, dt, evaluate_energy);
}

// Compiled for AVX-512, AVX2 and baseline x86-64, picked at load time. No FMA
// contraction (ISO C++ mode), so every version gives the same bits.
MESOWAVE_KERNEL_CLONES
void CohesiveFrictionalContact::kernel(SphereSystem& system, double dt, bool evaluate_energy) {
  NoExtension none;
  run<SphereSystem::ContactResult>(system, dt, evaluate_energy, none);
}

void CohesiveFrictionalContact::after_step(SphereSystem& system, double dt) {
  travelled_ += system.max_speed() * dt;
  // Two spheres close in by at most twice the distance the fastest one moved.
  if (2.0 * travelled_ > margin_) detect_contacts(system);
}

void CohesiveFrictionalContact::detect_contacts(SphereSystem& system) {
  travelled_ = 0;
  ++detection_passes_;
  const double factor = 1.0 + margin_ / (2.0 * system.radius_min());
  // This rank's contacts (every contact in one process): those with an end of its own. The
  // contacts: the bonds, then the detected pairs (each with its old slot, or kNoBond when new,
  // with its normal). Their state is looked up only for the slots laid out here.
  std::vector<std::uint32_t> first = system.held_bond_network().first, second = system.held_bond_network().second;
  std::vector<std::uint32_t> known_slot;
  std::vector<Vec3> normal;
  const std::size_t nb = first.size();

  // Where each held bond and each detected pair lives now.
  std::vector<std::uint32_t> slot_of_bond(nb, kNoBond);
  std::vector<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>> old_pairs;
  for (std::size_t s = 0; s < bond_.size(); ++s) {
    if (bond_[s] != kNoBond) slot_of_bond[system.held_bond(bond_[s])] = std::uint32_t(s);
    else old_pairs.emplace_back(system.global_id(system.first(s)), system.global_id(system.second(s)), std::uint32_t(s));
  }
  std::sort(old_pairs.begin(), old_pairs.end());
  {
    const auto near = system.spheres_near_own(factor * 2.0 * system.radius_max());
    const auto pairs = find_pairs_within(near.centres, near.radii, factor);
    const auto at = [&](std::uint32_t q) { return Vec3{near.centres[q][0], near.centres[q][1], near.centres[q][2]}; };
    std::size_t b = 0;  // bonds and pairs are both sorted by (first, second)
    for (const auto& p : pairs) {
      const std::uint32_t i = near.ids[p.i], j = near.ids[p.j];
      if (!system.is_own(i) && !system.is_own(j)) continue;
      const double reach = near.radii[p.i] + near.radii[p.j] + margin_;
      const Vec3 d = at(p.j) - at(p.i);
      if (norm2(d) > reach * reach) continue;
      while (b < nb && (first[b] < i || (first[b] == i && second[b] < j))) ++b;
      if (b < nb && first[b] == i && second[b] == j) continue;  // bonded
      const auto known = std::lower_bound(old_pairs.begin(), old_pairs.end(), std::make_tuple(i, j, 0u));
      first.push_back(i);
      second.push_back(j);
      known_slot.push_back(known != old_pairs.end() && std::get<0>(*known) == i && std::get<1>(*known) == j
                               ? std::get<2>(*known)
                               : kNoBond);
      normal.push_back(known_slot.back() == kNoBond ? (1.0 / norm(d)) * d : Vec3{});
    }
  }
  // Same contacts as before (the usual case for waves: bonds only): keep the layout.
  const std::size_t pairs = system.sum_over_ranks(first.size() - nb);
  if (detection_passes_ > 1 && pairs == 0 && system.global_slot_count() == system.bond_count()) return;
  before_relayout(system);
  const auto order = system.set_contacts(first, second, nb, moments());
  set_slots(order.size(), [&](std::size_t s) {
    const std::uint32_t c = order[s];
    if (c < nb) {
      const auto bond = std::uint32_t(system.held_bond_id(c));
      if (slot_of_bond[c] != kNoBond) return slot(slot_of_bond[c]);
      const BondGeometry g = system.bond_geometry0(bond);
      return Slot{g.normal, {}, g.overlap_m, bond, kCohesive};
    }
    if (const std::uint32_t old = known_slot[c - nb]; old != kNoBond) return slot(old);
    return Slot{normal[c - nb], {}, 0.0, kNoBond, kFrictional};
  });
  after_relayout(system);
}

// The law of both papers, with its two shortcuts: the linearised network and
// the axial chain model the same law where the scene lets them (model_choice.hpp).
void register_cohesive_frictional_law(Plugins& p) {
  p.laws.add({
      .name = "cohesive_frictional",
      .summary = "Yade's CohFrictMat / CohFrictPhys with Law2_ScGeom6D_CohFrictPhys_CohesionMoment, momentRotationLaw "
                 "off: F_n = K_n (u - u_0) (Eq. 1), incremental shear (Eq. 2), K_n = E_dem 2 R_A R_B/(R_A + R_B), "
                 "K_s = nu_dem K_n (Eq. 3), Mohr-Coulomb with strengths T R^2, C R^2 (Eqs. 4-6)",
      .parameters = {},
      .models = {"full", "linear", "chain"},
      .make = [](const std::string& model, SpherePart spheres, BondNetwork bonds,
                 const LawInput& in) -> std::unique_ptr<Model> {
        if (model == "chain") return std::make_unique<AxialChain>(std::move(spheres), bonds, in.material, *in.line);
        if (model == "linear")
          return std::make_unique<SphereSystem>(std::move(spheres), std::move(bonds), in.material,
                                                std::make_unique<LinearBondedNetwork>(), in.domain);
        refuse_unbonded_overlaps(spheres, bonds, in.material.bond_factor);
        return std::make_unique<SphereSystem>(std::move(spheres), std::move(bonds), in.material,
                                              std::make_unique<CohesiveFrictionalContact>(), in.domain);
      },
      .shortcut_obstacle = [](const std::string&, const Scene&) { return std::string(); },
      .describe = [](const LawParameters&) { return nlohmann::ordered_json::object(); },
  });
}

}  // namespace mesowave::dem
