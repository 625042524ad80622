#pragma once
// Explicit dynamics of the EFG model (shock paper Sections 2.5, 3.2, 3.3): the semi-discrete
// equations of Eq. (18) with inertia,
//   M a = f_ext(t) - f_int(u) - alpha M v,   f_int = sum_g B_g^T sigma_g w_g t,
// sigma_g = PointMaterial::update(B_g u, state_g) at every Gauss point g of the background cells.
//
// Mass: the ROW SUM of the consistent MLS mass, m_I = sum_J int rho phi_I phi_J t dA = int rho phi_I t dA
// (the MLS functions are a partition of unity, sum_J phi_J = 1), by the model's own Gauss points,
// the same for u_x and u_y. It keeps the total mass rho t A exactly and needs no nodal volumes (a
// Voronoi area is not what a non-interpolating MLS parameter carries). MLS functions of a linear
// basis are NOT positive everywhere (they dip below zero near the edge of their support), so m_I > 0
// is not guaranteed by construction: it holds on the regular grids of the tests (an interior m_I is
// rho t h^2 to 2e-3, one two spacings from an edge 0.946 of it: tests/efg/explicit_dynamics_test), and a node whose row sum
// is <= 0 is refused (InputError naming the node) instead of giving a negative or infinite 1/m.
//
// Time stepping: central differences with half-step velocities (Belytschko, Liu, Moran, "Nonlinear
// Finite Elements", Box 6.1), variable step allowed:
//   v^{n+1/2} = ((1 - c) v^{n-1/2} + dt_n M^-1 (f_ext^n - f_int^n)) / (1 + c),   c = alpha dt_n / 2,
//   dt_n = (dt_{n-1/2} + dt_{n+1/2}) / 2 (v^{1/2} = dt_{1/2}/2 a^0 at the start, from rest),
//   u^{n+1} = u^n + dt_{n+1/2} v^{n+1/2}.
// Damping: none by default; optionally mass-proportional, alpha [1/s] (the mw-fem convention).
//
// Essential conditions: the rows C u = d of efg/constraints (ConstraintSet: collocated points and
// weak edge rows, e.g. the rollers v = 0 of a strip's long sides). The MLS parameters are not nodal
// displacements, so a row couples several unknowns and "set the constrained dof to zero" does not
// exist. They are enforced exactly at every step by the forward-increment Lagrange multiplier method
// (Carpenter, Taylor and Katona 1991, IJNME 32: 103-128): with the unconstrained predictor u*,
//   lambda = (C M^-1 C^T)^-1 (C u* - d) / dt^2,   u^{n+1} = u* - dt^2 M^-1 C^T lambda,
// i.e. the velocity is projected M-orthogonally onto C v = 0. This is the same scheme as central
// differences on the reduced unknowns of ConstraintSet (u = T q + g with the consistent reduced mass
// T^T M T; tested), keeps M diagonal and needs one small dense factorisation of C M^-1 C^T (one row per
// boundary hat). The constraint forces do no work (C v = 0), so the energy balance below holds.
//
// Stable step: dt_crit = 2 / omega_max, omega_max^2 the largest eigenvalue of M^-1 K on the
// constrained space (K of the linear law D, ElasticModel::stiffness), by Lanczos (core/lanczos) on
// Q M^-1/2 K M^-1/2 Q, Q the orthogonal projector onto C M^-1/2 y = 0; the top Ritz value plus its
// residual (an estimate from above, as the DEM's). A step dt_s above dt_crit is refused (InputError
// naming both); dt_s = 0 takes dt_fraction x dt_crit. When a PointMaterial stiffens (modulus_scale > 1,
// the Y-function's Eq. (24)), the step is dt = dt_base / sqrt(max(1, s_max)), s_max the largest
// modulus_scale over the Gauss points, re-read every `stiffness_check_every` steps (and at step 0).
// This is the bound omega_max(K_t) <= sqrt(s_max) omega_max(K) for a tangent D_t <= s_max D at every
// point; between checks a point may stiffen further, which dt_fraction < 1 covers (state both).
//
// Energy: with the half-step velocities,
//   KE^{n+1/2} = 1/2 v^{n+1/2}.M v^{n+1/2},
//   W^{n+1/2} = W^{n-1/2} + f^n . (dt_n / 2)(v^{n-1/2} + v^{n+1/2}) for f = f_int, f_ext and the damping force,
// and KE + W_int + W_damp (+ W_visc) - W_ext = 0 up to round-off for any dt sequence and material. For a linear
// law and a constant step W_int^{n+1/2} = 1/2 u^n.K u^{n+1}: the balance is then the central
// difference's conserved shadow energy (tested against the assembled K), not 1/2 u.K u + KE.
// drift = max |KE + W_int + W_damp + W_visc - W_ext - jumps| / max(W_ext, KE, W_int) over the run.
//
// Shock (bulk) viscosity, off by default (DynamicsOptions::viscosity): the artificial viscosity of von
// Neumann and Richtmyer (1950, J. Appl. Phys. 21: 232-237) in the linear + quadratic form of Wilkins
// (1980, J. Comput. Phys. 36: 281-303) as LS-DYNA states it (Hallquist, LS-DYNA Theory Manual, "Artificial
// bulk viscosity"; Benson 1992, Comput. Methods Appl. Mech. Eng. 99: 235-394): at every Gauss
// point g, from its volumetric strain rate eps_dot_v (PointState::strain_rate_1_s = B_g v^{n-1/2}, with
// eps_dot_zz = 0 in plane strain and -nu / (1 - nu) (eps_dot_xx + eps_dot_yy) in plane stress: efg/hugoniot's
// volumetric_strain), only in compression,
//   q_g = rho l_g (C_0 l_g eps_dot_v^2 - C_1 c_g eps_dot_v)   for eps_dot_v < 0,   q_g = 0 otherwise,
// l_g = sqrt(area of the point's background cell) (LS-DYNA's length of a 2D solid: the node spacing on the
// regular square grids), c_g = c_0 sqrt(modulus_scale_g) the point's current dilatational speed (c_0 =
// sqrt(D_11 / rho), D_11 the P-wave modulus in plane strain; modulus_scale the law's tangent over D, which
// the Y-function raises). q is a pressure: the stress -q I joins sigma_g in the internal force,
//   f_visc = sum_g B_g^T (-q_g, -q_g, 0) w_g t,
// kept apart from f_int so that its work is booked on its own, W_visc^{n+1/2} = W_visc^{n-1/2} + f_visc^n .
// (dt_n / 2)(v^{n-1/2} + v^{n+1/2}), and the identity reads KE + W_int + W_damp + W_visc - W_ext = jumps.
// The points' PointState::stress (sensors, snapshots, the cracks' criterion) stays the law's stress, q
// excluded (q is numerical, not the material's; Abaqus and LS-DYNA keep it out of the output stresses too).
// Stable step: LS-DYNA's per-element dt <= l / (Q + sqrt(Q^2 + c^2)), Q = C_1 c + C_0 l |eps_dot_v|, is
// (l / c) r with r = sqrt(1 + xi^2) - xi, xi = Q / c (the central difference's limit with a damping ratio
// xi). The eigenvalue step dt_base / sqrt(s_max) plays l / c here, so a compressing point multiplies it by
// r_g: dt = dt_base / sqrt(s_max) x min_g r_g (conservative: s_max and the smallest r need not be at one
// point). It is set at every stiffness check with the modulus scale, and between checks the step is only
// shrunk, the same step, when min_g r_g of the current rates asks for less (a shock's compression rate
// grows within a few steps). C_0 = C_1 = 0 (the default) runs none of it: the same bits as without.
//
// Parallelism and bits: the Gauss points (strain, PointMaterial::update, sigma w t) in parallel, each
// point writing its own entry; then each node gathers its points' B^T sigma w t in point order (a fixed
// per-node list): f_int has the same bits for any thread count, and so have the dof updates (one
// thread per dof) and the energies (partial sums over fixed blocks of dofs, added in block order).
//
// Guards: after every step a displacement that is not finite or beyond `displacement_bound_m`
// (0: the body's diagonal - no small-strain solution moves that far) stops the run with an InputError
// naming the step, the time, the node and its position. Nothing of the run is returned.
#include <Eigen/Core>
#include <Eigen/Cholesky>
#include <Eigen/SparseCore>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "mesowave/efg/constraints.hpp"
#include "mesowave/efg/elastic_model.hpp"
#include "mesowave/efg/point_material.hpp"
#include "mesowave/efg/pressure_load.hpp"
#include "mesowave/efg/vtk_output.hpp"

