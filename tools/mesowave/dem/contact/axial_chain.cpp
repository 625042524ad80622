#include "mesowave/dem/contact/axial_chain.hpp"

#include <algorithm>
#include <cmath>

namespace mesowave::dem {
namespace {

inline double damped(double a, double v, double dt, double alpha) {
  const double p = a * (v + 0.5 * dt * a);
  return a * (1.0 - alpha * double((p > 0) - (p < 0)));
}

// The chain is one process's model: a rank's part is refused before anything is built.
SphereSet one_process_set(SpherePart&& spheres) {
  if (spheres.domain()) refuse_ranks("chain");
  return std::move(spheres).take_own();
}

}  // namespace

AxialChain::AxialChain(SpherePart spheres, const BondNetwork& bonds, const CohesiveFrictionalMaterial& material,
                       const Vec3& axis)
    : spheres_(one_process_set(std::move(spheres))), material_(material), axis_((1.0 / norm(axis)) * axis),
      first_(bonds.first), second_(bonds.second) {
  const std::size_t n = spheres_.size();
  kn_.resize(first_.size());
  inv_strength_.resize(first_.size());
  for (std::size_t b = 0; b < first_.size(); ++b) {
    const double ri = spheres_.radius_m[first_[b]], rj = spheres_.radius_m[second_[b]];
    kn_[b] = normal_stiffness(material_, ri, rj);
    const double strength = tensile_bond_strength(material_, ri, rj);
    inv_strength_[b] = std::isinf(strength) ? 0.0 : 1.0 / strength;
  }
  s_.assign(n, 0);
  v_.assign(n, 0);
  a_.assign(n, 0);
  a_undamped_.assign(n, 0);
  f_.assign(n, 0);
  f_ext_.assign(n, 0);
  inv_mass_.resize(n);
  for (std::size_t k = 0; k < n; ++k) inv_mass_[k] = 1.0 / spheres_.mass_kg[k];
}

void AxialChain::add_external_force(std::size_t k, const Vec3& force) {
  if (f_ext_[k] == 0 && std::find(forced_.begin(), forced_.end(), k) == forced_.end()) forced_.push_back(std::uint32_t(k));
  f_ext_[k] += dot(force, axis_);
}

double AxialChain::impose_displacement(std::size_t k, const Vec3& e, double u_now, double u_next, double dt) {
  const double along = dot(e, axis_);  // +-1 for an axial actuator
  const double v_imposed = along * (u_next - u_now) / dt;
  const double v_before = v_[k] - dt * a_[k];
  const double a_imposed = (v_imposed - v_before) / dt;
  // A constrained degree of freedom is not damped (Yade: blocked DOFs skip the integrator).
  const double force = spheres_.mass_kg[k] * (a_imposed - a_undamped_[k]);
  energy_.external_work_J += force * (v_before + v_imposed) * 0.5 * dt;
  s_[k] = along * u_next;
  v_[k] = v_imposed;
  a_[k] = a_imposed;
  return along * force;
}

void AxialChain::step(double dt, bool evaluate_energy) {
  const std::size_t n = s_.size(), m = first_.size();
  forced_v_before_.resize(forced_.size());
  for (std::size_t i = 0; i < forced_.size(); ++i) forced_v_before_[i] = v_[forced_[i]];
  std::copy(f_ext_.begin(), f_ext_.end(), f_.begin());
  double elastic = 0, peak = peak_ratio_;
  for (std::size_t b = 0; b < m; ++b) {
    const std::uint32_t i = first_[b], j = second_[b];
    const double ds = s_[j] - s_[i];
    const double fn = kn_[b] * ds;  // = -F_n: tension positive
    f_[i] += fn;
    f_[j] -= fn;
    peak = std::max(peak, std::abs(fn) * inv_strength_[b]);
    if (evaluate_energy) elastic += 0.5 * fn * ds;
  }
  const double alpha = material_.damping;
  double kinetic = 0, damping = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double a_free = f_[k] * inv_mass_[k];
    const double a = alpha != 0 ? damped(a_free, v_[k], dt, alpha) : a_free;
    const double v1 = v_[k] + dt * a;
    if (alpha != 0) damping += spheres_.mass_kg[k] * (a_free - a) * (v_[k] + v1) * 0.5 * dt;
    if (evaluate_energy) kinetic += 0.5 * spheres_.mass_kg[k] * v_[k] * v1;
    v_[k] = v1;
    a_[k] = a;
    a_undamped_[k] = a_free;
    s_[k] += dt * v1;
  }
  for (std::size_t i = 0; i < forced_.size(); ++i) {
    const std::uint32_t k = forced_[i];
    energy_.external_work_J += f_ext_[k] * (forced_v_before_[i] + v_[k]) * 0.5 * dt;
    f_ext_[k] = 0;
  }
  forced_.clear();
  peak_ratio_ = peak;
  energy_.damping_J += damping;
  if (evaluate_energy) {
    energy_.kinetic_J = kinetic;
    energy_.elastic_J = elastic;
  }
}

