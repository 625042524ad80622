#include "mesowave/dem/sphere_system.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>

namespace mesowave::dem {
namespace {

// Eq. (7) as Yade's NewtonIntegrator::cundallDamp2nd applies it.
inline double damped(double a, double v, double dt, double alpha) {
  const double p = a * (v + 0.5 * dt * a);
  return a * (1.0 - alpha * double((p > 0) - (p < 0)));
}

// The symmetric linearisation of a bond at step 0 (for the critical time
// step): F_j = -K_n (n.dd) n - K_s' [P_t dd - (k_i th_i + k_j th_j) x n],
// torques -k_i n x F_j and -k_j n x F_j, with Yade's kinematic branches
// k = r dist0 / (r_i + r_j) and K_s' = K_s (r_i + r_j) / dist0.
struct LinearBond {
  Vec3 n;
  double kn, ks, ki, kj;
  void forces(const Vec3& di, const Vec3& ti, const Vec3& dj, const Vec3& tj, Vec3& fi, Vec3& mi, Vec3& fj,
              Vec3& mj) const {
    const Vec3 dd = dj - di;
    const double dn = dot(n, dd);
    const Vec3 st = (dd - dn * n) - cross(ki * ti + kj * tj, n);
    fj = -(kn * dn) * n - ks * st;
    fi = -fj;
    const Vec3 c = cross(n, fj);
    mi = -ki * c;
    mj = -kj * c;
  }
};

LinearBond linear_bond(const SphereSet& s, const BondNetwork& b, const CohesiveFrictionalMaterial& m, std::size_t k) {
  const double ri = s.radius_m[b.first[k]], rj = s.radius_m[b.second[k]];
  const double dist0 = ri + rj - b.overlap0_m[k];
  const double alpha = (ri + rj) / dist0;
  return {b.normal0[k], normal_stiffness(m, ri, rj), alpha * shear_stiffness(m, ri, rj), ri / alpha, rj / alpha};
}

}  // namespace

SphereSystem::SphereSystem(SphereSet spheres, BondNetwork bonds, const CohesiveFrictionalMaterial& material,
                           bool displacement_state, bool track_rotation)
    : spheres_(std::move(spheres)), bonds_(std::move(bonds)), material_(material),
      displacement_state_(displacement_state), track_rotation_(track_rotation) {
  const std::size_t n = spheres_.size();
  x_ = displacement_state_ ? std::vector<Vec3>(n) : spheres_.centre_m;
  v_.assign(n, {});
  w_.assign(n, {});
  a_.assign(n, {});
  f_ext_.assign(n, {});
  if (track_rotation_) theta_.assign(n, {});
  inv_mass_.resize(n);
  inv_inertia_.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    inv_mass_[k] = 1.0 / spheres_.mass_kg[k];
    inv_inertia_[k] = 1.0 / spheres_.inertia_kg_m2[k];
  }
  is_forced_.assign(n, 0);
  constrained_.assign(n, 0);
  a_undamped_.assign(n, {});
  const std::size_t sphere_blocks = (n + kSphereBlock - 1) / kSphereBlock;
  sphere_block_kinetic_.assign(sphere_blocks, 0);
  sphere_block_damping_.assign(sphere_blocks, 0);
  sphere_block_vmax2_.assign(sphere_blocks, 0);
  f_acc_.assign(n, {});
  t_acc_.assign(n, {});
  threads_ = omp_get_max_threads();
  // A fixed number of Morton ranges, set by the sphere count alone (never by
  // the thread count, which must not change the bits): ~1000 spheres each.
  partitions_ = std::clamp<std::size_t>(n / 1024, 1, 64);
  sphere_chunk_ = (n + partitions_ - 1) / partitions_;
  first_ = bonds_.first;
  second_ = bonds_.second;
}