namespace mesowave::efg {

/// m_I = int rho phi_I t dA per node [kg] by the model's Gauss points (row sums of the consistent
/// mass). InputError: density <= 0, a node with m_I <= 0 (named, with its position).
Eigen::VectorXd lumped_mass(const ElasticModel& model);

struct StableStep {
  double omega_max_rad_s = 0;        ///< constrained, Lanczos ritz + residual
  double dt_critical_s = 0;          ///< 2 / omega_max
  double omega_free_rad_s = 0;       ///< without the constraints (for the report)
  int iterations = 0;                ///< Lanczos iterations (constrained)
  std::string method;
};

/// The stable step of `model` with lumped `mass` (per node) under `constraints` (may be null), with
/// `extra_stiffness` (full dofs, e.g. crack faces' penalties) added to K when not null.
StableStep stable_step(const ElasticModel& model, const Eigen::VectorXd& mass_per_node, const ConstraintSet* constraints,
                       const Eigen::SparseMatrix<double>* extra_stiffness = nullptr);

/// A point whose velocity and stress are recorded: its own shape functions and its own PointState
/// (updated every step, so a history-dependent law gives the same stress as at a Gauss point there).
struct Sensor {
  std::string name;
  Vec2 x;
};

struct SensorSample {
  Eigen::Vector2d velocity_m_s = Eigen::Vector2d::Zero();  ///< (v^{n-1/2} + v^{n+1/2}) / 2 at t^n
  Eigen::Vector3d stress_Pa = Eigen::Vector3d::Zero();     ///< Voigt (xx, yy, xy), from u^n
};

struct EnergySample {
  double t_s = 0;  ///< t^{n+1/2}
  double kinetic_J = 0, internal_work_J = 0, external_work_J = 0, damping_J = 0;
  /// the kinetic energy the cracks' hook changed at fixed times by replacing v (DynamicsCracks), so far
  double kinetic_jump_J = 0;
  /// the bulk viscosity's work f_visc . du so far (see the top of this file; 0 when it is off)
  double viscous_J = 0;
  double balance_J() const {
    return kinetic_J + internal_work_J + damping_J + viscous_J - external_work_J - kinetic_jump_J;
  }
};

/// The shock viscosity's coefficients (see the top of this file); both 0: off.
struct BulkViscosity {
  double quadratic = 0;  ///< C_0 (LS-DYNA's Q1 = 1.5), >= 0
  double linear = 0;     ///< C_1 (LS-DYNA's Q2 = 0.06), >= 0
  bool on() const { return quadratic > 0 || linear > 0; }
  /// InputError: a coefficient negative or not finite.
  void validate() const;
};

/// q [Pa] at a point of density rho, length l and dilatational speed c under the volumetric strain rate
/// eps_dot_v [1/s]: rho l (C_0 l eps_dot_v^2 - C_1 c eps_dot_v) in compression (eps_dot_v < 0), else 0.
double bulk_viscosity_pressure_Pa(double rho_kg_m3, double length_m, double c_m_s, double eps_dot_v_1_s,
                                  const BulkViscosity& q);
/// The factor r = sqrt(1 + xi^2) - xi, xi = C_1 + C_0 l |eps_dot_v| / c, that the point's stable step
/// l / c takes under the viscosity (LS-DYNA's l / (Q + sqrt(Q^2 + c^2))); 1 when eps_dot_v >= 0.
double bulk_viscosity_step_factor(double length_m, double c_m_s, double eps_dot_v_1_s, const BulkViscosity& q);

/// Cracks that open and grow during a run (efg/dynamic_cracks implements it; issue 16). At every step n
/// the run calls add_forces(u^n, f) with f zero, adds f to the continuum's f_int (so W_int holds the
/// faces' work and the energy balance stays exact), and after u^{n+1} calls advance(t^{n+1}, u^{n+1},
/// v^{n+1/2}, states) with the points' states of step n (stress, strain rate); before the first step it
/// calls start(lumped mass). When advance returns true the
/// CrackSet changed and the model's shape functions were recomputed: the run rebuilds its node gather
/// lists and its sensors' and snapshot nodes' shape functions, and recomputes the stable step with
/// stiffness_bound() added to K (then dt = dt_fraction x that step, or the caller's dt where lower).
/// The lumped mass stays the one of the start: the row sums move between nodes when the shape
/// functions are cut, the body's mass does not change, and a mass changed at a crack would change the
/// kinetic energy without a force doing work. Runs with constraint rows are refused (their rows hold
/// the shape functions of the start, which a crack would make stale). When advance() replaces v, the
/// kinetic energy changes at a fixed time with no force doing it: the run adds that change,
/// 1/2 v'.M v' - 1/2 v.M v (in the fixed block order of the step's own sum), to kinetic_jump_J, and the
/// identity reads KE + W_int + W_damp - W_ext = kinetic_jump_J (zero when no hook replaces v).
class DynamicsCracks {
 public:
  virtual ~DynamicsCracks() = default;
  /// Once, before the first step: the run's lumped mass per node (the kinetic energy's).
  virtual void start(const Eigen::VectorXd& /*mass_per_node*/) {}
  virtual void add_forces(const Eigen::VectorXd& u, Eigen::VectorXd& f) const = 0;
  /// u = u^{n+1}, v = v^{n+1/2}. A hook may replace both when it changes the shape functions (a projection
  /// of the parameters onto the new space, efg/field_projection); the run goes on from what it leaves.
  virtual bool advance(double t_s, Eigen::VectorXd& u, Eigen::VectorXd& v, const std::vector<PointState>& states) = 0;
  /// An upper bound of the faces' stiffness (full dof numbering) for the stable step.
  virtual Eigen::SparseMatrix<double> stiffness_bound() const = 0;
};

struct DynamicsOptions {
  double duration_s = 0;            ///< simulated time; the run stops at the first t^n >= duration
  double dt_s = 0;                  ///< 0: dt_fraction x the stable step; else refused above it
  double dt_fraction = 0.9;         ///< in (0, 1]
  double alpha_damping_per_s = 0;   ///< mass-proportional damping alpha [1/s], >= 0
  int stiffness_check_every = 10;   ///< steps between re-reading the largest modulus_scale
  std::int64_t sample_stride = 1;   ///< sensors and energies every this many steps (and the last)
  std::int64_t snapshot_stride = 0; ///< node snapshots every this many steps (0: none)
  double displacement_bound_m = 0;  ///< blow-up guard (0: the body's diagonal)
  std::size_t min_points_per_thread = 2000;  ///< core/threads: fewer points per thread are not worth it
  bool allow_unstable = false;      ///< tests only: run above the stable step to see the guard stop it
  std::function<void(std::int64_t step, double t_s)> progress;  ///< now and then, from one thread
  DynamicsCracks* cracks = nullptr;  ///< growing cracks (see DynamicsCracks); null: none
  BulkViscosity viscosity{};         ///< shock viscosity (see the top of this file); default off
};

struct DynamicsResult {
  std::vector<double> sample_t_s;                   ///< t^n of each sample
  std::vector<std::vector<SensorSample>> sensors;   ///< [sensor][sample]
  std::vector<EnergySample> energy;                 ///< per sample
  std::vector<std::pair<double, NodeSnapshot>> snapshots;  ///< (t, nodes): u^h and the nearest point's stress
  std::int64_t steps = 0;
  double t_end_s = 0;
  double dt_first_s = 0, dt_min_s = 0;  ///< the base step, the smallest used (after stiffening)
  double max_modulus_scale = 1;         ///< the largest over points and time
  double energy_drift = 0;              ///< see the header: max |balance| / max(W_ext, KE)
  double max_constraint_violation_m = 0;  ///< max |C u - d| over the steps
  double max_viscous_pressure_Pa = 0;     ///< the largest q over points and steps (0: viscosity off)
  double min_viscous_step_factor = 1;     ///< the smallest r the step took (1: off or never compressed)
  StableStep stable;
  double wall_s = 0;
  int threads = 1;
  Eigen::VectorXd u, u_previous, v;     ///< u^N, u^{N-1}, v^{N-1/2} (MLS parameters)
};

class ExplicitDynamics {
 public:
  /// `model`, `material` and `constraints` (may be null) must outlive this object. Computes the
  /// lumped mass, the unit load vectors, the constraint factor and the stable step (InputError: a
  /// mass <= 0, a load edge of no length, C M^-1 C^T not positive definite).
  ExplicitDynamics(const ElasticModel& model, const PointMaterial& material, const ConstraintSet* constraints,
                   std::vector<PressureLoad> loads);

