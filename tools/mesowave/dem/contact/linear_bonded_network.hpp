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

/// One bond's response under the law above: the force f on the second sphere
/// (the first gets -f), c = n0 x F_s (the torque on sphere i is -arm_i c, on j
/// -arm_j c), and the parts the kernel also reports. The one definition of the
/// law: the dynamic kernel runs it per bond and step, the static solve
/// (dem/calibration/static_elastic.hpp) assembles the stiffness matrix from it.
struct LinearBondResponse {
  Vec3 f, c, fs;
  double fn, kn, ks, a0;
  double arm_i, arm_j;
};

/// `two_E_dem` = 2 E_dem, `ratio` = K_s / K_n, u0 the step-0 overlap, n the
/// step-0 normal (first -> second), dd = d_j - d_i.
__attribute__((always_inline)) inline LinearBondResponse linear_bond_response(double two_E_dem, double ratio, double ri,
                                                                               double rj, double u0, const Vec3& n,
                                                                               const Vec3& dd, const Vec3& theta_i,
                                                                               const Vec3& theta_j) {
  LinearBondResponse r;
  const double sum = ri + rj, dist0 = sum - u0;
  const double inv = 1.0 / (sum * dist0);  // one division for K_n and a0
  r.kn = two_E_dem * ri * rj * dist0 * inv;
  r.ks = ratio * r.kn;
  r.a0 = sum * sum * inv;
  const double dn = dot(n, dd);
  const Vec3 st = r.a0 * (dd - dn * n) - cross(ri * theta_i + rj * theta_j, n);
  r.fn = -r.kn * dn;
  r.fs = -r.ks * st;
  r.f = r.fn * n + r.fs;
  r.c = cross(n, r.fs);
  r.arm_i = ri - 0.5 * u0;
  r.arm_j = rj - 0.5 * u0;
  return r;
}

/// The kernel (sphere_system.hpp composes it).
class LinearBondedNetwork : public ContactKernel {
public:
  std::string name() const override { return "linear"; }
  bool displacement_state() const override { return true; }
  bool track_rotation() const override { return true; }
  bool reads_velocities() const override { return false; }  // d and theta only (kernel())
  void attach(SphereSystem& system) override;
  void contact_forces(SphereSystem& system, double dt, bool evaluate_energy) override;
  std::size_t memory_bytes() const override {
    return nx_.size() * 4 * sizeof(double) + records_.size() * sizeof(SphereRecord);
  }
  /// Nothing of its own changes from step to step (n0, u_0 and the layout are
  /// fixed at attach); the system saves the motion.
  void save_state(const SphereSystem&, StateGroup&) const override {}
  void load_state(SphereSystem&, const StateGroup&) override {}

private:
  void kernel(SphereSystem& system, bool evaluate_energy);
  // Per contact, in slot order, one array per component (vector loads).
  std::vector<double> nx_, ny_, nz_;  ///< n0, first -> second
  std::vector<double> overlap0_;      ///< u_0
  /// The held spheres' d, theta and r, one line a sphere, packed at the start of each step: a
  /// contact's second sphere is then one line, not two to five (contact_ends.hpp).
  std::vector<SphereRecord> records_;
};

}  // namespace mesowave::dem
