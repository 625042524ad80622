#include "mesowave/experiment/experiment.hpp"

#include <cmath>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>
#include <toml++/toml.h>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/io/toml_keys.hpp"

namespace mesowave::experiment {
namespace {

// Millimetres as the file gives them: positions are scaled and made relative in
// mm, so that a value read as 40 mm stays 40 * factor (and 40 / 50 = 0.8) exactly.
double in_mm(double m) { return m / units::mm; }

/// One table of the file (io/toml_keys.hpp), with the values that carry their origin.
class Keys : public io::TomlKeys {
public:
  using io::TomlKeys::TomlKeys;
  /// A value with its origin: {value = ..., source = "...", cite = "..."}; `count` 0 = a number.
  std::optional<std::vector<double>> sourced(const std::string& key, std::size_t count = 0) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    const toml::table* t = n->as_table();
    if (!t)
      throw InputError(where() + "." + key + " must be a table {value = ..., source = \"...\", cite = \"...\"} (where it comes from)");
    Keys k(*t, where() + "." + key);
    if (!k.has("value")) throw InputError(k.where() + " needs value");
    std::vector<double> out;
    if (count == 0) out.push_back(*k.number("value"));
    else out = *k.numbers("value", count);
    for (double x : out) require_finite(k.where() + ".value", x);
    k.origin();
    k.finish();
    return out;
  }
  std::optional<double> sourced_number(const std::string& key) {
    auto v = sourced(key);
    return v ? std::optional<double>(v->front()) : std::nullopt;
  }
  double required_number(const std::string& key) {
    auto v = sourced_number(key);
    if (!v) throw InputError(where() + " needs " + key);
    return *v;
  }
  /// source and cite: the kinds lab-data files use (io/quantity_file.hpp); paper, derived
  /// and assumed values say where they come from.
  std::pair<std::string, std::string> origin() {
    static const std::set<std::string> kinds = {"paper", "derived", "synthetic", "assumed", "placeholder", "measured"};
    const std::string source = text("source", "");
    if (!kinds.count(source))
      throw InputError(where() + ".source (\"" + source + "\") must be paper, derived, synthetic, assumed, measured or placeholder");
    const std::string cite = text("cite", "");
    if (cite.empty() && (source == "paper" || source == "derived" || source == "assumed"))
      throw InputError(where() + " (source \"" + source + "\") needs cite: where the value comes from or why it was assumed");
    return {source, cite};
  }
};

const toml::table& table(const toml::table& root, const std::string& key, const std::string& origin) {
  const toml::node* n = root.get(key);
  if (!n) throw InputError(origin + " needs a [" + key + "] table");
  if (const toml::table* t = n->as_table()) return *t;
  throw InputError(origin + ": [" + key + "] must be a table");
}

Specimen read_specimen(Keys& k) {
  Specimen s;
  const std::string shape = k.text("shape", "");
  if (shape == "box") {
    s.shape = Specimen::Shape::box;
    const auto size = k.sourced("size_mm", 3);
    if (!size) throw InputError(k.where() + ": a box needs size_mm = {value = [X, Y, Z], ...}");
    for (std::size_t d = 0; d < 3; ++d) s.size_m[d] = require_positive(k.where() + ".size_mm", (*size)[d], "mm") * units::mm;
  } else if (shape == "cylinder") {
    s.shape = Specimen::Shape::cylinder;
    const double D = require_positive(k.where() + ".diameter_mm", k.required_number("diameter_mm"), "mm");
    const double L = require_positive(k.where() + ".length_mm", k.required_number("length_mm"), "mm");
    s.size_m = {D * units::mm, D * units::mm, L * units::mm};
  } else {
    throw InputError(k.where() + ".shape (\"" + shape + "\") must be box or cylinder");
  }
  if (auto rho = k.sourced_number("density_kg_m3")) s.density_kg_m3 = require_positive(k.where() + ".density_kg_m3", *rho, "kg/m3");
  if (auto E = k.sourced_number("E_GPa")) s.E_Pa = require_positive(k.where() + ".E_GPa", *E, "GPa") * units::GPa;
  if (auto nu = k.sourced_number("nu")) s.nu = require_in_range(k.where() + ".nu", *nu, -1.0, 0.5);
  return s;
}

/// InputError unless the point lies on the named face of the specimen (within 1 um) and inside it.
void check_on_face(const Specimen& s, const Transducer& t, const std::string& where) {
  const double tol = 1e-3 * units::mm;
  const auto& p = t.centre_m;
  auto at = [&] {
    return "(" + format_number(in_mm(p[0])) + ", " + format_number(in_mm(p[1])) + ", " + format_number(in_mm(p[2])) + ") mm";
  };
  const bool cylinder = s.shape == Specimen::Shape::cylinder;
  if (t.face == "curved") {
    if (!cylinder) throw InputError(where + ".face \"curved\" needs a cylinder specimen (a box has x-, x+, y-, y+, z-, z+)");
    const double r = std::hypot(p[0] - s.radius_m(), p[1] - s.radius_m());
    if (std::abs(r - s.radius_m()) > tol || p[2] < -tol || p[2] > s.length_m() + tol)
      throw InputError(where + ".centre_mm " + at() + " is not on the curved face (" + format_number(in_mm(r)) +
                       " mm from the axis, radius " + format_number(in_mm(s.radius_m())) + " mm)");
    return;
  }
  const bool face_ok = t.face.size() == 2 && t.face[0] >= 'x' && t.face[0] <= 'z' && (t.face[1] == '-' || t.face[1] == '+');
  if (!face_ok) throw InputError(where + ".face (\"" + t.face + "\") must be x-, x+, y-, y+, z-, z+ or curved");
  const auto axis = std::size_t(t.face[0] - 'x');
  if (cylinder && axis != 2)
    throw InputError(where + ".face (\"" + t.face + "\"): a cylinder's faces are z- and z+ (its ends) and curved");
  const double plane = t.face[1] == '+' ? s.size_m[axis] : 0.0;
  if (std::abs(p[axis] - plane) > tol)
    throw InputError(where + ".centre_mm " + at() + " is not on face " + t.face + " (" + "xyz"[axis] + " = " +
                     format_number(in_mm(plane)) + " mm)");
  for (std::size_t d = 0; d < 3; ++d)
    if (p[d] < -tol || p[d] > s.size_m[d] + tol) throw InputError(where + ".centre_mm " + at() + " lies outside the specimen");
  if (cylinder && std::hypot(p[0] - s.radius_m(), p[1] - s.radius_m()) > s.radius_m() + tol)
    throw InputError(where + ".centre_mm " + at() + " lies outside the cylinder's end face");
}

bool is_axis(const std::string& name) {
  return name == "x" || name == "-x" || name == "y" || name == "-y" || name == "z" || name == "-z";
}

Transducer read_transducer(Keys& k, const Specimen& s) {
  Transducer t;
  t.name = k.text("name", "");
  if (t.name.empty()) throw InputError(k.where() + " needs a name");
  for (char c : t.name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.'))
      throw InputError(k.where() + ": name \"" + t.name + "\" may hold only letters, digits, - _ and .");
  const std::string role = k.text("role", "");
  if (role == "actuator") t.role = Transducer::Role::actuator;
  else if (role == "sensor") t.role = Transducer::Role::sensor;
  else throw InputError(k.where() + " (" + t.name + ").role (\"" + role + "\") must be actuator or sensor");
  const std::string where = k.where() + " (" + t.name + ")";
  t.face = k.text("face", "");
  const auto centre = k.numbers("centre_mm", 3), size = k.numbers("patch_mm", 2);
  if (!centre || !size) throw InputError(where + " needs centre_mm = [x, y, z] and patch_mm = [a, b]");
  for (std::size_t d = 0; d < 3; ++d) t.centre_m[d] = require_finite(where + ".centre_mm", (*centre)[d], "mm") * units::mm;
  for (std::size_t d = 0; d < 2; ++d) t.patch_m[d] = require_positive(where + ".patch_mm", (*size)[d], "mm") * units::mm;
  check_on_face(s, t, where);
  if (t.role == Transducer::Role::sensor) {
    t.quantity = parse_motion_quantity(k.text("quantity", to_string(t.quantity)), where + ".quantity");
    t.component = k.text("component", t.component);
    if (t.component != "normal" && t.component != "magnitude" && !is_axis(t.component))
      throw InputError(where + ".component (\"" + t.component + "\") must be normal, magnitude or x, -x, y, -y, z, -z");
  } else {
    t.direction = k.text("direction", t.direction);
    if (t.direction != "inward" && !is_axis(t.direction))
      throw InputError(where + ".direction (\"" + t.direction + "\") must be inward or x, -x, y, -y, z, -z");
  }
  std::tie(t.source, t.cite) = k.origin();
  return t;
}

}  // namespace

std::string Specimen::describe() const {
  if (shape == Shape::cylinder)
    return format_number(in_mm(size_m[0])) + " x " + format_number(in_mm(size_m[2])) + " mm cylinder";
  return format_number(in_mm(size_m[0])) + " x " + format_number(in_mm(size_m[1])) + " x " + format_number(in_mm(size_m[2])) +
         " mm box";
}

std::vector<const Transducer*> Experiment::actuators() const {
  std::vector<const Transducer*> out;
  for (const auto& t : transducers)
    if (t.role == Transducer::Role::actuator) out.push_back(&t);
  return out;
}

std::vector<const Transducer*> Experiment::sensors() const {
  std::vector<const Transducer*> out;
  for (const auto& t : transducers)
    if (t.role == Transducer::Role::sensor) out.push_back(&t);
  return out;
}

Experiment parse_experiment(const std::string& text, const std::string& origin) {
  toml::table root;
  try {
    root = toml::parse(text, origin);
  } catch (const toml::parse_error& e) {
    throw InputError(origin + ":" + std::to_string(e.source().begin.line) + ": " + std::string(e.description()));
  }
  static const std::set<std::string> sections = {"specimen", "transducer", "burst", "record"};
  for (const auto& [key, node] : root)
    if (!sections.count(std::string(key.str())))
      throw InputError(origin + ": unknown section [" + std::string(key.str()) + "] (specimen, transducer, burst, record)");
  Experiment e;
  {
    Keys k(table(root, "specimen", origin), origin + ": [specimen]");
    e.specimen = read_specimen(k);
    k.finish();
  }
  const toml::array* list = root.get("transducer") ? root.get("transducer")->as_array() : nullptr;
  if (!list) throw InputError(origin + " needs [[transducer]] tables (its actuators and sensors)");
  std::set<std::string> names;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const toml::table* t = (*list)[i].as_table();
    if (!t) throw InputError(origin + ": transducers are [[transducer]] tables");
    Keys k(*t, origin + ": [[transducer]] " + std::to_string(i + 1));
    Transducer x = read_transducer(k, e.specimen);
    k.finish();
    if (!names.insert(x.name).second) throw InputError(k.where() + ": the name \"" + x.name + "\" is used twice");
    e.transducers.push_back(std::move(x));
  }
  if (e.actuators().empty() || e.sensors().empty())
    throw InputError(origin + ": an experiment needs at least one actuator and one sensor (found " +
                     std::to_string(e.actuators().size()) + " and " + std::to_string(e.sensors().size()) + ")");
  {
    Keys k(table(root, "burst", origin), origin + ": [burst]");
    e.burst.frequency_hz = require_positive(k.where() + ".frequency_kHz", k.required_number("frequency_kHz"), "kHz") * units::kHz;
    e.burst.cycles = require_positive(k.where() + ".cycles", k.required_number("cycles"));
    e.burst.amplitude_N = require_finite(k.where() + ".amplitude_N", k.required_number("amplitude_N"), "N");
    e.burst.delay_s = require_in_range(k.where() + ".delay_us", k.sourced_number("delay_us").value_or(0.0), 0.0, 1e9, "us") * units::us;
    k.finish();
  }
  {
    Keys k(table(root, "record", origin), origin + ": [record]");
    e.record.duration_s = require_positive(k.where() + ".duration_ms", k.required_number("duration_ms"), "ms") * units::ms;
    e.record.sample_interval_s =
        require_positive(k.where() + ".sample_interval_us", k.required_number("sample_interval_us"), "us") * units::us;
    k.finish();
  }
  return e;
}

