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

std::size_t CohesiveFrictionalContact::broken_bond_count() const {
  std::size_t broken = 0;
  for (const Slot& s : slots_) broken += s.bond != kNoBond && s.status == kFrictional;
  return broken;
}

std::size_t CohesiveFrictionalContact::memory_bytes() const {
  return SphereSystem::memory_bytes() + slots_.size() * sizeof(Slot);
}

void CohesiveFrictionalContact::contact_forces(double dt, bool evaluate_energy) {
  const double two_young = 2.0 * material_.young_Pa, ratio = material_.stiffness_ratio;
  const double tan_mu = std::tan(material_.friction_angle_rad);
  const double T = material_.tensile_strength_Pa, C = material_.cohesion_Pa;
  const bool finite_T = std::isfinite(T), finite_C = std::isfinite(C);
  const double* radius = spheres_.radius_m.data();
  const Vec3* x = x_.data();
  const Vec3* v = v_.data();
  const Vec3* w = w_.data();
  Slot* slots = slots_.data();
  const std::uint32_t* first = first_.data();
  const std::uint32_t* second = second_.data();

  for_each_contact([&](std::size_t b, ContactOut& o, ContactSums& sums) __attribute__((always_inline)) {
    Slot& slot = slots[b];
    const std::uint32_t i = first[b], j = second[b];
    const Vec3 d = x[j] - x[i];
    const double dist = std::sqrt(norm2(d));
    const double ri = radius[i], rj = radius[j], sum = ri + rj;
    const double inv = 1.0 / (sum * dist);  // one division: 1/dist, K_n and the factor a
    const double inv_dist = sum * inv;
    const Vec3 n = inv_dist * d;
    const double u = sum - dist;
    const double kn = two_young * ri * rj * dist * inv, ks = ratio * kn;

    // ScGeom::precompute + rotate: carry the shear force with the contact frame.
    const Vec3 n_prev = slot.normal;
    Vec3 fs = slot.shear;
    const Vec3 wi = w[i], wj = w[j];
    fs -= cross(fs, cross(n_prev, n));
    fs -= cross(fs, (0.5 * dt * dot(n_prev, wi + wj)) * n_prev);
    // Shear increment, Eq. (2): ScGeom::getIncidentVel with avoidGranularRatcheting.
    Vec3 v_rel = (sum * sum * inv) * (v[j] - v[i]) - rj * cross(wj, n) - ri * cross(wi, n);
    v_rel -= dot(n, v_rel) * n;
    fs -= (ks * dt) * v_rel;
    // Eq. (1).
    double fn = kn * (u - slot.overlap0);

    const double r_min = std::min(ri, rj), r2 = r_min * r_min;
    double fs2 = norm2(fs);
    double max_fs = 0;
    bool slip_check = true;
    if (slot.status == kCohesive) {
      if (-fn > T * r2) {  // Eq. (6): tensile failure; Yade removes the interaction this step
        slot.status = kFrictional;
        fn = 0;
        fs = {};
        fs2 = 0;
        slip_check = false;
      } else {
        max_fs = std::max(0.0, C * r2 + fn * tan_mu);  // Eq. (4)
        if (fs2 > max_fs * max_fs) {                    // cohesion lost, friction remains (Eq. 5)
          slot.status = kFrictional;
          max_fs = std::max(0.0, fn * tan_mu);
          if (fn < 0) fn = 0;
        } else {
          slip_check = false;
          // Peak bond force / strength (T R^2, C R^2; K_n R for bonds that never break).
          const double sn = finite_T ? T * r2 : kn * r_min, ss = finite_C ? C * r2 : kn * r_min;
          const double num = std::max(fn * fn * ss * ss, fs2 * sn * sn), den = sn * sn * ss * ss;
          if (num > sums.peak2 * den) sums.peak2 = num / den;
        }
      }
    } else if (fn <= 0) {  // open: no force; a later touch starts a fresh shear history
      fn = 0;
      fs = {};
      fs2 = 0;
      slip_check = false;
    } else {
      max_fs = fn * tan_mu;  // Eq. (5)
    }
    if (slip_check && fs2 > max_fs * max_fs) {
      const Vec3 trial = fs;
      fs *= max_fs / std::sqrt(fs2);
      if (ks > 0) sums.plastic += dot(trial - fs, fs) / ks;
      fs2 = norm2(fs);
    }
    slot.shear = fs;
    slot.normal = n;
    o.f = fn * n + fs;
    o.c = cross(n, fs);
    o.arm[0] = ri - 0.5 * u;
    o.arm[1] = rj - 0.5 * u;
    // The shear increment carries the factor (r_i + r_j)/|x_j - x_i|: the spring is that times K_s.
    if (evaluate_energy) sums.elastic += 0.5 * fn * fn / kn + (ks > 0 ? 0.5 * fs2 * dist / (sum * ks) : 0.0);
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
  for (std::size_t s = 0; s < slots_.size(); ++s) {
    if (slots_[s].bond != kNoBond) slot_of_bond[slots_[s].bond] = std::uint32_t(s);
    else old_pairs.emplace_back(first_[s], second_[s], std::uint32_t(s));
  }
  std::sort(old_pairs.begin(), old_pairs.end());

  std::vector<std::uint32_t> first(bonds_.first), second(bonds_.second);
  std::vector<Slot> natural(nb);
  for (std::size_t b = 0; b < nb; ++b) {
    natural[b] = slot_of_bond[b] != kNoBond
                     ? slots_[slot_of_bond[b]]
                     : Slot{bonds_.normal0[b], {}, bonds_.overlap0_m[b], std::uint32_t(b), kCohesive};
  }
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
      natural.push_back(slots_[std::get<2>(*known)]);
    else
      natural.push_back(Slot{(1.0 / norm(d)) * d, {}, 0.0, kNoBond, kFrictional});
  }
  if (natural.size() == slots_.size() && detection_passes_ > 1) {
    // Same contacts as before (the usual case for waves): keep the layout.
    bool same = true;
    for (std::size_t s = 0; s < slots_.size() && same; ++s) same = slots_[s].bond != kNoBond;
    if (same) return;
  }
  const auto order = set_contacts(first, second);
  slots_.resize(order.size());
  for (std::size_t s = 0; s < order.size(); ++s) slots_[s] = natural[order[s]];
}

}  // namespace mesowave::dem
