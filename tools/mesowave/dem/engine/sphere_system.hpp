#pragma once
// Spheres with six degrees of freedom, the state both 3-D models share, and
// the leapfrog integrator in the order of Yade's NewtonIntegrator:
//   a = F/m;  a_k <- a_k (1 - alpha_d sgn(a_k (v_k + a_k dt/2)))   (Eq. 7, per component)
//   v += dt a;  x += dt v;   the same for the angular velocity with the torque.
//
// A contact law is a kernel the integrator composes (ContactKernel below, one
// class and file per law, registered in contact_law.hpp): it computes one
// contact at a time - the force on its second sphere, the torque factors and,
// for laws with rolling/twisting springs, a moment (for_each_contact below).
// The integrator knows no law. Contacts are laid out so that a step gives the same bits on any
// number of threads, with no atomics and no per-thread buffers: the spheres
// are cut into a fixed number of Morton ranges; contacts inside a range add
// their forces in place (one thread owns a range), contacts between ranges
// leave a record that each sphere gathers, in a fixed order, in the pass that
// also updates its motion. Sums over spheres or contacts (energies) are taken
// per fixed task and added in task order, for the same reason.
//
// Distributed (distribute(), dem/parallel/sphere_system_domain.cpp, docs/mpi.md): each rank
// owns a range of whole sphere blocks in Morton order - a compact piece of space - computes
// every contact that touches one of its spheres (a contact across two ranks on both, from
// the same inputs in the same orientation, first < second: the same bits) and moves only
// its own spheres; after each step it sends its neighbour ranks the motion of the spheres
// they hold as ghosts (the other ends of their contacts), every rank the spheres the
// actuators and sensors read, and the task sums are redone from the contacts' values
// gathered in slot order, so every rank holds what the single-process run holds of its
// own spheres, its ghosts and the observed spheres, bit for bit. The critical step's Lanczos
// runs on each rank's own rows (scaled_stiffness_action, stiffness_dot), and a rank keeps
// its held bonds only, made by itself (held_bond_network, make_bond_network). A rank's
// per-sphere arrays hold only the spheres it holds (own, ghosts, observed), numbered locally
// in global id order (hold()), so that first < second and every sphere's order of terms
// survive; the Model interface takes global ids (the packing's order), a contact kernel reads
// local ones. The spheres' statics (centre, radius, mass, inertia, packing index) are held the
// same way (held_spheres()): the constructor takes its own spheres' from its part of the set
// (SpherePart); a ghost's come from its owner with the layout that brings it, an observed
// sphere's with distribute().
#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "mesowave/dem/contact/bond_network.hpp"
#include "mesowave/dem/contact/material.hpp"
#include "mesowave/dem/engine/contact_ends.hpp"
#include "mesowave/dem/engine/model.hpp"
#include "mesowave/dem/engine/sphere_set.hpp"

namespace mesowave::dem {

class SphereSystem;

/// A contact law as the integrator sees it. The system calls attach() once
/// (the law sets its contacts with set_contacts and keeps its per-contact
/// arrays in slot order), contact_forces() every step inside the step's
/// parallel region (the law runs for_each_contact there) and after_step()
/// serially after the motion update (contact detection).
class ContactKernel {
public:
  virtual ~ContactKernel() = default;
  virtual std::string name() const = 0;  ///< the model's name: full | linear
  /// The integrated position is the displacement from step 0 (linearised
  /// network, best precision for tiny amplitudes) instead of the absolute position.
  virtual bool displacement_state() const = 0;
  /// Integrate the rotation vector theta (small rotations; the linearised network needs it).
  virtual bool track_rotation() const = 0;
  virtual void attach(SphereSystem& system) = 0;
  virtual void contact_forces(SphereSystem& system, double dt, bool evaluate_energy) = 0;
  virtual void after_step(SphereSystem& /*system*/, double /*dt*/) {}
  virtual std::size_t broken_bond_count() const { return 0; }
  /// The same over the given slots only (a distributed run counts each bond on one rank).
  virtual std::size_t broken_bonds_in(const std::vector<std::uint32_t>& /*slots*/) const { return 0; }
  /// The kernel reads the velocities and angular velocities (false: positions and rotations
  /// only), so a distributed run sends its ghosts only what the law reads.
  virtual bool reads_velocities() const { return true; }
  virtual std::size_t memory_bytes() const = 0;
  /// The law's state that changes from step to step (a checkpoint, state_group.hpp):
  /// bonds broken, shear forces, contacts detected and their layout. load_state
  /// restores it into a law attached to a system built from the same packing.
  virtual void save_state(const SphereSystem& system, StateGroup& group) const = 0;
  virtual void load_state(SphereSystem& system, const StateGroup& group) = 0;
  /// Rolling and twisting stiffness of a bond between spheres of radii ri and rj at step 0
  /// (moment = -k_r theta_bend - k_tw theta_twist), for the critical time step; 0 for laws without moments.
  virtual void moment_stiffness(const SphereSystem& /*system*/, double /*ri*/, double /*rj*/, double& k_r, double& k_tw) const {
    k_r = k_tw = 0;
  }
};

/// The integrator: spheres, their motion and a contact kernel.
class SphereSystem final : public Model {
public:
  /// With a `domain` of several ranks (docs/mpi.md) the system is split from the start: the
  /// law lays out and holds only the contacts of this rank's spheres; distribute() must then
  /// be given the same domain. `spheres` and `bonds`: the whole set and network in one process,
  /// this rank's parts of them on several (SpherePart with the domain, make_bond_network of it:
  /// the bonds with an end of its own). `spheres_per_partition`: the layout's partition size
  /// (partition_count), another only for benchmarks that compare two.
  SphereSystem(SpherePart spheres, BondNetwork bonds, const CohesiveFrictionalMaterial& material,
               std::unique_ptr<ContactKernel> kernel, Domain* domain = nullptr,
               std::size_t spheres_per_partition = kSpheresPerPartition);
  ~SphereSystem() override;

