#include "mesowave/dem/scene.hpp"

#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <set>
#include <sstream>
#include <toml++/toml.h>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"

namespace mesowave::dem {
namespace {

// A TOML table whose keys must all be read: finish() names any left over.
class Keys {
public:
  Keys(const toml::table& table, std::string where) : table_(table), where_(std::move(where)) {}

  const toml::node* get(const std::string& key) {
    used_.insert(key);
    return table_.get(key);
  }
  bool has(const std::string& key) const { return table_.contains(key); }

  std::optional<double> number(const std::string& key) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    if (auto v = n->value<double>()) return *v;
    throw InputError(where_ + "." + key + " must be a number");
  }
  double number(const std::string& key, double fallback) { return number(key).value_or(fallback); }
  double required_number(const std::string& key) {
    auto v = number(key);
    if (!v) throw InputError(where_ + " needs " + key);
    return *v;
  }
  std::optional<std::string> text(const std::string& key) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    if (auto v = n->value<std::string>()) return *v;
    throw InputError(where_ + "." + key + " must be a string");
  }
  std::string text(const std::string& key, const std::string& fallback) { return text(key).value_or(fallback); }
  std::optional<std::vector<double>> numbers(const std::string& key, std::size_t count) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    const toml::array* a = n->as_array();
    if (!a || a->size() != count)
      throw InputError(where_ + "." + key + " must be an array of " + std::to_string(count) + " numbers");
    std::vector<double> out;
    for (const auto& e : *a) {
      auto v = e.value<double>();
      if (!v) throw InputError(where_ + "." + key + " must be an array of " + std::to_string(count) + " numbers");
      out.push_back(*v);
    }
    return out;
  }
  const std::string& where() const { return where_; }
  void finish() const {
    for (const auto& [key, node] : table_)
      if (!used_.count(std::string(key.str())))
        throw InputError(where_ + " has an unknown key \"" + std::string(key.str()) + "\"");
  }

private:
  const toml::table& table_;
  std::string where_;
  std::set<std::string> used_;
};

const toml::table& table_or_empty(const toml::table& root, const std::string& key, const std::string& origin) {
  static const toml::table empty;
  const toml::node* n = root.get(key);
  if (!n) return empty;
  if (const toml::table* t = n->as_table()) return *t;
  throw InputError(origin + ": [" + key + "] must be a table");
}

Vec3 vec_mm(const std::vector<double>& v) { return {v[0] * units::mm, v[1] * units::mm, v[2] * units::mm}; }