bool AxialChain::has_non_finite_state() const {
  for (std::size_t k = 0; k < s_.size(); ++k)
    if (!std::isfinite(s_[k] + v_[k])) return true;
  return false;
}

void AxialChain::scaled_stiffness_action(const double* x, double* y) const {
  const std::size_t n = s_.size();
  std::fill(y, y + n, 0.0);
  for (std::size_t b = 0; b < first_.size(); ++b) {
    const std::uint32_t i = first_[b], j = second_[b];
    const double si = 1.0 / std::sqrt(spheres_.mass_kg[i]), sj = 1.0 / std::sqrt(spheres_.mass_kg[j]);
    const double ds = sj * x[j] - si * x[i];
    y[i] -= si * kn_[b] * ds;
    y[j] += sj * kn_[b] * ds;
  }
}

double AxialChain::scaled_stiffness_row_sum_bound() const {
  std::vector<double> row(s_.size(), 0.0);
  for (std::size_t b = 0; b < first_.size(); ++b) {
    const std::uint32_t i = first_[b], j = second_[b];
    const double mi = spheres_.mass_kg[i], mj = spheres_.mass_kg[j];
    row[i] += kn_[b] / mi + kn_[b] / std::sqrt(mi * mj);
    row[j] += kn_[b] / mj + kn_[b] / std::sqrt(mi * mj);
  }
  return row.empty() ? 0.0 : *std::max_element(row.begin(), row.end());
}

// Between steps the external forces are spent (f_ext_ zero, forced_ empty) and
// f_ is rewritten before it is read: the motion, the peak ratio and the
// energies carry over.
void AxialChain::save_state(StateGroup& group) const {
  group.write("s", s_);
  group.write("v", v_);
  group.write("a", a_);
  group.write("a_undamped", a_undamped_);
  group.write("peak_ratio", peak_ratio_);
  group.write("kinetic_J", energy_.kinetic_J);
  group.write("elastic_J", energy_.elastic_J);
  group.write("external_work_J", energy_.external_work_J);
  group.write("damping_J", energy_.damping_J);
}

void AxialChain::load_state(const StateGroup& group) {
  group.read_into("s", s_);
  group.read_into("v", v_);
  group.read_into("a", a_);
  group.read_into("a_undamped", a_undamped_);
  peak_ratio_ = group.read_double("peak_ratio");
  energy_.kinetic_J = group.read_double("kinetic_J");
  energy_.elastic_J = group.read_double("elastic_J");
  energy_.external_work_J = group.read_double("external_work_J");
  energy_.damping_J = group.read_double("damping_J");
}

std::size_t AxialChain::memory_bytes() const {
  return s_.size() * (6 * sizeof(double) + sizeof(Vec3) + 3 * sizeof(double)) +
         first_.size() * (2 * sizeof(std::uint32_t) + 2 * sizeof(double));
}

}  // namespace mesowave::dem