  std::string name() const override { return kernel_->name(); }
  /// Interactions evaluated each step, on all ranks (the linearised network's are its bonds).
  std::size_t contact_count() const override { return global_slots_; }
  std::size_t broken_bond_count() const override;
  std::size_t sphere_count() const override { return sphere_total_; }
  std::size_t bond_count() const override { return bond_count_; }
  std::size_t degrees_of_freedom() const override { return 6 * sphere_total_; }
  /// Distributed, these read a held sphere, or on rank 0 after collect_state() any sphere (what a
  /// snapshot writes).
  Vec3 reference_position(std::size_t k) const override { return held_or_collected(spheres_.centre_m, collected_.centre, k); }
  double radius(std::size_t k) const override { return held_or_collected(spheres_.radius_m, collected_.radius, k); }
  double mass(std::size_t k) const override { return spheres_.mass_kg[local_id(k)]; }
  std::uint32_t packing_index(std::size_t k) const override {
    return held_or_collected(spheres_.packing_index, collected_.packing_index, k);
  }
  /// The smallest and largest radius of all spheres (every rank's).
  double radius_min() const { return radius_min_; }
  double radius_max() const { return radius_max_; }
  /// Distributed, these read a held sphere; displacement() and velocity(), what a snapshot
  /// writes, also any sphere on rank 0 after collect_state().
  Vec3 displacement(std::size_t k) const override;
  Vec3 velocity(std::size_t k) const override { return held_or_collected(v_, collected_.v, k); }
  Vec3 acceleration(std::size_t k) const override { return a_[observed_local_id(k)]; }
  void add_external_force(std::size_t k, const Vec3& force) override;
  double impose_displacement(std::size_t k, const Vec3& e, double u_now, double u_next, double dt) override;
  void set_velocity(std::size_t k, const Vec3& v) override { v_[local_id(k)] = v; }
  /// Keeps the accelerations of the blocks (kSphereBlock spheres) that hold an observed sphere.
  /// May be called again between steps (benchmarks compare both): a block kept anew holds its
  /// accelerations from the next step on.
  void observe(const std::vector<std::size_t>& spheres) override;
  void step(double dt, bool evaluate_energy) override;
  EnergyAccount energy() const override;
  double peak_force_ratio() const override { return peak_ratio_; }
  bool has_non_finite_state() const override;
  Rows stiffness_rows() const override { return {6 * own_begin(), 6 * (own_end() - own_begin())}; }
  void scaled_stiffness_action(const double* x, double* y) const override;
  double stiffness_dot(const double* a, const double* b) const override;
  double scaled_stiffness_row_sum_bound() const override;
  std::size_t memory_bytes() const override;
  void save_state(StateGroup& group) const override;
  void load_state(const StateGroup& group) override;
  int threads() const override { return parallel_ ? threads_ : 1; }
  void distribute(Domain& domain, const std::vector<std::size_t>& observed) override;
  std::string distribution() const override;
  void collect_state() override;
  void collect_energy() override;
  /// What contact detection searches: the spheres within `reach_m` of one of this process's own
  /// (all of them in one process), sorted by global id, with their positions (positions()) and
  /// radii. Distributed (collective), a rank's own spheres and a geometric ghost layer: every
  /// other rank's sphere blocks whose centres' bounding box comes within `reach_m` of one of this
  /// rank's blocks' (docs/mpi.md), so that any pair closer than `reach_m` with an end of its own
  /// is found, on both ranks when the ends are on two, from the same positions.
  struct Nearby {
    std::vector<std::uint32_t> ids;
    std::vector<std::array<double, 3>> centres;
    std::vector<double> radii;
  };
  Nearby spheres_near_own(double reach_m);
  /// The sum of every rank's count, the largest of their values (itself in one process; collective).
  std::size_t sum_over_ranks(std::size_t count) const;
  double max_over_ranks(double value) const;

