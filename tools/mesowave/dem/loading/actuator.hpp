#pragma once
// An actuator loads the model each step; one class per kind of loading, one
// file each (force_actuator, displacement_actuator, rigid_wall), each kind
// registered by name with its scene keys and factory (plugins.hpp). The
// simulation calls before_step at t_n (forces for step n) and after_step once
// x_{n+1} exists (constraints at t_{n+1}); adding a kind is its file and one
// line in plugins.def, touching neither the loop nor the integrator.
#include <string>
#include <vector>

#include "mesowave/dem/engine/model.hpp"

namespace mesowave::dem {

class Actuator {
public:
  virtual ~Actuator() = default;
  virtual const std::string& name() const = 0;
  virtual void before_step(Model& /*model*/, double /*t_s*/, double /*dt_s*/) {}
  virtual void after_step(Model& /*model*/, double /*t_s*/, double /*dt_s*/) {}
  /// The spheres it acts on (model numbering): every sphere it reads or loads, since on several
  /// MPI ranks every rank holds these and not the others (docs/mpi.md).
  virtual const std::vector<std::size_t>& spheres() const = 0;
  /// One line for the run summary ("force 1 N, 100 kHz 5-cycle Hann burst along +x on 4 spheres").
  virtual std::string description() const = 0;
  /// Total force it applied to the specimen along its direction in the last
  /// step [N] (for a prescribed motion: the force needed to impose it).
  virtual double applied_force() const = 0;
  /// Largest stiffness / mass it adds to one sphere [1/s^2] (a wall's contact
  /// springs), for the critical time step; 0 for loads that add none.
  virtual double added_stiffness_per_mass() const { return 0; }
  /// What it carries from step to step (a checkpoint, state_group.hpp); a
  /// load that is a function of time alone keeps only its last force.
  virtual void save_state(StateGroup& group) const = 0;
  virtual void load_state(const StateGroup& group) = 0;
};

}  // namespace mesowave::dem
