#pragma once
// What the simulation loop, the actuators and the sensors see of a DEM model,
// whichever one runs: the full cohesive-frictional law, the linearised bonded
// network or the axial chain (docs/models.md, "Three models": model only what
// the scene needs). Spheres are addressed in the model's own numbering (Morton order);
// `packing_index` maps back.
//
// Time levels (Yade's NewtonIntegrator, leapfrog): step n computes forces
// from positions x_n, then v_{n+1/2} = v_{n-1/2} + dt a_n, x_{n+1} = x_n + dt v_{n+1/2}.
// After step n: acceleration() is a_n, velocity() is v_{n+1/2},
// displacement() is x_{n+1} - x_0.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "mesowave/core/ordered_dot.hpp"
#include "mesowave/dem/engine/sphere_statics.hpp"
#include "mesowave/dem/engine/state_group.hpp"
#include "mesowave/dem/engine/vec3.hpp"

namespace mesowave::dem {

class Domain;

/// Energies of the run. Kinetic energy is the leapfrog product
/// 1/2 m v_{n-1/2} . v_{n+1/2} (plus its rotational part), which together
/// with the spring energy at x_n is exactly conserved by leapfrog for a
/// linear undamped network; work and dissipation use the matching
/// trapezoid g_n . (v_{n-1/2} + v_{n+1/2}) dt / 2.
struct EnergyAccount {
  double kinetic_J = 0;        ///< at the last energy evaluation
  double elastic_J = 0;        ///< springs: F_n^2 / (2 K_n) + |F_s|^2 / (2 a K_s), a = (r_i + r_j)/|x_j - x_i|
  double external_work_J = 0;  ///< done by actuators since step 0
  double damping_J = 0;        ///< dissipated by local damping since step 0
  double plastic_J = 0;        ///< dissipated by frictional sliding since step 0
  double stored() const { return kinetic_J + elastic_J; }
  /// stored + dissipated - supplied; zero for a perfect balance.
  double residual() const { return kinetic_J + elastic_J + damping_J + plastic_J - external_work_J; }
};

/// InputError: `model` runs on one process only (Model::distribute's default).
[[noreturn]] void refuse_ranks(const std::string& model);

class Model : public SphereStatics {
public:
  virtual std::string name() const = 0;  ///< full | linear | chain
  virtual std::size_t bond_count() const = 0;
  /// Interactions evaluated each step (bonds plus candidate contacts).
  virtual std::size_t contact_count() const { return bond_count(); }
  virtual std::size_t broken_bond_count() const { return 0; }
  virtual std::size_t degrees_of_freedom() const = 0;

  virtual Vec3 displacement(std::size_t k) const = 0;
  virtual Vec3 velocity(std::size_t k) const = 0;
  virtual Vec3 acceleration(std::size_t k) const = 0;

  /// Adds an external force acting during the next step only.
  virtual void add_external_force(std::size_t k, const Vec3& force) = 0;
  /// After a step: makes sphere k's displacement along the unit vector `e`
  /// equal to u_next (= u(t_{n+1})), its velocity along e (u_next - u_now)/dt
  /// (Yade: a blocked DOF with imposed velocity). The work of the constraint
  /// is booked as external work. Returns the force along e the constraint
  /// applied to the sphere during the step.
  virtual double impose_displacement(std::size_t k, const Vec3& e, double u_now, double u_next, double dt) = 0;
  /// Initial condition (tests, free vibration): v_{-1/2}.
  virtual void set_velocity(std::size_t k, const Vec3& v) = 0;
  /// The spheres whose acceleration() the sensors read and on which the actuators call
  /// impose_displacement(), given once before the first step. A model may then keep the
  /// accelerations of those only: a step writes no others (issue 17: two of the sphere
  /// update's ten arrays), and acceleration() or impose_displacement() of another sphere is a
  /// std::logic_error. Without a call every sphere's is kept.
  virtual void observe(const std::vector<std::size_t>& spheres) { (void)spheres; }

  /// One time step. With `evaluate_energy` the kinetic and elastic energies
  /// of this step are computed (an extra few flops per bond and sphere).
  virtual void step(double dt, bool evaluate_energy) = 0;

  virtual EnergyAccount energy() const = 0;
  /// Largest bond force / strength seen so far: max over bonds and steps of
  /// max(|F_n| / (T R^2), |F_s| / (C R^2)); 0 with unbreakable bonds.
  virtual double peak_force_ratio() const = 0;
  /// True if any position or velocity is not finite.
  virtual bool has_non_finite_state() const = 0;

  /// The rows of the vectors below that this process holds: all degrees_of_freedom() of them
  /// in one process; distributed (docs/mpi.md), its own spheres' six each.
  struct Rows {
    std::size_t first = 0, count = 0;
  };
  virtual Rows stiffness_rows() const { return {0, degrees_of_freedom()}; }
  /// y = M^{-1/2} K M^{-1/2} x for the linearised network at step 0 (the
  /// symmetric part), both vectors' stiffness_rows(): its largest eigenvalue gives
  /// the critical time step 2 / sqrt(lambda_max). Collective when distributed.
  virtual void scaled_stiffness_action(const double* x, double* y) const = 0;
  /// sum_i a_i b_i of two such vectors over every process's rows, added in row order: the
  /// bits of one process holding them all. Collective when distributed.
  virtual double stiffness_dot(const double* a, const double* b) const { return ordered_dot(a, b, stiffness_rows().count); }
  /// Upper bound of lambda_max (Gershgorin: largest absolute row sum over every row).
  /// Collective when distributed.
  virtual double scaled_stiffness_row_sum_bound() const = 0;

  /// Everything that changes from step to step (positions, velocities,
  /// energies, the contact law's state), exactly (state_group.hpp), so that a
  /// run restarted from it continues to the same bits. Called between steps.
  /// Distributed: on every rank (collective: the state is gathered to rank 0
  /// as it is written), after collect_energy(); rank 0's `group` writes, the
  /// others' writes nowhere.
  virtual void save_state(StateGroup& group) const = 0;
  /// Reads what save_state wrote, into a model built from the same scene and
  /// packing (distributed: on every rank, for any rank count); InputError if
  /// the state does not fit it.
  virtual void load_state(const StateGroup& group) = 0;

  /// Bytes held by the model's arrays.
  virtual std::size_t memory_bytes() const = 0;
  /// Threads the step runs on (1 for small systems, where a parallel region costs more than it saves).
  virtual int threads() const = 0;
  /// Splits the steps that follow over the ranks of `domain` (several; docs/mpi.md), to the
  /// same bits as one process. Called once, before the first step. `observed`: the spheres
  /// the actuators and sensors read or load (every rank then holds their motion after each
  /// step; the others only its own spheres' and its ghosts'). The model must have been made
  /// for this domain (LawInput::domain), so that it never held the other ranks' contacts.
  /// InputError for a model that does not run distributed (the default).
  virtual void distribute(Domain& domain, const std::vector<std::size_t>& observed);
  /// Distributed: gathers every sphere's displacement and velocity to rank 0, which writes a
  /// snapshot from this whole copy (kept until the next step); collective: every rank calls it.
  /// A no-op in one process.
  virtual void collect_state() {}
  /// Distributed: makes energy() whole on this rank after a step that did not evaluate the
  /// energies (collective; the loop calls it once, after the last step). A no-op in one process.
  virtual void collect_energy() {}
  /// What a distributed model tells of its split (empty for one process): ranks, spheres per
  /// rank, ghosts (docs/mpi.md).
  virtual std::string distribution() const { return {}; }
};

}  // namespace mesowave::dem