std::vector<std::uint32_t> SphereSystem::set_contacts(const std::vector<std::uint32_t>& first,
                                                      const std::vector<std::uint32_t>& second) {
  const std::size_t count = first.size(), n = spheres_.size();
  std::vector<std::uint32_t> order;
  order.reserve(count);
  interior_start_.assign(partitions_ + 1, 0);
  for (std::size_t c = 0; c < count; ++c) {
    const std::size_t p = first[c] / sphere_chunk_;
    if (p == second[c] / sphere_chunk_) ++interior_start_[p + 1];
  }
  for (std::size_t p = 0; p < partitions_; ++p) interior_start_[p + 1] += interior_start_[p];
  order.resize(count);
  std::vector<std::uint32_t> fill(interior_start_.begin(), interior_start_.end() - 1);
  cross_begin_ = interior_start_[partitions_];
  std::size_t cross = cross_begin_;
  for (std::size_t c = 0; c < count; ++c) {
    const std::size_t p = first[c] / sphere_chunk_;
    order[p == second[c] / sphere_chunk_ ? fill[p]++ : cross++] = std::uint32_t(c);
  }
  first_.resize(count);
  second_.resize(count);
  for (std::size_t s = 0; s < count; ++s) {
    first_[s] = first[order[s]];
    second_[s] = second[order[s]];
  }
  const std::vector<std::uint32_t> cross_first(first_.begin() + std::ptrdiff_t(cross_begin_), first_.end());
  const std::vector<std::uint32_t> cross_second(second_.begin() + std::ptrdiff_t(cross_begin_), second_.end());
  cross_incidence_ = make_incidence(n, cross_first, cross_second);
  out_.assign(count - cross_begin_, ContactOut{});
  cross_blocks_ = (count - cross_begin_ + kContactBlock - 1) / kContactBlock;
  const std::size_t tasks = partitions_ + cross_blocks_;
  // Dissipation is cumulative: keep what the old tasks held.
  double plastic = 0;
  for (double p : task_plastic_) plastic += p;
  task_elastic_.assign(tasks, 0);
  task_plastic_.assign(tasks, 0);
  task_plastic_[0] = plastic;
  task_peak2_.assign(tasks, 0);
  // A parallel region costs a few microseconds: worth it only for big systems.
  parallel_ = threads_ > 1 && count >= 8 * kContactBlock && partitions_ > 1;
  return order;
}

Vec3 SphereSystem::displacement(std::size_t k) const {
  return displacement_state_ ? x_[k] : x_[k] - spheres_.centre_m[k];
}

void SphereSystem::add_external_force(std::size_t k, const Vec3& force) {
  if (!is_forced_[k]) {
    is_forced_[k] = 1;
    forced_.push_back(std::uint32_t(k));
  }
  f_ext_[k] += force;
}

double SphereSystem::impose_displacement(std::size_t k, const Vec3& e, double u_now, double u_next, double dt) {
  const double v_imposed = (u_next - u_now) / dt;
  const double v_before = dot(v_[k], e) - dt * dot(a_[k], e);  // v_{n-1/2} along e
  // A constrained degree of freedom is not damped (Yade: blocked DOFs skip the
  // integrator); its force balance uses the undamped F/m of this step.
  const double a_free = constrained_[k] ? dot(a_undamped_[k], e) : dot(a_[k], e);
  constrained_[k] = 1;
  const double a_imposed = (v_imposed - v_before) / dt;
  x_[k] += (u_next - dot(displacement(k), e)) * e;
  v_[k] += (v_imposed - dot(v_[k], e)) * e;
  a_[k] += (a_imposed - a_free) * e;
  // The constraint force m (a_imposed - a_free) does work over the step.
  const double force = spheres_.mass_kg[k] * (a_imposed - a_free);
  energy_.external_work_J += force * (v_before + v_imposed) * 0.5 * dt;
  return force;
}

