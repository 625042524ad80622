#pragma once
// The full contact law of both papers, as Yade 2023.02a computes it with
// Ig2_Sphere_Sphere_ScGeom6D + Ip2_CohFrictMat_CohFrictMat_CohFrictPhys +
// Law2_ScGeom6D_CohFrictPhys_CohesionMoment (momentRotationLaw off, fragile):
//
//  geometry (ScGeom): n = (x_j - x_i)/|x_j - x_i|, u = r_i + r_j - |x_j - x_i|,
//    contact point x_i + (r_i - u/2) n;
//  shear frame (ScGeom::rotate): F_s -= F_s x (n_prev x n);  F_s -= F_s x (dt/2 (n_prev.(w_i + w_j)) n_prev);
//  shear increment (ScGeom::getIncidentVel, avoidGranularRatcheting):
//    v_rel = a (v_j - v_i) - r_j w_j x n - r_i w_i x n,  a = (r_i + r_j)/|x_j - x_i|,
//    dU_s = dt (v_rel - (n.v_rel) n);   F_s -= K_s dU_s                        (Eq. 2)
//  normal force F_n = K_n (u - u_0), compression positive                   (Eq. 1)
//  a bond breaks in tension when -F_n > T R^2 (no force that step, shear reset);
//  Mohr-Coulomb: |F_s| <= C R^2 + F_n tan(mu) while cohesive           (Eqs. 4, 6)
//    (exceeding it breaks the cohesion), |F_s| <= F_n tan(mu) after       (Eq. 5)
//    (excess sheared off, booked as plastic dissipation);
//  force F_n n + F_s on sphere j, its opposite on i, both at the contact point.
//
// One deliberate difference from Yade: Yade erases an interaction that broke
// in tension and, if the spheres overlap again, creates a fresh one with
// u_0 = 0, which in a packing made dense by overlaps pushes with K_n u at once.
// Here a broken bond keeps its u_0: it carries compression (K_n (u - u_0) > 0)
// and friction only, never cohesion again. Pairs that were never bonded come
// into contact through detection (Verlet list rebuilt when spheres have
// moved half its margin) with u_0 = 0.
#include "mesowave/dem/sphere_system.hpp"

namespace mesowave::dem {

class CohesiveFrictionalContact : public SphereSystem {
public:
  /// InputError if spheres overlap at step 0 without being bonded (C_f < 1):
  /// they would start as contacts carrying K_n u, not force-free.
  CohesiveFrictionalContact(SphereSet spheres, BondNetwork bonds, const CohesiveFrictionalMaterial& material);

  std::string name() const override { return "full"; }
  std::size_t contact_count() const override { return bond_.size(); }
  std::size_t broken_bond_count() const override;
  std::size_t memory_bytes() const override;
  /// Candidate-list builds so far (the first at step 0).
  std::size_t detection_passes() const { return detection_passes_; }

protected:
  void contact_forces(double dt, bool evaluate_energy) override;
  void after_step(double dt) override;

private:
  void kernel(double dt, bool evaluate_energy);
  void detect_contacts();

  enum : std::uint8_t { kCohesive = 0, kFrictional = 1 };
  static constexpr std::uint32_t kNoBond = 0xffffffffu;
  /// What a contact carries from step to step, with its constants.
  struct Slot {
    Vec3 normal;       ///< n of the last step (ScGeom::normal)
    Vec3 shear;        ///< F_s (CohFrictPhys::shearForce)
    double overlap0;   ///< u_0 (0 for contacts that were never bonded)
    std::uint32_t bond;  ///< bond index, kNoBond for a detected contact
    std::uint8_t status;
  };
  Slot slot(std::size_t s) const;
  void set_slots(const std::vector<Slot>& slots);
  // The same, in slot order, one array per component (vector loads and stores).
  std::vector<double> nx_, ny_, nz_, sx_, sy_, sz_, overlap0_;
  std::vector<std::uint32_t> bond_;
  std::vector<double> cohesive_;  ///< 1 while the bond holds, 0 after (a double: one vector width for the whole loop)
  double margin_ = 0, travelled_ = 0;
  std::size_t detection_passes_ = 0;
};

}  // namespace mesowave::dem
