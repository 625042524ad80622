#include "mesowave/dem/cohesive_frictional_contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <tuple>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/dem/neighbour_search.hpp"

namespace mesowave::dem {

CohesiveFrictionalContact::CohesiveFrictionalContact(SphereSet spheres, BondNetwork bonds,
                                                     const CohesiveFrictionalMaterial& material)
    : SphereSystem(std::move(spheres), std::move(bonds), material, false, false) {
  const auto stray = unbonded_overlaps(spheres_, bonds_);
  if (!stray.empty()) {
    double worst = 0;
    for (auto [i, j] : stray)
      worst = std::max(worst, spheres_.radius_m[i] + spheres_.radius_m[j] - norm(spheres_.centre_m[j] - spheres_.centre_m[i]));
    throw InputError(std::to_string(stray.size()) + " pairs of spheres overlap at step 0 without a bond (bond factor C_f " +
                     format_number(material.bond_factor) + " < 1; largest overlap " + format_number(worst) +
                     " m): the full law would start them as contacts pushing with K_n u; raise C_f to bond them, or "
                     "run --model linear/chain, which never adds contacts");
  }
  const double r_min = *std::min_element(spheres_.radius_m.begin(), spheres_.radius_m.end());
  margin_ = 0.1 * r_min;
  detect_contacts();
}

CohesiveFrictionalContact::Slot CohesiveFrictionalContact::slot(std::size_t s) const {
  return {{nx_[s], ny_[s], nz_[s]}, {sx_[s], sy_[s], sz_[s]}, overlap0_[s], bond_[s],
          cohesive_[s] != 0 ? kCohesive : kFrictional};
}

void CohesiveFrictionalContact::set_slots(const std::vector<Slot>& slots) {
  const std::size_t m = slots.size();
  nx_.resize(m), ny_.resize(m), nz_.resize(m), sx_.resize(m), sy_.resize(m), sz_.resize(m);
  overlap0_.resize(m), bond_.resize(m), cohesive_.resize(m);
  for (std::size_t s = 0; s < m; ++s) {
    nx_[s] = slots[s].normal.x, ny_[s] = slots[s].normal.y, nz_[s] = slots[s].normal.z;
    sx_[s] = slots[s].shear.x, sy_[s] = slots[s].shear.y, sz_[s] = slots[s].shear.z;
    overlap0_[s] = slots[s].overlap0;
    bond_[s] = slots[s].bond;
    cohesive_[s] = slots[s].status == kCohesive ? 1.0 : 0.0;
  }
}

std::size_t CohesiveFrictionalContact::broken_bond_count() const {
  std::size_t broken = 0;
  for (std::size_t s = 0; s < bond_.size(); ++s) broken += bond_[s] != kNoBond && cohesive_[s] == 0;
  return broken;
}

std::size_t CohesiveFrictionalContact::memory_bytes() const {
  return SphereSystem::memory_bytes() + bond_.size() * (8 * sizeof(double) + sizeof(std::uint32_t));
}

void CohesiveFrictionalContact::contact_forces(double dt, bool evaluate_energy) { kernel(dt, evaluate_energy); }

// Compiled for AVX-512, AVX2 and baseline x86-64, picked at load time. No FMA
// contraction (ISO C++ mode), so every version gives the same bits.
__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
void CohesiveFrictionalContact::kernel(double dt, bool evaluate_energy) {
  const double two_young = 2.0 * material_.young_Pa, ratio = material_.stiffness_ratio;
  const double tan_mu = std::tan(material_.friction_angle_rad);
  const double T = material_.tensile_strength_Pa, C = material_.cohesion_Pa;
  // Reference strengths for the peak ratio: T R^2 and C R^2, or K_n R when a strength is not given.
  const double T_ref = std::isfinite(T) ? T : 0.0, C_ref = std::isfinite(C) ? C : 0.0;
  const double T_none = std::isfinite(T) ? 0.0 : 1.0, C_none = std::isfinite(C) ? 0.0 : 1.0;
  const double half_dt = 0.5 * dt;
  const double energy_on = evaluate_energy ? 1.0 : 0.0;
  const double* radius = spheres_.radius_m.data();
  const Vec3* x = x_.data();
  const Vec3* v = v_.data();
  const Vec3* w = w_.data();
  double *nx = nx_.data(), *ny = ny_.data(), *nz = nz_.data();
  double *sx = sx_.data(), *sy = sy_.data(), *sz = sz_.data();
  const double* overlap0 = overlap0_.data();
  double* cohesion = cohesive_.data();
  const std::uint32_t* first = first_.data();
  const std::uint32_t* second = second_.data();

  for_each_contact([&](std::size_t b, ContactResult& r) __attribute__((always_inline)) {
    const std::uint32_t i = first[b], j = second[b];
    const Vec3 d = x[j] - x[i];
    const double dist = std::sqrt(norm2(d));
    const double ri = radius[i], rj = radius[j], sum = ri + rj;
    const double inv = 1.0 / (sum * dist);  // one division: 1/dist, K_n and the factor a
    const Vec3 n = (sum * inv) * d;
    const double u = sum - dist;
    const double kn = two_young * ri * rj * dist * inv, ks = ratio * kn;

    // ScGeom::precompute + rotate: carry the shear force with the contact frame.
    const Vec3 n_prev{nx[b], ny[b], nz[b]};
    Vec3 fs{sx[b], sy[b], sz[b]};
    const Vec3 wi = w[i], wj = w[j];
    fs -= cross(fs, cross(n_prev, n));
    fs -= cross(fs, (half_dt * dot(n_prev, wi + wj)) * n_prev);
    // Shear increment, Eq. (2): ScGeom::getIncidentVel with avoidGranularRatcheting.
    Vec3 v_rel = (sum * sum * inv) * (v[j] - v[i]) - rj * cross(wj, n) - ri * cross(wi, n);
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
    const double shear_break = (cohesive - tension_break) * (fs2 > cohesive_max * cohesive_max ? 1.0 : 0.0);
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
    r.elastic = energy_on * (0.5 * fn_new * fn_new / kn + 0.5 * norm2(fs_new) * dist * inv * dist * inv_ks);
  });
}

void CohesiveFrictionalContact::after_step(double dt) {
  travelled_ += max_speed_ * dt;
  // Two spheres close in by at most twice the distance the fastest one moved.
  if (2.0 * travelled_ > margin_) detect_contacts();
}

void CohesiveFrictionalContact::detect_contacts() {
  travelled_ = 0;
  ++detection_passes_;
  const std::size_t n = spheres_.size(), nb = bonds_.size();
  std::vector<std::array<double, 3>> pos(n);
  for (std::size_t k = 0; k < n; ++k) pos[k] = {x_[k].x, x_[k].y, x_[k].z};
  const double r_min = *std::min_element(spheres_.radius_m.begin(), spheres_.radius_m.end());
  const auto pairs = find_pairs_within(pos, spheres_.radius_m, 1.0 + margin_ / (2.0 * r_min));

  // Where each bond and each detected pair lives now.
  std::vector<std::uint32_t> slot_of_bond(nb, kNoBond);
  std::vector<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>> old_pairs;
  for (std::size_t s = 0; s < bond_.size(); ++s) {
    if (bond_[s] != kNoBond) slot_of_bond[bond_[s]] = std::uint32_t(s);
    else old_pairs.emplace_back(first_[s], second_[s], std::uint32_t(s));
  }
  std::sort(old_pairs.begin(), old_pairs.end());

  std::vector<std::uint32_t> first(bonds_.first), second(bonds_.second);
  std::vector<Slot> natural(nb);
  for (std::size_t b = 0; b < nb; ++b)
    natural[b] = slot_of_bond[b] != kNoBond ? slot(slot_of_bond[b])
                                            : Slot{bonds_.normal0[b], {}, bonds_.overlap0_m[b], std::uint32_t(b), kCohesive};
  std::size_t b = 0;  // bonds and pairs are both sorted by (first, second)
  for (const auto& p : pairs) {
    const double reach = spheres_.radius_m[p.i] + spheres_.radius_m[p.j] + margin_;
    const Vec3 d = x_[p.j] - x_[p.i];
    if (norm2(d) > reach * reach) continue;
    while (b < nb && (bonds_.first[b] < p.i || (bonds_.first[b] == p.i && bonds_.second[b] < p.j))) ++b;
    if (b < nb && bonds_.first[b] == p.i && bonds_.second[b] == p.j) continue;  // bonded
    const auto known = std::lower_bound(old_pairs.begin(), old_pairs.end(), std::make_tuple(p.i, p.j, 0u));
    first.push_back(p.i);
    second.push_back(p.j);
    if (known != old_pairs.end() && std::get<0>(*known) == p.i && std::get<1>(*known) == p.j)
      natural.push_back(slot(std::get<2>(*known)));
    else
      natural.push_back(Slot{(1.0 / norm(d)) * d, {}, 0.0, kNoBond, kFrictional});
  }
  // Same contacts as before (the usual case for waves: bonds only): keep the layout.
  if (detection_passes_ > 1 && natural.size() == nb && bond_.size() == nb) return;
  const auto order = set_contacts(first, second);
  std::vector<Slot> slots(order.size());
  for (std::size_t s = 0; s < order.size(); ++s) slots[s] = natural[order[s]];
  set_slots(slots);
}

}  // namespace mesowave::dem
