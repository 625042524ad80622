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
#include <algorithm>
#include <cmath>
#include <type_traits>

#include "mesowave/dem/engine/contact_ends.hpp"
#include "mesowave/dem/engine/sphere_system.hpp"

namespace mesowave::dem {

/// The full law would start a pair that overlaps at step 0 without a bond (C_f < 1) as a contact
/// pushing with K_n u: InputError, before the system is made (its factory calls it: every sphere
/// and its layer are at hand then). Of a rank's part and its bonds on several ranks (collective).
void refuse_unbonded_overlaps(const SpherePart& spheres, const BondNetwork& bonds, double bond_factor);

/// The kernel (sphere_system.hpp composes it).
class CohesiveFrictionalContact : public ContactKernel {
public:
  std::string name() const override { return "full"; }
  bool displacement_state() const override { return false; }
  bool track_rotation() const override { return false; }
  /// InputError if spheres overlap at step 0 without being bonded (C_f < 1):
  /// they would start as contacts carrying K_n u, not force-free.
  void attach(SphereSystem& system) override;
  void contact_forces(SphereSystem& system, double dt, bool evaluate_energy) override;
  void after_step(SphereSystem& system, double dt) override;
  std::size_t broken_bond_count() const override;
  std::size_t broken_bonds_in(const std::vector<std::uint32_t>& slots) const override;
  std::size_t memory_bytes() const override { return bond_.size() * (8 * sizeof(double) + sizeof(std::uint32_t)); }
  /// The contacts in slot order (pairs and per-slot state: normals, shear
  /// forces, u_0, bond, cohesion) and the detection's travel since its last
  /// pass. Loading lays the same contacts out again (each rank its own; each
  /// must come back to its slot) and refuses a list that does not fit.
  void save_state(const SphereSystem& system, StateGroup& group) const override;
  void load_state(SphereSystem& system, const StateGroup& group) override;
  /// Candidate-list builds so far (the first at step 0).
  std::size_t detection_passes() const { return detection_passes_; }

protected:
  /// The law's kernel with an extension (a law built on this one, e.g. the
  /// moment law of cohesive_moment_contact.hpp): for each contact, after the
  /// forces' trial values, extension.trial(slot, i, j, n, n_prev, w_i, w_j,
  /// K_n, K_s, F_n, R_min, dt) returns 1 if its own strengths break the bond
  /// (a break like a shear failure), and extension.finish(slot, intact,
  /// energy_on, K_s, result) adds its part once the bond's fate is known.
  template <class Result, class Extension>
  void run(SphereSystem& system, double dt, bool evaluate_energy, Extension& extension) __attribute__((always_inline));
  struct NoExtension {};
  /// The bond a contact slot holds (kNoBond for a detected contact).
  std::uint32_t bond_of_slot(std::size_t s) const { return bond_[s]; }
  static constexpr std::uint32_t kNoBond = 0xffffffffu;
  /// Called around a new slot layout (contact detection changed the contacts):
  /// an extension keeping per-slot state saves it by bond, then restores it.
  virtual void before_relayout(const SphereSystem& /*system*/) {}
  virtual void after_relayout(const SphereSystem& /*system*/) {}
  /// True for an extension that adds moments (the integrator keeps room for them).
  virtual bool moments() const { return false; }

private:
  void kernel(SphereSystem& system, double dt, bool evaluate_energy);
  void detect_contacts(SphereSystem& system);