  /// The held spheres (own, ghosts, observed), in local numbering: every sphere in one process.
  /// Distributed, the constructor keeps its own spheres' statics; a ghost's come from its owner
  /// with the layout that brings it, an observed sphere's with distribute() (docs/mpi.md).
  const SphereSet& held_spheres() const { return spheres_; }
  /// Bond b's spheres (first < second), a held bond's (held_bond); its step-0 normal and u_0 are
  /// bond_geometry0().
  std::uint32_t bond_first(std::size_t b) const { return bonds_.first[held_bond(b)]; }
  std::uint32_t bond_second(std::size_t b) const { return bonds_.second[held_bond(b)]; }
  /// The spheres rank r of `ranks` owns, [starts[r], starts[r + 1]): whole blocks of kSphereBlock
  /// spheres in Morton order, rank r the blocks [B r / N, B (r + 1) / N) of B.
  static std::vector<std::size_t> rank_starts(std::size_t spheres, int ranks);
  /// Split over several ranks (a Domain of more than one).
  bool distributed() const { return domain_ != nullptr; }
  /// Sphere k (a global id) is this rank's own (every sphere is in one process).
  bool is_own(std::size_t k) const { return k >= own_begin() && k < own_end(); }
  /// The held bonds: those with an end of this rank's own (all in one process), by index, so
  /// sorted by (first, second) too; own_begin and own_end give the rank's spheres (their pairs
  /// only: no ids, no step-0 geometry, which bond_geometry0 makes anew).
  const BondNetwork& held_bond_network() const { return bonds_; }
  /// The index of held bond h (h in one process).
  std::size_t held_bond_id(std::size_t h) const {
    return h < held_cross_bonds_.size() ? held_cross_bonds_[h] : held_bond_begin_ + (h - held_cross_bonds_.size());
  }
  /// Bond b's place among the held bonds (b in one process); std::logic_error for a bond not held.
  std::size_t held_bond(std::size_t b) const;
  /// Bond b (< bond_count()) has an end of this rank's own (every bond in one process).
  bool holds_bond(std::size_t b) const;
  /// Bond b's unit normal and u_0 at step 0, from its spheres' statics (bond_geometry: the bits
  /// make_bond_network had; no copy is kept, 32 B a bond). Distributed, of a held bond only
  /// (std::logic_error for another), whose spheres this rank holds once its contacts are laid out.
  BondGeometry bond_geometry0(std::size_t b) const {
    const std::uint32_t i = bond_first(b), j = bond_second(b);
    return bond_geometry(reference_position(i), reference_position(j), radius(i), radius(j));
  }
  const CohesiveFrictionalMaterial& material() const { return material_; }
  const ContactKernel& kernel() const { return *kernel_; }
  /// Angular velocity w_{n+1/2} of sphere k (and its initial value, for tests).
  Vec3 angular_velocity(std::size_t k) const { return w_[local_id(k)]; }
  void set_angular_velocity(std::size_t k, const Vec3& w) { w_[local_id(k)] = w; }

  // What a contact kernel reads: the held spheres in local numbering (every sphere, in the
  // model's numbering, in one process), the contacts in slot order.
  const Vec3* positions() const { return x_.data(); }  ///< x (absolute, or the displacement: displacement_state)
  const Vec3* velocities() const { return v_.data(); }
  const Vec3* angular_velocities() const { return w_.data(); }
  const Vec3* rotations() const { return theta_.data(); }  ///< theta (track_rotation only)
  const double* radii() const { return spheres_.radius_m.data(); }
  const std::uint32_t* first() const { return first_.data(); }  ///< local ids
  const std::uint32_t* second() const { return second_.data(); }
  /// The spheres this process holds (all in one process; own, ghosts and observed distributed).
  std::size_t held_sphere_count() const { return x_.size(); }
  /// Held sphere l's global id (l in one process).
  std::uint32_t global_id(std::size_t l) const { return domain_ ? held_ids_[l] : std::uint32_t(l); }
  /// Sphere k's local id (k in one process); std::logic_error for a sphere not held here.
  std::uint32_t local_id(std::size_t k) const;
  /// The slots this process holds: every contact, or on several ranks (a system made for a
  /// domain) only the contacts with an end of this rank's own, in the order of the whole layout.
  std::size_t slot_count() const { return first_.size(); }
  /// The contacts of the whole layout (all ranks').
  std::size_t global_slot_count() const { return global_slots_; }
  /// Held slot s's place in the whole layout (s in one process).
  std::uint32_t global_slot(std::size_t s) const { return domain_ ? global_slot_[s] : std::uint32_t(s); }
  /// A law's checkpoint of a per-slot array (save_state): written in the whole layout's slot
  /// order, whichever ranks hold the slots. Distributed (collective), rank 0 writes the array a
  /// piece of StateGroup::kPieceRows slots at a time, each piece's values sent by their
  /// reporters (every slot once); the other ranks' `group` writes nowhere (StateGroup::nowhere).
  void write_slots(StateGroup& group, const std::string& name, const std::vector<double>& held) const;
  void write_slots(StateGroup& group, const std::string& name, const std::vector<std::uint32_t>& held) const;
  /// A restart (load_state, once set_contacts has laid out the checkpoint's contacts): the held
  /// slots' part of the whole layout's array `name` (InputError if its length is not the
  /// layout's), read a piece at a time; any rank count may restart a checkpoint. The held slots
  /// are in the whole layout's order, so a law that read its held slots' rows ascending has them
  /// in place.
  std::vector<double> read_slots(const StateGroup& group, const std::string& name) const;
  /// A restart's contact list (arrays `first` and `second`, `rows` rows, a checkpoint's whole
  /// layout), read a piece at a time, each contact checked against the packing (first < second <
  /// the sphere count); false, on every rank, if one does not fit. A value that is not an index
  /// ends it on every rank with StateGroup::not_an_index for the file's first such value, the
  /// line one process gives, whichever ranks read them. One process keeps every
  /// contact (`rows_held` stays empty: row c is slot c). Several ranks (collective) each read a
  /// share of the rows and send each contact to the ranks of its ends: each gets its held
  /// contacts (an end of its own) with their rows (`rows_held`, ascending).
  bool read_held_contacts(const StateGroup& group, std::size_t rows, std::vector<std::uint32_t>& rows_held,
                          std::vector<std::uint32_t>& first, std::vector<std::uint32_t>& second) const;
  std::uint32_t first(std::size_t slot) const { return first_[slot]; }  ///< local ids
  std::uint32_t second(std::size_t slot) const { return second_[slot]; }
  /// Largest |v| after the last step.
  double max_speed() const { return max_speed_; }

