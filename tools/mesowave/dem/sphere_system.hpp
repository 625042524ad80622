#pragma once
// Spheres with six degrees of freedom, the state both 3-D models share, and
// the leapfrog integrator in the order of Yade's NewtonIntegrator:
//   a = F/m;  a_k <- a_k (1 - alpha_d sgn(a_k (v_k + a_k dt/2)))   (Eq. 7, per component)
//   v += dt a;  x += dt v;   the same for the angular velocity with the torque.
//
// A contact law (one class, one file) only fills one record per contact: the
// force on its second sphere and the torque factors. The integrator gathers
// each sphere's records in ascending contact order, so a step gives the same
// bits on any number of threads (no atomics, no per-thread buffers), and the
// gather is fused with the update of the sphere's motion (one pass over the
// spheres per step). Sums over spheres or contacts (energies) are taken per
// fixed-size block and added in block order, for the same reason.
#include <cstdint>
#include <vector>

#include "mesowave/dem/bond_network.hpp"
#include "mesowave/dem/material.hpp"
#include "mesowave/dem/model.hpp"
#include "mesowave/dem/sphere_set.hpp"

namespace mesowave::dem {

class SphereSystem : public Model {
public:
  /// `displacement_state`: the integrated position is the displacement from
  /// step 0 (linearised network, best precision for tiny amplitudes) instead
  /// of the absolute position (full law). `track_rotation`: integrate the
  /// rotation vector theta (small rotations; the linearised network needs it).
  SphereSystem(SphereSet spheres, BondNetwork bonds, const CohesiveFrictionalMaterial& material,
               bool displacement_state, bool track_rotation);

  std::size_t sphere_count() const override { return spheres_.size(); }
  std::size_t bond_count() const override { return bonds_.size(); }
  std::size_t degrees_of_freedom() const override { return 6 * spheres_.size(); }
  Vec3 reference_position(std::size_t k) const override { return spheres_.centre_m[k]; }
  double radius(std::size_t k) const override { return spheres_.radius_m[k]; }
  double mass(std::size_t k) const override { return spheres_.mass_kg[k]; }
  std::uint32_t packing_index(std::size_t k) const override { return spheres_.packing_index[k]; }
  Vec3 displacement(std::size_t k) const override;
  Vec3 velocity(std::size_t k) const override { return v_[k]; }
  Vec3 acceleration(std::size_t k) const override { return a_[k]; }
  void add_external_force(std::size_t k, const Vec3& force) override;
  void impose_displacement(std::size_t k, const Vec3& e, double u_now, double u_next, double dt) override;
  void set_velocity(std::size_t k, const Vec3& v) override { v_[k] = v; }
  void step(double dt, bool evaluate_energy) override;
  EnergyAccount energy() const override;
  double peak_force_ratio() const override { return peak_ratio_; }
  bool has_non_finite_state() const override;
  void scaled_stiffness_action(const double* x, double* y) const override;
  double scaled_stiffness_row_sum_bound() const override;
  std::size_t memory_bytes() const override;
  int threads() const override { return threads_; }

  const SphereSet& spheres() const { return spheres_; }
  const BondNetwork& bonds() const { return bonds_; }

protected:
  /// Per contact: force on the second sphere (the first gets -f), c = n x f,
  /// and the lever arms: the torque on the first sphere is -arm[0] c, on the
  /// second -arm[1] c (Yade's applyForceAtContactPoint at the contact point).
  struct alignas(64) ContactOut {
    Vec3 f;
    Vec3 c;
    double arm[2];
  };

  /// Fills out_[0 .. contact count) for positions x_n. Runs inside the
  /// step's parallel region: a law uses an orphaned `omp for` over blocks of
  /// kContactBlock contacts and writes its block sums to block_elastic_,
  /// block_plastic_ (added to) and block_peak_.
  virtual void contact_forces(double dt, bool evaluate_energy) = 0;
  /// Serial work after a step (contact detection, bookkeeping).
  virtual void after_step(double /*dt*/) {}
  /// Reshapes the per-contact arrays after the contact list changed.
  void set_contact_count(std::size_t count, Incidence incidence);

  static constexpr std::size_t kContactBlock = 1024;
  static constexpr std::size_t kSphereBlock = 256;

  SphereSet spheres_;
  BondNetwork bonds_;
  CohesiveFrictionalMaterial material_;
  bool displacement_state_, track_rotation_;
  int threads_ = 1;
  bool parallel_ = false;

  std::vector<Vec3> x_, v_, w_, a_, theta_, f_ext_;
  std::vector<double> inv_mass_, inv_inertia_;
  Incidence contact_incidence_;  ///< incidence of the evaluated contacts (bonds first)
  std::vector<ContactOut> out_;
  std::vector<double> block_elastic_, block_plastic_, block_peak_;
  std::vector<double> sphere_block_kinetic_, sphere_block_damping_, sphere_block_vmax2_;
  double peak_ratio_ = 0;
  double max_speed_ = 0;  ///< largest |v| after the last step
  EnergyAccount energy_;

private:
  void integrate(double dt, bool evaluate_energy);
  std::vector<std::uint32_t> forced_;  ///< spheres with an external force this step
  std::vector<Vec3> forced_v_before_;
  std::vector<std::uint8_t> is_forced_;
};

}  // namespace mesowave::dem
