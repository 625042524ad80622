#pragma once
// A rank's part of the sphere set: what the setup reads before the model exists (docs/mpi.md,
// stage 3 steps 10 and 11). The part holds the rank's own spheres - whole indices begin() ..
// begin() + own_count() - 1, its range of the Morton order (SphereSystem::rank_starts) - and a
// layer: every other sphere whose centre lies within a reach of the box of one of its own blocks
// (runs of SphereSystem::kSphereBlock spheres in Morton order, compact pieces of space), enough
// for every bond and step-0 overlap with an end of its own (the reach is C_f (2 r_max) or
// 2 r_max, the larger). Spheres fetched later, the actuators' and sensors', join the layer. A
// rank makes its part from the rows of the packing file it read: no rank reads the packing or
// makes the set whole (a small model's part may still reach every sphere). In one process the
// part is the whole set (an implicit conversion) and no call communicates.
//
// What reads every sphere - the bounding box, a radius statistic, a selection - reads the own
// spheres and combines the ranks' results through the domain so that every rank gets one
// process's bits: a minimum or maximum (exact in any order), an arg-min with one process's tie
// rule, a sum chained rank after rank, a gather in whole-index order. Those calls are collective:
// every rank makes them, in the same order.
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "mesowave/dem/engine/sphere_set.hpp"
#include "mesowave/dem/packing/packing.hpp"
#include "mesowave/dem/engine/sphere_statics.hpp"

namespace mesowave::dem {

class Domain;

class SpherePart final : public SphereStatics {
public:
  /// One process's part: the whole set.
  SpherePart(SphereSet whole);  // NOLINT(google-explicit-constructor): a whole set is one process's part
  /// Rank domain.rank()'s part (domain.size() > 1) of a packing file, from the rows it read
  /// (`rows`, read_packing_file's part of several), with density `density_kg_m3`. The spheres
  /// are sorted across the ranks along the Morton curve of every centre (MortonFrame over the box
  /// of all, ties by packing index: make_sphere_set's numbering), each rank takes its range
  /// (SphereSystem::rank_starts), and the layer comes from the owners: every other sphere whose
  /// centre lies within reach_radii x r_max (the largest radius) of the box of an own block.
  /// InputError as make_sphere_set for the rows this rank read.
  SpherePart(const Packing& rows, double density_kg_m3, Domain& domain, double reach_radii);

  Domain* domain() const { return domain_; }
  std::size_t total() const { return total_; }
  std::size_t begin() const { return begin_; }
  std::size_t own_count() const { return own_; }
  bool owns(std::size_t k) const { return k >= begin_ && k < begin_ + own_; }
  /// The rank that owns sphere k (a whole index): 0 in one process.
  int owner(std::size_t k) const;
  /// The spheres held here: the own ones first (local index k: whole index begin() + k), then the
  /// layer in ascending whole index.
  const SphereSet& spheres() const { return set_; }
  std::size_t whole_index(std::size_t local) const {
    return local < own_ ? begin_ + local : layer_index_[local - own_];
  }
  /// The local index of sphere k (a whole index) held here; std::logic_error if it is not.
  std::size_t local(std::size_t k) const;
  bool holds(std::size_t k) const;

  // SphereStatics, by whole index, of a sphere held here (std::logic_error for another).
  std::size_t sphere_count() const override { return total_; }
  Vec3 reference_position(std::size_t k) const override { return set_.centre_m[local(k)]; }
  double radius(std::size_t k) const override { return set_.radius_m[local(k)]; }
  double mass(std::size_t k) const override { return set_.mass_kg[local(k)]; }
  std::uint32_t packing_index(std::size_t k) const override { return set_.packing_index[local(k)]; }

  // Collective on several ranks; one process reads its set.
  /// The smallest and the largest radius of all spheres.
  double radius_min() const;
  double radius_max() const;
  /// Sum r_k / N in whole-index order (the ranks add one after the other: one process's bits).
  double radius_mean() const;
  /// The whole index of the sphere whose key(local) is least (pairs compare lexicographically);
  /// ties: the lowest whole index, as one process's first-found scan has it.
  std::size_t arg_min(const std::function<std::pair<double, double>(std::size_t local)>& key) const;
  /// The whole indices of the own spheres of every rank for which keep(local) holds: ascending,
  /// or in ascending packing index.
  std::vector<std::size_t> select(const std::function<bool(std::size_t local)>& keep, bool by_packing_index = false) const;
  /// value(local) of every sphere, in whole-index order, on every rank (a gather of one double a
  /// sphere: small sets only, a line of spheres).
  std::vector<double> gathered(const std::function<double(std::size_t local)>& value) const;
  /// The step-0 centre of sphere k (a whole index) on every rank, from its owner.
  Vec3 centre_of(std::size_t k) const;
  /// Every rank takes the statics of the spheres `ids` (whole indices) from their owners into
  /// its layer, so that the queries above answer for them.
  void fetch(std::vector<std::size_t> ids);

  /// The own spheres, for the model (the part is spent).
  SphereSet take_own() &&;

private:
  SphereSet set_;
  std::size_t begin_ = 0, own_ = 0, total_ = 0;
  std::vector<std::size_t> starts_;  ///< SphereSystem::rank_starts: rank r owns [starts_[r], starts_[r + 1])
  double density_ = 0;               ///< of the spheres a rank's part receives (set_sphere)
  std::vector<std::uint32_t> layer_index_;  ///< whole index of set_'s sphere own_ + i, ascending
  Domain* domain_ = nullptr;
};

}  // namespace mesowave::dem