  /// Per contact between partitions, what its two spheres gather: the force f on the
  /// second sphere (the first gets -f) and the torques' parts t[0] = arm_0 c, t[1] = arm_1 c
  /// (the torque on the first sphere is -t[0], on the second -t[1]).
  struct ContactOut {
    Vec3 f;
    Vec3 t[2];
  };
  /// What a law computes for one contact: the force on the second sphere (the first gets -f),
  /// c = n x f and the lever arms - the torque on the first sphere is -arm[0] c, on the second
  /// -arm[1] c (Yade's applyForceAtContactPoint at the contact point) - and what the simulation
  /// adds up (summed in slot order, never inside a vector loop, so the sums do not depend on the
  /// vector width either).
  struct ContactResult {
    Vec3 f;
    Vec3 c;
    double arm[2];
    double elastic;  ///< spring energy (only when evaluate_energy)
    double plastic;  ///< dissipated by sliding this step
    double ratio2;   ///< (bond force / strength)^2, 0 for contacts without cohesion
  };
  /// For laws with rolling/twisting springs: also a moment m on the second
  /// sphere, -m on the first (Yade's addTorque(id2, m), addTorque(id1, -m)).
  struct MomentContactResult : ContactResult {
    Vec3 m;
  };

  /// Sets the contacts (pairs first < second) and lays them out in slots:
  /// the spheres are cut into a fixed number of Morton ranges (partitions,
  /// set by the sphere count alone); contacts inside one partition come
  /// first, grouped by partition, then the contacts between partitions; in each group the
  /// bonds (the first `bonds` given) before the detected pairs, each in the order given.
  /// Returns the order: slot s holds the contact given at position order[s].
  /// A law keeps its per-contact arrays in slot order.
  /// Distributed (collective), a rank gives only its contacts, those with an end of its own, and
  /// holds only their slots, in the whole layout's order (so every sphere of the rank sums the
  /// serial terms in the serial order); `order` has one entry a slot held. Each part must then
  /// come in the order the whole layout has it within a group (bonds by index, pairs by (first,
  /// second), as detection lists them; or a checkpoint's slot order): the whole layout is worked
  /// out from each rank's counts, and the slot of a contact across two ranks is sent by the rank
  /// of its first sphere.
  std::vector<std::uint32_t> set_contacts(const std::vector<std::uint32_t>& first, const std::vector<std::uint32_t>& second,
                                          std::size_t bonds, bool moments = false);
  /// The bonds as the contacts (a network without detection): set_contacts of the held bonds;
  /// returns the bond in each slot.
  std::vector<std::uint32_t> set_bond_contacts();

  /// Runs kernel(slot, result) for every contact; call it from contact_forces
  /// (inside the step's parallel region). The kernel runs on chunks of
  /// kChunk contacts as one vector loop (`GCC ivdep`: it must not depend on
  /// other contacts of the chunk); the results are then applied one by one in
  /// slot order: contacts inside a partition add their force to its spheres
  /// directly (one thread owns a partition, so no races and no atomics),
  /// contacts between partitions leave a record that each sphere gathers in
  /// slot order. Either way every sphere sums the same terms in the same
  /// order on any number of threads.
  /// `Result` is ContactResult, or MomentContactResult for a law with moments
  /// (set_contacts with `moments` then keeps room for them).
  /// `sum_elastic`: add up the elastic energies (energy steps); `sum_plastic`: the dissipation
  /// (laws that slide). `stage(chunk, m, ahead)` runs before each chunk's vector loop, on contacts
  /// [chunk, chunk + m): a law fetches its spheres' data there (ContactEnds, contact_ends.hpp),
  /// and asks for the lines of the contacts `ahead` (ContactEnds::prefetch; empty for systems
  /// that fit in the caches: prefetch_ahead()).
  struct NoStage {
    void operator()(std::size_t, std::size_t, ContactRange) const {}
  };
  template <class Result = ContactResult, class Kernel, class Stage = NoStage>
  void for_each_contact(Kernel&& kernel, bool sum_elastic, bool sum_plastic, Stage&& stage = {}) __attribute__((always_inline));

