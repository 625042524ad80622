#pragma once
// The cohesive-frictional law with rolling and twisting moments: Yade's
// Law2_ScGeom6D_CohFrictPhys_CohesionMoment with momentRotationLaw = true
// (CohFrictMat / Ip2_CohFrictMat_CohFrictMat_CohFrictPhys), on top of the
// full law of cohesive_frictional_contact.hpp (forces, breakage, friction
// unchanged). Scene: [material] law = "cohesive_moment".
//
//  stiffnesses (Ip2): k_r = alpha_kr K_s R_A R_B,  k_tw = alpha_ktw K_s R_A R_B   (K_s of Eq. 3)
//  incremental moments (useIncrementalForm = true), carried with the contact
//  frame like the shear force, w_rel = w_j - w_i:
//    M_b -= k_r dt (w_rel - (n.w_rel) n),   M_t -= k_tw dt (n.w_rel) n
//  M = M_b + M_t on sphere j, -M on sphere i;
//  strengths of a bond (setCohesion, R = min(R_A, R_B)):
//    |M_b| <= 0.25 T R^3 + eta_roll R F_n,   |M_t| <= 0.5 C R^3 + eta_twist R F_n
//  (0.25 T R^3: the moment at which pure bending of a circular section of
//  radius R reaches T; 0.5 C R^3 the same for torsion and C). Exceeding either
//  breaks the bond as a shear failure does (fragile); a broken bond, or a
//  contact that was never bonded, carries no moment (always_use_moment_law off).
//
// Differences from Yade, both deliberate: the incremental form (Yade's default
// is the total form, which its own documentation says does not apply moment
// plasticity correctly); eta_roll, eta_twist >= 0 (Yade's negative "no
// plasticity" value is not offered: 0 means the cohesive part alone).
#include "mesowave/dem/contact/cohesive_frictional_contact.hpp"

namespace mesowave::dem {

/// What the moment law adds to the shared material (SI, dimensionless).
struct MomentParameters {
  double alpha_kr = 2.0, alpha_ktw = 2.0;  ///< Yade's CohFrictMat defaults
  double eta_roll = 0.0, eta_twist = 0.0;
};

/// k_r and k_tw of a bond between radii r_a, r_b (Ip2_CohFrictMat_CohFrictMat_CohFrictPhys).
inline double rolling_stiffness(const CohesiveFrictionalMaterial& m, const MomentParameters& p, double r_a, double r_b) {
  return p.alpha_kr * shear_stiffness(m, r_a, r_b) * r_a * r_b;
}
inline double twisting_stiffness(const CohesiveFrictionalMaterial& m, const MomentParameters& p, double r_a, double r_b) {
  return p.alpha_ktw * shear_stiffness(m, r_a, r_b) * r_a * r_b;
}
/// The cohesive parts of the moment strengths: 0.25 T R^3 and 0.5 C R^3, R the smaller radius.
inline double rolling_strength(const CohesiveFrictionalMaterial& m, double r_a, double r_b) {
  const double r = std::min(r_a, r_b);
  return 0.25 * m.tensile_strength_Pa * r * r * r;
}
inline double twisting_strength(const CohesiveFrictionalMaterial& m, double r_a, double r_b) {
  const double r = std::min(r_a, r_b);
  return 0.5 * m.cohesion_Pa * r * r * r;
}

class CohesiveMomentContact : public CohesiveFrictionalContact {
public:
  explicit CohesiveMomentContact(const MomentParameters& parameters) : p_(parameters) {}
  void contact_forces(SphereSystem& system, double dt, bool evaluate_energy) override;
  std::size_t memory_bytes() const override;
  void moment_stiffness(const SphereSystem& system, double ri, double rj, double& k_r, double& k_tw) const override;
  /// The full law's state and the bending and twisting moments per slot.
  void save_state(const SphereSystem& system, StateGroup& group) const override;
  void load_state(SphereSystem& system, const StateGroup& group) override;
  /// The moments M_b, M_t of contact slot s (on its second sphere).
  Vec3 bending_moment(std::size_t s) const { return {mb_[0][s], mb_[1][s], mb_[2][s]}; }
  Vec3 twisting_moment(std::size_t s) const { return {mt_[0][s], mt_[1][s], mt_[2][s]}; }

protected:
  bool moments() const override { return true; }
  void before_relayout(const SphereSystem& system) override;
  void after_relayout(const SphereSystem& system) override;

private:
  struct Moments;
  void kernel(SphereSystem& system, double dt, bool evaluate_energy);
  MomentParameters p_;
  std::vector<double> mb_[3], mt_[3];  ///< per slot
  std::vector<Vec3> saved_b_, saved_t_;  ///< per bond, across a relayout
};

}  // namespace mesowave::dem
