#include "mesowave/dem/scene/scene.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <sstream>
#include <toml++/toml.h>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/dem/contact/material_parameters.hpp"
#include "mesowave/dem/scene/plugins.hpp"
#include "mesowave/dem/scene/scene_keys.hpp"
#include "mesowave/experiment/experiment.hpp"

namespace mesowave::dem {
namespace {

const toml::table& table_or_empty(const toml::table& root, const std::string& key, const std::string& origin) {
  static const toml::table empty;
  const toml::node* n = root.get(key);
  if (!n) return empty;
  if (const toml::table* t = n->as_table()) return *t;
  throw InputError(origin + ": [" + key + "] must be a table");
}

Vec3 vec_mm(const std::vector<double>& v) { return {v[0] * units::mm, v[1] * units::mm, v[2] * units::mm}; }

UniaxialTestSpec read_test(SceneKeys& k, const std::vector<SensorSpec>& sensors) {
  UniaxialTestSpec t;
  const std::string kind = k.text("kind", "");
  if (kind == "compression") t.kind = UniaxialTestSpec::Kind::compression;
  else if (kind == "tension") t.kind = UniaxialTestSpec::Kind::tension;
  else throw InputError(k.where() + ".kind (\"" + kind + "\") must be compression or tension");
  auto names = [&](const std::string& key, const std::string& want, const char* what, bool required) {
    std::vector<std::string> out;
    const toml::node* n = k.get(key);
    if (!n) {
      if (required) throw InputError(k.where() + " needs " + key + " = [sensor names] (" + what + ")");
      return out;
    }
    if (auto single = n->value<std::string>()) out.push_back(*single);
    else if (const toml::array* a = n->as_array())
      for (const auto& e : *a) {
        auto v = e.value<std::string>();
        if (!v) throw InputError(k.where() + "." + key + " must list sensor names");
        out.push_back(*v);
      }
    else throw InputError(k.where() + "." + key + " must list sensor names");
    if (out.empty() && required) throw InputError(k.where() + "." + key + " is empty (" + what + ")");
    for (const auto& name : out) {
      const SensorSpec* found = nullptr;
      for (const auto& s : sensors) if (s.name == name) found = &s;
      if (!found) throw InputError(k.where() + "." + key + ": no sensor named \"" + name + "\"");
      if (found->kind != want) throw InputError(k.where() + "." + key + ": sensor " + name + " is not " + what);
    }
    return out;
  };
  t.load = names("load", "force", "a force sensor", true);
  t.axial = names("axial", "strain", "an extensometer", true);
  t.lateral = names("lateral", "strain", "an extensometer", false);
  const auto broken = names("broken_bonds", "broken_bonds", "a broken_bonds sensor", false);
  if (broken.size() > 1) throw InputError(k.where() + ".broken_bonds names one sensor");
  if (!broken.empty()) t.broken_bonds = broken.front();
  std::optional<double> interval;
  for (const auto& name : t.sensor_names())
    for (const auto& s : sensors)
      if (s.name == name) {
        if (interval && *interval != s.sample_interval_s)
          throw InputError(k.where() + ": the test's sensors must sample together; " + name +
                           " has another sample_interval_ns than " + t.load.front());
        interval = s.sample_interval_s;
      }
  if (auto area = k.number("area_mm2")) t.area_m2 = require_positive(k.where() + ".area_mm2", *area, "mm2") * units::mm * units::mm;
  const bool pct = k.has("modulus_levels_pct"), abs = k.has("modulus_levels_MPa");
  if (pct && abs) throw InputError(k.where() + ": give modulus_levels_pct or modulus_levels_MPa, not both");
  if (pct || abs) {
    const auto v = *k.numbers(pct ? "modulus_levels_pct" : "modulus_levels_MPa", 2);
    const std::string key = k.where() + (pct ? ".modulus_levels_pct" : ".modulus_levels_MPa");
    if (!(v[0] >= 0 && v[1] > v[0] && (abs || v[1] < 100)))
      throw InputError(key + " [" + format_number(v[0]) + ", " + format_number(v[1]) + "] must rise from a lower to an upper level" +
                       (pct ? " below 100 % of the peak" : ""));
    t.levels_absolute = abs;
    t.levels[0] = pct ? v[0] / 100 : v[0] * units::MPa;
    t.levels[1] = pct ? v[1] / 100 : v[1] * units::MPa;
  }
  t.stop_drop = require_in_range(k.where() + ".stop_drop_pct", k.number("stop_drop_pct", 0.0), 0.0, 99.0, "%") / 100;
  t.stop_armed_above_Pa = require_in_range(k.where() + ".stop_armed_above_MPa", k.number("stop_armed_above_MPa", 0.0), 0.0, 1e6, "MPa") * units::MPa;
  if (t.stop_drop > 0 && !k.has("stop_armed_above_MPa"))
    throw InputError(k.where() + ": stop_drop_pct needs stop_armed_above_MPa, the stress above which a drop counts (a "
                     "testing machine's break detection; the first load steps are noisy)");
  t.stop_at_Pa = require_in_range(k.where() + ".stop_at_MPa", k.number("stop_at_MPa", 0.0), 0.0, 1e6, "MPa") * units::MPa;
  t.inertial_number_bound = require_in_range(k.where() + ".inertial_number_bound", k.number("inertial_number_bound", 1e-4), 0.0, 1.0);
  return t;
}
}  // namespace

namespace {

/// A curved-face patch's azimuth from its relative centre (the bounding box of a cylinder is square
/// in x-y, so fractions give the angle); InputError for a centre off the circle.
void place_on_curved_face(Patch& patch, const std::string& where) {
  const double u = patch.centre_rel.x - 0.5, v = patch.centre_rel.y - 0.5;
  if (std::abs(std::hypot(u, v) - 0.5) > 1e-6)
    throw InputError(where + ".centre_rel (" + format_number(patch.centre_rel.x) + ", " + format_number(patch.centre_rel.y) +
                     ", ...) is not on the curved face: x and y must lie on the circle of radius 0.5 about (0.5, 0.5)");
  patch.face.azimuth_rad = std::atan2(v, u);
}

}  // namespace

SphereTarget read_target(SceneKeys& k) {
  SphereTarget t;
  const bool has_face = k.has("face"), has_point = k.has("point_mm"), has_sphere = k.has("sphere");
  if (int(has_face) + int(has_point) + int(has_sphere) != 1)
    throw InputError(k.where() + " needs exactly one of face (with centre_mm and patch_mm), point_mm or sphere");
  if (has_face) {
    t.kind = SphereTarget::Kind::patch;
    t.patch.face = Face::parse(*k.text("face"), true);
    if (k.has("centre_mm") && k.has("centre_rel")) throw InputError(k.where() + ": give centre_mm or centre_rel, not both");
    if (t.patch.face.curved && !k.has("centre_rel"))
      throw InputError(k.where() + ": a patch on the curved face takes centre_rel (fractions of the packing's extent: "
                       "the cylinder's axis is the centre of its bounding box)");
    auto centre = k.numbers(k.has("centre_rel") ? "centre_rel" : "centre_mm", 3);
    auto size = k.numbers("patch_mm", 2);
    if (!centre || !size)
      throw InputError(k.where() + " on a face needs centre_mm = [x, y, z] (or centre_rel, fractions of the packing's "
                       "extent) and patch_mm = [a, b]");
    t.patch.relative = k.has("centre_rel");
    if (t.patch.relative) {
      for (int d = 0; d < 3; ++d)
        t.patch.centre_rel[d] = require_in_range(k.where() + ".centre_rel", (*centre)[std::size_t(d)], 0.0, 1.0);
      if (t.patch.face.curved) place_on_curved_face(t.patch, k.where());
    } else {
      t.patch.centre_m = vec_mm(*centre);
    }
    t.patch.size_m[0] = require_positive(k.where() + ".patch_mm", (*size)[0], "mm") * units::mm;
    t.patch.size_m[1] = require_positive(k.where() + ".patch_mm", (*size)[1], "mm") * units::mm;
    if (auto depth = k.number("depth_mm")) t.patch.depth_m = require_positive(k.where() + ".depth_mm", *depth, "mm") * units::mm;
  } else if (has_point) {
    t.kind = SphereTarget::Kind::point;
    t.point_m = vec_mm(*k.numbers("point_mm", 3));
  } else {
    t.kind = SphereTarget::Kind::end;
    const std::string which = *k.text("sphere");
    if (which != "first" && which != "last")
      throw InputError(k.where() + ".sphere (\"" + which + "\") must be \"first\" or \"last\" (the ends of a line)");
    t.last = which == "last";
  }
  return t;
}


namespace {

void add_experiment_transducers(Scene& s, const experiment::Experiment& e,
                                const std::function<void(const std::string&)>& check_name) {
  for (const experiment::Transducer& t : e.transducers) {
    check_name(t.name);
    SphereTarget target;
    target.kind = SphereTarget::Kind::patch;
    Patch& patch = target.patch;
    patch.face = Face::parse(t.face, true);
    if (patch.face.curved) patch.face.azimuth_rad = experiment::azimuth(e.specimen, t.centre_m);
    // The same fractions of the packing's extent as of the specimen's: the scene fits a smaller model of the test.
    patch.relative = true;
    const auto rel = experiment::relative_position(e.specimen, t.centre_m);
    patch.centre_rel = {rel[0], rel[1], rel[2]};
    patch.size_m[0] = t.patch_m[0];
    patch.size_m[1] = t.patch_m[1];
    if (t.role == experiment::Transducer::Role::actuator) {
      ActuatorSpec a;
      a.name = t.name;
      a.kind = "force";
      a.target = target;
      a.direction = t.direction;
      a.amplitude = e.burst.amplitude_N;
      a.frequency_hz = e.burst.frequency_hz;
      a.cycles = e.burst.cycles;
      a.delay_s = e.burst.delay_s;
      s.actuators.push_back(std::move(a));
    } else {
      SensorSpec m;
      m.kind = "motion";
      m.name = t.name;
      m.quantity = t.quantity;
      m.component = t.component;
      m.target = target;
      s.sensors.push_back(std::move(m));
    }
  }
}

}  // namespace

double read_ramp(SceneKeys& k) {
  return require_in_range(k.where() + ".ramp_us", k.number("ramp_us", 0.0), 0.0, 1e12, "us") * units::us;
}

void read_actuator_load(SceneKeys& k, ActuatorSpec& spec, double scale, bool burst) {
  spec.target = read_target(k);
  spec.direction = k.text("direction", spec.target.kind == SphereTarget::Kind::patch ? "inward" : "");
  if (spec.direction.empty()) throw InputError(k.where() + " needs direction (x, -x, ...) when it is not on a face");
  direction_vector(spec.direction, spec.target, k.where(), std::nullopt, true);
  if (spec.direction == "magnitude" || spec.direction == "normal")
    throw InputError(k.where() + ".direction must be inward or an axis (x, -x, ...)");
  const std::string& key = actuator_kinds().get(spec.kind, k.where() + ".kind").amplitude_key;
  for (const auto& other : actuator_kinds().entries())
    if (!other.amplitude_key.empty() && other.amplitude_key != key && k.has(other.amplitude_key))
      throw InputError(k.where() + ": a " + spec.kind + " actuator takes " + key + ", not " + other.amplitude_key);
  spec.amplitude = require_finite(k.where() + "." + key, k.required_number(key)) * scale;
  if (burst) {
    spec.frequency_hz = require_positive(k.where() + ".frequency_kHz", k.required_number("frequency_kHz"), "kHz") * units::kHz;
    spec.cycles = require_positive(k.where() + ".cycles", k.number("cycles", 5.0));
  }
  spec.delay_s = require_in_range(k.where() + ".delay_us", k.number("delay_us", 0.0), 0.0, 1e9, "us") * units::us;
  if (!burst) spec.ramp_s = read_ramp(k);
}

std::string SphereTarget::describe() const {
  auto mm = [](const Vec3& v) {
    std::string text = "(";
    text += format_number(v.x / units::mm);
    text += ", ";
    text += format_number(v.y / units::mm);
    text += ", ";
    text += format_number(v.z / units::mm);
    text += ") mm";
    return text;
  };
  switch (kind) {
    case Kind::patch:
      if (std::isinf(patch.size_m[0])) return "face " + patch.face.name();
      return format_number(patch.size_m[0] / units::mm) + " x " + format_number(patch.size_m[1] / units::mm) +
             " mm patch on face " + patch.face.name() + " at " +
             (patch.relative ? "(" + format_number(patch.centre_rel.x) + ", " + format_number(patch.centre_rel.y) + ", " +
                                   format_number(patch.centre_rel.z) + ") of the packing's extent"
                             : mm(patch.centre_m));
    case Kind::point: return "sphere nearest to " + mm(point_m);
    case Kind::end: return last ? "last sphere of the line" : "first sphere of the line";
  }
  return "";
}

Vec3 direction_vector(const std::string& name, const SphereTarget& target, const std::string& who,
                      const std::optional<Vec3>& line, bool check_only) {
  if (name == "line" || name == "-line") {
    if (check_only) return {1, 0, 0};
    if (!line) throw InputError(who + ": direction \"" + name + "\" needs a packing whose centres lie on one line");
    return name == "line" ? *line : -*line;
  }
  if (name == "inward" || name == "normal") {
    if (target.kind != SphereTarget::Kind::patch)
      throw InputError(who + ": \"" + name + "\" needs a face; give x, -x, y, -y, z or -z instead");
    const Vec3 out = target.patch.face.outward_normal();
    return name == "normal" ? out : -out;
  }
  if (name == "magnitude") return {};
  const bool minus = !name.empty() && name[0] == '-';
  const std::string axis = minus ? name.substr(1) : (name.size() == 2 && name[0] == '+' ? name.substr(1) : name);
  if (axis != "x" && axis != "y" && axis != "z")
    throw InputError(who + ": direction \"" + name + "\" must be inward/normal, line, magnitude, or x, -x, y, -y, z, -z");
  Vec3 v;
  v[axis[0] - 'x'] = minus ? -1.0 : 1.0;
  return v;
}

const std::vector<std::string>& material_keys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k;
    for (const auto& p : material_parameters()) k.push_back(p.key);
    return k;
  }();
  return keys;
}