  /// The integrator's blocking (kernels size their chunks by it).
  static constexpr std::size_t kContactBlock = 2048;
  static constexpr std::size_t kChunk = 32;
  static_assert(kChunk == kEndsChunk, "a law stages its contact ends a chunk at a time (contact_ends.hpp)");
  static constexpr std::size_t kSphereBlock = 256;
  /// The partitions (Morton ranges; set_contacts): about kSpheresPerPartition spheres each, but at
  /// least kMinPartitions where ranges of kSpheresPerPartitionMin spheres allow that many, and at
  /// most kMaxPartitions. Set by the sphere count alone: the same bits on any number of threads
  /// or ranks. Fewer, larger ranges put fewer contacts across them (each leaves a record that
  /// integrate gathers); four still give two threads' dynamic schedule tasks to balance. 16,384
  /// instead of 4,096 spheres a range: the 50 and 75 mm cubes' step 4-7 % shorter, both laws,
  /// 1 and 2 threads (docs/benchmarks.md, "The step near the memory limit", ninth part).
  static constexpr std::size_t kSpheresPerPartition = 16384;
  static constexpr std::size_t kSpheresPerPartitionMin = 4096;
  static constexpr std::size_t kMinPartitions = 4, kMaxPartitions = 64;
  static std::size_t partition_count(std::size_t spheres, std::size_t spheres_per_partition = kSpheresPerPartition) {
    const std::size_t lowest = std::clamp<std::size_t>(spheres / kSpheresPerPartitionMin, 1, kMinPartitions);
    return std::clamp(spheres / std::max<std::size_t>(spheres_per_partition, 1), lowest, kMaxPartitions);
  }
  /// How many contacts ahead a chunk asks for its second spheres' lines (ContactEnds::prefetch,
  /// and the sums for_each_contact adds to), from kPrefetchFromSpheres held spheres on: below,
  /// the lines are mostly in the caches and the requests cost their instructions (up to 17 % of
  /// the step on one thread; on two, gains and losses by the host's state). Measured in
  /// docs/benchmarks.md, "The step near the memory limit", eighth part; the bits do not depend on it.
  static constexpr std::size_t kPrefetchAhead = 128;
  static constexpr std::size_t kPrefetchFromSpheres = 32768;
  /// The distance this system's chunks ask ahead: 0 or kPrefetchAhead by the held spheres, unless set.
  std::size_t prefetch_ahead() const {
    return prefetch_set_.value_or(x_.size() >= kPrefetchFromSpheres ? kPrefetchAhead : 0);
  }
  /// Sets that distance whatever the size (0: none): for tests and benchmarks that compare the
  /// two (the same bits).
  void set_prefetch_ahead(std::size_t contacts) { prefetch_set_ = contacts; }

  /// One chunk's results, one array per component (structure of arrays), so that the kernel's
  /// vector loop stores each component of kChunk contacts with contiguous vector stores. The
  /// torques' parts arm c are formed there too (ti = arm_0 c, tj = arm_1 c: the same products the
  /// spheres' sums then subtract), so that the scalar pass that adds them up only adds.
  template <bool Moments>
  struct alignas(64) ChunkResults {
    double f[3][kChunk], ti[3][kChunk], tj[3][kChunk], elastic[kChunk], plastic[kChunk], ratio2[kChunk];
    double m[Moments ? 3 : 1][Moments ? kChunk : 1];
    template <class Result>
    __attribute__((always_inline)) void store(std::size_t q, const Result& r) {
      f[0][q] = r.f.x, f[1][q] = r.f.y, f[2][q] = r.f.z;
      ti[0][q] = r.arm[0] * r.c.x, ti[1][q] = r.arm[0] * r.c.y, ti[2][q] = r.arm[0] * r.c.z;
      tj[0][q] = r.arm[1] * r.c.x, tj[1][q] = r.arm[1] * r.c.y, tj[2][q] = r.arm[1] * r.c.z;
      elastic[q] = r.elastic, plastic[q] = r.plastic, ratio2[q] = r.ratio2;
      if constexpr (Moments) m[0][q] = r.m.x, m[1][q] = r.m.y, m[2][q] = r.m.z;
    }
    Vec3 force(std::size_t q) const { return {f[0][q], f[1][q], f[2][q]}; }
    Vec3 torque_first(std::size_t q) const { return {ti[0][q], ti[1][q], ti[2][q]}; }
    Vec3 torque_second(std::size_t q) const { return {tj[0][q], tj[1][q], tj[2][q]}; }
    Vec3 moment(std::size_t q) const { return {m[0][q], m[1][q], m[2][q]}; }
  };

private:
  SphereSet spheres_;  ///< the held spheres' statics, local numbering (held_spheres()); no ids
  std::size_t sphere_total_ = 0;
  double radius_min_ = 0, radius_max_ = 0;
  BondNetwork bonds_;  ///< the held bonds (all in one process), without ids
  std::size_t bond_count_ = 0;  ///< in the whole network
  CohesiveFrictionalMaterial material_;
  std::unique_ptr<ContactKernel> kernel_;
  bool displacement_state_, track_rotation_;
  int threads_ = 1;
  bool parallel_ = false;
  std::optional<std::size_t> prefetch_set_;

  // The held bonds (an end of this rank's own; all in one process), in bond order: those whose
  // first sphere lies below the rank's spheres (held_cross_bonds_, their indices), then the bonds
  // [held_bond_begin_, held_bond_end_), whose first sphere is its own (bonds are sorted by first sphere).
  std::vector<std::uint32_t> held_cross_bonds_;
  std::size_t held_bond_begin_ = 0, held_bond_end_ = 0;
  void keep_held_bonds();

  // Per held sphere, in local numbering (hold()).
  std::vector<Vec3> x_, v_, w_, a_, theta_, f_ext_;
  std::vector<double> inv_mass_, inv_inertia_;
  std::vector<double> inv_mass3_, inv_inertia3_;  ///< the same, once per Cartesian component
  std::vector<std::uint32_t> first_, second_;  ///< contacts in slot order (the slots held), local ids
  double peak_ratio_ = 0;
  double max_speed_ = 0;  ///< largest |v| after the last step
  EnergyAccount energy_;

