#include "mesowave/efg/explicit_dynamics.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "mesowave/core/check.hpp"
#include "mesowave/core/lanczos.hpp"
#include "mesowave/core/threads.hpp"
#include "mesowave/efg/hugoniot.hpp"
#include "mesowave/efg/node_grid.hpp"

namespace mesowave::efg {

namespace {

std::string point_text(const Vec2& x) {
  return "(" + format_number(x.x()) + ", " + format_number(x.y()) + ") m";
}

constexpr std::int64_t block_nodes = 512;  // the energies' fixed partial sums: independent of the thread count

}  // namespace

void BulkViscosity::validate() const {
  if (!std::isfinite(quadratic) || quadratic < 0)
    throw InputError("bulk viscosity C_0 (quadratic, " + format_number(quadratic) + ") must be >= 0 and finite");
  if (!std::isfinite(linear) || linear < 0)
    throw InputError("bulk viscosity C_1 (linear, " + format_number(linear) + ") must be >= 0 and finite");
}

double bulk_viscosity_pressure_Pa(double rho, double l, double c, double eps_dot_v, const BulkViscosity& q) {
  if (!(eps_dot_v < 0)) return 0.0;  // only in compression
  return rho * l * (q.quadratic * l * eps_dot_v * eps_dot_v - q.linear * c * eps_dot_v);
}

double bulk_viscosity_step_factor(double l, double c, double eps_dot_v, const BulkViscosity& q) {
  if (!(eps_dot_v < 0)) return 1.0;
  const double xi = q.linear + q.quadratic * l * std::abs(eps_dot_v) / c;  // Q / c
  return 1.0 / (xi + std::sqrt(1.0 + xi * xi));  // = sqrt(1 + xi^2) - xi, without the cancellation
}

Eigen::VectorXd lumped_mass(const ElasticModel& model) {
  const double rho = model.material().density_kg_m3, t = model.material().thickness_m;
  require_positive("density (explicit dynamics)", rho, "kg/m3");
  const auto& points = model.discretisation().points;
  const auto& shape = model.shape_functions();
  Eigen::VectorXd m = Eigen::VectorXd::Zero(Eigen::Index(model.mls().node_count()));
  for (std::size_t p = 0; p < shape.size(); ++p) {  // row sums: int rho phi_I (sum_J phi_J = 1) t dA
    const double w = rho * t * points[p].weight_m2;
    for (std::size_t a = 0; a < shape[p].nodes.size(); ++a) m[shape[p].nodes[a]] += w * shape[p].phi[a];
  }
  for (Eigen::Index i = 0; i < m.size(); ++i)
    if (!(m[i] > 0))
      throw InputError("the lumped mass (row sum of the consistent MLS mass) of node " + std::to_string(i) + " at " +
                       point_text(model.mls().nodes()[std::size_t(i)]) + " is " + format_quantity(m[i], "kg") +
                       ": not positive (its shape function is mostly negative; use a larger support or a regular grid)");
  return m;
}

StableStep stable_step(const ElasticModel& model, const Eigen::VectorXd& mass, const ConstraintSet* constraints,
                       const Eigen::SparseMatrix<double>* extra_stiffness) {
  Eigen::SparseMatrix<double> K = model.stiffness();
  if (extra_stiffness) K += *extra_stiffness;
  const auto n = Eigen::Index(model.dof_count());
  Eigen::VectorXd inv_sqrt_m(n);
  for (Eigen::Index i = 0; i < n; ++i) inv_sqrt_m[i] = 1.0 / std::sqrt(mass[i / 2]);
  Eigen::SparseMatrix<double> G;  // C M^-1/2
  Eigen::LLT<Eigen::MatrixXd> S;  // of G G^T
  const bool constrained = constraints && constraints->C().rows() > 0;
  if (constrained) {
    G = constraints->C() * inv_sqrt_m.asDiagonal();
    S.compute(Eigen::MatrixXd(G * G.transpose()));
  }
  const auto run = [&](bool project) {
    const auto Q = [&](Eigen::VectorXd& y) {
      if (project) y -= G.transpose() * S.solve(Eigen::VectorXd(G * y));
    };
    return largest_eigenvalue(
        std::size_t(n),
        [&](const double* x, double* y) {
          Eigen::VectorXd z = Eigen::Map<const Eigen::VectorXd>(x, n);
          Q(z);
          Eigen::VectorXd k = K * Eigen::VectorXd(inv_sqrt_m.cwiseProduct(z));
          k = inv_sqrt_m.cwiseProduct(k);
          Q(k);
          Eigen::Map<Eigen::VectorXd>(y, n) = k;
        },
        400, 1e-9);
  };
  StableStep s;
  const LanczosResult free = run(false);
  s.omega_free_rad_s = std::sqrt(std::max(0.0, free.ritz + free.residual));
  const LanczosResult c = constrained ? run(true) : free;
  s.omega_max_rad_s = std::sqrt(std::max(0.0, c.ritz + c.residual));
  s.iterations = c.iterations;
  s.dt_critical_s = s.omega_max_rad_s > 0 ? 2.0 / s.omega_max_rad_s : std::numeric_limits<double>::infinity();
  s.method = std::string("2 / omega_max, omega_max^2 = Lanczos top Ritz value + residual of M^-1/2 K M^-1/2") +
             (constrained ? " on the constrained space (C M^-1/2 y = 0)" : "");
  return s;
}

ExplicitDynamics::ExplicitDynamics(const ElasticModel& model, const PointMaterial& material,
                                   const ConstraintSet* constraints, std::vector<PressureLoad> loads)
    : model_(&model), material_(&material), constraints_(constraints), loads_(std::move(loads)) {
  mass_ = lumped_mass(model);
  const auto n = Eigen::Index(model.dof_count());
  inv_mass_dof_.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) inv_mass_dof_[i] = 1.0 / mass_[i / 2];
  for (const PressureLoad& l : loads_) {
    if (!l.pressure) throw InputError("pressure load '" + l.name + "' has no history");
    unit_loads_.push_back(unit_pressure_load(model, l.edge));
  }
  if (constraints_ && constraints_->C().rows() > 0) {
    C_ = constraints_->C();
    const Eigen::SparseMatrix<double> CMC = constraints_->C() * inv_mass_dof_.asDiagonal() * constraints_->C().transpose();
    schur_.compute(Eigen::MatrixXd(CMC));
    if (schur_.info() != Eigen::Success)
      throw InputError("C M^-1 C^T of the " + std::to_string(C_.rows()) + " constraint rows is not positive definite");
  }
  stable_ = stable_step(model, mass_, constraints_);

