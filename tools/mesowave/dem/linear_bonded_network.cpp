#include "mesowave/dem/linear_bonded_network.hpp"

#include <algorithm>
#include <cmath>

namespace mesowave::dem {

LinearBondedNetwork::LinearBondedNetwork(SphereSet spheres, BondNetwork bonds, const CohesiveFrictionalMaterial& material)
    : SphereSystem(std::move(spheres), std::move(bonds), material, true, true) {}

void LinearBondedNetwork::contact_forces(double /*dt*/, bool evaluate_energy) {
  const std::size_t m = bonds_.size();
  const std::size_t blocks = (m + kContactBlock - 1) / kContactBlock;
  const double young = material_.young_Pa, ratio = material_.stiffness_ratio;
  const double T = material_.tensile_strength_Pa, C = material_.cohesion_Pa;
  const double inv_T = std::isinf(T) ? 0.0 : 1.0 / T, inv_C = std::isinf(C) ? 0.0 : 1.0 / C;
  const double* radius = spheres_.radius_m.data();
  const std::uint32_t* first = bonds_.first.data();
  const std::uint32_t* second = bonds_.second.data();
  const double* overlap0 = bonds_.overlap0_m.data();
  const Vec3* normal0 = bonds_.normal0.data();

#pragma omp for schedule(static)
  for (std::size_t blk = 0; blk < blocks; ++blk) {
    double elastic = 0, peak2 = 0;
    const std::size_t end = std::min(m, (blk + 1) * kContactBlock);
    for (std::size_t b = blk * kContactBlock; b < end; ++b) {
      const std::uint32_t i = first[b], j = second[b];
      const double ri = radius[i], rj = radius[j], sum = ri + rj, u0 = overlap0[b];
      const double kn = young * 2.0 * ri * rj / sum, ks = ratio * kn;
      const double a0 = sum / (sum - u0);
      const Vec3 n = normal0[b];
      const Vec3 dd = x_[j] - x_[i];
      const double dn = dot(n, dd);
      const Vec3 st = a0 * (dd - dn * n) - cross(ri * theta_[i] + rj * theta_[j], n);
      const double fn = -kn * dn;
      const Vec3 fs = -ks * st;
      ContactOut& o = out_[b];
      o.f = fn * n + fs;
      o.c = cross(n, fs);
      o.arm[0] = ri - 0.5 * u0;
      o.arm[1] = rj - 0.5 * u0;
      const double fs2 = norm2(fs);
      const double r_min = std::min(ri, rj), r2 = r_min * r_min;
      peak2 = std::max(peak2, std::max(fn * fn * inv_T * inv_T, fs2 * inv_C * inv_C) / (r2 * r2));
      // The shear spring acting on a0 P_t dd is a0 K_s (Yade's incident-velocity factor).
      if (evaluate_energy) elastic += 0.5 * fn * fn / kn + (ks > 0 ? 0.5 * fs2 / (a0 * ks) : 0.0);
    }
    block_elastic_[blk] = elastic;
    block_peak_[blk] = std::sqrt(peak2);
  }
}

}  // namespace mesowave::dem
