#pragma once
// Scene files (TOML): everything one DEM run needs - the packing, the
// material, the time step and duration, actuators, sensors and outputs.
// Keys carry their unit in the name (E_dem_GPa, dt_ns, centre_mm); unknown
// keys are errors, so a typo cannot silently fall back to a default. The
// format is documented for users in docs/formats.md; shipped scenes live in
// pipeline/<study>/scenes/.
//
//   [scene]     name, description
//   [packing]   file (relative paths are relative to the working directory)
//   [experiment] file (relative to the scene file's folder): the study's experiment (experiment/experiment.hpp: specimen, transducers,
//               burst, record); its actuators become force actuators driven by its burst, its
//               sensors motion sensors, each at the same fractions of the packing's extent as of
//               the specimen's (patches keep their size); its record gives the duration. The
//               scene may add [[actuator]]s and [[sensor]]s of its own.
//   [material]  E_dem_GPa, nu_dem, friction_angle_deg, T_MPa, C_MPa (both optional:
//               absent = bonds never break), density_kg_m3 (optional: the packing's),
//               damping (alpha_d), bond_factor (C_f)
//   [time]      dt_ns, duration_ms
//   [model]     choice (auto | full | linear | chain), linear_validity_bound, energy_check_steps,
//               damping_law (local: Eq. 7 with alpha_d, the paper's | viscous: mass-proportional
//               viscous damping c = 4 alpha_d f_c of the same amplitude loss per cycle, 2 alpha_d,
//               at the bursts' centre frequency f_c - linear, so superposition holds)
//   [[actuator]] name, kind (force | displacement | velocity), where (face + centre_mm + patch_mm
//               [+ depth_mm] | point_mm | sphere = "first"/"last"), direction (inward | line | x | -x | ...),
//               amplitude_N (force) or amplitude_nm (displacement) with frequency_kHz, cycles;
//               velocity_mm_s (velocity: a platen moving at constant speed); delay_us
//   [[actuator]] kind = "wall": a rigid frictionless wall on a face (face, velocity_mm_s inward, delay_us)
//   [[sensor]]  name, quantity (acceleration | velocity | displacement), component
//               (normal | line | x | -x | y | ... | magnitude), where (as for actuators), sample_interval_ns;
//               or quantity = "force" with actuator = NAME: the force that actuator applies;
//               or quantity = "strain": an extensometer along component (x | y | z | line) between two
//               pads (face + centre_mm + gauge_mm + patch_mm) or between = ["first", "last"];
//               or quantity = "broken_bonds": the count of broken bonds
//   [test]      a virtual lab test read from those sensors (uniaxial_test.hpp): kind (compression |
//               tension), load, axial, lateral, broken_bonds (sensor names), area_mm2,
//               modulus_levels_pct or modulus_levels_MPa, stop_drop_pct, stop_armed_above_MPa,
//               stop_at_MPa, inertial_number_bound
//   [output]    snapshot_interval_us (0 = none)
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "mesowave/dem/contact/material.hpp"
#include "mesowave/dem/loading/motion_sensor.hpp"
#include "mesowave/dem/loading/sphere_selection.hpp"
#include "mesowave/dem/calibration/uniaxial_analysis.hpp"

namespace mesowave::dem {

/// Where an actuator or sensor sits.
struct SphereTarget {
  enum class Kind { patch, point, end } kind = Kind::patch;
  Patch patch;         ///< kind patch
  Vec3 point_m;        ///< kind point: the sphere nearest to it
  bool last = false;   ///< kind end: first or last sphere of a line
  std::string describe() const;
};

struct ActuatorSpec {
  std::string name;
  std::string kind = "force";       ///< a registered actuator kind (plugins.hpp): force | displacement | velocity | wall
  SphereTarget target;
  std::string direction = "inward"; ///< inward (needs a face) | line | -line | x | -x | y | -y | z | -z
  double amplitude = 0;             ///< N (force), m (displacement) or m/s (velocity, wall)
  double frequency_hz = 0;
  double cycles = 5;
  double delay_s = 0;
  double ramp_s = 0;                ///< velocity, wall: the time over which the velocity is reached
};

/// A scene's [[sensor]]: a registered kind over a set of spheres, with its own quantity and
/// sampling interval. The FEM's recording point is another concept with another name
/// (fem::ProbePoint, fem/case.hpp: one node, the case's quantity); both come from the lab's
/// experiment::Transducer where a scene or a case takes an experiment.
struct SensorSpec {
  std::string kind = "motion";  ///< a registered sensor kind (plugins.hpp): motion | force | strain | broken_bonds
  std::string name;
  std::string actuator;  ///< kind force: the actuator whose force it records
  MotionQuantity quantity = MotionQuantity::acceleration;  ///< kind motion (experiment/motion_quantity.hpp)
  std::string component = "normal";  ///< normal (outward, needs a face) | line | x | -x | ... | magnitude
  SphereTarget target;
  SphereTarget ends[2];              ///< kind strain: the extensometer's two pads
  double sample_interval_s = 0;      ///< 0: every step
};

struct Scene {
  std::filesystem::path source;  ///< the file it was read from, if any
  std::string name, description;
  std::filesystem::path packing_file;
  std::filesystem::path experiment_file;  ///< [experiment] file, if the transducers come from one
  std::string contact_law = "cohesive_frictional";  ///< a registered contact law (plugins.hpp)
  CohesiveFrictionalMaterial material;
  LawParameters law_parameters;  ///< the law's own [material] keys, SI
  bool density_given = false;  ///< false: take the packing file's particle density
  double dt_s = 0, duration_s = 0;
  std::string model = "auto";
  std::string damping_law = "local";  ///< local (Eq. 7) | viscous (c = 4 alpha_d f_c, mass-proportional)
  double linear_validity_bound = 1e-3;
  int energy_check_steps = 100;
  std::vector<ActuatorSpec> actuators;
  std::vector<SensorSpec> sensors;
  UniaxialTestSpec test;
  double snapshot_interval_s = 0;
};

/// `base`: the folder a relative [experiment] file is found in (read_scene_file: the scene's own).
Scene parse_scene(const std::string& text, const std::string& origin, const std::filesystem::path& base = {});

/// The keys of a scene's [material] table, in order (E_dem_GPa, nu_dem, ...).
const std::vector<std::string>& material_keys();
/// Sets one [material] value with the scene file's checks; InputError naming
/// the value as `name` ("scene.toml: [material].nu_dem", "--nu-dem") when it is
/// out of range or the key is unknown.
void set_material_value(Scene& scene, const std::string& key, double value, const std::string& name);

/// InputError for a missing file, bad TOML, unknown keys or values out of range.
Scene read_scene_file(const std::filesystem::path& path);

/// Unit vector of a direction or component name (x, -x, ...); for "inward" or
/// "normal" the face's inward/outward normal; for "line" / "-line" the axis of
/// a line of spheres (first to last sphere), given as `line`; zero vector for
/// "magnitude". InputError naming `who` when a face or a line is needed but missing.
Vec3 direction_vector(const std::string& name, const SphereTarget& target, const std::string& who,
                      const std::optional<Vec3>& line = std::nullopt, bool check_only = false);

}  // namespace mesowave::dem