Experiment read_experiment_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError("experiment file " + path.string() + " cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  Experiment e = parse_experiment(text.str(), path.string());
  e.source = path;
  return e;
}

double azimuth(const Specimen& s, const std::array<double, 3>& p) {
  return std::atan2(p[1] - s.radius_m(), p[0] - s.radius_m());
}

std::array<double, 3> outward_normal(const Specimen& s, const Transducer& t) {
  if (t.face == "curved") {
    const double phi = azimuth(s, t.centre_m);
    return {std::cos(phi), std::sin(phi), 0.0};
  }
  std::array<double, 3> n{};
  n[std::size_t(t.face[0] - 'x')] = t.face[1] == '+' ? 1.0 : -1.0;
  return n;
}

std::array<double, 3> relative_position(const Specimen& s, const std::array<double, 3>& p) {
  std::array<double, 3> r{};
  for (std::size_t d = 0; d < 3; ++d) r[d] = in_mm(p[d]) / in_mm(s.size_m[d]);
  return r;
}

Experiment scaled(const Experiment& e, double factor) {
  require_positive("the experiment's scale factor", factor);
  Experiment out = e;
  for (double& a : out.specimen.size_m) a = in_mm(a) * factor * units::mm;
  for (auto& t : out.transducers)
    for (double& x : t.centre_m) x = in_mm(x) * factor * units::mm;
  return out;
}

