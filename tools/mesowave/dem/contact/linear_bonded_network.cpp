#include "mesowave/dem/contact/linear_bonded_network.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "mesowave/core/kernel_clones.hpp"
#include "mesowave/dem/engine/contact_ends.hpp"

namespace mesowave::dem {

void LinearBondedNetwork::attach(SphereSystem& system) {
  const auto order = system.set_bond_contacts();
  const std::size_t m = order.size();
  nx_.resize(m), ny_.resize(m), nz_.resize(m), overlap0_.resize(m);
  for (std::size_t s = 0; s < m; ++s) {
    const BondGeometry g = system.bond_geometry0(order[s]);
    nx_[s] = g.normal.x, ny_[s] = g.normal.y, nz_[s] = g.normal.z;
    overlap0_[s] = g.overlap_m;
  }
  records_.resize(system.held_sphere_count());  // packed each step (kernel); sized here for memory_bytes
}

void LinearBondedNetwork::contact_forces(SphereSystem& system, double /*dt*/, bool evaluate_energy) {
  kernel(system, evaluate_energy);
}

// Compiled for AVX-512, AVX2 and baseline x86-64, picked at load time. No FMA
// contraction (ISO C++ mode), so every version gives the same bits.
MESOWAVE_KERNEL_CLONES
void LinearBondedNetwork::kernel(SphereSystem& system, bool evaluate_energy) {
  const CohesiveFrictionalMaterial& material = system.material();
  const double two_E_dem = 2.0 * material.E_dem_Pa, ratio = material.stiffness_ratio;
  const double T = material.tensile_strength_Pa, C = material.cohesion_Pa;
  // The strengths' choices as 0/1 factors, not bools: the vectoriser cannot select on a scalar bool
  // inside the vector loop (GCC 12 left the whole loop scalar).
  const double T_ref = std::isfinite(T) ? T : 0.0, C_ref = std::isfinite(C) ? C : 0.0;
  const double T_none = std::isfinite(T) ? 0.0 : 1.0, C_none = std::isfinite(C) ? 0.0 : 1.0;
  const double *nx = nx_.data(), *ny = ny_.data(), *nz = nz_.data(), *overlap0 = overlap0_.data();
  const std::uint32_t* first = system.first();
  const std::uint32_t* second = system.second();

  // d, theta and r of every held sphere as one line each (their arrays as the last step left them;
  // distributed, the ghosts' as their owners sent them), then staged a chunk at a time.
  const std::size_t n = system.held_sphere_count();
#pragma omp single
  records_.resize(n);  // a new layout may hold other spheres; the barrier after it orders the writes
  {
    const Vec3 *d = system.positions(), *theta = system.rotations();
    const double* radius = system.radii();
    SphereRecord* records = records_.data();
#pragma omp for schedule(static)
    for (std::size_t block = 0; block < n; block += SphereSystem::kSphereBlock)
      pack_sphere_records(d, theta, radius, block, std::min(n, block + SphereSystem::kSphereBlock), records);
  }
  const SphereRecord* records = records_.data();
  RecordEnds ends;
  // Two versions of the loop, the energy's divisions only in the one for energy steps (on the
  // others nothing reads the elastic energy).
  const auto contacts = [&](auto energy) __attribute__((always_inline)) {
    const auto kernel = [&](std::size_t b, SphereSystem::ContactResult& r) __attribute__((always_inline)) {
      const double ri = ends.scalar(0, b), rj = ends.scalar(1, b);
      const LinearBondResponse q = linear_bond_response(two_E_dem, ratio, ri, rj, overlap0[b], Vec3{nx[b], ny[b], nz[b]},
                                                        ends.at(0, 1, b) - ends.at(0, 0, b), ends.at(1, 0, b), ends.at(1, 1, b));
      const double fn = q.fn, kn = q.kn, ks = q.ks, a0 = q.a0;
      const Vec3 fs = q.fs;
      r.f = q.f;
      r.c = q.c;
      r.arm[0] = q.arm_i;
      r.arm[1] = q.arm_j;
      const double fs2 = norm2(fs);
      // Bond force / strength (T R^2, C R^2; K_n R for bonds that never break).
      const double r_min = std::min(ri, rj);
      // (x + 0 and 1 x are exact: the same bits as choosing with a branch.)
      const double sn = T_ref * r_min * r_min + T_none * (kn * r_min), ss = C_ref * r_min * r_min + C_none * (kn * r_min);
      r.ratio2 = std::max(fn * fn / (sn * sn), fs2 / (ss * ss));
      r.plastic = 0;
      r.elastic = 0;
      if constexpr (decltype(energy)::value) {
        // The shear spring acting on a0 P_t dd is a0 K_s (Yade's incident-velocity factor).
        const double shear_energy = 0.5 * fs2 / (a0 * ks);
        r.elastic = 0.5 * fn * fn / kn + (ks > 0 ? shear_energy : 0.0);
      }
    };
    system.for_each_contact(kernel, decltype(energy)::value, false,
                            [&](std::size_t chunk, std::size_t m, ContactRange ahead) {
                              RecordEnds::prefetch(records, second, ahead);
                              ends.fill(records, first, second, chunk, m);
                            });
  };
  if (evaluate_energy)
    contacts(std::true_type{});
  else
    contacts(std::false_type{});
}

}  // namespace mesowave::dem
