#pragma once
// The DEM's plug-ins, registered by name (LAMMPS style: pair_style, fix,
// compute): contact laws, actuator kinds and sensor kinds. Each entry is
// its factory, the scene keys it reads (with units and ranges), its rule for
// the model choice and its description for the run report; the scene parser,
// the simulation, the model choice and the run report only look names up.
//
// Adding one is one file (+ header) with a register_<id> function and one
// line MW_DEM_PLUGIN(id) in plugins.def. The list is explicit rather than a
// static registrar object in each file: the library is a static archive, and
// the linker drops an archive member nothing refers to, so a file holding only
// a registrar would silently vanish from every tool (--whole-archive or an
// OBJECT library would cure that for our tools but not for a user linking the
// archive); the explicit list also fixes the order (the order of the help texts
// and error messages) and runs at first use, never during static initialisation.
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "mesowave/dem/loading/actuator.hpp"
#include "mesowave/dem/contact/bond_network.hpp"
#include "mesowave/dem/contact/material.hpp"
#include "mesowave/dem/engine/model.hpp"
#include "mesowave/dem/scene/scene.hpp"
#include "mesowave/dem/scene/scene_keys.hpp"
#include "mesowave/dem/loading/sensor.hpp"
#include "mesowave/dem/loading/sphere_selection.hpp"
#include "mesowave/dem/engine/sphere_part.hpp"

namespace mesowave::dem {

/// One key a plug-in reads from its scene table: the unit is in the key's name (amplitude_N).
struct KeySpec {
  std::string key, unit;
  double min = 0, max = 0;
  std::string meaning;
  double fallback = 0;  ///< the value when the key is absent
};

/// Where an actuator or sensor acts, by packing index (what a second code needs to reproduce it).
struct Placement {
  std::string name;
  std::string kind;                      ///< force | displacement | velocity | acceleration | ...
  std::vector<std::uint32_t> spheres;    ///< packing indices, ascending (an extensometer: its first pad)
  Vec3 direction;                        ///< load direction or sensor component (zero: magnitude)
  double amplitude = 0, frequency_hz = 0, cycles = 0, delay_s = 0;  ///< actuators
  std::vector<std::uint32_t> spheres_b;  ///< an extensometer's second pad
};

// ---- contact laws ([material] law = "...") ----

/// What a law's factory gets.
struct LawInput {
  const CohesiveFrictionalMaterial& material;  ///< the parameters every law shares (Eqs. 3-7)
  const LawParameters& parameters;             ///< the law's own keys (material_parameters.hpp), SI
  std::optional<Vec3> line;                    ///< the axis of a line of spheres (the chain)
  Domain* domain = nullptr;  ///< several MPI ranks: the model holds its rank's share from the start (docs/mpi.md)
};

struct ContactLaw {
  std::string name;     ///< the scene's [material] law
  std::string summary;  ///< one line: what it is, with its equations
  /// Its own [material] keys beyond the shared ones (material_parameters.hpp),
  /// dimensionless or SI in the key's unit; LawInput::parameters holds them.
  std::vector<KeySpec> parameters;
  /// The models it provides: "full" (the law itself) and the shortcuts that
  /// stand in for it where valid ("linear", "chain"; model_choice.hpp).
  std::vector<std::string> models;
  /// Builds `model` (one of `models`).
  std::function<std::unique_ptr<Model>(const std::string& model, SpherePart, BondNetwork, const LawInput&)> make;
  /// The validity rule for the model choice: why `model` (a shortcut) cannot
  /// stand in for this law with these values, "" if it can.
  std::function<std::string(const std::string& model, const Scene&)> shortcut_obstacle;
  /// The law's own parameters for the run report (SI, keys with units).
  std::function<nlohmann::ordered_json(const LawParameters&)> describe;
};

// ---- actuator kinds ([[actuator]] kind = "...") ----

/// Where an actuator acts, once its spheres are known.
struct ActuatorSite {
  const ActuatorSpec& spec;
  const std::vector<std::size_t>& spheres;  ///< model numbering
  Vec3 direction;
  SpherePart& statics;  ///< the spheres at step 0, a rank's part (the model is made after; a wall selects)
  const Box& box;
  const CohesiveFrictionalMaterial& material;
  double duration_s;
};

struct ActuatorKind {
  std::string name, summary;
  std::vector<KeySpec> keys;
  /// Reads the kind's keys of an [[actuator]] table (name and kind are read).
  std::function<void(SceneKeys&, ActuatorSpec&)> parse;
  std::function<std::unique_ptr<Actuator>(const ActuatorSite&)> make;
  /// For the model choice's validity estimate: the largest force it puts on
  /// one of its `spheres` spheres, given the stiffest K_n there [N].
  std::function<double(const ActuatorSpec&, std::size_t spheres, double stiffest_kn, double duration_s)> peak_sphere_force;
  std::string amplitude_key;  ///< the amplitude's scene key (amplitude_N); "" if it has none of its own
  std::string report_key;     ///< the amplitude's key in the run report (SI: amplitude_N, amplitude_m, velocity_m_s)
  bool moving = false;        ///< a platen moving at a speed (mw-dem --velocity-mm-s sets it)
};

// ---- sensor kinds ([[sensor]] quantity = "...") ----

/// Where a sensor reads, once the model exists.
struct SensorSite {
  const SensorSpec& spec;
  const SphereStatics& statics;  ///< the spheres at step 0 (the model is made after)
  /// The spheres of each of targets(spec), model numbering.
  const std::vector<std::vector<std::size_t>>& groups;
  std::optional<Vec3> line;
  std::int64_t every;  ///< steps between samples
  const std::vector<std::unique_ptr<Actuator>>& actuators;
};

struct SensorKind {
  std::string name;                     ///< SensorSpec::kind
  std::vector<std::string> quantities;  ///< the [[sensor]] quantity values it answers to
  std::string summary;
  std::vector<KeySpec> keys;
  /// Reads the kind's keys (name, quantity and sample_interval_ns are read).
  std::function<void(SceneKeys&, SensorSpec&, const std::string& quantity, const std::vector<ActuatorSpec>&)> parse;
  /// The sphere groups it reads, with a label for errors (" (first pad)"), resolved before the model is built.
  std::function<std::vector<std::pair<const SphereTarget*, std::string>>(const SensorSpec&)> targets;
  /// Builds the sensor and says where it sits (the run report's sensor_points).
  std::function<std::unique_ptr<Sensor>(const SensorSite&, Placement&)> make;
};

/// Plug-ins of one sort, in registration order.
template <class Entry>
class Registry {
public:
  explicit Registry(std::string what) : what_(std::move(what)) {}
  void add(Entry entry);  ///< std::logic_error for a name registered twice
  const Entry* find(const std::string& name) const {
    for (const auto& e : entries_)
      if (e.name == name) return &e;
    return nullptr;
  }
  /// InputError "`who` (\"x\") must be a, b or c" for an unknown name.
  const Entry& get(const std::string& name, const std::string& who) const;
  const std::vector<Entry>& entries() const { return entries_; }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& e : entries_) out.push_back(e.name);
    return out;
  }
  /// "a, b or c".
  std::string listing() const;

