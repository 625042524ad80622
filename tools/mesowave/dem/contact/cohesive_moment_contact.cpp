#include "mesowave/dem/contact/cohesive_moment_contact.hpp"

#include "mesowave/core/kernel_clones.hpp"
#include "mesowave/dem/contact/axial_chain.hpp"
#include "mesowave/dem/scene/plugins.hpp"

namespace mesowave::dem {

// The extension of the full law's kernel (CohesiveFrictionalContact::run).
// The trial moments go through the per-slot arrays: the kernel runs a chunk
// of contacts as one vector loop, so nothing may be kept across contacts.
struct CohesiveMomentContact::Moments {
  const double* radius;
  const std::uint32_t *first, *second;
  double *bx, *by, *bz, *tx, *ty, *tz;
  double alpha_kr, alpha_ktw, eta_roll, eta_twist, T, C;

  double trial(std::size_t s, std::uint32_t i, std::uint32_t j, const Vec3& n, const Vec3& n_prev, const Vec3& wi,
               const Vec3& wj, double /*kn*/, double ks, double fn, double r_min, double dt) {
    Vec3 mb{bx[s], by[s], bz[s]}, mt{tx[s], ty[s], tz[s]};
    // Carried with the contact frame as the shear force is (ScGeom::rotate).
    const Vec3 tilt = cross(n_prev, n), spin = (0.5 * dt * dot(n_prev, wi + wj)) * n_prev;
    mb -= cross(mb, tilt);
    mb -= cross(mb, spin);
    mt -= cross(mt, tilt);
    mt -= cross(mt, spin);
    const Vec3 w_rel = wj - wi;
    const double twist = dot(n, w_rel);
    const double rr = radius[i] * radius[j];
    mb -= (alpha_kr * ks * rr * dt) * (w_rel - twist * n);
    mt -= (alpha_ktw * ks * rr * dt * twist) * n;
    bx[s] = mb.x, by[s] = mb.y, bz[s] = mb.z;
    tx[s] = mt.x, ty[s] = mt.y, tz[s] = mt.z;
    const double r3 = r_min * r_min * r_min;
    const double roll_max = std::max(0.0, 0.25 * T * r3 + eta_roll * r_min * fn);
    const double twist_max = std::max(0.0, 0.5 * C * r3 + eta_twist * r_min * fn);
    return norm2(mb) > roll_max * roll_max || norm2(mt) > twist_max * twist_max ? 1.0 : 0.0;
  }

