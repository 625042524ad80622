#include "mesowave/dem/engine/checkpoint.hpp"

#include <cmath>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/dem/contact/material_parameters.hpp"
#include "mesowave/dem/scene/scene_overrides.hpp"
#include "mesowave/io/hdf5.hpp"
#include "mesowave/io/output_stage.hpp"
#include "mesowave/io/sha256.hpp"

namespace mesowave::dem {
namespace {

constexpr const char* kFormat = "mesowave-dem-checkpoint";
constexpr std::int64_t kFormatVersion = 1;

std::string shown(const nlohmann::ordered_json& value) {
  if (value.is_null()) return "(not given)";
  if (value.is_boolean()) return value.get<bool>() ? "(given)" : "(not given)";
  return value.dump();
}

bool is_strength_option(const std::string& option) {
  for (const char* o : kStrengthOptions)
    if (option == o) return true;
  return false;
}

// The first option whose value differs, in either identity (the strengths' left out with `stronger_bonds`).
void check_options(const nlohmann::ordered_json& had, const nlohmann::ordered_json& has, const std::string& file,
                   bool stronger_bonds) {
  for (const auto* side : {&had, &has})
    for (const auto& [option, value] : side->items()) {
      if (stronger_bonds && is_strength_option(option)) continue;
      const nlohmann::ordered_json a = had.contains(option) ? had[option] : nlohmann::ordered_json();
      const nlohmann::ordered_json b = has.contains(option) ? has[option] : nlohmann::ordered_json();
      if (a != b)
        throw InputError("checkpoint " + file + " is of a run with " + option + " " + shown(a) + ", this run has " +
                         shown(b) + (stronger_bonds ? ": a restart with stronger bonds differs from its checkpoint's run "
                                                      "in T and C alone"
                                                    : ": a restart takes the options of the run it continues"));
    }
}

void check_file(const std::string& what, const std::string& had, const std::string& has, const std::string& file) {
  const auto brief = [](const std::string& sha) { return sha.empty() ? std::string("none") : sha.substr(0, 12) + "..."; };
  if (had != has)
    throw InputError("checkpoint " + file + " is of another " + what + " (SHA-256 " + brief(had) + ", this run's " +
                     brief(has) + ")");
}

}  // namespace

CheckpointIdentity run_identity(const std::filesystem::path& scene_file, const Scene& scene,
                                const SceneOverrides& o, const std::string& model) {
  CheckpointIdentity id;
  id.scene_sha256 = io::sha256_file(scene_file);
  id.packing_sha256 = io::sha256_file(scene.packing_file);
  id.tensile_strength_Pa = scene.material.tensile_strength_Pa;
  id.cohesion_Pa = scene.material.cohesion_Pa;
  if (!scene.experiment_file.empty()) id.experiment_sha256 = io::sha256_file(scene.experiment_file);
  // Every option of scene_overrides.hpp that changes the results (not --packing:
  // its content is hashed; not the snapshot interval or --curves: outputs only).
  auto& j = id.options;
  j["--model"] = model;
  j["--frequency-kHz"] = o.frequency_kHz;
  j["--dt-ns"] = o.dt_ns;
  j["--duration-ms"] = o.duration_ms;
  j["--unbreakable-bonds"] = o.unbreakable;
  j["--stop-at-MPa"] = o.stop_at_MPa;
  j["--velocity-mm-s"] = o.velocity_mm_s;
  j["--modulus-levels-MPa"] = o.modulus_levels_MPa;
  for (const MaterialParameter& p : material_parameters())
    if (!p.option.empty()) {
      const auto it = o.material.find(p.key);
      j[p.option] = it != o.material.end() ? nlohmann::ordered_json(it->second) : nlohmann::ordered_json();
    }
  return id;
}

void write_checkpoint_file(const std::filesystem::path& file, const CheckpointIdentity& identity,
                           const std::function<void(StateGroup& root)>& body) {
  io::OutputStage stage;  // a temporary sibling, renamed into place once whole
  const std::filesystem::path temp = stage.stage(file);
  {
    const io::h5::Handle f = io::h5::create_file(temp);
    io::h5::set_attribute(f.id(), "format", std::string(kFormat));
    io::h5::set_attribute(f.id(), "format_version", kFormatVersion);
    io::h5::set_attribute(f.id(), "scene_sha256", identity.scene_sha256);
    io::h5::set_attribute(f.id(), "packing_sha256", identity.packing_sha256);
    io::h5::set_attribute(f.id(), "experiment_sha256", identity.experiment_sha256);
    io::h5::set_attribute(f.id(), "options", identity.options.dump());
    io::h5::set_attribute(f.id(), "tensile_strength_Pa", identity.tensile_strength_Pa);
    io::h5::set_attribute(f.id(), "cohesion_Pa", identity.cohesion_Pa);
    StateGroup root(H5Gopen2(f.id(), "/", H5P_DEFAULT), file.string() + ":/");
    body(root);
  }
  stage.commit();
}

void read_checkpoint_file(const std::filesystem::path& file, const CheckpointIdentity& identity,
                          const std::function<void(const StateGroup& root)>& body, bool stronger_bonds) {
  const io::h5::Handle f = io::h5::open_file(file);
  const std::string name = file.string();
  if (!io::h5::has_attribute(f.id(), "format") || io::h5::string_attribute(f.id(), "format") != kFormat)
    throw InputError(name + " is not a mesowave DEM checkpoint (no format = \"" + kFormat + "\")");
  const double version = io::h5::double_attribute(f.id(), "format_version");
  if (version != double(kFormatVersion))
    throw InputError("checkpoint " + name + " has format_version " + std::to_string(version) + "; this mw-dem reads " +
                     std::to_string(kFormatVersion));
  check_file("scene file", io::h5::string_attribute(f.id(), "scene_sha256"), identity.scene_sha256, name);
  check_file("packing file", io::h5::string_attribute(f.id(), "packing_sha256"), identity.packing_sha256, name);
  check_file("experiment file", io::h5::string_attribute(f.id(), "experiment_sha256"), identity.experiment_sha256, name);
  nlohmann::ordered_json options;
  try {
    options = nlohmann::ordered_json::parse(io::h5::string_attribute(f.id(), "options"));
  } catch (const nlohmann::json::exception&) {
    throw InputError("checkpoint " + name + ": its options attribute is not JSON (a damaged file)");
  }
  check_options(options, identity.options, name, stronger_bonds);
  if (stronger_bonds) {
    if (!io::h5::has_attribute(f.id(), "tensile_strength_Pa") || !io::h5::has_attribute(f.id(), "cohesion_Pa"))
      throw InputError("checkpoint " + name + " records no bond strengths (an older mw-dem wrote it): it cannot start a "
                       "run with stronger bonds");
    const auto MPa = [](double Pa) { return std::isfinite(Pa) ? format_number(Pa / 1e6) + " MPa" : std::string("none"); };
    const double T0 = io::h5::double_attribute(f.id(), "tensile_strength_Pa");
    const double C0 = io::h5::double_attribute(f.id(), "cohesion_Pa");
    if (!(identity.tensile_strength_Pa >= T0) || !(identity.cohesion_Pa >= C0))
      throw InputError("checkpoint " + name + " is of a run with T " + MPa(T0) + ", C " + MPa(C0) + "; this run has T " +
                       MPa(identity.tensile_strength_Pa) + ", C " + MPa(identity.cohesion_Pa) +
                       ": a restart with stronger bonds needs both at least the checkpoint's");
  }
  const StateGroup root(H5Gopen2(f.id(), "/", H5P_DEFAULT), name + ":/");
  body(root);
}

}  // namespace mesowave::dem