  gather_ = build_gather(model.shape_functions(), model.mls().node_count());
  gather_version_ = crack_version();
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const Rect& c : model.discretisation().cells)
    x0 = std::min(x0, c.x0), x1 = std::max(x1, c.x1), y0 = std::min(y0, c.y0), y1 = std::max(y1, c.y1);
  body_diagonal_m_ = std::hypot(x1 - x0, y1 - y0);
  const auto& cells = model.discretisation().cells;
  for (const GaussPoint& g : model.discretisation().points) {
    const Rect& c = cells[std::size_t(g.cell)];
    point_length_m_.push_back(std::sqrt((c.x1 - c.x0) * (c.y1 - c.y0)));
  }
  c0_m_s_ = std::sqrt(model.material().D()(0, 0) / model.material().density_kg_m3);
}

double ExplicitDynamics::point_viscous_pressure(std::size_t p, const PointState& st, const BulkViscosity& q,
                                                double* step_factor) const {
  const double eps_dot_v = volumetric_strain(st.strain_rate_1_s, model_->material());  // linear in the rate
  const double c = c0_m_s_ * std::sqrt(std::max(0.0, st.modulus_scale));
  const double l = point_length_m_[p];
  if (step_factor) *step_factor = bulk_viscosity_step_factor(l, c, eps_dot_v, q);
  return bulk_viscosity_pressure_Pa(model_->material().density_kg_m3, l, c, eps_dot_v, q);
}

std::vector<double> ExplicitDynamics::bulk_viscosity_pressures(const std::vector<PointState>& states,
                                                               const BulkViscosity& q) const {
  q.validate();
  if (states.size() != point_length_m_.size())
    throw InputError("bulk viscosity: " + std::to_string(states.size()) + " point states for " +
                     std::to_string(point_length_m_.size()) + " Gauss points");
  std::vector<double> out(states.size());
  for (std::size_t p = 0; p < states.size(); ++p) out[p] = point_viscous_pressure(p, states[p], q, nullptr);
  return out;
}