void SphereSystem::step(double dt, bool evaluate_energy) {
  forced_v_before_.resize(forced_.size());
  for (std::size_t i = 0; i < forced_.size(); ++i) forced_v_before_[i] = v_[forced_[i]];

#pragma omp parallel if (parallel_)
  {
    contact_forces(dt, evaluate_energy);  // ends with the implicit barrier of its omp for
    integrate(dt, evaluate_energy);
  }

  for (std::size_t i = 0; i < forced_.size(); ++i) {
    const std::uint32_t k = forced_[i];
    energy_.external_work_J += dot(f_ext_[k], forced_v_before_[i] + v_[k]) * 0.5 * dt;
    f_ext_[k] = {};
    is_forced_[k] = 0;
  }
  forced_.clear();

  double peak2 = 0, vmax2 = 0;
  for (double p : task_peak2_) peak2 = std::max(peak2, p);
  for (double v2 : sphere_block_vmax2_) vmax2 = std::max(vmax2, v2);
  peak_ratio_ = std::max(peak_ratio_, std::sqrt(peak2));
  max_speed_ = std::sqrt(vmax2);
  if (evaluate_energy) {
    double kinetic = 0, elastic = 0;
    for (double e : sphere_block_kinetic_) kinetic += e;
    for (double e : task_elastic_) elastic += e;
    energy_.kinetic_J = kinetic;
    energy_.elastic_J = elastic;
  }
  after_step(dt);
}

void SphereSystem::integrate(double dt, bool evaluate_energy) {
  const double alpha = material_.damping;
  const std::size_t n = spheres_.size();
  const std::size_t blocks = (n + kSphereBlock - 1) / kSphereBlock;
  const std::uint32_t* offset = cross_incidence_.offset.data();
  const std::uint32_t* entry = cross_incidence_.entry.data();
  const ContactOut* out = out_.data();
  const double* mass = spheres_.mass_kg.data();
  const double* inertia = spheres_.inertia_kg_m2.data();

#pragma omp for schedule(static)
  for (std::size_t blk = 0; blk < blocks; ++blk) {
    double kinetic = 0, damping = 0, vmax2 = 0;
    const std::size_t end = std::min(n, (blk + 1) * kSphereBlock);
    for (std::size_t k = blk * kSphereBlock; k < end; ++k) {
      // Fixed order: contacts inside the partition (summed in slot order by
      // for_each_contact), then those across partitions, then external loads.
      Vec3 f = f_acc_[k], t = t_acc_[k];
      f_acc_[k] = {};
      t_acc_[k] = {};
      for (std::uint32_t e = offset[k]; e < offset[k + 1]; ++e) {
        const std::uint32_t code = entry[e];
        const ContactOut& o = out[code >> 1];
        const unsigned side = code & 1u;
        const double sign = side ? 1.0 : -1.0;
        f += sign * o.f;
        t -= o.arm[side] * o.c;
      }
      f += f_ext_[k];
      // Translation.
      const Vec3 a_free = inv_mass_[k] * f;
      const Vec3 v0 = v_[k];
      Vec3 a = a_free;
      if (alpha != 0) {
        a = {damped(a.x, v0.x, dt, alpha), damped(a.y, v0.y, dt, alpha), damped(a.z, v0.z, dt, alpha)};
        damping += mass[k] * dot(a_free - a, v0 + (v0 + dt * a)) * 0.5 * dt;
      }
      const Vec3 v1 = v0 + dt * a;
      if (evaluate_energy) kinetic += 0.5 * mass[k] * dot(v0, v1);
      vmax2 = std::max(vmax2, norm2(v1));
      v_[k] = v1;
      a_[k] = a;
      x_[k] += dt * v1;
      if (constrained_[k]) a_undamped_[k] = a_free;
      // Rotation (spheres: scalar inertia).
      const Vec3 b_free = inv_inertia_[k] * t;
      const Vec3 w0 = w_[k];
      Vec3 b = b_free;
      if (alpha != 0) {
        b = {damped(b.x, w0.x, dt, alpha), damped(b.y, w0.y, dt, alpha), damped(b.z, w0.z, dt, alpha)};
        damping += inertia[k] * dot(b_free - b, w0 + (w0 + dt * b)) * 0.5 * dt;
      }
      const Vec3 w1 = w0 + dt * b;
      if (evaluate_energy) kinetic += 0.5 * inertia[k] * dot(w0, w1);
      w_[k] = w1;
      if (track_rotation_) theta_[k] += dt * w1;
    }
    sphere_block_kinetic_[blk] = kinetic;
    sphere_block_damping_[blk] += damping;
    sphere_block_vmax2_[blk] = vmax2;
  }
}

