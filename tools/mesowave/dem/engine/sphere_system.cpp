#include "mesowave/dem/engine/sphere_system.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "mesowave/core/error.hpp"
#include "mesowave/core/kernel_clones.hpp"
#include "mesowave/dem/parallel/domain.hpp"

namespace mesowave::dem {
namespace {

// Eq. (7) as Yade's NewtonIntegrator::cundallDamp2nd applies it.
inline double damped(double a, double v, double dt, double alpha) {
  const double p = a * (v + 0.5 * dt * a);
  return a * (1.0 - alpha * double((p > 0) - (p < 0)));
}

// The symmetric linearisation of a bond at step 0 (for the critical time
// step): F_j = -K_n (n.dd) n - K_s' [P_t dd - (k_i th_i + k_j th_j) x n],
// torques -k_i n x F_j and -k_j n x F_j, with Yade's kinematic branches
// k = r dist0 / (r_i + r_j) and K_s' = K_s (r_i + r_j) / dist0.
// With a law's rolling and twisting springs k_r, k_tw (0 without) the moment
// on j is -k_r P_t (th_j - th_i) - k_tw n n.(th_j - th_i), on i its opposite.
struct LinearBond {
  Vec3 n;
  double kn, ks, ki, kj, kr = 0, ktw = 0;
  void forces(const Vec3& di, const Vec3& ti, const Vec3& dj, const Vec3& tj, Vec3& fi, Vec3& mi, Vec3& fj,
              Vec3& mj) const {
    const Vec3 dd = dj - di;
    const double dn = dot(n, dd);
    const Vec3 st = (dd - dn * n) - cross(ki * ti + kj * tj, n);
    fj = -(kn * dn) * n - ks * st;
    fi = -fj;
    const Vec3 c = cross(n, fj);
    mi = -ki * c;
    mj = -kj * c;
    if (kr != 0 || ktw != 0) {
      const Vec3 dth = tj - ti;
      const double twist = dot(n, dth);
      const Vec3 m = -kr * (dth - twist * n) - (ktw * twist) * n;
      mi -= m;
      mj += m;
    }
  }
};

// A held bond between spheres centred at ci and cj of radii ri and rj (the setup's Lanczos applies
// every one a hundred times or so, so from the held spheres' statics by place, not by index).
LinearBond linear_bond(const SphereSystem& system, const Vec3& ci, const Vec3& cj, double ri, double rj) {
  const CohesiveFrictionalMaterial& m = system.material();
  const BondGeometry g = bond_geometry(ci, cj, ri, rj);
  const double dist0 = ri + rj - g.overlap_m;
  const double alpha = (ri + rj) / dist0;
  LinearBond lb{g.normal, normal_stiffness(m, ri, rj), alpha * shear_stiffness(m, ri, rj), ri / alpha, rj / alpha};
  system.kernel().moment_stiffness(system, ri, rj, lb.kr, lb.ktw);
  return lb;
}

// Sphere i of `from` becomes sphere j of `to` (its statics; not its packing file id).
void copy_sphere(const SphereSet& from, std::size_t i, SphereSet& to, std::size_t j) {
  to.centre_m[j] = from.centre_m[i];
  to.radius_m[j] = from.radius_m[i];
  to.mass_kg[j] = from.mass_kg[i];
  to.inertia_kg_m2[j] = from.inertia_kg_m2[i];
  to.packing_index[j] = from.packing_index[i];
}

}  // namespace

SphereSystem::SphereSystem(SpherePart spheres, BondNetwork bonds, const CohesiveFrictionalMaterial& material,
                           std::unique_ptr<ContactKernel> kernel, Domain* domain, std::size_t spheres_per_partition)
    : bonds_(std::move(bonds)), material_(material), kernel_(std::move(kernel)),
      displacement_state_(kernel_->displacement_state()), track_rotation_(kernel_->track_rotation()) {
  if (spheres.domain() != domain)
    throw std::logic_error("SphereSystem: the spheres are not this domain's part (SpherePart with its domain)");
  const std::size_t n = sphere_total_ = spheres.total();
  if (n > 0) radius_min_ = spheres.radius_min(), radius_max_ = spheres.radius_max();
  const std::size_t sphere_blocks = (n + kSphereBlock - 1) / kSphereBlock;
  sphere_block_kinetic_.assign(sphere_blocks, 0);
  block_keeps_acceleration_.assign(sphere_blocks, 1);
  sphere_block_damping_.assign(sphere_blocks, 0);
  sphere_block_vmax2_.assign(sphere_blocks, 0);
  threads_ = omp_get_max_threads();
  partitions_ = partition_count(n, spheres_per_partition);
  sphere_chunk_ = (n + partitions_ - 1) / partitions_;
  if (domain) split(*domain);
  // Until the law lays its contacts out, a rank holds its own spheres (one process all): what
  // it holds later comes from the owners.
  std::vector<std::uint32_t> own(own_end() - own_begin());
  for (std::size_t k = 0; k < own.size(); ++k) own[k] = std::uint32_t(own_begin() + k);
  if (own_begin() != spheres.begin() || own.size() != spheres.own_count())
    throw std::logic_error("SphereSystem: the part's own spheres are not the rank's range (SphereSystem::rank_starts)");
  SphereSet mine = std::move(spheres).take_own();
  std::vector<std::int64_t>().swap(mine.ids);  // the packing file's ids: read before the system only
  if (!domain) {
    spheres_ = std::move(mine);
    hold(std::move(own));
  } else {
    hold(own, mine, own);
  }
  keep_held_bonds();
  kernel_->attach(*this);
}

void SphereSystem::hold(std::vector<std::uint32_t> ids, const SphereSet& arrived, const std::vector<std::uint32_t>& arrived_ids) {
  const std::size_t m = ids.size();
  // Where each sphere held from now on was held before (both lists sorted; none at construction).
  std::vector<std::size_t> from(m, kNotHeld);
  for (std::size_t l = 0, o = 0; l < m; ++l) {
    while (o < held_ids_.size() && held_ids_[o] < ids[l]) ++o;
    if (o < held_ids_.size() && held_ids_[o] == ids[l]) from[l] = o;
  }
  if (domain_) {  // the statics first: a new sphere's step-0 position is its centre
    SphereSet next = sphere_set_of_size(m, false);
    for (std::size_t l = 0; l < m; ++l) {
      if (from[l] != kNotHeld) {
        copy_sphere(spheres_, from[l], next, l);
      } else {
        const auto at = std::lower_bound(arrived_ids.begin(), arrived_ids.end(), ids[l]);
        if (at == arrived_ids.end() || *at != ids[l])
          throw std::logic_error("SphereSystem::hold: sphere " + std::to_string(ids[l]) + " is new here and no statics came with it");
        copy_sphere(arrived, std::size_t(at - arrived_ids.begin()), next, l);
      }
    }
    spheres_ = std::move(next);
  }
  const auto relay = [&](auto& array, const auto& start) {
    std::remove_reference_t<decltype(array)> next(m);
    for (std::size_t l = 0; l < m; ++l) next[l] = from[l] != kNotHeld ? array[from[l]] : start(l);
    array = std::move(next);
  };
  const auto zero = [](std::size_t) { return Vec3{}; };
  relay(x_, [&](std::size_t l) { return displacement_state_ ? Vec3{} : spheres_.centre_m[l]; });
  for (auto* state : {&v_, &w_, &a_, &a_undamped_, &f_ext_, &f_acc_, &t_acc_}) relay(*state, zero);
  if (track_rotation_) relay(theta_, zero);
  relay(is_forced_, [](std::size_t) { return std::uint8_t(0); });
  inv_mass_.resize(m), inv_inertia_.resize(m), inv_mass3_.resize(3 * m), inv_inertia3_.resize(3 * m);
  for (std::size_t l = 0; l < m; ++l) {
    inv_mass_[l] = 1.0 / spheres_.mass_kg[l];
    inv_inertia_[l] = 1.0 / spheres_.inertia_kg_m2[l];
    for (std::size_t d = 0; d < 3; ++d) inv_mass3_[3 * l + d] = inv_mass_[l], inv_inertia3_[3 * l + d] = inv_inertia_[l];
  }
  if (!domain_) return;
  own_local_ = std::size_t(std::lower_bound(ids.begin(), ids.end(), std::uint32_t(own_begin_)) - ids.begin());
  held_ids_ = std::move(ids);
  for (auto* lists : {&ghost_sends_, &ghost_receives_})
    for (auto& g : *lists) {
      g.local.resize(g.spheres.size());
      for (std::size_t q = 0; q < g.spheres.size(); ++q) g.local[q] = local_id(g.spheres[q]);
    }
  observed_local_.resize(observed_.size());
  for (std::size_t q = 0; q < observed_.size(); ++q) observed_local_[q] = local_id(observed_[q]);
}

void SphereSystem::number_contacts_locally() {
  if (domain_)
    for (auto* ends : {&first_, &second_})
      for (std::uint32_t& k : *ends) k = local_id(k);
  const std::vector<std::uint32_t> cross_first(first_.begin() + std::ptrdiff_t(cross_begin_), first_.end());
  const std::vector<std::uint32_t> cross_second(second_.begin() + std::ptrdiff_t(cross_begin_), second_.end());
  cross_incidence_ = make_incidence(held_sphere_count(), cross_first, cross_second);
}

std::size_t SphereSystem::find_local(std::size_t k) const {
  if (!domain_) return k;
  if (k >= own_begin_ && k < own_end_) return k - own_begin_ + own_local_;
  const auto at = std::lower_bound(held_ids_.begin(), held_ids_.end(), std::uint32_t(k));
  return at != held_ids_.end() && *at == k ? std::size_t(at - held_ids_.begin()) : kNotHeld;
}

std::uint32_t SphereSystem::local_id(std::size_t k) const {
  const std::size_t l = find_local(k);
  if (l == kNotHeld) throw std::logic_error("SphereSystem: sphere " + std::to_string(k) + " is not held on this rank");
  return std::uint32_t(l);
}

SphereSystem::~SphereSystem() = default;

// One process takes the whole network; each of several ranks its part (make_bond_network with the
// domain): the bonds with an end of its own, whose indices it keeps as two runs.
void SphereSystem::keep_held_bonds() {
  std::vector<Vec3>().swap(bonds_.normal0);  // bond_geometry0 makes them anew
  std::vector<double>().swap(bonds_.overlap0_m);
  const std::size_t first = own_begin(), end = own_end();
  if (!domain_ && !bonds_.is_part()) {
    bond_count_ = held_bond_end_ = bonds_.size();
    return;
  }
  if (!domain_ || bonds_.own_begin != first || bonds_.own_end != end)
    throw std::logic_error("SphereSystem: the bonds are not this rank's part of the network (make_bond_network with its domain)");
  bond_count_ = bonds_.whole_size;
  const std::size_t cross = std::size_t(std::lower_bound(bonds_.first.begin(), bonds_.first.end(), first) - bonds_.first.begin());
  held_cross_bonds_.assign(bonds_.ids.begin(), bonds_.ids.begin() + std::ptrdiff_t(cross));
  // An empty run of own-first bonds sits past every index, where held_bond finds none.
  held_bond_begin_ = cross < bonds_.size() ? bonds_.ids[cross] : bond_count_;
  held_bond_end_ = held_bond_begin_ + (bonds_.size() - cross);
  if (cross < bonds_.size() && bonds_.ids.back() + 1 != held_bond_end_)
    throw std::logic_error("SphereSystem: this rank's own-first bonds are not one run of indices");
  std::vector<std::uint32_t>().swap(bonds_.ids);
}

std::size_t SphereSystem::held_bond(std::size_t b) const {
  if (b >= held_bond_begin_ && b < held_bond_end_) return held_cross_bonds_.size() + (b - held_bond_begin_);
  const auto at = std::lower_bound(held_cross_bonds_.begin(), held_cross_bonds_.end(), std::uint32_t(b));
  if (b >= held_bond_end_ || at == held_cross_bonds_.end() || *at != b)
    throw std::logic_error("SphereSystem: bond " + std::to_string(b) + " has no end on this rank");
  return std::size_t(at - held_cross_bonds_.begin());
}

bool SphereSystem::holds_bond(std::size_t b) const {
  return (b >= held_bond_begin_ && b < held_bond_end_) ||
         std::binary_search(held_cross_bonds_.begin(), held_cross_bonds_.end(), std::uint32_t(b));
}

std::vector<std::uint32_t> SphereSystem::set_contacts(const std::vector<std::uint32_t>& first,
                                                      const std::vector<std::uint32_t>& second, std::size_t bonds,
                                                      bool moments) {
  return finish_layout(first, second, domain_ ? lay_out_held(first, second, bonds) : lay_out_whole(first, second), moments);
}

std::vector<std::uint32_t> SphereSystem::lay_out_whole(const std::vector<std::uint32_t>& first,
                                                       const std::vector<std::uint32_t>& second) {
  const std::size_t count = first.size();
  // Interior contacts by partition, then those across partitions, each in the order given.
  global_interior_start_.assign(partitions_ + 1, 0);
  for (std::size_t c = 0; c < count; ++c) {
    const std::size_t p = first[c] / sphere_chunk_;
    if (p == second[c] / sphere_chunk_) ++global_interior_start_[p + 1];
  }
  for (std::size_t p = 0; p < partitions_; ++p) global_interior_start_[p + 1] += global_interior_start_[p];
  std::vector<std::uint32_t> order(count);
  std::vector<std::uint32_t> fill(global_interior_start_.begin(), global_interior_start_.end() - 1);
  global_cross_begin_ = global_interior_start_[partitions_];
  std::size_t cross = global_cross_begin_;
  for (std::size_t c = 0; c < count; ++c) {
    const std::size_t p = first[c] / sphere_chunk_;
    order[p == second[c] / sphere_chunk_ ? fill[p]++ : cross++] = std::uint32_t(c);
  }
  global_slots_ = count;
  interior_start_ = global_interior_start_;
  return order;
}

std::vector<std::uint32_t> SphereSystem::set_bond_contacts() {
  std::vector<std::uint32_t> order = set_contacts(bonds_.first, bonds_.second, bonds_.size());
  for (std::uint32_t& c : order) c = std::uint32_t(held_bond_id(c));
  return order;
}

std::vector<std::uint32_t> SphereSystem::finish_layout(const std::vector<std::uint32_t>& first,
                                                       const std::vector<std::uint32_t>& second,
                                                       std::vector<std::uint32_t> order, bool moments) {
  const std::size_t held = order.size();
  global_cross_blocks_ = (global_slots_ - global_cross_begin_ + kContactBlock - 1) / kContactBlock;
  cross_begin_ = interior_start_[partitions_];
  first_.resize(held);
  second_.resize(held);
  for (std::size_t s = 0; s < held; ++s) {
    first_[s] = first[order[s]];
    second_[s] = second[order[s]];
  }
  if (domain_) lay_out_domain();  // the ghosts and the held spheres, then the local ids
  else number_contacts_locally();
  out_.assign(held - cross_begin_, ContactOut{});
  if (moments) out_moment_.assign(held - cross_begin_, Vec3{});
  else out_moment_.clear();
  cross_blocks_ = (held - cross_begin_ + kContactBlock - 1) / kContactBlock;
  const std::size_t tasks = partitions_ + global_cross_blocks_;
  // Dissipation is cumulative: keep what the old tasks held.
  double plastic = 0;
  for (double p : task_plastic_) plastic += p;
  task_elastic_.assign(tasks, 0);
  task_plastic_.assign(tasks, 0);
  task_plastic_[0] = plastic;
  task_peak2_.assign(tasks, 0);
  // A parallel region costs a few microseconds: worth it only for big systems.
  parallel_ = threads_ > 1 && held >= 8 * kContactBlock && partitions_ > 1;
  return order;
}

Vec3 SphereSystem::displacement(std::size_t k) const {
  if (displacement_state_) return held_or_collected(x_, collected_.x, k);
  if (const std::size_t l = find_local(k); l != kNotHeld) return x_[l] - spheres_.centre_m[l];  // one look-up (sensors)
  return held_or_collected(x_, collected_.x, k) - reference_position(k);
}

void SphereSystem::add_external_force(std::size_t sphere, const Vec3& force) {
  const std::uint32_t k = local_id(sphere);
  if (!is_forced_[k]) {
    is_forced_[k] = 1;
    forced_.push_back(k);
  }
  f_ext_[k] += force;
}

void SphereSystem::observe(const std::vector<std::size_t>& spheres) {
  std::fill(block_keeps_acceleration_.begin(), block_keeps_acceleration_.end(), std::uint8_t(0));
  for (const std::size_t k : spheres) {
    if (k >= sphere_total_) throw std::logic_error("SphereSystem::observe: no sphere " + std::to_string(k));
    block_keeps_acceleration_[k / kSphereBlock] = 1;
  }
}

std::size_t SphereSystem::observed_local_id(std::size_t k) const {
  if (k >= sphere_total_ || !block_keeps_acceleration_[k / kSphereBlock])
    throw std::logic_error("SphereSystem: the acceleration of sphere " + std::to_string(k) +
                           " is not kept (not among the observed spheres)");
  return local_id(k);
}

double SphereSystem::impose_displacement(std::size_t sphere, const Vec3& e, double u_now, double u_next, double dt) {
  const std::size_t k = observed_local_id(sphere);
  const double v_imposed = (u_next - u_now) / dt;
  const double v_before = dot(v_[k], e) - dt * dot(a_[k], e);  // v_{n-1/2} along e
  // A constrained degree of freedom is not damped (Yade: blocked DOFs skip the
  // integrator); its force balance uses the undamped F/m of this step.
  const double a_free = dot(a_undamped_[k], e);
  const double a_imposed = (v_imposed - v_before) / dt;
  x_[k] += (u_next - dot(displacement(sphere), e)) * e;
  v_[k] += (v_imposed - dot(v_[k], e)) * e;
  a_[k] += (a_imposed - a_free) * e;
  // The constraint force m (a_imposed - a_free) does work over the step.
  const double force = spheres_.mass_kg[k] * (a_imposed - a_free);
  energy_.external_work_J += force * (v_before + v_imposed) * 0.5 * dt;
  return force;
}

void SphereSystem::step(double dt, bool evaluate_energy) {
  collected_ = {};  // rank 0's whole copy is spent (collect_state)
  if (domain_ && slot_elastic_.size() != first_.size())  // after a new layout (lay_out_domain)
    for (auto* values : {&slot_elastic_, &slot_plastic_}) values->resize(first_.size());
  forced_v_before_.resize(forced_.size());
  for (std::size_t i = 0; i < forced_.size(); ++i) forced_v_before_[i] = v_[forced_[i]];

#pragma omp parallel if (parallel_)
  {
    kernel_->contact_forces(*this, dt, evaluate_energy);  // ends with the implicit barrier of its omp for
    integrate(dt, evaluate_energy);
  }
  if (domain_) share_step(evaluate_energy);

  for (std::size_t i = 0; i < forced_.size(); ++i) {
    const std::uint32_t k = forced_[i];
    energy_.external_work_J += dot(f_ext_[k], forced_v_before_[i] + v_[k]) * 0.5 * dt;
    f_ext_[k] = {};
    is_forced_[k] = 0;
  }
  forced_.clear();

  double peak2 = 0, vmax2 = 0;
  for (double p : task_peak2_) peak2 = std::max(peak2, p);
  for (double v2 : sphere_block_vmax2_) vmax2 = std::max(vmax2, v2);
  if (domain_) vmax2 = vmax2_all_;  // other ranks' blocks are theirs: share_step brought the largest
  peak_ratio_ = std::max(peak_ratio_, std::sqrt(peak2));
  max_speed_ = std::sqrt(vmax2);
  if (evaluate_energy) {
    double kinetic = 0, elastic = 0;
    for (double e : sphere_block_kinetic_) kinetic += e;
    for (double e : task_elastic_) elastic += e;
    energy_.kinetic_J = kinetic;
    energy_.elastic_J = elastic;
  }
  kernel_->after_step(*this, dt);
  if (domain_ && ghosts_stale_) exchange_ghosts();  // contact detection brought new ghosts
}

void SphereSystem::integrate(double dt, bool evaluate_energy) {
  const std::size_t n = sphere_total_;
  // Distributed: this rank's blocks only (the others move theirs; share_step brings them).
  const std::size_t first_block = domain_ ? own_block_begin_ : 0;
  const std::size_t blocks = domain_ ? own_block_end_ : (n + kSphereBlock - 1) / kSphereBlock;
  const std::uint32_t* offset = cross_incidence_.offset.data();
  const std::uint32_t* entry = cross_incidence_.entry.data();
  const ContactOut* out = out_.data();
  const Vec3* moment = out_moment_.empty() ? nullptr : out_moment_.data();

  // The blocks in groups of kDampingGroup: each block's damping terms are summed in component
  // order, as one chain of additions (the order fixes the bits); the chains of a group's blocks
  // are independent, so they are added side by side (kDampingGroup additions in flight instead
  // of one waiting for the last).
  const std::size_t groups = (blocks - first_block + kDampingGroup - 1) / kDampingGroup;
  const bool damped = material_.damping != 0 || material_.viscous_damping_1_s != 0;
#pragma omp for schedule(static)
  for (std::size_t group = 0; group < groups; ++group) {
    const std::size_t b0 = first_block + group * kDampingGroup, b1 = std::min(blocks, b0 + kDampingGroup);
    alignas(64) double damping[kDampingGroup][kDampingTerms];
    for (std::size_t blk = b0; blk < b1; ++blk) {
      const std::size_t begin = own_local(blk * kSphereBlock), end = own_local(std::min(n, (blk + 1) * kSphereBlock));
      // Total force and torque, in a fixed order: contacts inside the partition
      // (summed in slot order by for_each_contact), those across partitions,
      // then external loads.
      for (std::size_t k = begin; k < end; ++k) {
        Vec3 f = f_acc_[k], t = t_acc_[k];
        for (std::uint32_t e = offset[k]; e < offset[k + 1]; ++e) {
          const std::uint32_t code = entry[e];
          const ContactOut& o = out[code >> 1];
          const unsigned side = code & 1u;
          const double sign = side ? 1.0 : -1.0;
          f += sign * o.f;
          t -= o.t[side];
          if (moment) t += sign * moment[code >> 1];
        }
        // Only forced spheres read their external force: f + 0 would be f anyway (f is never -0:
        // it is summed from +0, and a sum is -0 only when both terms are).
        if (is_forced_[k]) f += f_ext_[k];
        f_acc_[k] = f;
        t_acc_[k] = t;
      }
      update_motion(begin, end, blk, dt, evaluate_energy, damping[blk - b0]);
    }
    if (!damped) continue;
    double sum[kDampingGroup] = {};
    if (b1 - b0 == kDampingGroup) {
      for (std::size_t c = 0; c < kDampingTerms; ++c)
        for (std::size_t g = 0; g < kDampingGroup; ++g) sum[g] += damping[g][c];
    } else {
      for (std::size_t g = 0; g < b1 - b0; ++g)
        for (std::size_t c = 0; c < kDampingTerms; ++c) sum[g] += damping[g][c];
    }
    for (std::size_t blk = b0; blk < b1; ++blk) sphere_block_damping_[blk] += sum[blk - b0];
  }
}

// Eq. (7) and leapfrog, per Cartesian component, over the flat arrays of one
// block: one vector loop for the translations, one for the rotations. The
// per-component energy terms go through a buffer and are added in component
// order, so the sums do not depend on the vector width: the kinetic energy
// here, the damping terms by the caller (integrate), translations then rotations.
MESOWAVE_KERNEL_CLONES
void SphereSystem::update_motion(std::size_t begin, std::size_t end, std::size_t blk, double dt, bool evaluate_energy,
                                 double* damping_terms) {
  const double alpha = material_.damping, half_dt = 0.5 * dt;
  // Mass-proportional viscous damping (scene.hpp, damping_law viscous), implicit midpoint:
  // v_{n+1/2} = ((1 - c dt/2) v_{n-1/2} + dt F/m) / (1 + c dt/2), i.e. a = (a - c v_{n-1/2}) / (1 + c dt/2).
  const double c_visc = material_.viscous_damping_1_s, inv_den = 1.0 / (1.0 + half_dt * c_visc);
  const bool viscous = c_visc != 0;
  const std::size_t m = 3 * (end - begin);
  double kin[3 * kSphereBlock];
  double vmax2 = 0, kinetic = 0;
  // Only the observed spheres' blocks keep the accelerations (observe()).
  const bool keep_a = block_keeps_acceleration_[blk] != 0;
  for (int part = 0; part < 2; ++part) {
    const bool rotation = part == 1;
    double* f = &(rotation ? t_acc_ : f_acc_)[begin].x;
    double* v = &(rotation ? w_ : v_)[begin].x;
    double* a_out = &a_[begin].x;
    double* a_free_out = &a_undamped_[begin].x;
    double* x = rotation ? (track_rotation_ ? &theta_[begin].x : nullptr) : &x_[begin].x;
    const double* inv_m = &(rotation ? inv_inertia3_ : inv_mass3_)[3 * begin];
    double* dmp = damping_terms + part * 3 * kSphereBlock;
    double part_vmax2 = 0;
#pragma omp simd reduction(max : part_vmax2)
    for (std::size_t c = 0; c < m; ++c) {
      const double a_free = f[c] * inv_m[c];
      const double v0 = v[c];
      const double p = a_free * (v0 + half_dt * a_free);
      const double sign = p > 0.0 ? 1.0 : (p < 0.0 ? -1.0 : 0.0);
      const double a_local = a_free * (1.0 - alpha * sign);
      const double a = viscous ? (a_local - c_visc * v0) * inv_den : a_local;
      const double v1 = v0 + dt * a;
      const double mass = 1.0 / inv_m[c];
      kin[c] = 0.5 * mass * v0 * v1;
      dmp[c] = mass * (a_free - a) * (v0 + v1) * half_dt;
      v[c] = v1;
      f[c] = 0.0;
      if (!rotation && keep_a) {
        a_out[c] = a;
        a_free_out[c] = a_free;
      }
      if (!rotation) {
        x[c] += dt * v1;
        part_vmax2 = std::max(part_vmax2, v1 * v1);
      }
    }
    if (rotation && x)
#pragma omp simd
      for (std::size_t c = 0; c < m; ++c) x[c] += dt * v[c];
    if (!rotation) vmax2 = part_vmax2;
    // A short block's terms end in +0: adding it changes no sum (sums here are never -0).
    std::fill(dmp + m, dmp + 3 * kSphereBlock, 0.0);
    if (evaluate_energy)
      for (std::size_t c = 0; c < m; ++c) kinetic += kin[c];
  }
  sphere_block_kinetic_[blk] = kinetic;
  sphere_block_vmax2_[blk] = 3.0 * vmax2;  // |v|^2 <= 3 max_k v_k^2: a safe bound for contact detection
}

EnergyAccount SphereSystem::energy() const {
  EnergyAccount e = energy_;
  e.damping_J = 0;
  for (double d : sphere_block_damping_) e.damping_J += d;
  e.plastic_J = 0;
  for (double p : task_plastic_) e.plastic_J += p;
  return e;
}

bool SphereSystem::has_non_finite_state() const {
  // Distributed: each rank checks its own spheres, and all agree (collective).
  const std::size_t begin = own_local(own_begin()), end = own_local(own_end());
  std::uint64_t bad = 0;
  for (std::size_t k = begin; k < end && !bad; ++k)
    bad = !std::isfinite(x_[k].x + x_[k].y + x_[k].z + v_[k].x + v_[k].y + v_[k].z + w_[k].x + w_[k].y + w_[k].z);
  return domain_ ? domain_->sum(bad) > 0 : bad != 0;
}

// Distributed, a rank computes its own spheres' rows: from its held bonds (every bond with an end
// of its own), in bond order (so each row sums the terms of one process in its order), with the other end's x
// from its owner (ghost_rows). Each end's M^-1/2 factors are taken once a call, per sphere (the same
// 1/sqrt(m) and 1/sqrt(I) as per bond end, so the same bits): per bond end they were most of the work.
void SphereSystem::scaled_stiffness_action(const double* x, double* y) const {
  const std::size_t first = own_begin(), own = own_end() - first;
  std::fill(y, y + 6 * own, 0.0);
  std::vector<std::uint32_t> ghost_ids;
  const std::vector<double> ghost = domain_ ? ghost_rows(x, ghost_ids) : std::vector<double>();
  // Per own sphere, then per ghost (in ghost_ids' order): 1/sqrt(m), 1/sqrt(I).
  std::vector<double> scale(2 * (own + ghost_ids.size()));
  std::vector<std::uint32_t> ghost_local;  // the ghosts' local ids, in ghost_ids' order (the lists' order)
  for (const auto& g : ghost_receives_) ghost_local.insert(ghost_local.end(), g.local.begin(), g.local.end());
  const auto scale_of = [&](std::size_t at, std::size_t l) {
    scale[2 * at] = 1.0 / std::sqrt(spheres_.mass_kg[l]);
    scale[2 * at + 1] = 1.0 / std::sqrt(spheres_.inertia_kg_m2[l]);
  };
  for (std::size_t k = 0; k < own; ++k) scale_of(k, own_local(first + k));
  for (std::size_t g = 0; g < ghost_ids.size(); ++g) scale_of(own + g, ghost_local[g]);
  struct End {
    const double* rows;  ///< x's six rows of the sphere
    const double* scale;
    std::size_t local;  ///< its statics' place
    double* y;  ///< its six rows of y, own spheres only
  };
  const auto end_of = [&](std::size_t k) {
    if (is_own(k)) return End{x + 6 * (k - first), &scale[2 * (k - first)], own_local(k), y + 6 * (k - first)};
    const auto g = std::size_t(std::lower_bound(ghost_ids.begin(), ghost_ids.end(), std::uint32_t(k)) - ghost_ids.begin());
    return End{ghost.data() + 6 * g, &scale[2 * (own + g)], ghost_local[g], nullptr};
  };
  const auto dof = [](const End& e, int part) {
    const double s = e.scale[part];
    const double* v = e.rows + 3 * part;
    return Vec3{s * v[0], s * v[1], s * v[2]};
  };
  const auto add = [](const End& e, int part, const Vec3& g) {
    if (!e.y) return;
    const double s = e.scale[part];
    for (int d = 0; d < 3; ++d) e.y[3 * part + d] -= s * g[d];  // K x = -(force)
  };
  for (std::size_t h = 0; h < bonds_.size(); ++h) {  // in bond order
    const End i = end_of(bonds_.first[h]), j = end_of(bonds_.second[h]);
    const LinearBond lb = linear_bond(*this, spheres_.centre_m[i.local], spheres_.centre_m[j.local], spheres_.radius_m[i.local],
                                      spheres_.radius_m[j.local]);
    Vec3 fi, mi, fj, mj;
    lb.forces(dof(i, 0), dof(i, 1), dof(j, 0), dof(j, 1), fi, mi, fj, mj);
    add(i, 0, fi);
    add(i, 1, mi);
    add(j, 0, fj);
    add(j, 1, mj);
  }
}

double SphereSystem::stiffness_dot(const double* a, const double* b) const {
  const auto continue_sum = [&](double sum) { return ordered_dot(a, b, stiffness_rows().count, sum); };
  return domain_ ? chained_sum(*domain_, continue_sum) : continue_sum(0.0);
}

double SphereSystem::scaled_stiffness_row_sum_bound() const {
  const std::size_t first = own_begin();
  std::vector<double> row(6 * (own_end() - first), 0.0);
  for (std::size_t h = 0; h < bonds_.size(); ++h) {
    const std::size_t ends[2] = {bonds_.first[h], bonds_.second[h]};
    const std::size_t local[2] = {local_id(ends[0]), local_id(ends[1])};
    const LinearBond lb = linear_bond(*this, spheres_.centre_m[local[0]], spheres_.centre_m[local[1]], spheres_.radius_m[local[0]],
                                      spheres_.radius_m[local[1]]);
    double end_scale[2][2], scale[12];  // M^-1/2: each end's 1/sqrt(m) and 1/sqrt(I), once
    for (int e = 0; e < 2; ++e)
      end_scale[e][0] = 1.0 / std::sqrt(spheres_.mass_kg[local[e]]), end_scale[e][1] = 1.0 / std::sqrt(spheres_.inertia_kg_m2[local[e]]);
    for (int c = 0; c < 12; ++c) scale[c] = end_scale[c / 6][(c % 6) < 3 ? 0 : 1];
    for (int c = 0; c < 12; ++c) {  // column c of the bond's 12 x 12 block
      Vec3 u[4] = {};
      u[c / 3][c % 3] = 1.0;
      Vec3 g[4];
      lb.forces(u[0], u[1], u[2], u[3], g[0], g[1], g[2], g[3]);
      for (int r = 0; r < 12; ++r) {
        const std::size_t k = ends[r / 6];
        if (!is_own(k)) continue;
        const double entry = -g[r / 3][r % 3];
        row[6 * (k - first) + std::size_t(r % 6)] += std::abs(entry) * scale[r] * scale[c];
      }
    }
  }
  const double bound = row.empty() ? 0.0 : *std::max_element(row.begin(), row.end());
  return domain_ ? domain_->max(bound) : bound;  // a maximum: exact in any order
}

// Between steps the external forces are spent (f_ext_ zero, forced_ empty) and
// the per-step buffers (forces, contact records, elastic and peak per task) are
// rewritten before they are read; what carries over is the motion, the peak
// ratio, the speed that drives contact detection, the energies - the cumulative
// sums kept per task and per sphere block, in the order they are added - and
// the law's state. The law goes first: a new contact layout resets the per-task
// plastic sums, which are then read over it.
// Distributed, the caller has shared every block's damping (Model::save_state); rank 0 writes
// each sphere array a piece at a time from the ranks' own spheres (write_spheres), and the other
// ranks' group writes nowhere.
void SphereSystem::save_state(StateGroup& group) const {
  write_spheres(group, "x", x_);
  write_spheres(group, "v", v_);
  write_spheres(group, "w", w_);
  write_spheres(group, "a", a_);
  write_spheres(group, "a_undamped", a_undamped_);
  if (track_rotation_) write_spheres(group, "theta", theta_);
  group.write("peak_ratio", peak_ratio_);
  group.write("max_speed", max_speed_);
  group.write("kinetic_J", energy_.kinetic_J);
  group.write("elastic_J", energy_.elastic_J);
  group.write("external_work_J", energy_.external_work_J);
  group.write("sphere_block_damping_J", sphere_block_damping_);
  StateGroup law = group.create("law");
  kernel_->save_state(*this, law);
  group.write("task_plastic_J", task_plastic_);
}

std::vector<double> SphereSystem::read_slots(const StateGroup& group, const std::string& name) const {
  if (!domain_) {
    std::vector<double> whole(global_slots_);
    group.read_into(name, whole);
    return whole;
  }
  return group.read_at(name, global_slots_, global_slot_);
}

// Distributed, every rank reads its held spheres' and slots' rows of each array, a piece at a time.
void SphereSystem::load_state(const StateGroup& group) {
  kernel_->load_state(*this, group.open("law"));
  const auto read_held = [&](const char* name, std::vector<Vec3>& held) {
    if (!domain_) return group.read_into(name, held);
    held = group.read_vec3s_at(name, sphere_total_, held_ids_);
  };
  read_held("x", x_);
  read_held("v", v_);
  read_held("w", w_);
  read_held("a", a_);
  read_held("a_undamped", a_undamped_);
  if (track_rotation_) read_held("theta", theta_);
  peak_ratio_ = group.read_double("peak_ratio");
  max_speed_ = group.read_double("max_speed");
  energy_.kinetic_J = group.read_double("kinetic_J");
  energy_.elastic_J = group.read_double("elastic_J");
  energy_.external_work_J = group.read_double("external_work_J");
  group.read_into("sphere_block_damping_J", sphere_block_damping_);
  group.read_into("task_plastic_J", task_plastic_);
  if (domain_) {
    broken_ = std::size_t(domain_->sum(kernel_->broken_bonds_in(reported_)));
    ghosts_stale_ = false;  // every rank read its held spheres' state
  }
}

std::size_t SphereSystem::memory_bytes() const {
  const std::size_t n = held_sphere_count();
  // The statics (centre, radius, mass, inertia, packing index), the motion (x, v, w, a, a undamped, f_ext,
  // theta), 1/m and 1/I (once, then once a component), the forced flag.
  std::size_t bytes = n * (sizeof(Vec3) * (7 + (track_rotation_ ? 1 : 0)) + 3 * sizeof(double) + sizeof(std::uint32_t) +
                           8 * sizeof(double) + 1);
  bytes += bonds_.size() * 2 * sizeof(std::uint32_t) + held_cross_bonds_.size() * sizeof(std::uint32_t);
  bytes += kernel_->memory_bytes() + out_moment_.size() * sizeof(Vec3);
  bytes += out_.size() * sizeof(ContactOut) + cross_incidence_.entry.size() * sizeof(std::uint32_t) +
           first_.size() * 2 * sizeof(std::uint32_t) + 2 * n * sizeof(Vec3);
  // Distributed: the held slots' places and values, the held spheres' ids.
  bytes += global_slot_.size() * sizeof(std::uint32_t) + slot_elastic_.size() * 2 * sizeof(double) +
           owned_values_.size() * sizeof(double) + held_ids_.size() * sizeof(std::uint32_t);
  return bytes;
}

}  // namespace mesowave::dem
