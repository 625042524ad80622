#pragma once
// An mw-fem run assembled from its description (FemCase: the body, the
// burst, the sensors, the record) and the pieces that are not the solver:
// where the burst is applied, where signals are recorded, the time step and
// sampling, the threads, the space-time record file and the cost report.
#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "mesowave/core/threads.hpp"
#include "mesowave/experiment/experiment.hpp"
#include "mesowave/fem/solver.hpp"

namespace mesowave::fem {

/// Where mw-fem records a signal: a named point whose nearest node's dof becomes a Probe
/// (make_probes), with an optional component. Not the DEM's SensorSpec (dem/scene/scene.hpp),
/// which is a scene's [[sensor]] table: a registered sensor kind (motion, force, strain,
/// broken bonds) over a set of spheres (a patch, a point, a line's end), its own quantity and
/// sampling interval. A probe point has none of those - one node, the case's one quantity
/// (FemCase::quantity), every sample - so the two are different concepts with different names;
/// both are made from the lab's transducers (experiment::Transducer), each by its solver.
/// mw-fem --sensor "S=0,0,1000" or "B=25,50,25/y": the name, the point in mm and the component
/// (x | y | z | r | normal; built in code also -x | -y | -z | -r: the opposite sign).
struct ProbePoint {
  std::string name;
  std::array<double, 3> position_m{};
  std::string component;  ///< "" = the caller's default
};
ProbePoint parse_probe_point(const std::string& text);
/// "25,50,0" in mm -> metres.
std::array<double, 3> parse_point_mm(const std::string& text, const std::string& what);

/// The axis (0, 1, 2) of the box face a point lies on (within tol), and whether
/// it is the upper face; nullopt for an interior point.
std::optional<std::pair<int, bool>> box_face_of(const std::array<double, 3>& p, const std::array<double, 3>& size,
                                                double tol);

/// Probes at the nodes nearest the points; InputError for a point
/// farther than one mesh size from any node (outside the body). A component
/// "normal" on a box needs `box_size`.
std::vector<Probe> make_probes(const FemModel& model, const std::vector<ProbePoint>& points, MotionQuantity quantity,
                               const std::string& default_component,
                               const std::optional<std::array<double, 3>>& box_size = std::nullopt);

/// A force on the plane coordinate[axis] = value at `point` in direction `component`
/// (0, 1, 2) pointing `sign` (+1 or -1): on the nearest node if radius == 0,
/// else a uniform traction over the face cells within `radius` of the point.
BurstLoad make_load(const FemModel& model, int axis, double value, const std::array<double, 3>& point,
                    double patch_radius_m, int component, double sign, const signal::HannBurst& burst);

/// Time step and sampling: dt = sample_dt / stride with the smallest stride that
/// keeps dt <= the stable step, or the given dt (InputError above the stable step
/// or when the sampling interval is not a whole number of steps).
struct Stepping {
  double dt_s = 0, sample_dt_s = 0;
  std::int64_t steps = 0, stride = 1;
};
Stepping choose_stepping(const FemModel& model, double duration_s, double sample_dt_s,
                         std::optional<double> dt_s = std::nullopt);

/// One wave run on a continuum (the rod paper's Abaqus/Explicit reference,
/// Section 4.3.1): a Hann-burst force on a rod or a box, in SI units.
struct FemCase {
  enum class Body { rod, box } body = Body::rod;
  IsotropicMaterial material;
  double mesh_m = 1e-3;
  // Rod along z, ends z = 0 and z = L: the force at the centre of z = 0, default sensor S at the far end's centre.
  double radius_m = 0, length_m = 0;
  std::string rod_model = "axisymmetric";  ///< axisymmetric | 3d
  std::optional<double> spacetime_step_m;  ///< rod: record the axial quantity along the axis every this far
  // Box [0,X] x [0,Y] x [0,Z]: the force normal to the face the source lies on, pushing into the body.
  std::array<double, 3> size_m{}, source_m{};
  double frequency_hz = 100e3, cycles = 5, force_N = 1;
  double patch_radius_m = 0;  ///< 0: a point force; else a uniform traction over the face within it
  double alpha_damping_per_s = 0;
  double duration_s = 1.5e-3, sample_dt_s = 0.1e-6;
  std::optional<double> dt_s;  ///< default: choose_stepping's
  MotionQuantity quantity = MotionQuantity::acceleration;
  std::vector<ProbePoint> probe_points;  ///< mw-fem --sensor; a rod without any records S at the far end's centre
  int threads = 0;  ///< requested (core/threads.hpp; 0: the machine's free cores)
};

/// The case of a study's experiment (experiment/experiment.hpp), on a specimen `scale` times
/// its size: a box as Body::box (the actuator's centre the source, its patch the equal-area
/// disc, its sensors at their positions, "normal" their face's outward normal); a cylinder as
/// Body::rod, axisymmetric rings about its axis. InputError, naming the transducer and the
/// reason, for what this FEM cannot represent: more than one actuator, a burst delay, sensors
/// of different quantities, a magnitude component; on a cylinder, an actuator anywhere but on
/// the axis of the z- end pushing inward (the load would not be axisymmetric and the ring
/// model needs it to be; there is no 3D cylinder reference) or a sensor component other than
/// normal (radial on the curved face, axial on the ends) or z. The burst and record come from
/// the experiment; set a field after this call to override it.
void apply_experiment(FemCase& c, const experiment::Experiment& e, double scale = 1.0);

/// The material of a run: each value given (mw-fem's --E-GPa, --nu, --density-kg-m3) beats the
/// specimen's (an experiment that prints its material, as the steel rod's); InputError naming
/// the option for a value neither gives.
IsotropicMaterial material_of(std::optional<double> E_GPa, std::optional<double> nu, std::optional<double> density_kg_m3,
                              const experiment::Specimen* specimen);

/// `mw-fem rod --experiment`: the experiment's rod (experiment::rod_of: a cylinder whose file gives
/// its material), at `length_mm` if given - its one override, the quick pipeline's shorter rod
/// (experiment::with_length: the transducers stay on the ends). InputError for a radius given
/// beside it: the rod's radius is the file's.
experiment::Experiment rod_experiment(const experiment::Experiment& e, std::optional<double> radius_mm,
                                      std::optional<double> length_mm);
/// `mw-fem rod` without an experiment: the rod of --radius-mm and --length-mm (both needed).
void set_rod_size(FemCase& c, std::optional<double> radius_mm, std::optional<double> length_mm);

/// The case as a model ready to run: mesh, load, probes, stepping.
struct FemSetup {
  FemCase spec;
  FemModel model;
  BurstLoad load;
  std::vector<Probe> probes;
  Stepping stepping;
  std::optional<SpaceTimeRequest> spacetime;
};
/// InputError for a bad material, a source off the box's faces, a box without
/// sensors, a sensor outside the body, an unknown rod model.
FemSetup assemble_fem_case(const FemCase& spec);

struct FemRun {
  ExplicitResult result;  ///< the probes' signals, then the excitation (force, sampled like them)
  ThreadChoice threads;
  std::map<std::string, std::string> attributes;  ///< for the signal file: model, solver, mesh, dt, burst
};
/// Runs it on the threads of core/threads.hpp's rule (at least 4000 elements a thread).
FemRun run_fem_case(const FemSetup& setup, const std::function<void(std::int64_t)>& progress = {});
/// What every run's record carries besides the probes' signals (run_fem_case's and
/// superpose_fem's alike): the excitation signal (the burst, sampled like them) and the
/// signal file's attributes.
void complete_fem_run(const FemSetup& setup, FemRun& run);

/// The run's JSON report: model, mesh, stable step, stepping, threads and why, cost.
nlohmann::ordered_json fem_report(const FemSetup& setup, const FemRun& run, double peak_rss_MiB,
                                  const std::filesystem::path& signals);

/// Space-time record along a line of nodes: HDF5 with /spacetime/samples
/// [time, position], attributes t0_s, dt_s, quantity, unit, component and the
/// dataset position_m.
void write_spacetime_file(const std::filesystem::path& path, const std::vector<double>& samples,
                          const SpaceTimeRequest& request, double dt_s, const std::string& component,
                          const std::map<std::string, std::string>& attributes);

/// Axial dofs of the rod axis nodes every `step_m` along z (rod models).
SpaceTimeRequest rod_axis_line(const FemModel& model, double step_m, MotionQuantity quantity);

}  // namespace mesowave::fem
