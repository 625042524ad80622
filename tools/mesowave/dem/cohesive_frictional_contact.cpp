#include "mesowave/dem/cohesive_frictional_contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

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
  first_ = bonds_.first;
  second_ = bonds_.second;
  overlap0_ = bonds_.overlap0_m;
  normal_ = bonds_.normal0;
  shear_.assign(first_.size(), {});
  status_.assign(first_.size(), kCohesive);
  const double r_min = *std::min_element(spheres_.radius_m.begin(), spheres_.radius_m.end());
  margin_ = 0.1 * r_min;
  detect_contacts();
}

std::size_t CohesiveFrictionalContact::broken_bond_count() const {
  return std::size_t(std::count(status_.begin(), status_.begin() + std::ptrdiff_t(bonds_.size()), kFrictional));
}

std::size_t CohesiveFrictionalContact::memory_bytes() const {
  return SphereSystem::memory_bytes() + first_.size() * (2 * sizeof(std::uint32_t) + sizeof(double) + 2 * sizeof(Vec3) + 1);
}

void CohesiveFrictionalContact::contact_forces(double dt, bool evaluate_energy) {
  const std::size_t m = first_.size();
  const std::size_t blocks = (m + kContactBlock - 1) / kContactBlock;
  const double young = material_.young_Pa, ratio = material_.stiffness_ratio;
  const double tan_mu = std::tan(material_.friction_angle_rad);
  const double T = material_.tensile_strength_Pa, C = material_.cohesion_Pa;
  const double inv_T = std::isinf(T) ? 0.0 : 1.0 / T, inv_C = std::isinf(C) ? 0.0 : 1.0 / C;
  const double* radius = spheres_.radius_m.data();

#pragma omp for schedule(static)
  for (std::size_t blk = 0; blk < blocks; ++blk) {
    double elastic = 0, plastic = 0, peak2 = 0;
    const std::size_t end = std::min(m, (blk + 1) * kContactBlock);
    for (std::size_t b = blk * kContactBlock; b < end; ++b) {
      const std::uint32_t i = first_[b], j = second_[b];
      const Vec3 d = x_[j] - x_[i];
      const double dist = std::sqrt(norm2(d));
      const double inv_dist = 1.0 / dist;
      const Vec3 n = inv_dist * d;
      const double ri = radius[i], rj = radius[j], sum = ri + rj;
      const double u = sum - dist;
      const double kn = young * 2.0 * ri * rj / sum, ks = ratio * kn;

      // ScGeom::precompute + rotate: carry the shear force with the contact frame.
      const Vec3 n_prev = normal_[b];
      Vec3 fs = shear_[b];
      const Vec3 wi = w_[i], wj = w_[j];
      const Vec3 axis = cross(n_prev, n);
      const Vec3 twist = (0.5 * dt * dot(n_prev, wi + wj)) * n_prev;
      fs -= cross(fs, axis);
      fs -= cross(fs, twist);
      // Shear increment, Eq. (2).
      Vec3 v_rel = (sum * inv_dist) * (v_[j] - v_[i]) - rj * cross(wj, n) - ri * cross(wi, n);
      v_rel -= dot(n, v_rel) * n;
      fs -= (ks * dt) * v_rel;
      // Eq. (1).
      double fn = kn * (u - overlap0_[b]);

      const double r_min = std::min(ri, rj), r2 = r_min * r_min;
      std::uint8_t state = status_[b];
      double fs2 = norm2(fs);
      double max_fs = 0;
      bool check_slip = true;
      if (state == kCohesive) {
        if (-fn > T * r2) {  // Eq. (6): tensile failure; Yade removes the interaction this step
          state = kFrictional;
          fn = 0;
          fs = {};
          fs2 = 0;
          check_slip = false;
        } else {
          max_fs = std::max(0.0, C * r2 + fn * tan_mu);  // Eq. (4)
          if (fs2 > max_fs * max_fs) {                    // cohesion lost, friction remains (Eq. 5)
            state = kFrictional;
            max_fs = std::max(0.0, fn * tan_mu);
            if (fn < 0) fn = 0;
          } else {
            peak2 = std::max(peak2, std::max(fn * fn * inv_T * inv_T, fs2 * inv_C * inv_C) / (r2 * r2));
            check_slip = false;
          }
        }
      } else if (fn <= 0) {  // open: no force; a later touch starts a fresh shear history
        fn = 0;
        fs = {};
        fs2 = 0;
        check_slip = false;
      } else {
        max_fs = fn * tan_mu;  // Eq. (5)
      }
      if (check_slip && fs2 > max_fs * max_fs) {
        const Vec3 trial = fs;
        fs *= max_fs / std::sqrt(fs2);
        if (ks > 0) plastic += dot(trial - fs, fs) / ks;
        fs2 = norm2(fs);
      }
      status_[b] = state;
      shear_[b] = fs;
      normal_[b] = n;
      ContactOut& o = out_[b];
      o.f = fn * n + fs;
      o.c = cross(n, fs);
      o.arm[0] = ri - 0.5 * u;
      o.arm[1] = rj - 0.5 * u;
      // The shear increment carries the factor (r_i + r_j)/|x_j - x_i|: the spring is that times K_s.
      if (evaluate_energy) elastic += 0.5 * fn * fn / kn + (ks > 0 ? 0.5 * fs2 * dist / (sum * ks) : 0.0);
    }
    block_elastic_[blk] = elastic;
    block_plastic_[blk] += plastic;
    block_peak_[blk] = std::sqrt(peak2);
  }
}

