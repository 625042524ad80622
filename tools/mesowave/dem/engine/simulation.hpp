#pragma once
// One DEM run from a scene: builds the spheres (Morton order) and the step-0
// bonds, chooses the model (model_choice.hpp), computes the critical time
// step and refuses a larger one, places actuators and sensors, and steps:
//
//   for n = 0 .. steps-1 (t_n = n dt):
//     actuators.before_step(t_n)    external forces of step n
//     model.step(dt)                contact forces at x_n, then leapfrog
//     actuators.after_step(t_n)     constraints at t_{n+1}
//     sensors.record(n)
//     every energy_check_steps: energies; a non-finite state or stored energy
//       above 4x (initial + work put in) stops the run with an error;
//     a [test]'s stop rule (a drop after the peak, a stress reached) ends it early;
//     a checkpoint (checkpoint.hpp) when one is due, then the progress report
//       (which stops an interrupted run).
//
// restore() reads a checkpoint into a Simulation built from the same scene and
// packing; run() then continues from the step it holds, to the same bits.
//
// After the run the linear model's measured peak bond force / strength is
// checked against the scene's bound (the chain's against 1: no breakage), and
// a [test] is analysed (uniaxial_test.hpp).
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mesowave/dem/engine/checkpoint.hpp"
#include "mesowave/dem/loading/actuator.hpp"
#include "mesowave/dem/engine/model.hpp"
#include "mesowave/dem/scene/model_choice.hpp"
#include "mesowave/dem/packing/packing.hpp"
#include "mesowave/dem/scene/plugins.hpp"
#include "mesowave/dem/scene/scene.hpp"
#include "mesowave/dem/loading/sensor.hpp"
#include "mesowave/dem/engine/time_step.hpp"
#include "mesowave/dem/calibration/uniaxial_analysis.hpp"
#include "mesowave/signal/signal.hpp"

namespace mesowave::dem {

struct SimulationOptions {
  std::string model = "auto";     ///< overrides the scene's [model] choice unless auto
  bool refuse_unstable_dt = true; ///< tests switch it off to watch the blow-up detection work
  std::function<void(std::int64_t done, std::int64_t total)> on_progress;
  /// Called at t = 0 and every scene.snapshot_interval_s (if > 0).
  std::function<void(const Model& model, double t_s, std::int64_t index)> on_snapshot;
  /// Superposition (superposition.hpp), >= 0: actuator number `impulse_actuator`
  /// pushes a unit impulse (1 N on step 0, shared by its spheres, along its
  /// direction), the other actuators push nothing, every sensor samples every
  /// step, and the peak bond force / strength is left to the caller to check
  /// (it scales with the burst the response is convolved with). After the
  /// scene's sensors the run adds one per actuator: the mean velocity of its
  /// spheres along its direction, v_{n+1/2} (the power it puts in), then each
  /// motion sensor's displacement twin (the same spheres and component; what a
  /// viscous damping windows, superposition.hpp). -1: the scene's loads.
  int impulse_actuator = -1;
  CheckpointOptions checkpoint;  ///< none unless checkpoint.file is set
  /// Written every intact_checkpoint.every_steps steps while no bond is broken, and no more after
  /// the first break: the last one holds the elastic prefix that a run with stronger bonds
  /// shares (restore_stronger, checkpoint.hpp). None unless intact_checkpoint.file is set.
  CheckpointOptions intact_checkpoint;
  /// Several MPI ranks (dem/parallel/domain.hpp, docs/mpi.md): the model is split over them
  /// and every rank runs this Simulation, to the same bits as one process. nullptr: one process.
  Domain* domain = nullptr;
};

struct RunReport {
  std::string scene;
  ModelChoice choice;
  CohesiveFrictionalMaterial material;
  std::string contact_law;
  LawParameters law_parameters;
  std::vector<Placement> actuator_placements, sensor_placements;
  std::size_t spheres = 0, bonds = 0, contacts = 0, broken_bonds = 0, degrees_of_freedom = 0;
  int threads = 1;
  std::string distribution;  ///< a distributed run's split as rank 0 holds it (Model::distribution); empty for one process
  double dt_s = 0, duration_s = 0;
  std::int64_t steps = 0;
  CriticalTimeStep dt_cr;
  std::size_t memory_bytes = 0;
  std::vector<std::string> actuators, sensors, notes;
  // After a run:
  bool ran = false;
  double setup_s = 0, wall_s = 0, steps_per_s = 0, ns_per_contact_step = 0;
  EnergyAccount energy;
  std::string stop_reason;  ///< why the run ended before its duration (a test's stop rule); empty otherwise
  std::optional<UniaxialTestResult> test;  ///< the [test] analysis
  double peak_stored_J = 0;
  double peak_force_ratio = 0;
  double validity_bound = 0;  ///< the bound the peak ratio was checked against (0: none)
  std::vector<signal::Signal> signals;
  /// Each sensor's sampling interval in steps, as the scene asks (an impulse run samples every step regardless).
  std::vector<std::int64_t> sample_interval_steps;
};

class Simulation {
public:
  /// InputError for anything the user can fix (scene, packing, dt above the limit...). The
  /// packing is dropped once the spheres are made from it (move it in: 24 B a sphere less at setup).
  /// With options.domain of several ranks it is this rank's rows (read_packing_file's part).
  Simulation(const Scene& scene, Packing packing, SimulationOptions options);
  /// With the default options. (Not a default argument: GCC 12 then warns of a json member of
  /// the caller's temporary options as maybe uninitialised, a false positive.)
  Simulation(const Scene& scene, Packing packing);
  ~Simulation();