Eigen::VectorXd ExplicitDynamics::external_force(double t_s) const {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(Eigen::Index(model_->dof_count()));
  for (std::size_t l = 0; l < loads_.size(); ++l) f += loads_[l].pressure(t_s) * unit_loads_[l];
  return f;
}

double ExplicitDynamics::point_forces(const Eigen::VectorXd& u, const Eigen::VectorXd* v, std::vector<PointState>& states,
                                      std::vector<Eigen::Vector3d>& s, int threads) const {
  const auto& shape = model_->shape_functions();
  const auto& points = model_->discretisation().points;
  const double t = model_->material().thickness_m;
  const auto np = std::int64_t(shape.size());
  double smax = 1.0;
#pragma omp parallel for num_threads(threads) schedule(static) reduction(max : smax)
  for (std::int64_t p = 0; p < np; ++p) {
    PointState& st = states[std::size_t(p)];
    st.strain_rate_1_s = v ? strain_of(shape[std::size_t(p)], *v) : Eigen::Vector3d::Zero();
    s[std::size_t(p)] = material_->update(strain_of(shape[std::size_t(p)], u), st) * (t * points[std::size_t(p)].weight_m2);
    smax = std::max(smax, st.modulus_scale);
  }
  return smax;
}

ExplicitDynamics::NodeGather ExplicitDynamics::build_gather(const std::vector<ShapeFunctions>& shape, std::size_t nodes) {
  NodeGather g;
  g.start.assign(nodes + 1, 0);
  for (const auto& sf : shape)
    for (std::int32_t i : sf.nodes) ++g.start[std::size_t(i) + 1];
  for (std::size_t i = 0; i < nodes; ++i) g.start[i + 1] += g.start[i];
  g.point.resize(std::size_t(g.start[nodes]));
  g.dphi_dx.resize(g.point.size());
  g.dphi_dy.resize(g.point.size());
  std::vector<std::int64_t> fill(g.start.begin(), g.start.end() - 1);
  for (std::size_t p = 0; p < shape.size(); ++p)  // ascending p within each node: the summation order
    for (std::size_t a = 0; a < shape[p].nodes.size(); ++a) {
      const auto k = std::size_t(fill[std::size_t(shape[p].nodes[a])]++);
      g.point[k] = std::int32_t(p);
      g.dphi_dx[k] = shape[p].dphi_dx[a];
      g.dphi_dy[k] = shape[p].dphi_dy[a];
    }
  return g;
}

Eigen::Vector2d ExplicitDynamics::node_internal_force(std::int64_t i, const std::vector<Eigen::Vector3d>& s) const {
  return node_internal_force(gather_, i, s);
}

Eigen::Vector2d ExplicitDynamics::node_internal_force(const NodeGather& g, std::int64_t i,
                                                      const std::vector<Eigen::Vector3d>& s) const {
  double fx = 0, fy = 0;
  for (auto k = std::size_t(g.start[std::size_t(i)]); k < std::size_t(g.start[std::size_t(i) + 1]); ++k) {
    const Eigen::Vector3d& sp = s[std::size_t(g.point[k])];
    fx += g.dphi_dx[k] * sp[0] + g.dphi_dy[k] * sp[2];
    fy += g.dphi_dy[k] * sp[1] + g.dphi_dx[k] * sp[2];
  }
  return {fx, fy};
}

Eigen::Vector2d ExplicitDynamics::node_viscous_force(const NodeGather& g, std::int64_t i, const std::vector<double>& qwt) const {
  double fx = 0, fy = 0;  // B^T (-q, -q, 0) w t
  for (auto k = std::size_t(g.start[std::size_t(i)]); k < std::size_t(g.start[std::size_t(i) + 1]); ++k) {
    const double q = qwt[std::size_t(g.point[k])];
    fx -= g.dphi_dx[k] * q;
    fy -= g.dphi_dy[k] * q;
  }
  return {fx, fy};
}

Eigen::VectorXd ExplicitDynamics::internal_force(const Eigen::VectorXd& u, std::vector<PointState>& states) const {
  return internal_force_with(u, nullptr, states);
}

Eigen::VectorXd ExplicitDynamics::internal_force(const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                                                 std::vector<PointState>& states) const {
  return internal_force_with(u, &v, states);
}