SphereTarget read_target(Keys& k) {
  SphereTarget t;
  const bool has_face = k.has("face"), has_point = k.has("point_mm"), has_sphere = k.has("sphere");
  if (int(has_face) + int(has_point) + int(has_sphere) != 1)
    throw InputError(k.where() + " needs exactly one of face (with centre_mm and patch_mm), point_mm or sphere");
  if (has_face) {
    t.kind = SphereTarget::Kind::patch;
    t.patch.face = Face::parse(*k.text("face"));
    auto centre = k.numbers("centre_mm", 3);
    auto size = k.numbers("patch_mm", 2);
    if (!centre || !size) throw InputError(k.where() + " on a face needs centre_mm = [x, y, z] and patch_mm = [a, b]");
    t.patch.centre_m = vec_mm(*centre);
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

}  // namespace

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
      return format_number(patch.size_m[0] / units::mm) + " x " + format_number(patch.size_m[1] / units::mm) +
             " mm patch on face " + patch.face.name() + " at " + mm(patch.centre_m);
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

Scene parse_scene(const std::string& text, const std::string& origin) {
  toml::table root;
  try {
    root = toml::parse(text, origin);
  } catch (const toml::parse_error& e) {
    throw InputError(origin + ":" + std::to_string(e.source().begin.line) + ": " + std::string(e.description()));
  }
  static const std::set<std::string> sections = {"scene", "packing", "material", "time", "model",
                                                 "actuator", "sensor", "output"};
  for (const auto& [key, node] : root)
    if (!sections.count(std::string(key.str())))
      throw InputError(origin + ": unknown section [" + std::string(key.str()) + "]");

  Scene s;
  {
    Keys k(table_or_empty(root, "scene", origin), origin + ": [scene]");
    s.name = k.text("name", "scene");
    s.description = k.text("description", "");
    k.finish();
  }
  {
    Keys k(table_or_empty(root, "packing", origin), origin + ": [packing]");
    auto file = k.text("file");
    if (!file || file->empty()) throw InputError(origin + ": [packing] needs file (a packing HDF5 file from mw-pack)");
    s.packing_file = *file;
    k.finish();
  }
  {
    Keys k(table_or_empty(root, "material", origin), origin + ": [material]");
    auto& m = s.material;
    m.young_Pa = require_positive(k.where() + ".E_dem_GPa", k.required_number("E_dem_GPa"), "GPa") * units::GPa;
    m.stiffness_ratio = require_in_range(k.where() + ".nu_dem", k.number("nu_dem", 0.0), 0.0, 10.0);
    m.friction_angle_rad = require_in_range(k.where() + ".friction_angle_deg", k.number("friction_angle_deg", 0.0),
                                            0.0, 89.9, "deg") * std::numbers::pi / 180.0;
    if (auto T = k.number("T_MPa")) m.tensile_strength_Pa = require_positive(k.where() + ".T_MPa", *T, "MPa") * units::MPa;
    if (auto C = k.number("C_MPa")) m.cohesion_Pa = require_positive(k.where() + ".C_MPa", *C, "MPa") * units::MPa;
    if (auto rho = k.number("density_kg_m3")) {
      m.density_kg_m3 = require_positive(k.where() + ".density_kg_m3", *rho, "kg/m3");
      s.density_given = true;
    }
    m.damping = require_in_range(k.where() + ".damping", k.number("damping", 0.0), 0.0, 0.99);
    m.bond_factor = require_positive(k.where() + ".bond_factor", k.number("bond_factor", 1.1));
    k.finish();
  }
  {
    Keys k(table_or_empty(root, "time", origin), origin + ": [time]");
    s.dt_s = require_positive(k.where() + ".dt_ns", k.required_number("dt_ns"), "ns") * units::ns;
    s.duration_s = require_positive(k.where() + ".duration_ms", k.required_number("duration_ms"), "ms") * units::ms;
    k.finish();
  }
  {
    Keys k(table_or_empty(root, "model", origin), origin + ": [model]");
    s.model = k.text("choice", "auto");
    if (s.model != "auto" && s.model != "full" && s.model != "linear" && s.model != "chain")
      throw InputError(k.where() + ".choice (\"" + s.model + "\") must be auto, full, linear or chain");
    s.linear_validity_bound = require_in_range(k.where() + ".linear_validity_bound", k.number("linear_validity_bound", 1e-3), 1e-12, 1.0);
    s.energy_check_steps = int(require_in_range(k.where() + ".energy_check_steps", k.number("energy_check_steps", 100), 1, 1e9));
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
  if (const toml::node* list = root.get("actuator")) {
    const toml::array* a = list->as_array();
    if (!a) throw InputError(origin + ": actuators are [[actuator]] tables");
    for (std::size_t i = 0; i < a->size(); ++i) {
      const toml::table* t = (*a)[i].as_table();
      if (!t) throw InputError(origin + ": actuators are [[actuator]] tables");
      Keys k(*t, origin + ": [[actuator]] " + std::to_string(i + 1));
      ActuatorSpec spec;
      spec.name = k.text("name", "");
      unique_name(spec.name, k.where());
      spec.kind = k.text("kind", "force");
      spec.target = read_target(k);
      spec.direction = k.text("direction", spec.target.kind == SphereTarget::Kind::patch ? "inward" : "");
      if (spec.direction.empty()) throw InputError(k.where() + " needs direction (x, -x, ...) when it is not on a face");
      direction_vector(spec.direction, spec.target, k.where(), std::nullopt, true);
      if (spec.direction == "magnitude" || spec.direction == "normal")
        throw InputError(k.where() + ".direction must be inward or an axis (x, -x, ...)");
      static const std::map<std::string, std::string> amplitude_key = {
          {"force", "amplitude_N"}, {"displacement", "amplitude_nm"}, {"velocity", "velocity_mm_s"}};
      if (!amplitude_key.count(spec.kind))
        throw InputError(k.where() + ".kind (\"" + spec.kind + "\") must be force, displacement or velocity");
      for (const auto& [kind, key] : amplitude_key)
        if (kind != spec.kind && k.has(key))
          throw InputError(k.where() + ": a " + spec.kind + " actuator takes " + amplitude_key.at(spec.kind) + ", not " + key);
      const std::string key = amplitude_key.at(spec.kind);
      const double scale = spec.kind == "force" ? 1.0 : spec.kind == "displacement" ? units::nm : units::mm;
      spec.amplitude = require_finite(k.where() + "." + key, k.required_number(key)) * scale;
      if (spec.kind != "velocity") {
        spec.frequency_hz = require_positive(k.where() + ".frequency_kHz", k.required_number("frequency_kHz"), "kHz") * units::kHz;
        spec.cycles = require_positive(k.where() + ".cycles", k.number("cycles", 5.0));
      }
      spec.delay_s = require_in_range(k.where() + ".delay_us", k.number("delay_us", 0.0), 0.0, 1e9, "us") * units::us;
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
      Keys k(*t, origin + ": [[sensor]] " + std::to_string(i + 1));
      SensorSpec spec;
      spec.name = k.text("name", "");
      unique_name(spec.name, k.where());
      const std::string quantity = k.text("quantity", "acceleration");
      if (quantity == "force") {
        auto actuator = k.text("actuator");
        if (!actuator) throw InputError(k.where() + ": quantity force needs actuator = NAME (the force it applies)");
        bool known = false;
        for (const auto& a : s.actuators) known = known || a.name == *actuator;
        if (!known) throw InputError(k.where() + ": no actuator named \"" + *actuator + "\"");
        spec.actuator = *actuator;
        if (auto interval = k.number("sample_interval_ns"))
          spec.sample_interval_s = require_positive(k.where() + ".sample_interval_ns", *interval, "ns") * units::ns;
        k.finish();
        s.sensors.push_back(std::move(spec));
        continue;
      }
      spec.quantity = parse_motion_quantity(quantity);
      spec.target = read_target(k);
      spec.component = k.text("component", spec.target.kind == SphereTarget::Kind::patch ? "normal" : "");
      if (spec.component.empty()) throw InputError(k.where() + " needs component (x, -x, ..., magnitude) when it is not on a face");
      if (spec.component == "inward") throw InputError(k.where() + ".component must be normal, an axis or magnitude");
      direction_vector(spec.component, spec.target, k.where(), std::nullopt, true);
      if (auto interval = k.number("sample_interval_ns"))
        spec.sample_interval_s = require_positive(k.where() + ".sample_interval_ns", *interval, "ns") * units::ns;
      k.finish();
      s.sensors.push_back(std::move(spec));
    }
  }
  {
    Keys k(table_or_empty(root, "output", origin), origin + ": [output]");
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
  Scene s = parse_scene(text.str(), path.string());
  s.source = path;
  return s;
}

}  // namespace mesowave::dem