EnergyAccount SphereSystem::energy() const {
  EnergyAccount e = energy_;
  e.damping_J = 0;
  for (double d : sphere_block_damping_) e.damping_J += d;
  e.plastic_J = 0;
  for (double p : task_plastic_) e.plastic_J += p;
  return e;
}

bool SphereSystem::has_non_finite_state() const {
  for (std::size_t k = 0; k < x_.size(); ++k)
    if (!std::isfinite(x_[k].x + x_[k].y + x_[k].z + v_[k].x + v_[k].y + v_[k].z + w_[k].x + w_[k].y + w_[k].z))
      return true;
  return false;
}

void SphereSystem::scaled_stiffness_action(const double* x, double* y) const {
  const std::size_t n = spheres_.size();
  std::fill(y, y + 6 * n, 0.0);
  auto dof = [&](const double* v, std::size_t k, int part) {
    const double s = 1.0 / std::sqrt(part == 0 ? spheres_.mass_kg[k] : spheres_.inertia_kg_m2[k]);
    return Vec3{s * v[6 * k + 3 * part], s * v[6 * k + 3 * part + 1], s * v[6 * k + 3 * part + 2]};
  };
  auto add = [&](std::size_t k, int part, const Vec3& g) {
    const double s = 1.0 / std::sqrt(part == 0 ? spheres_.mass_kg[k] : spheres_.inertia_kg_m2[k]);
    for (int d = 0; d < 3; ++d) y[6 * k + 3 * part + d] -= s * g[d];  // K x = -(force)
  };
  for (std::size_t b = 0; b < bonds_.size(); ++b) {
    const LinearBond lb = linear_bond(spheres_, bonds_, material_, b);
    const std::size_t i = bonds_.first[b], j = bonds_.second[b];
    Vec3 fi, mi, fj, mj;
    lb.forces(dof(x, i, 0), dof(x, i, 1), dof(x, j, 0), dof(x, j, 1), fi, mi, fj, mj);
    add(i, 0, fi);
    add(i, 1, mi);
    add(j, 0, fj);
    add(j, 1, mj);
  }
}

double SphereSystem::scaled_stiffness_row_sum_bound() const {
  const std::size_t n = spheres_.size();
  std::vector<double> row(6 * n, 0.0);
  for (std::size_t b = 0; b < bonds_.size(); ++b) {
    const LinearBond lb = linear_bond(spheres_, bonds_, material_, b);
    const std::size_t ends[2] = {bonds_.first[b], bonds_.second[b]};
    double scale[12];
    for (int c = 0; c < 12; ++c) {
      const std::size_t k = ends[c / 6];
      scale[c] = 1.0 / std::sqrt((c % 6) < 3 ? spheres_.mass_kg[k] : spheres_.inertia_kg_m2[k]);
    }
    for (int c = 0; c < 12; ++c) {  // column c of the bond's 12 x 12 block
      Vec3 u[4] = {};
      u[c / 3][c % 3] = 1.0;
      Vec3 g[4];
      lb.forces(u[0], u[1], u[2], u[3], g[0], g[1], g[2], g[3]);
      for (int r = 0; r < 12; ++r) {
        const double entry = -g[r / 3][r % 3];
        row[6 * ends[r / 6] + (r % 6)] += std::abs(entry) * scale[r] * scale[c];
      }
    }
  }
  return row.empty() ? 0.0 : *std::max_element(row.begin(), row.end());
}

std::size_t SphereSystem::memory_bytes() const {
  const std::size_t n = spheres_.size();
  std::size_t bytes = n * (sizeof(Vec3) * (6 + (track_rotation_ ? 1 : 0)) + 3 * sizeof(double) + 2 * sizeof(double) +
                           sizeof(std::uint32_t) + sizeof(std::int64_t) + 1);
  bytes += bonds_.size() * (2 * sizeof(std::uint32_t) + sizeof(double) + sizeof(Vec3) + 2 * sizeof(std::uint32_t));
  bytes += out_.size() * sizeof(ContactOut) + cross_incidence_.entry.size() * sizeof(std::uint32_t) +
           first_.size() * 2 * sizeof(std::uint32_t) + 2 * n * sizeof(Vec3);
  return bytes;
}

}  // namespace mesowave::dem