  const Eigen::VectorXd& mass_per_node() const { return mass_; }
  const StableStep& stable() const { return stable_; }
  /// f_int(u) = sum_g B^T sigma(B u) w t, updating `states` (one per Gauss point). For the linear law
  /// it equals K u to round-off (tested). Parallel, the same bits for any thread count.
  Eigen::VectorXd internal_force(const Eigen::VectorXd& u, std::vector<PointState>& states) const;
  /// The same with the velocity v (MLS parameters) whose strain rate B v each point's state gets before
  /// its update (PointState::strain_rate_1_s), as in the run with v = v^{n-1/2}.
  Eigen::VectorXd internal_force(const Eigen::VectorXd& u, const Eigen::VectorXd& v, std::vector<PointState>& states) const;
  /// q_g [Pa] at every Gauss point from its state's strain rate and modulus_scale (as the run sets them:
  /// internal_force(u, v, states) first), for the coefficients `q` (see the top of this file).
  std::vector<double> bulk_viscosity_pressures(const std::vector<PointState>& states, const BulkViscosity& q) const;
  /// l_g per Gauss point [m]: sqrt(area of its background cell).
  const std::vector<double>& viscosity_length_m() const { return point_length_m_; }
  /// c_0 = sqrt(D_11 / rho) [m/s], the speed q's linear term scales by sqrt(modulus_scale).
  double dilatational_speed_m_s() const { return c0_m_s_; }
  /// f_ext(t) = sum_l p_l(t) f_1,l.
  Eigen::VectorXd external_force(double t_s) const;
  /// Runs from rest (u = v = 0, fresh PointStates). InputError: bad options (one line each), a step
  /// above the stable one, a blow-up (step, time, node named); a sensor the MLS refuses.
  DynamicsResult run(const DynamicsOptions& options, const std::vector<Sensor>& sensors = {}) const;