Eigen::VectorXd ExplicitDynamics::internal_force_with(const Eigen::VectorXd& u, const Eigen::VectorXd* v,
                                                      std::vector<PointState>& states) const {
  const std::size_t np = model_->shape_functions().size();
  if (states.size() != np) states.assign(np, PointState{});
  std::vector<Eigen::Vector3d> s(np);
  const int nt = region_threads(np, 2000);
  point_forces(u, v, states, s, nt);
  Eigen::VectorXd f(Eigen::Index(model_->dof_count()));
  const auto nn = std::int64_t(model_->mls().node_count());
  NodeGather now;  // the cracks changed since construction: the gather of the current shape functions
  const NodeGather* g = &gather_;
  if (crack_version() != gather_version_) g = &(now = build_gather(model_->shape_functions(), std::size_t(nn)));
#pragma omp parallel for num_threads(nt) schedule(static)
  for (std::int64_t i = 0; i < nn; ++i) f.segment<2>(2 * i) = node_internal_force(*g, i, s);
  return f;
}

DynamicsResult ExplicitDynamics::run(const DynamicsOptions& o, const std::vector<Sensor>& sensors) const {
  require_positive("duration", o.duration_s, "s");
  if (!std::isfinite(o.dt_s) || o.dt_s < 0) throw InputError("time step (" + format_quantity(o.dt_s, "s") + ") must be >= 0 (0: from the stable step)");
  if (!std::isfinite(o.dt_fraction) || o.dt_fraction <= 0 || o.dt_fraction > 1)
    throw InputError("time step fraction (" + format_number(o.dt_fraction) + ") must lie in (0, 1]");
  if (!std::isfinite(o.alpha_damping_per_s) || o.alpha_damping_per_s < 0)
    throw InputError("damping alpha (" + format_number(o.alpha_damping_per_s) + " 1/s) must be >= 0 and finite");
  if (o.stiffness_check_every < 1) throw InputError("stiffness check interval (" + std::to_string(o.stiffness_check_every) + " steps) must be >= 1");
  if (o.sample_stride < 1) throw InputError("sample stride (" + std::to_string(o.sample_stride) + ") must be >= 1");
  if (o.snapshot_stride < 0) throw InputError("snapshot stride (" + std::to_string(o.snapshot_stride) + ") must be >= 0");
  if (!std::isfinite(o.displacement_bound_m) || o.displacement_bound_m < 0)
    throw InputError("displacement bound (" + format_quantity(o.displacement_bound_m, "m") + ") must be >= 0 (0: the body's diagonal)");
  o.viscosity.validate();
  const bool viscous = o.viscosity.on();
  DynamicsCracks* const cracks = o.cracks;
  if (cracks && C_.rows() > 0)
    throw InputError("growing cracks with " + std::to_string(C_.rows()) +
                     " constraint rows: not supported (the rows keep the shape functions of the start)");
  // with cracks, the stable step of K plus the faces' penalty stiffness (pre-placed cracks' too)
  StableStep stable = stable_;
  if (cracks) {
    const Eigen::SparseMatrix<double> Kc = cracks->stiffness_bound();
    stable = stable_step(*model_, mass_, constraints_, &Kc);
  }
  const double dt_crit = stable.dt_critical_s;
  if (o.dt_s > dt_crit && !o.allow_unstable)
    throw InputError("time step (" + format_quantity(o.dt_s * 1e6, "us") + ") exceeds the stable step 2/omega_max (" +
                     format_quantity(dt_crit * 1e6, "us") + ") of this model");
  double dt_base = o.dt_s > 0 ? o.dt_s : o.dt_fraction * dt_crit;
  const double bound = o.displacement_bound_m > 0 ? o.displacement_bound_m : body_diagonal_m_;

  const auto& shape = model_->shape_functions();
  const auto& points = model_->discretisation().points;
  const auto& nodes = model_->mls().nodes();
  const auto nn = std::int64_t(nodes.size());
  const auto ndof = Eigen::Index(2 * nn);
  const double alpha = o.alpha_damping_per_s;
  const int nt = region_threads(shape.size(), o.min_points_per_thread);
  const std::int64_t nblocks = (nn + block_nodes - 1) / block_nodes;

  std::vector<ShapeFunctions> sensor_sf;
  for (const Sensor& s : sensors) sensor_sf.push_back(model_->mls().evaluate(s.x, "sensor '" + s.name + "'"));
  std::vector<PointState> sensor_state(sensors.size()), states(shape.size());
  std::vector<ShapeFunctions> node_sf;
  std::vector<std::size_t> nearest_point;
  if (o.snapshot_stride > 0) {
    std::vector<Vec2> px;
    for (const GaussPoint& g : points) px.push_back(g.x);
    const NodeGrid grid(px, model_->discretisation().spacing_m);
    for (std::int64_t i = 0; i < nn; ++i) {
      const Vec2& x = nodes[std::size_t(i)];
      node_sf.push_back(model_->mls().evaluate(x, "node " + std::to_string(i)));
      double r = model_->discretisation().spacing_m;
      std::vector<std::int32_t> near = grid.within(x, r);
      while (near.empty()) near = grid.within(x, r *= 2);
      std::size_t best = std::size_t(near[0]);
      for (std::int32_t q : near)
        if ((px[std::size_t(q)] - x).squaredNorm() < (px[best] - x).squaredNorm()) best = std::size_t(q);
      nearest_point.push_back(best);
    }
  }

  DynamicsResult r;
  r.stable = stable;
  NodeGather gather_cracked;  // the gather lists after a crack changed the shape functions
  const NodeGather* gather = &gather_;
  if (crack_version() != gather_version_) {  // cracks placed after construction
    gather_cracked = build_gather(shape, std::size_t(nn));
    gather = &gather_cracked;
  }
  Eigen::VectorXd f_cracks;
  if (cracks) f_cracks = Eigen::VectorXd::Zero(ndof);
  bool recheck_step = false;
  double kinetic_jump = 0;  // the hook's changes of KE at fixed times (DynamicsCracks)
  if (cracks) cracks->start(mass_);
  r.threads = nt;
  r.dt_first_s = dt_base;
  r.dt_min_s = dt_base;
  r.sensors.resize(sensors.size());
  Eigen::VectorXd u = Eigen::VectorXd::Zero(ndof), v = Eigen::VectorXd::Zero(ndof), u_prev = u;
  Eigen::VectorXd f_int(ndof), f_ext(ndof), vs(ndof), f_visc;
  std::vector<Eigen::Vector3d> s(shape.size());
  std::vector<double> qwt;  // q_g w_g t per point (viscosity on)
  if (viscous) f_visc = Eigen::VectorXd::Zero(ndof), qwt.assign(shape.size(), 0.0);
  const auto nb = std::size_t(nblocks);
  std::vector<double> ke_b(nb), wi_b(nb), we_b(nb), wd_b(nb), wv_b(nb, 0.0);
  std::vector<std::int64_t> bad_b(nb);
  std::vector<double> p_now(loads_.size());
  double t = 0, dt_prev = 0, dt_half = dt_base, W_int = 0, W_ext = 0, W_damp = 0, W_visc = 0, worst = 0, scale_ref = 0;
  const double thickness = model_->material().thickness_m;
  const auto start = std::chrono::steady_clock::now();

  for (std::int64_t n = 0; t < o.duration_s; ++n) {
    // Stresses at the points from u^n, each point writing its own entry.
    const double smax = point_forces(u, &v, states, s, nt);  // v = v^{n-1/2}: the points' strain rates
    r.max_modulus_scale = std::max(r.max_modulus_scale, smax);
    double rmin = 1.0;  // the viscosity's step factor, smallest over the points
    if (viscous) {
      const auto np = std::int64_t(shape.size());
      double qmax = 0;
#pragma omp parallel for num_threads(nt) schedule(static) reduction(min : rmin) reduction(max : qmax)
      for (std::int64_t p = 0; p < np; ++p) {
        double rp = 1.0;
        const double q = point_viscous_pressure(std::size_t(p), states[std::size_t(p)], o.viscosity, &rp);
        qwt[std::size_t(p)] = q * points[std::size_t(p)].weight_m2 * thickness;
        rmin = std::min(rmin, rp);
        qmax = std::max(qmax, q);
      }
      r.max_viscous_pressure_Pa = std::max(r.max_viscous_pressure_Pa, qmax);
      r.min_viscous_step_factor = std::min(r.min_viscous_step_factor, rmin);
    }
    if (n % o.stiffness_check_every == 0 || recheck_step) {  // the stable step of the stiffened law
      recheck_step = false;
      dt_half = dt_base / std::sqrt(std::max(1.0, smax));
      if (viscous) dt_half *= rmin;
      r.dt_min_s = std::min(r.dt_min_s, dt_half);
    } else if (viscous) {  // between checks: only shrink, when the rates ask for it
      dt_half = std::min(dt_half, dt_base / std::sqrt(std::max(1.0, smax)) * rmin);
      r.dt_min_s = std::min(r.dt_min_s, dt_half);
    }
    const double dt_avg = n == 0 ? 0.5 * dt_half : 0.5 * (dt_prev + dt_half);
    const double c = 0.5 * alpha * dt_avg, keep = (1 - c) / (1 + c), gain = dt_avg / (1 + c);
    for (std::size_t l = 0; l < loads_.size(); ++l) p_now[l] = loads_[l].pressure(t);
    // Each node: f_int by its points in point order, f_ext, the unconstrained velocity.
#pragma omp parallel for num_threads(nt) schedule(static)
    for (std::int64_t i = 0; i < nn; ++i) {
      f_int.segment<2>(2 * i) = node_internal_force(*gather, i, s);
      if (viscous) f_visc.segment<2>(2 * i) = node_viscous_force(*gather, i, qwt);
      for (Eigen::Index d = 2 * i; d < 2 * i + 2; ++d) {
        double fe = 0;
        for (std::size_t l = 0; l < loads_.size(); ++l) fe += p_now[l] * unit_loads_[l][d];
        f_ext[d] = fe;
        if (viscous)
          vs[d] = keep * v[d] + gain * (fe - f_int[d] - f_visc[d]) * inv_mass_dof_[d];
        else
          vs[d] = keep * v[d] + gain * (fe - f_int[d]) * inv_mass_dof_[d];
      }
    }
    if (cracks) {  // the faces' cohesive tractions and contact: part of f_int
      f_cracks.setZero();
      cracks->add_forces(u, f_cracks);
      for (Eigen::Index d = 0; d < ndof; ++d) {
        f_int[d] += f_cracks[d];
        vs[d] -= gain * f_cracks[d] * inv_mass_dof_[d];
      }
    }
    if (C_.rows() > 0) {  // forward-increment multipliers: C u^{n+1} = d exactly
      const Eigen::VectorXd residual = (C_ * Eigen::VectorXd(u + dt_half * vs) - constraints_->d()) / dt_half;
      const Eigen::VectorXd lambda = schur_.solve(residual);
      vs -= inv_mass_dof_.cwiseProduct(Eigen::VectorXd(C_.transpose() * lambda));
    }
    // Energies (fixed blocks), u^{n+1}, the guard.
    u_prev = u;
#pragma omp parallel for num_threads(nt) schedule(static)
    for (std::int64_t b = 0; b < nblocks; ++b) {
      double ke = 0, wi = 0, we = 0, wd = 0, wv = 0;
      std::int64_t bad = -1;
      const Eigen::Index d1 = 2 * std::min(nn, (b + 1) * block_nodes);
      for (Eigen::Index d = 2 * b * block_nodes; d < d1; ++d) {
        const double m = mass_[d / 2], sum = 0.5 * dt_avg * (v[d] + vs[d]);
        ke += 0.5 * m * vs[d] * vs[d];
        wi += f_int[d] * sum;
        we += f_ext[d] * sum;
        wd += 0.5 * alpha * m * (v[d] + vs[d]) * sum;
        if (viscous) wv += f_visc[d] * sum;
        u[d] += dt_half * vs[d];
        if (bad < 0 && !(std::abs(u[d]) <= bound)) bad = d;
      }
      ke_b[std::size_t(b)] = ke, wi_b[std::size_t(b)] = wi, we_b[std::size_t(b)] = we, wd_b[std::size_t(b)] = wd;
      wv_b[std::size_t(b)] = wv;
      bad_b[std::size_t(b)] = bad;
    }
    double ke = 0;
    for (std::int64_t b = 0; b < nblocks; ++b) {
      if (bad_b[std::size_t(b)] >= 0) {
        const auto d = bad_b[std::size_t(b)];
        const Vec2& x = nodes[std::size_t(d / 2)];
        throw InputError("the explicit run blew up at step " + std::to_string(n) + " (t = " + format_quantity(t * 1e6, "us") +
                         "): node " + std::to_string(d / 2) + " at " + point_text(x) + " has u_" + (d % 2 ? "y" : "x") +
                         " = " + format_number(u[d]) + " m, beyond the bound " + format_quantity(bound, "m") +
                         " (a step above the stable one, or a law stiffening faster than the step is shrunk)");
      }
      ke += ke_b[std::size_t(b)];
      W_int += wi_b[std::size_t(b)], W_ext += we_b[std::size_t(b)], W_damp += wd_b[std::size_t(b)];
      W_visc += wv_b[std::size_t(b)];
    }
    const EnergySample e{t + 0.5 * dt_half, ke, W_int, W_ext, W_damp, kinetic_jump, W_visc};
    worst = std::max(worst, std::abs(e.balance_J()));
    scale_ref = std::max({scale_ref, std::abs(W_ext), ke, std::abs(W_int)});

    const bool last = t + dt_half >= o.duration_s;
    if (n % o.sample_stride == 0 || last) {
      r.sample_t_s.push_back(t);
      for (std::size_t k = 0; k < sensors.size(); ++k) {
        SensorSample smp;
        smp.velocity_m_s = n == 0 ? Eigen::Vector2d::Zero() : Eigen::Vector2d(0.5 * (displacement_of(sensor_sf[k], v) + displacement_of(sensor_sf[k], vs)));
        sensor_state[k].strain_rate_1_s = strain_of(sensor_sf[k], v);
        smp.stress_Pa = material_->update(strain_of(sensor_sf[k], u_prev), sensor_state[k]);
        r.sensors[k].push_back(smp);
      }
      r.energy.push_back(e);
      if (C_.rows() > 0)
        r.max_constraint_violation_m =
            std::max(r.max_constraint_violation_m, (C_ * u - constraints_->d()).cwiseAbs().maxCoeff());
    } else {
      for (std::size_t k = 0; k < sensors.size(); ++k) {
        sensor_state[k].strain_rate_1_s = strain_of(sensor_sf[k], v);
        material_->update(strain_of(sensor_sf[k], u_prev), sensor_state[k]);
      }
    }
    if (o.snapshot_stride > 0 && (n % o.snapshot_stride == 0 || last)) {
      NodeSnapshot snap;
      for (std::int64_t i = 0; i < nn; ++i) {
        snap.positions_m.push_back(nodes[std::size_t(i)]);
        snap.displacement_m.push_back(displacement_of(node_sf[std::size_t(i)], u_prev));
        snap.stress_Pa.push_back(states[nearest_point[std::size_t(i)]].stress);
      }
      r.snapshots.emplace_back(t, std::move(snap));
    }
    if (cracks && cracks->advance(t + dt_half, u, vs, states)) {  // a crack changed: new shape functions
      // the hook may have replaced v^{n+1/2}: its KE by the same fixed blocks as the step's sum above
      double ke_after = 0;
      for (std::int64_t b = 0; b < nblocks; ++b) {
        double kb = 0;
        const Eigen::Index d1 = 2 * std::min(nn, (b + 1) * block_nodes);
        for (Eigen::Index d = 2 * b * block_nodes; d < d1; ++d) kb += 0.5 * mass_[d / 2] * vs[d] * vs[d];
        ke_after += kb;
      }
      kinetic_jump += ke_after - ke;
      gather_cracked = build_gather(shape, std::size_t(nn));
      gather = &gather_cracked;
      for (std::size_t k = 0; k < sensors.size(); ++k)
        sensor_sf[k] = model_->mls().evaluate(sensors[k].x, "sensor '" + sensors[k].name + "'");
      for (std::size_t i = 0; i < node_sf.size(); ++i) node_sf[i] = model_->mls().evaluate(nodes[i], "node " + std::to_string(i));
      const Eigen::SparseMatrix<double> Kc = cracks->stiffness_bound();
      stable = stable_step(*model_, mass_, constraints_, &Kc);
      r.stable = stable;
      dt_base = std::min(dt_base, o.dt_fraction * stable.dt_critical_s);
      recheck_step = true;
    }
    v = vs;
    t += dt_half;
    dt_prev = dt_half;
    r.steps = n + 1;
    if (o.progress && (n % 100 == 0)) o.progress(n, t);
  }
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.t_end_s = t;
  r.energy_drift = scale_ref > 0 ? worst / scale_ref : 0.0;
  r.u = u;
  r.u_previous = u_prev;
  r.v = v;
  return r;
}

}  // namespace mesowave::efg