void CohesiveFrictionalContact::after_step(double dt) {
  travelled_ += max_speed_ * dt;
  // Two spheres close by at most twice the distance the fastest one moved.
  if (2.0 * travelled_ > margin_) detect_contacts();
}

void CohesiveFrictionalContact::detect_contacts() {
  travelled_ = 0;
  const std::size_t n = spheres_.size(), nb = bonds_.size();
  std::vector<std::array<double, 3>> pos(n);
  for (std::size_t k = 0; k < n; ++k) pos[k] = {x_[k].x, x_[k].y, x_[k].z};
  const double r_min = *std::min_element(spheres_.radius_m.begin(), spheres_.radius_m.end());
  const auto pairs = find_pairs_within(pos, spheres_.radius_m, 1.0 + margin_ / (2.0 * r_min));

  std::vector<std::uint32_t> first(first_.begin(), first_.begin() + std::ptrdiff_t(nb));
  std::vector<std::uint32_t> second(second_.begin(), second_.begin() + std::ptrdiff_t(nb));
  std::vector<double> overlap0(overlap0_.begin(), overlap0_.begin() + std::ptrdiff_t(nb));
  std::vector<Vec3> shear(shear_.begin(), shear_.begin() + std::ptrdiff_t(nb));
  std::vector<Vec3> normal(normal_.begin(), normal_.begin() + std::ptrdiff_t(nb));
  std::vector<std::uint8_t> status(status_.begin(), status_.begin() + std::ptrdiff_t(nb));
  auto less = [](std::uint32_t a1, std::uint32_t a2, std::uint32_t b1, std::uint32_t b2) {
    return a1 < b1 || (a1 == b1 && a2 < b2);
  };
  std::size_t b = 0, old = nb;  // bonds and old candidates are sorted by (first, second)
  for (const auto& p : pairs) {
    const double reach = spheres_.radius_m[p.i] + spheres_.radius_m[p.j] + margin_;
    if (norm2(x_[p.j] - x_[p.i]) > reach * reach) continue;
    while (b < nb && less(first_[b], second_[b], p.i, p.j)) ++b;
    if (b < nb && first_[b] == p.i && second_[b] == p.j) continue;  // bonded
    while (old < first_.size() && less(first_[old], second_[old], p.i, p.j)) ++old;
    const bool known = old < first_.size() && first_[old] == p.i && second_[old] == p.j;
    first.push_back(p.i);
    second.push_back(p.j);
    overlap0.push_back(0.0);
    shear.push_back(known ? shear_[old] : Vec3{});
    normal.push_back(known ? normal_[old] : (1.0 / norm(x_[p.j] - x_[p.i])) * (x_[p.j] - x_[p.i]));
    status.push_back(kFrictional);
  }
  const bool changed = first.size() != first_.size() || !std::equal(first.begin(), first.end(), first_.begin()) ||
                       !std::equal(second.begin(), second.end(), second_.begin());
  first_ = std::move(first);
  second_ = std::move(second);
  overlap0_ = std::move(overlap0);
  shear_ = std::move(shear);
  normal_ = std::move(normal);
  status_ = std::move(status);
  if (changed || out_.size() != first_.size()) set_contact_count(first_.size(), make_incidence(n, first_, second_));
  ++detection_passes_;
}

}  // namespace mesowave::dem