void set_material_value(Scene& s, const std::string& key, double value, const std::string& name) {
  const MaterialParameter& p = material_parameter(key, name);
  const double checked = p.positive ? require_positive(name, value, p.unit) : require_in_range(name, value, p.min, p.max, p.unit);
  s.material.*p.field = p.to_si(checked);
  if (p.field == &CohesiveFrictionalMaterial::density_kg_m3) s.density_given = true;
}

Scene parse_scene(const std::string& text, const std::string& origin, const std::filesystem::path& base) {
  toml::table root;
  try {
    root = toml::parse(text, origin);
  } catch (const toml::parse_error& e) {
    throw InputError(origin + ":" + std::to_string(e.source().begin.line) + ": " + std::string(e.description()));
  }
  static const std::set<std::string> sections = {"scene", "packing", "experiment", "material", "time", "model",
                                                 "actuator", "sensor", "test", "output"};
  for (const auto& [key, node] : root)
    if (!sections.count(std::string(key.str())))
      throw InputError(origin + ": unknown section [" + std::string(key.str()) + "]");

  Scene s;
  {
    SceneKeys k(table_or_empty(root, "scene", origin), origin + ": [scene]");
    s.name = k.text("name", "scene");
    s.description = k.text("description", "");
    k.finish();
  }
  {
    SceneKeys k(table_or_empty(root, "packing", origin), origin + ": [packing]");
    auto file = k.text("file");
    if (!file || file->empty()) throw InputError(origin + ": [packing] needs file (a packing HDF5 file from mw-pack)");
    s.packing_file = *file;
    k.finish();
  }
  {
    SceneKeys k(table_or_empty(root, "material", origin), origin + ": [material]");
    if (!k.has("E_dem_GPa")) throw InputError(k.where() + " needs E_dem_GPa");
    for (const std::string& key : material_keys())
      if (auto v = k.number(key)) set_material_value(s, key, *v, k.where() + "." + key);
    s.contact_law = k.text("law", s.contact_law);
    for (const KeySpec& p : contact_laws().get(s.contact_law, k.where() + ".law").parameters)
      s.law_parameters[p.key] = require_in_range(k.where() + "." + p.key, k.number(p.key, p.fallback), p.min, p.max, p.unit);
    k.finish();
  }
  std::optional<experiment::Experiment> lab;
  if (root.contains("experiment")) {
    SceneKeys k(table_or_empty(root, "experiment", origin), origin + ": [experiment]");
    auto file = k.text("file");
    if (!file || file->empty())
      throw InputError(k.where() + " needs file (an experiment description, lab-data/<study>/experiment.toml)");
    s.experiment_file = (base / *file).lexically_normal();
    k.finish();
    lab = experiment::read_experiment_file(s.experiment_file);
  }
  {
    SceneKeys k(table_or_empty(root, "time", origin), origin + ": [time]");
    s.dt_s = require_positive(k.where() + ".dt_ns", k.required_number("dt_ns"), "ns") * units::ns;
    if (lab && k.has("duration_ms"))
      throw InputError(k.where() + ".duration_ms: the experiment's [record] gives the duration (" +
                       s.experiment_file.string() + "; --duration-ms overrides it for one run)");
    s.duration_s = lab ? lab->record.duration_s
                       : require_positive(k.where() + ".duration_ms", k.required_number("duration_ms"), "ms") * units::ms;
    k.finish();
  }
  {
    SceneKeys k(table_or_empty(root, "model", origin), origin + ": [model]");
    s.model = k.text("choice", "auto");
    if (s.model != "auto" && s.model != "full" && s.model != "linear" && s.model != "chain")
      throw InputError(k.where() + ".choice (\"" + s.model + "\") must be auto, full, linear or chain");
    s.linear_validity_bound = require_in_range(k.where() + ".linear_validity_bound", k.number("linear_validity_bound", 1e-3), 1e-12, 1.0);
    s.energy_check_steps = int(require_in_range(k.where() + ".energy_check_steps", k.number("energy_check_steps", 100), 1, 1e9));
    s.damping_law = k.text("damping_law", "local");
    if (s.damping_law != "local" && s.damping_law != "viscous")
      throw InputError(k.where() + ".damping_law (\"" + s.damping_law + "\") must be local or viscous");
    k.finish();
  }
  std::set<std::string> names;
  auto unique_name = [&](const std::string& name, const std::string& where) {
    if (name.empty()) throw InputError(where + " needs a name");
    if (!names.insert(name).second) throw InputError(where + ": the name \"" + name + "\" is used twice");
    for (char c : name)
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.'))
        throw InputError(where + ": name \"" + name + "\" may hold only letters, digits, - _ and .");
  };
  if (lab) add_experiment_transducers(s, *lab, [&](const std::string& name) { unique_name(name, origin + ": " + s.experiment_file.string()); });
  if (const toml::node* list = root.get("actuator")) {
    const toml::array* a = list->as_array();
    if (!a) throw InputError(origin + ": actuators are [[actuator]] tables");
    for (std::size_t i = 0; i < a->size(); ++i) {
      const toml::table* t = (*a)[i].as_table();
      if (!t) throw InputError(origin + ": actuators are [[actuator]] tables");
      SceneKeys k(*t, origin + ": [[actuator]] " + std::to_string(i + 1));
      ActuatorSpec spec;
      spec.name = k.text("name", "");
      unique_name(spec.name, k.where());
      spec.kind = k.text("kind", "force");
      actuator_kinds().get(spec.kind, k.where() + ".kind").parse(k, spec);
      k.finish();
      s.actuators.push_back(std::move(spec));
    }
  }
  if (const toml::node* list = root.get("sensor")) {
    const toml::array* a = list->as_array();
    if (!a) throw InputError(origin + ": sensors are [[sensor]] tables");
    for (std::size_t i = 0; i < a->size(); ++i) {
      const toml::table* t = (*a)[i].as_table();
      if (!t) throw InputError(origin + ": sensors are [[sensor]] tables");
      SceneKeys k(*t, origin + ": [[sensor]] " + std::to_string(i + 1));
      SensorSpec spec;
      spec.name = k.text("name", "");
      unique_name(spec.name, k.where());
      const std::string quantity = k.text("quantity", "acceleration");
      const SensorKind& kind = sensor_kind_for_quantity(quantity, k.where());
      spec.kind = kind.name;
      kind.parse(k, spec, quantity, s.actuators);
      if (auto interval = k.number("sample_interval_ns"))
        spec.sample_interval_s = require_positive(k.where() + ".sample_interval_ns", *interval, "ns") * units::ns;
      k.finish();
      s.sensors.push_back(std::move(spec));
    }
  }
  if (root.contains("test")) {
    SceneKeys k(table_or_empty(root, "test", origin), origin + ": [test]");
    s.test = read_test(k, s.sensors);
    k.finish();
  }
  {
    SceneKeys k(table_or_empty(root, "output", origin), origin + ": [output]");
    s.snapshot_interval_s = require_in_range(k.where() + ".snapshot_interval_us", k.number("snapshot_interval_us", 0.0),
                                             0.0, 1e12, "us") * units::us;
    k.finish();
  }
  if (s.sensors.empty()) throw InputError(origin + ": a scene needs at least one [[sensor]]");
  return s;
}

Scene read_scene_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError("scene file " + path.string() + " cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  Scene s = parse_scene(text.str(), path.string(), path.parent_path());
  s.source = path;
  return s;
}

}  // namespace mesowave::dem