  void finish(std::size_t s, double intact, double energy_on, double ks, SphereSystem::MomentContactResult& r) {
    const Vec3 mb = intact * Vec3{bx[s], by[s], bz[s]}, mt = intact * Vec3{tx[s], ty[s], tz[s]};
    bx[s] = mb.x, by[s] = mb.y, bz[s] = mb.z;
    tx[s] = mt.x, ty[s] = mt.y, tz[s] = mt.z;
    r.m = mb + mt;
    const double ri = radius[first[s]], rj = radius[second[s]], r_min = std::min(ri, rj);
    const double kr = alpha_kr * ks * ri * rj, ktw = alpha_ktw * ks * ri * rj;
    const double inv_kr_raw = 1.0 / kr, inv_ktw_raw = 1.0 / ktw;
    const double inv_kr = kr > 0.0 ? inv_kr_raw : 0.0, inv_ktw = ktw > 0.0 ? inv_ktw_raw : 0.0;
    r.elastic += energy_on * (0.5 * norm2(mb) * inv_kr + 0.5 * norm2(mt) * inv_ktw);
    // Moment / strength against the cohesive parts (infinite strengths add nothing).
    const double r3 = r_min * r_min * r_min;
    const double roll_ref = 0.25 * T * r3, twist_ref = 0.5 * C * r3;
    r.ratio2 = std::max(r.ratio2, std::max(norm2(mb) / (roll_ref * roll_ref), norm2(mt) / (twist_ref * twist_ref)));
  }
};

void CohesiveMomentContact::contact_forces(SphereSystem& system, double dt, bool evaluate_energy) {
  kernel(system, dt, evaluate_energy);
}

// Compiled for AVX-512, AVX2 and baseline x86-64 (as the full law's kernel).
MESOWAVE_KERNEL_CLONES
void CohesiveMomentContact::kernel(SphereSystem& system, double dt, bool evaluate_energy) {
  const CohesiveFrictionalMaterial& m = system.material();
  Moments ext{system.radii(), system.first(), system.second(),
              mb_[0].data(), mb_[1].data(), mb_[2].data(), mt_[0].data(), mt_[1].data(), mt_[2].data(),
              p_.alpha_kr, p_.alpha_ktw, p_.eta_roll, p_.eta_twist, m.tensile_strength_Pa, m.cohesion_Pa};
  run<SphereSystem::MomentContactResult>(system, dt, evaluate_energy, ext);
}

std::size_t CohesiveMomentContact::memory_bytes() const {
  return CohesiveFrictionalContact::memory_bytes() + 6 * mb_[0].size() * sizeof(double);
}

void CohesiveMomentContact::moment_stiffness(const SphereSystem& system, double ri, double rj, double& k_r,
                                             double& k_tw) const {
  k_r = rolling_stiffness(system.material(), p_, ri, rj);
  k_tw = twisting_stiffness(system.material(), p_, ri, rj);
}

void CohesiveMomentContact::save_state(const SphereSystem& system, StateGroup& group) const {
  CohesiveFrictionalContact::save_state(system, group);
  const char* axes[3] = {"x", "y", "z"};
  for (int d = 0; d < 3; ++d) {
    system.write_slots(group, std::string("bending_") + axes[d] + "_N_m", mb_[d]);
    system.write_slots(group, std::string("twisting_") + axes[d] + "_N_m", mt_[d]);
  }
}

void CohesiveMomentContact::load_state(SphereSystem& system, const StateGroup& group) {
  for (int d = 0; d < 3; ++d) std::vector<double>().swap(mb_[d]), std::vector<double>().swap(mt_[d]);  // as the base's
  CohesiveFrictionalContact::load_state(system, group);
  const char* axes[3] = {"x", "y", "z"};
  for (int d = 0; d < 3; ++d) {
    mb_[d] = system.read_slots(group, std::string("bending_") + axes[d] + "_N_m");
    mt_[d] = system.read_slots(group, std::string("twisting_") + axes[d] + "_N_m");
  }
}

void CohesiveMomentContact::before_relayout(const SphereSystem& system) {
  // By held bond (those of this rank's slots): the bonds keep their moments across layouts.
  saved_b_.assign(system.held_bond_network().size(), Vec3{});
  saved_t_.assign(system.held_bond_network().size(), Vec3{});
  for (std::size_t s = 0; s < mb_[0].size(); ++s)
    if (const std::uint32_t b = bond_of_slot(s); b != kNoBond) {
      saved_b_[system.held_bond(b)] = bending_moment(s);
      saved_t_[system.held_bond(b)] = twisting_moment(s);
    }
}

void CohesiveMomentContact::after_relayout(const SphereSystem& system) {
  const std::size_t slots = system.slot_count();
  for (int d = 0; d < 3; ++d) {
    mb_[d].assign(slots, 0.0);
    mt_[d].assign(slots, 0.0);
  }
  for (std::size_t s = 0; s < slots; ++s)
    if (const std::uint32_t b = bond_of_slot(s); b != kNoBond)
      for (int d = 0; d < 3; ++d) {
        mb_[d][s] = saved_b_[system.held_bond(b)][d];
        mt_[d][s] = saved_t_[system.held_bond(b)][d];
      }
}

void register_cohesive_moment_law(Plugins& p) {
  p.laws.add({
      .name = "cohesive_moment",
      .summary = "the cohesive_frictional law with rolling and twisting moments (Yade's momentRotationLaw = true, "
                 "incremental form): k_r = alpha_kr K_s R_A R_B, k_tw = alpha_ktw K_s R_A R_B, bond moment strengths "
                 "0.25 T R^3 + eta_roll R F_n and 0.5 C R^3 + eta_twist R F_n",
      .parameters = {{"alpha_kr", "", 0, 1e6, "rolling stiffness k_r / (K_s R_A R_B) (Yade's alphaKr)", 2.0},
                     {"alpha_ktw", "", 0, 1e6, "twisting stiffness k_tw / (K_s R_A R_B) (Yade's alphaKtw)", 2.0},
                     {"eta_roll", "", 0, 1e6, "frictional rolling strength / (R F_n) (Yade's etaRoll)", 0.0},
                     {"eta_twist", "", 0, 1e6, "frictional twisting strength / (R F_n) (Yade's etaTwist)", 0.0}},
      // The chain stays valid: on a line loaded along it the rotations, hence the moments, stay zero.
      .models = {"full", "chain"},
      .make = [](const std::string& model, SpherePart spheres, BondNetwork bonds,
                 const LawInput& in) -> std::unique_ptr<Model> {
        if (model == "chain") return std::make_unique<AxialChain>(std::move(spheres), bonds, in.material, *in.line);
        MomentParameters mp;
        const auto take = [&](const char* key, double& value) {
          if (auto it = in.parameters.find(key); it != in.parameters.end()) value = it->second;
        };
        take("alpha_kr", mp.alpha_kr), take("alpha_ktw", mp.alpha_ktw);
        take("eta_roll", mp.eta_roll), take("eta_twist", mp.eta_twist);
        refuse_unbonded_overlaps(spheres, bonds, in.material.bond_factor);
        return std::make_unique<SphereSystem>(std::move(spheres), std::move(bonds), in.material,
                                              std::make_unique<CohesiveMomentContact>(mp), in.domain);
      },
      .shortcut_obstacle = [](const std::string&, const Scene&) { return std::string(); },
      .describe = [](const LawParameters& parameters) {
        nlohmann::ordered_json j;
        for (const auto& [key, value] : parameters) j[key] = value;
        return j;
      },
  });
}

}  // namespace mesowave::dem