  void integrate(double dt, bool evaluate_energy);
  /// Moves the spheres of one block; writes its damping terms (Eq. 7's work, per component:
  /// translations, then rotations, each padded to 3 kSphereBlock with +0) to `damping_terms`.
  void update_motion(std::size_t begin, std::size_t end, std::size_t block, double dt, bool evaluate_energy,
                     double* damping_terms);
  static constexpr std::size_t kDampingGroup = 4;
  static constexpr std::size_t kDampingTerms = 6 * kSphereBlock;

  std::size_t partitions_ = 1, sphere_chunk_ = 1, cross_begin_ = 0, cross_blocks_ = 0;
  std::vector<std::uint32_t> interior_start_;  ///< partitions + 1
  // The whole layout's (all ranks'; the same as the held one in one process): the energies are
  // summed per task of the whole layout, in its slot order, so that the bits do not depend on the
  // split. The held slots' places in it (global_slot_) are kept on several ranks only.
  std::size_t global_slots_ = 0, global_cross_begin_ = 0, global_cross_blocks_ = 0;
  std::vector<std::uint32_t> global_interior_start_, global_slot_;
  std::size_t global_task_of(std::size_t global_slot) const;
  /// Distributed write_slots: value(s) of each reported slot s.
  void write_reported_slots(StateGroup& group, const std::string& name, bool indices,
                            const std::function<double(std::uint32_t held_slot)>& value) const;
  /// A checkpoint's sphere array (global ids). Distributed (collective), rank 0 writes it a piece
  /// at a time, each piece from the own spheres of the ranks whose range meets it.
  void write_spheres(StateGroup& group, const std::string& name, const std::vector<Vec3>& held) const;
  /// Distributed: rank 0 gets the whole array (global ids) gathered from each rank's own
  /// spheres, the other ranks an empty one (collective; the snapshots' collect_state).
  template <class T>  // Vec3 or double
  std::vector<T> gathered_spheres(const std::vector<T>& held) const;
  Incidence cross_incidence_;                  ///< entries index out_ (slot - cross_begin_)
  std::vector<ContactOut> out_;
  std::vector<Vec3> out_moment_;  ///< moment of each contact between partitions (laws with moments only)
  std::vector<Vec3> f_acc_, t_acc_;
  std::vector<double> task_elastic_, task_plastic_, task_peak2_;
  std::vector<double> sphere_block_kinetic_, sphere_block_damping_, sphere_block_vmax2_;
  std::vector<Vec3> a_undamped_;           ///< F/m before damping (a constrained DOF is not damped)
  /// Per block of kSphereBlock spheres (global ids): whether a_ and a_undamped_ are kept (observe()).
  std::vector<std::uint8_t> block_keeps_acceleration_;
  /// Sphere k's local id, a std::logic_error if its acceleration is not kept (observe()).
  std::size_t observed_local_id(std::size_t k) const;
  std::vector<std::uint32_t> forced_;  ///< spheres with an external force this step
  std::vector<Vec3> forced_v_before_;
  std::vector<std::uint8_t> is_forced_;
  static constexpr std::size_t kNotHeld = ~std::size_t(0);
  /// Sphere k's local id, or kNotHeld.
  std::size_t find_local(std::size_t k) const;
  /// Rank 0 after collect_state() (until the next step): every sphere's x and v, and its
  /// statics, in global ids.
  struct Collected {
    std::vector<Vec3> x, v, centre;
    std::vector<double> radius;
    std::vector<std::uint32_t> packing_index;
  } collected_;
  template <class T>
  const T& held_or_collected(const std::vector<T>& held, const std::vector<T>& whole, std::size_t k) const {
    if (const std::size_t l = find_local(k); l != kNotHeld) return held[l];
    if (whole.empty()) throw std::logic_error("SphereSystem: sphere " + std::to_string(k) + " is not held on this rank");
    return whole[k];
  }
  /// Distributed: the statics of the ghosts `ghost_receives_` lists, from their owners (a layout's
  /// new ghosts take theirs from it), the ghosts in the lists' order (sorted by id).
  SphereSet ghost_statics();
  /// 7 doubles a sphere (centre, radius, mass, inertia, packing index), and back.
  static constexpr std::size_t kStatics = 7;
  void append_statics(std::size_t local, std::vector<double>& out) const;
  static SphereSet statics_from(const double* values, std::size_t count);
  /// Lays the per-sphere arrays out for the spheres `ids` (sorted global ids; distributed: own,
  /// ghosts, observed), keeping the state of those held before; a sphere new here starts from
  /// step 0's state (a new ghost's motion comes from its owner before the next step). The
  /// contacts' ends (global ids in first_/second_ on entry) are then numbered locally.
  /// A sphere new here takes its statics from `arrived` (its spheres `arrived_ids`, sorted: the
  /// constructor's own spheres, ghost_statics(), the observed spheres' from distribute()).
  void hold(std::vector<std::uint32_t> ids, const SphereSet& arrived = {}, const std::vector<std::uint32_t>& arrived_ids = {});
  /// first_/second_ from global to local ids, and the cross records' incidence over them.
  void number_contacts_locally();