  enum : std::uint8_t { kCohesive = 0, kFrictional = 1 };
  /// What a contact carries from step to step, with its constants.
  struct Slot {
    Vec3 normal;       ///< n of the last step (ScGeom::normal)
    Vec3 shear;        ///< F_s (CohFrictPhys::shearForce)
    double overlap0;   ///< u_0 (0 for contacts that were never bonded)
    std::uint32_t bond;  ///< bond index, kNoBond for a detected contact
    std::uint8_t status;
  };
  Slot slot(std::size_t s) const;
  /// The per-slot arrays made anew, slot s from slot_at(s) (reading the old arrays meanwhile),
  /// one slot at a time: a record per contact for the whole list at once would double the peak.
  template <class SlotAt>
  void set_slots(std::size_t m, const SlotAt& slot_at);
  // The same, in slot order, one array per component (vector loads and stores).
  std::vector<double> nx_, ny_, nz_, sx_, sy_, sz_, overlap0_;
  std::vector<std::uint32_t> bond_;
  std::vector<double> cohesive_;  ///< 1 while the bond holds, 0 after (a double: one vector width for the whole loop)
  double margin_ = 0, travelled_ = 0;
  std::size_t detection_passes_ = 0;
};

template <class Result, class Extension>
inline void CohesiveFrictionalContact::run(SphereSystem& system, double dt, bool evaluate_energy, Extension& extension) {
  constexpr bool extended = !std::is_same_v<Extension, NoExtension>;
  const CohesiveFrictionalMaterial& material = system.material();
  const double two_E_dem = 2.0 * material.E_dem_Pa, ratio = material.stiffness_ratio;
  const double tan_mu = std::tan(material.friction_angle_rad);
  const double T = material.tensile_strength_Pa, C = material.cohesion_Pa;
  // Reference strengths for the peak ratio: T R^2 and C R^2, or K_n R when a strength is not given.
  const double T_ref = std::isfinite(T) ? T : 0.0, C_ref = std::isfinite(C) ? C : 0.0;
  const double T_none = std::isfinite(T) ? 0.0 : 1.0, C_none = std::isfinite(C) ? 0.0 : 1.0;
  const double half_dt = 0.5 * dt;
  const double* radius = system.radii();
  const Vec3* x = system.positions();
  const Vec3* v = system.velocities();
  const Vec3* w = system.angular_velocities();
  double *nx = nx_.data(), *ny = ny_.data(), *nz = nz_.data();
  double *sx = sx_.data(), *sy = sy_.data(), *sz = sz_.data();
  const double* overlap0 = overlap0_.data();
  double* cohesion = cohesive_.data();
  const std::uint32_t* first = system.first();
  const std::uint32_t* second = system.second();

  // x, v and w at both ends, staged a chunk at a time before the vector loop (contact_ends.hpp).
  ContactEnds<3> ends;
  // Two versions of the loop, the energy's divisions only in the one for energy steps (on the
  // others nothing reads the elastic energy).
  const auto contacts = [&](auto energy) __attribute__((always_inline)) {
    [[maybe_unused]] constexpr double energy_on = decltype(energy)::value ? 1.0 : 0.0;
    const auto kernel = [&](std::size_t b, Result& r) __attribute__((always_inline)) {
      const std::uint32_t i = first[b], j = second[b];
      const Vec3 vi = ends.at(1, 0, b), vj = ends.at(1, 1, b), wi = ends.at(2, 0, b), wj = ends.at(2, 1, b);
      const Vec3 d = ends.at(0, 1, b) - ends.at(0, 0, b);
      const double dist = std::sqrt(norm2(d));
      const double ri = radius[i], rj = radius[j], sum = ri + rj;
      const double inv = 1.0 / (sum * dist);  // one division: 1/dist, K_n and the factor a
      const Vec3 n = (sum * inv) * d;
      const double u = sum - dist;
      const double kn = two_E_dem * ri * rj * dist * inv, ks = ratio * kn;

      // ScGeom::precompute + rotate: carry the shear force with the contact frame.
      const Vec3 n_prev{nx[b], ny[b], nz[b]};
      Vec3 fs{sx[b], sy[b], sz[b]};
      fs -= cross(fs, cross(n_prev, n));
      fs -= cross(fs, (half_dt * dot(n_prev, wi + wj)) * n_prev);
      // Shear increment, Eq. (2): ScGeom::getIncidentVel with avoidGranularRatcheting.
      Vec3 v_rel = (sum * sum * inv) * (vj - vi) - rj * cross(wj, n) - ri * cross(wi, n);
      v_rel -= dot(n, v_rel) * n;
      fs -= (ks * dt) * v_rel;
      const double fn = kn * (u - overlap0[b]);  // Eq. (1)
      const double fs2 = norm2(fs);

      // Strength and friction (Eqs. 4-6) as 0/1 flags and selects on doubles, no
      // branches, so the chunk runs as one vector loop.
      const double r_min = std::min(ri, rj), r2 = r_min * r_min;
      const double cohesive = cohesion[b];                                  // 1 while the bond holds
      const double tension_break = cohesive * (-fn > T * r2 ? 1.0 : 0.0);   // Eq. (6); Yade removes the interaction
      const double cohesive_max = std::max(0.0, C * r2 + fn * tan_mu);      // Eq. (4)
      double shear_break = (cohesive - tension_break) * (fs2 > cohesive_max * cohesive_max ? 1.0 : 0.0);
      // An extension's own strengths (moments) break the bond as a shear failure does (Yade's checkPlasticity).
      if constexpr (extended)
        shear_break = std::max(shear_break, (cohesive - tension_break) *
                                                extension.trial(b, i, j, n, n_prev, wi, wj, kn, ks, fn, r_min, dt));
      const double intact = cohesive - tension_break - shear_break;
      const double open = tension_break + (1.0 - cohesive) * (fn <= 0.0 ? 1.0 : 0.0);  // no force, shear history reset
      const double max_fs = intact != 0.0 ? cohesive_max : std::max(0.0, fn * tan_mu);  // Eq. (5) once cohesion is gone
      const double slip = (1.0 - open) * (fs2 > max_fs * max_fs ? 1.0 : 0.0);
      const double slip_scale = max_fs / std::sqrt(fs2);
      const double scale = open != 0.0 ? 0.0 : (slip != 0.0 ? slip_scale : 1.0);
      const Vec3 fs_new = scale * fs;
      const double no_normal = std::max(open, shear_break * (fn < 0.0 ? 1.0 : 0.0));
      const double fn_new = no_normal != 0.0 ? 0.0 : fn;
      cohesion[b] = intact;
      nx[b] = n.x, ny[b] = n.y, nz[b] = n.z;
      sx[b] = fs_new.x, sy[b] = fs_new.y, sz[b] = fs_new.z;

      r.f = fn_new * n + fs_new;
      r.c = cross(n, fs_new);
      r.arm[0] = ri - 0.5 * u;
      r.arm[1] = rj - 0.5 * u;
      const double inv_ks_raw = 1.0 / ks;
      const double inv_ks = ks > 0.0 ? inv_ks_raw : 0.0;
      // Excess shear sheared off (Yade's plasticDissipation); zero without sliding.
      r.plastic = dot(fs - fs_new, fs_new) * inv_ks;
      // Bond force / strength (T R^2, C R^2; K_n R for bonds that never break).
      const double sn = T_ref * r2 + T_none * kn * r_min, ss = C_ref * r2 + C_none * kn * r_min;
      r.ratio2 = intact * std::max(fn * fn / (sn * sn), fs2 / (ss * ss));
      // The shear increment carries the factor (r_i + r_j)/|x_j - x_i|: the spring is that times K_s.
      r.elastic = 0;
      if constexpr (decltype(energy)::value)
        r.elastic = 0.5 * fn_new * fn_new / kn + 0.5 * norm2(fs_new) * dist * inv * dist * inv_ks;
      if constexpr (extended) extension.finish(b, intact, energy_on, ks, r);
    };
    system.template for_each_contact<Result>(kernel, decltype(energy)::value, true, [&](std::size_t chunk, std::size_t m, ContactRange ahead) {
      ends.prefetch({x, v, w}, radius, second, ahead);
      ends.fill({x, v, w}, first, second, chunk, m);
    });
  };
  if (evaluate_energy)
    contacts(std::true_type{});
  else
    contacts(std::false_type{});
}

}  // namespace mesowave::dem
