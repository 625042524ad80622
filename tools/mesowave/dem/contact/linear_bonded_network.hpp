#pragma once
// The linearised bonded network: the full law (cohesive_frictional_contact.hpp)
// linearised about step 0, for waves whose forces stay far below the bond
// strengths. Fixed bond list and stiffness, no contact detection, no strength
// or friction checks; with d the displacements and theta the (small) rotations:
//
//   F_n = -K_n n0.(d_j - d_i)                                      (Eq. 1, u - u_0 to first order)
//   F_s = -K_s [a0 P_t (d_j - d_i) - (r_i theta_i + r_j theta_j) x n0]   (Eq. 2 summed over the steps,
//         with Yade's incident-velocity factor a0 = (r_i + r_j)/|x_j - x_i|_0)
//   force F_n n0 + F_s on j, its opposite on i, lever arms r - u_0/2.
//
// Valid while the amplitude is small: the run records the peak bond force /
// strength, and the simulation refuses the result above a stated bound.
#include "mesowave/dem/engine/sphere_system.hpp"

namespace mesowave::dem {

/// The kernel (sphere_system.hpp composes it).
class LinearBondedNetwork : public ContactKernel {
public:
  std::string name() const override { return "linear"; }
  bool displacement_state() const override { return true; }
  bool track_rotation() const override { return true; }
  void attach(SphereSystem& system) override;
  void contact_forces(SphereSystem& system, double dt, bool evaluate_energy) override;
  std::size_t memory_bytes() const override { return nx_.size() * 4 * sizeof(double); }
  /// Nothing of its own changes from step to step (n0, u_0 and the layout are
  /// fixed at attach); the system saves the motion.
  void save_state(const SphereSystem&, StateGroup&) const override {}
  void load_state(SphereSystem&, const StateGroup&) override {}

private:
  void kernel(SphereSystem& system, bool evaluate_energy);
  // Per contact, in slot order, one array per component (vector loads).
  std::vector<double> nx_, ny_, nz_;  ///< n0, first -> second
  std::vector<double> overlap0_;      ///< u_0
};

}  // namespace mesowave::dem