private:
  std::string what_;
  std::vector<Entry> entries_;
};

/// Every plug-in; a plug-in's register_<id>(Plugins&) adds its entries here.
struct Plugins {
  Registry<ContactLaw> laws{"contact law"};
  Registry<ActuatorKind> actuators{"actuator kind"};
  Registry<SensorKind> sensors{"sensor kind"};
};

/// Filled on first use from plugins.def.
const Registry<ContactLaw>& contact_laws();
const Registry<ActuatorKind>& actuator_kinds();
const Registry<SensorKind>& sensor_kinds();

/// The sensor kind answering to a [[sensor]] quantity; InputError naming `who` otherwise.
const SensorKind& sensor_kind_for_quantity(const std::string& quantity, const std::string& who);

/// What the kinds' readers share (scene.cpp): a target (face + centre_mm +
/// patch_mm [+ depth_mm] | point_mm | sphere) and a ramp time ramp_us.
SphereTarget read_target(SceneKeys& k);
double read_ramp(SceneKeys& k);
/// A load on spheres (force, displacement, velocity): target, direction, the
/// kind's amplitude_key (times `scale` to SI), then a burst (frequency_kHz,
/// cycles) or a ramp (ramp_us), and delay_us.
void read_actuator_load(SceneKeys& k, ActuatorSpec& spec, double scale, bool burst);
/// Model `model` (full | linear | chain) of contact law `law` (tests, benchmarks).
std::unique_ptr<Model> make_model(const std::string& law, const std::string& model, SpherePart spheres, BondNetwork bonds,
                                  const CohesiveFrictionalMaterial& material, const LawParameters& parameters = {},
                                  std::optional<Vec3> line = std::nullopt);
/// A moving platen's (velocity, wall) largest force on one sphere for the model
/// choice: the stiffest K_n there times the travel over the whole run.
double platen_peak_force(const ActuatorSpec& a, std::size_t spheres, double stiffest_kn, double duration_s);
/// Packing indices of model spheres, ascending (a Placement's spheres).
std::vector<std::uint32_t> packing_indices(const SphereStatics& statics, const std::vector<std::size_t>& spheres);

}  // namespace mesowave::dem