  const ModelChoice& choice() const { return choice_; }
  const CriticalTimeStep& time_step() const { return dt_cr_; }
  Model& model() { return *model_; }
  const Model& model() const { return *model_; }
  std::int64_t steps() const { return steps_; }
  /// Everything known before running (what `mw-dem info` prints).
  RunReport describe() const;
  /// Runs every step (from the restored one on). InputError on a blow-up or a violated validity check.
  RunReport run();
  /// Steps done so far (restore() sets it; 0 for a fresh run).
  std::int64_t steps_done() const { return loop_.done; }
  /// Writes the state after steps_done() steps to `file` (checkpoint.hpp).
  void save_checkpoint(const std::filesystem::path& file, const CheckpointIdentity& identity);
  /// Reads a checkpoint of this run (InputError if it is of another, checkpoint.hpp); call before run().
  /// After an InputError the Simulation may hold part of the checkpoint: build a new one.
  void restore(const std::filesystem::path& file, const CheckpointIdentity& identity);
  /// Reads an intact checkpoint of a run with weaker bonds (checkpoint.hpp): the same
  /// inputs and options but T and C, those at most this run's, no bond broken (InputError otherwise).
  /// The run continues to the same bits as one of this run's strengths from step 0.
  void restore_stronger(const std::filesystem::path& file, const CheckpointIdentity& identity);

  // What a solver other than the stepping loop reads (static_elastic.hpp):
  // the scene as run, the placed actuators and sensors, the [test] specimen.
  const Scene& scene() const { return scene_; }
  const std::vector<std::unique_ptr<Actuator>>& actuators() const { return actuators_; }
  std::vector<std::unique_ptr<Sensor>>& sensors() { return sensors_; }
  const std::optional<UniaxialTestSpecimen>& test_specimen() const { return test_specimen_; }

private:
  void restore(const std::filesystem::path& file, const CheckpointIdentity& identity, bool stronger_bonds);

  Scene scene_;
  SimulationOptions options_;
  ModelChoice choice_;
  CriticalTimeStep dt_cr_;
  std::unique_ptr<Model> model_;
  std::vector<std::unique_ptr<Actuator>> actuators_;
  std::vector<std::unique_ptr<Sensor>> sensors_;
  std::int64_t steps_ = 0;
  double setup_s_ = 0;
  std::size_t setup_rows_ = 0, setup_spheres_ = 0;  ///< several ranks: the packing rows this rank read, its part's spheres
  std::vector<std::string> notes_;
  std::vector<Placement> actuator_placements_, sensor_placements_;
  std::vector<std::int64_t> sample_interval_steps_;
  std::optional<UniaxialTestSpecimen> test_specimen_;
  /// What the step loop carries besides the model, actuators and sensors (saved in checkpoints).
  struct LoopState {
    std::int64_t done = 0;  ///< steps done
    double initial_stored_J = 0, max_work_J = 0, peak_stored_J = 0;  ///< the energy check's
    double test_peak_Pa = 0;  ///< a [test]'s peak stress so far (its stop rule's)
  } loop_;
};

}  // namespace mesowave::dem