  // A distributed run (dem/parallel/sphere_system_domain.cpp, docs/mpi.md): this rank's
  // spheres and blocks (per rank: sphere_counts_/displs_ in doubles, 3 a sphere; block_owner_
  // per block), the contacts it holds and computes (those with an end of its own: set_contacts)
  // and those whose energies, strength ratio and breakage it reports (the rank owning the first
  // sphere), the per-slot values, the ghost lists (per neighbour rank, sorted by id: the
  // spheres it sends there and those it receives from there) and the observed spheres (those
  // an actuator or sensor reads: every rank holds them; sorted by id, so by owner).
  Domain* domain_ = nullptr;
  int rank_ = 0;  ///< domain_->rank()
  std::size_t own_begin_ = 0, own_end_ = 0, own_block_begin_ = 0, own_block_end_ = 0, ghosts_ = 0;
  std::size_t own_local_ = 0;  ///< the local id of own_begin_ (own spheres are contiguous locally)
  std::vector<std::uint32_t> held_ids_;  ///< distributed: the held spheres' global ids, sorted
  std::size_t broken_ = 0;  ///< bonds broken on all ranks after the last step (shared with the motion)
  double vmax2_all_ = 0;    ///< the largest block bound of |v|^2 over all ranks after the last step
  std::vector<int> sphere_counts_, sphere_displs_, block_counts_, block_displs_, block_owner_;
  std::vector<std::uint32_t> reported_;
  std::vector<double> slot_elastic_, slot_plastic_, send_, recv_;
  struct GhostList {
    int rank;
    std::vector<std::uint32_t> spheres;  ///< global ids (or, for the elastic sums, slots and places)
    std::vector<double> buffer;
    std::vector<std::uint32_t> local = {};  ///< the spheres' local ids
  };
  std::vector<GhostList> ghost_sends_, ghost_receives_;
  std::vector<std::uint32_t> observed_, observed_local_;
  std::vector<int> observed_counts_, observed_displs_;
  // The elastic sums: per task of the whole layout the rank that adds it (task_owner_; per rank
  // its count), and on that rank its tasks' values in slot order (owned_values_, from
  // owned_start_ per owned task), filled from its own slots (own_elastic_: held slot, place) and
  // from the other reporters (elastic_receives_: places; elastic_sends_: held slots).
  std::vector<GhostList> elastic_sends_, elastic_receives_;
  std::vector<int> task_owner_, task_counts_;
  std::vector<std::uint32_t> owned_tasks_, owned_start_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> own_elastic_;
  std::vector<double> owned_values_;
  bool ghosts_stale_ = false;  ///< a new layout brought new ghosts: exchange before the next step
  double ghost_layer_m_ = 0;   ///< a test's too-thin ghost layer (MESOWAVE_TEST_GHOST_LAYER_MM); infinite otherwise
  int ghost_layer_rank_ = -1;   ///< the rank it thins (-1: all)
  // What the steps moved into this rank (docs/mpi.md's model): doubles received point to point
  // and by the collectives, and the exchanges counted.
  std::uint64_t ghost_doubles_ = 0, shared_doubles_ = 0, shared_steps_ = 0, ghost_messages_ = 0;
  std::size_t layer_spheres_ = 0;  ///< the last detection pass's geometric ghost layer (spheres_near_own)
  int owner(std::uint32_t sphere) const { return block_owner_[sphere / kSphereBlock]; }
  /// This rank's spheres [own_begin(), own_end()): all of them in one process.
  std::size_t own_begin() const { return domain_ ? own_begin_ : 0; }
  std::size_t own_end() const { return domain_ ? own_end_ : sphere_total_; }
  /// Own sphere k's local id.
  std::size_t own_local(std::size_t k) const { return k - own_begin() + own_local_; }
  /// The critical step's vectors at the ghosts (scaled_stiffness_action): x's rows of the spheres
  /// each neighbour holds as ghosts go there; returns the ghosts' rows (six a sphere) in the order
  /// of `ghost_ids`, the ghosts of every neighbour in rank order (so sorted by id).
  std::vector<double> ghost_rows(const double* x, std::vector<std::uint32_t>& ghost_ids) const;
  void split(Domain& domain);
  /// The slots of the whole layout by reporter (the rank of the first sphere): runs of
  /// consecutive slots, each (first slot, rank), ascending; the last ends at global_slots_.
  /// At most 2 (partitions + 1) runs a rank.
  std::vector<std::pair<std::uint32_t, int>> slot_runs_;
  /// Calls f(rank, begin, end) for each run's part in the whole layout's slots [begin, end).
  template <class F>
  void for_each_reporter(std::size_t begin, std::size_t end, const F& f) const;
  /// set_contacts' layout: in one process from the whole list; distributed (collective), the
  /// whole layout (global_* and slot_runs_) from the ranks' counts and the held slots' places in
  /// it (global_slot_, interior_start_). Each returns the order.
  std::vector<std::uint32_t> lay_out_whole(const std::vector<std::uint32_t>& first, const std::vector<std::uint32_t>& second);
  std::vector<std::uint32_t> lay_out_held(const std::vector<std::uint32_t>& first, const std::vector<std::uint32_t>& second,
                                          std::size_t bonds);
  /// set_contacts' end: the held contacts (global ids, `order` into the lists given) in slot
  /// order, then distributed the ghosts, the held spheres and the local ids.
  std::vector<std::uint32_t> finish_layout(const std::vector<std::uint32_t>& first, const std::vector<std::uint32_t>& second,
                                           std::vector<std::uint32_t> order, bool moments);
  void lay_out_domain();
  void exchange_ghosts();
  void share_step(bool evaluate_energy);
  void share_elastic();
};

template <class Result, class Kernel, class Stage>
inline void SphereSystem::for_each_contact(Kernel&& kernel, bool sum_elastic, bool sum_plastic, Stage&& stage) {
  constexpr bool moments = std::is_same_v<Result, MomentContactResult>;
  const std::size_t tasks = partitions_ + cross_blocks_;
  const std::size_t count = first_.size();
  const bool distributed = domain_ != nullptr;
  const std::uint32_t own_lo = std::uint32_t(own_local_), own_count = std::uint32_t(own_end_ - own_begin_);
  const std::uint32_t* first = first_.data();
  const std::uint32_t* second = second_.data();
#pragma omp for schedule(dynamic, 1)
  for (std::size_t task = 0; task < tasks; ++task) {
    const bool interior = task < partitions_;
    const std::size_t begin =
        interior ? interior_start_[task] : cross_begin_ + (task - partitions_) * kContactBlock;
    const std::size_t end = interior ? interior_start_[task + 1] : std::min(count, begin + kContactBlock);
    double elastic = 0, plastic = 0, peak2 = 0;
    Vec3* f = f_acc_.data();
    Vec3* t = t_acc_.data();
    // Inside a partition the contacts come in runs of one first sphere (the pairs are sorted by
    // it, bonds and detected contacts each): that sphere's force and torque are summed in
    // registers over the run and stored when the run ends, so a contact reads and writes only
    // its second sphere's sums in memory. Each sphere still gets the same terms in the same order
    // (slot order): within a run the first sphere is no contact's second (first < second), so no
    // other term reaches it in between. (Unsorted contacts would only make the runs shorter.)
    std::uint32_t run = begin < end ? first[begin] : 0;
    Vec3 run_f = interior && begin < end ? f[run] : Vec3{}, run_t = interior && begin < end ? t[run] : Vec3{};
    ChunkResults<moments> results;
    const std::size_t prefetch_ahead = this->prefetch_ahead();
    for (std::size_t chunk = begin; chunk < end; chunk += kChunk) {
      const std::size_t m = std::min(kChunk, end - chunk);
      // The lines of a later chunk's second spheres (the first come in order), so that their
      // misses overlap with this chunk's work: the law's data (stage) and the sums a partition's
      // contacts add to.
      ContactRange ahead;
      if (prefetch_ahead != 0) {
        ahead.begin = std::min(end, chunk + prefetch_ahead);
        ahead.end = std::min(end, ahead.begin + m);
        if (interior)
          for (std::size_t b = ahead.begin; b < ahead.end; ++b) {
            prefetch_line(&f[second[b]]);
            prefetch_line(&t[second[b]]);
          }
      }
      // The law runs on a private Result per contact, stored component by component into the chunk's
      // arrays: only stores to separate arrays indexed by q let GCC vectorize this loop (a store of the
      // whole struct into an array of structs kept it scalar: issue 17 item 3, docs/benchmarks.md).
      stage(chunk, m, ahead);
#pragma GCC ivdep
      for (std::size_t q = 0; q < m; ++q) {
        Result r;
        kernel(chunk + q, r);
        results.store(q, r);
      }
      if (distributed)  // summed in slot order by share_step, over every rank's values
        for (std::size_t q = 0; q < m; ++q) {
          slot_elastic_[chunk + q] = results.elastic[q];
          slot_plastic_[chunk + q] = results.plastic[q];
          // The strength ratio of the contacts this rank reports: a maximum, exact in any order.
          if (first[chunk + q] - own_lo < own_count) peak2 = std::max(peak2, results.ratio2[q]);
        }
      // The task's sums, in slot order, in the same loop as the forces, so that their chains of
      // dependent additions overlap with the scatter's work. The sums a step does not read are left
      // out (elastic: energy steps only; plastic: laws that slide), which changes nothing read.
      // (Skipping the plastic sum's zero terms, exact too, measured slower: docs/benchmarks.md.)
      const auto add_sums = [&](std::size_t q) __attribute__((always_inline)) {
        if (distributed) return;
        if (sum_elastic) elastic += results.elastic[q];
        if (sum_plastic) plastic += results.plastic[q];
        peak2 = std::max(peak2, results.ratio2[q]);
      };
      if (interior) {
        for (std::size_t q = 0; q < m; ++q) {
          add_sums(q);
          const std::size_t b = chunk + q;
          const std::uint32_t i = first[b], j = second[b];
          if (i != run) {
            f[run] = run_f, t[run] = run_t;
            run = i, run_f = f[i], run_t = t[i];
          }
          const Vec3 rf = results.force(q);
          run_f -= rf;
          f[j] += rf;
          run_t -= results.torque_first(q);
          t[j] -= results.torque_second(q);
          if constexpr (moments) {
            const Vec3 rm = results.moment(q);
            run_t -= rm;
            t[j] += rm;
          }
        }
      } else {
        for (std::size_t q = 0; q < m; ++q) {
          add_sums(q);
          ContactOut& o = out_[chunk + q - cross_begin_];
          o.f = results.force(q);
          o.t[0] = results.torque_first(q);
          o.t[1] = results.torque_second(q);
          if constexpr (moments) out_moment_[chunk + q - cross_begin_] = results.moment(q);
        }
      }
    }
    if (interior && begin < end) f[run] = run_f, t[run] = run_t;
    task_peak2_[task] = peak2;  // distributed: over the held task's reported slots (share_step)
    if (distributed) continue;  // the held tasks are not the whole layout's: share_step sums
    task_elastic_[task] = elastic;
    task_plastic_[task] += plastic;
  }
}

}  // namespace mesowave::dem