double patch_disc_radius_m(const Transducer& t) { return std::sqrt(t.patch_m[0] * t.patch_m[1] / std::numbers::pi); }

namespace {
std::string origin_of(const Experiment& e) { return e.source.empty() ? std::string("the experiment") : e.source.string(); }
}  // namespace

Rod rod_of(const Experiment& e) {
  const Specimen& s = e.specimen;
  if (s.shape != Specimen::Shape::cylinder)
    throw InputError(origin_of(e) + ": a rod is a cylinder specimen, this one is a " + s.describe());
  std::string missing;
  if (!s.E_Pa) missing += " E_GPa";
  if (!s.nu) missing += " nu";
  if (!s.density_kg_m3) missing += " density_kg_m3";
  if (!missing.empty()) throw InputError(origin_of(e) + ": [specimen] needs" + missing + " for a rod (its material)");
  return {s.radius_m(), s.length_m(), *s.E_Pa, *s.nu, *s.density_kg_m3};
}

Experiment with_length(const Experiment& e, double length_m) {
  if (e.specimen.shape != Specimen::Shape::cylinder)
    throw InputError(origin_of(e) + ": only a cylinder's length can be changed alone (this is a " + e.specimen.describe() + ")");
  require_positive("the rod length", in_mm(length_m), "mm");
  Experiment out = e;
  // The fraction in mm, as written (an end: exactly 0 or 1), so that an end lands exactly on the new length.
  for (auto& t : out.transducers) t.centre_m[2] = in_mm(t.centre_m[2]) / in_mm(e.specimen.size_m[2]) * length_m;
  out.specimen.size_m[2] = length_m;
  return out;
}

}  // namespace mesowave::experiment