 private:
  /// s_g = sigma_g(B_g u) w_g t at every Gauss point (updating `states`); the largest modulus_scale
  /// (at least 1). The one stress pass of internal_force and of the time step.
  /// Each point's strain rate B_g v goes into its state first (v null: zero).
  double point_forces(const Eigen::VectorXd& u, const Eigen::VectorXd* v, std::vector<PointState>& states,
                      std::vector<Eigen::Vector3d>& s, int threads) const;
  Eigen::VectorXd internal_force_with(const Eigen::VectorXd& u, const Eigen::VectorXd* v, std::vector<PointState>& states) const;
  /// Node i's f_int from the points' s_g, summed in point order (the same bits for any thread count).
  Eigen::Vector2d node_internal_force(std::int64_t i, const std::vector<Eigen::Vector3d>& s) const;
  /// per node: the points whose support holds it, ascending, with their shape-function derivatives
  /// at the node (copies of dphi_dx, dphi_dy, so that a node's sum streams its entries instead of
  /// chasing each point's arrays: the same products in the same order, the same bits)
  struct NodeGather {
    std::vector<std::int64_t> start;
    std::vector<std::int32_t> point;
    std::vector<double> dphi_dx, dphi_dy;
  };
  static NodeGather build_gather(const std::vector<ShapeFunctions>& shape, std::size_t nodes);
  Eigen::Vector2d node_internal_force(const NodeGather& g, std::int64_t i, const std::vector<Eigen::Vector3d>& s) const;
  /// Node i's f_visc from the points' q_g w_g t (stress -q I), in point order.
  Eigen::Vector2d node_viscous_force(const NodeGather& g, std::int64_t i, const std::vector<double>& qwt) const;
  /// q_g and r_g of point p from its state (see the top of this file).
  double point_viscous_pressure(std::size_t p, const PointState& st, const BulkViscosity& q, double* step_factor) const;

  const ElasticModel* model_;
  const PointMaterial* material_;
  const ConstraintSet* constraints_;
  std::vector<PressureLoad> loads_;
  std::vector<Eigen::VectorXd> unit_loads_;
  Eigen::VectorXd mass_, inv_mass_dof_;
  Eigen::LLT<Eigen::MatrixXd> schur_;             ///< of C M^-1 C^T
  Eigen::SparseMatrix<double, Eigen::RowMajor> C_;
  StableStep stable_;
  NodeGather gather_;
  std::uint64_t gather_version_ = 0;  ///< the CrackSet version gather_ was built for
  std::uint64_t crack_version() const { return model_->mls().cracks() ? model_->mls().cracks()->version() : 0; }
  double body_diagonal_m_ = 0;
  std::vector<double> point_length_m_;  ///< l_g of the viscosity
  double c0_m_s_ = 0;
};

}  // namespace mesowave::efg
