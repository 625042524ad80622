#include "mesowave/fem/case.hpp"

#include <cmath>
#include <sstream>

#include "mesowave/core/check.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/core/threads.hpp"
#include "mesowave/io/hdf5.hpp"

namespace mesowave::fem {

std::array<double, 3> parse_point_mm(const std::string& text, const std::string& what) {
  std::array<double, 3> p{};
  std::stringstream s(text);
  std::string item;
  int n = 0;
  while (std::getline(s, item, ',')) {
    if (n >= 3) throw InputError(what + " '" + text + "' must be three numbers X,Y,Z in mm");
    try {
      std::size_t used = 0;
      p[std::size_t(n)] = std::stod(item, &used) * units::mm;
      if (used != item.size()) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw InputError(what + " '" + text + "' must be three numbers X,Y,Z in mm");
    }
    require_finite(what, p[std::size_t(n)]);
    ++n;
  }
  if (n != 3) throw InputError(what + " '" + text + "' must be three numbers X,Y,Z in mm");
  return p;
}

ProbePoint parse_probe_point(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("sensor '" + text + "' must read NAME=X,Y,Z (mm), optionally /component");
  ProbePoint s;
  s.name = text.substr(0, eq);
  std::string rest = text.substr(eq + 1);
  const auto slash = rest.find('/');
  if (slash != std::string::npos) {
    s.component = rest.substr(slash + 1);
    rest = rest.substr(0, slash);
    if (s.component != "x" && s.component != "y" && s.component != "z" && s.component != "r" &&
        s.component != "normal")
      throw InputError("sensor " + s.name + " component '" + s.component + "' must be x, y, z, r or normal");
  }
  s.position_m = parse_point_mm(rest, "sensor " + s.name);
  return s;
}

std::optional<std::pair<int, bool>> box_face_of(const std::array<double, 3>& p, const std::array<double, 3>& size,
                                                double tol) {
  for (int d = 0; d < 3; ++d) {
    if (std::abs(p[std::size_t(d)]) <= tol) return std::make_pair(d, false);
    if (std::abs(p[std::size_t(d)] - size[std::size_t(d)]) <= tol) return std::make_pair(d, true);
  }
  return std::nullopt;
}

std::vector<Probe> make_probes(const FemModel& model, const std::vector<ProbePoint>& points, MotionQuantity quantity,
                               const std::string& default_component,
                               const std::optional<std::array<double, 3>>& box_size) {
  std::vector<Probe> probes;
  for (const auto& s : points) {
    for (const auto& p : probes)
      if (p.name == s.name) throw InputError("sensor name " + s.name + " is used twice");
    const std::size_t node = model.nearest_node(s.position_m);
    const auto x = model.position(node);
    const std::array<double, 3> q =
        model.dim == 3 ? s.position_m : std::array<double, 3>{std::hypot(s.position_m[0], s.position_m[1]), 0.0, s.position_m[2]};
    const double dist = std::hypot(x[0] - q[0], x[1] - q[1], x[2] - q[2]);
    if (dist > model.mesh_size_m)
      throw InputError("sensor " + s.name + " lies " + format_quantity(dist / units::mm, "mm") +
                       " from the nearest node: outside the body");
    std::string comp = s.component.empty() ? default_component : s.component;
    double sign = 1.0;
    std::string label;
    if (comp == "normal") {
      // The outward normal, as a transducer on the face sees it (and as mw-dem records "normal"):
      // -x on the face x = 0, +x on the face x = X.
      const auto face = box_size ? box_face_of(x, *box_size, model.mesh_size_m * 1e-6) : std::nullopt;
      if (!face) throw InputError("sensor " + s.name + ": component 'normal' needs a point on a face of the box");
      comp = std::string(1, "xyz"[face->first]);
      sign = face->second ? 1.0 : -1.0;
      label = (face->second ? "" : "-") + comp;
    }
    if (comp.size() == 2 && comp[0] == '-') {
      comp = comp.substr(1);
      sign = -1.0;
      label = "-" + comp;
    }
    std::size_t c = 0;
    if (model.dim == 3) {
      if (comp == "x") c = 0;
      else if (comp == "y") c = 1;
      else if (comp == "z") c = 2;
      else throw InputError("sensor " + s.name + ": component " + comp + " does not exist in a 3D model (x, y, z)");
    } else {
      if (comp == "r") c = 0;
      else if (comp == "z") c = 1;
      else throw InputError("sensor " + s.name + ": an axisymmetric model records r or z, not " + comp);
    }
    probes.push_back({s.name, node * std::size_t(model.dim) + c, quantity, label.empty() ? comp : label, sign});
  }
  return probes;
}

BurstLoad make_load(const FemModel& model, int axis, double value, const std::array<double, 3>& point,
                    double radius, int component, double sign, const signal::HannBurst& burst) {
  BurstLoad load{{}, burst};
  const auto dim = std::size_t(model.dim);
  const std::size_t comp = model.dim == 3 ? std::size_t(component) : (component == 2 ? 1 : 0);
  if (radius > 0) {
    const auto patch = surface_patch(model, axis, value, point, radius);
    if (patch.empty())
      throw InputError("the load patch (radius " + format_quantity(radius / units::mm, "mm") +
                       ") holds no face cell: make it larger than half the mesh size or use a point load");
    for (const auto& [node, w] : patch) load.dof_weights.emplace_back(node * dim + comp, sign * w);
  } else {
    load.dof_weights.emplace_back(model.nearest_node(point) * dim + comp, sign);
  }
  return load;
}

Stepping choose_stepping(const FemModel& model, double duration, double sample_dt, std::optional<double> dt) {
  require_positive("duration", duration, "s");
  require_positive("sampling interval", sample_dt, "s");
  const double stable = model.stable_dt();
  Stepping s;
  s.sample_dt_s = sample_dt;
  if (dt) {
    require_positive("time step", *dt, "s");
    if (*dt > stable)
      throw InputError("time step (" + format_quantity(*dt / units::us, "us") + ") exceeds the stable step (" +
                       format_quantity(stable / units::us, "us") + ", " + model.stable_dt_method + ") of this mesh");
    s.stride = std::max<std::int64_t>(1, std::llround(sample_dt / *dt));
    if (std::abs(double(s.stride) * *dt - sample_dt) > 1e-9 * sample_dt)
      throw InputError("the sampling interval (" + format_quantity(sample_dt / units::us, "us") +
                       ") must be a whole number of time steps (" + format_quantity(*dt / units::us, "us") + ")");
    s.dt_s = *dt;
  } else {
    s.stride = std::max<std::int64_t>(1, std::int64_t(std::ceil(sample_dt / stable * (1 - 1e-12))));
    s.dt_s = sample_dt / double(s.stride);
    while (s.dt_s > stable) s.dt_s = sample_dt / double(++s.stride);
  }
  s.steps = std::llround(duration / s.dt_s);
  if (s.steps > 2'000'000'000) throw InputError("the run would take more than 2e9 steps");
  return s;
}

SpaceTimeRequest rod_axis_line(const FemModel& model, double step, MotionQuantity quantity) {
  require_positive("space-time step", step, "m");
  SpaceTimeRequest r;
  r.quantity = quantity;
  const auto dim = std::size_t(model.dim);
  double next = 0;
  // Axis nodes in increasing z (both meshes number layer by layer).
  for (std::size_t n = 0; n < model.node_count(); ++n) {
    const auto x = model.position(n);
    if (std::abs(x[0]) > 1e-12 || std::abs(x[1]) > 1e-12) continue;
    if (x[2] + 1e-9 < next) continue;
    r.dofs.push_back(n * dim + (dim - 1));
    r.coordinate_m.push_back(x[2]);
    next = x[2] + step;
  }
  return r;
}

void write_spacetime_file(const std::filesystem::path& path, const std::vector<double>& samples,
                          const SpaceTimeRequest& req, double dt, const std::string& component,
                          const std::map<std::string, std::string>& attributes) {
  namespace h5 = io::h5;
  auto file = h5::create_file(path);
  h5::set_attribute(file.id(), "format", std::string("mesowave-spacetime"));
  h5::set_attribute(file.id(), "format_version", std::int64_t(1));
  for (const auto& [k, v] : attributes) h5::set_attribute(file.id(), k, v);
  auto g = h5::create_group(file.id(), "spacetime");
  h5::write_doubles(g.id(), "samples", samples, req.dofs.size(), true);
  h5::write_doubles(g.id(), "position_m", req.coordinate_m);
  h5::set_attribute(g.id(), "t0_s", 0.0);
  h5::set_attribute(g.id(), "dt_s", dt);
  h5::set_attribute(g.id(), "quantity", to_string(req.quantity));
  h5::set_attribute(g.id(), "unit", si_unit(req.quantity));
  h5::set_attribute(g.id(), "component", component);
}

void apply_experiment(FemCase& c, const experiment::Experiment& lab, double scale) {
  using experiment::Transducer;
  const experiment::Experiment e = experiment::scaled(lab, scale);
  const auto actuators = e.actuators();
  const auto sensors = e.sensors();
  const std::string where = e.source.empty() ? std::string("the experiment") : e.source.string();
  if (actuators.size() != 1)
    throw InputError(where + ": mw-fem drives one actuator, the experiment has " + std::to_string(actuators.size()));
  const Transducer& a = *actuators.front();
  if (a.direction != "inward") throw InputError(where + ": actuator " + a.name + " must push inward (mw-fem loads normal to its face)");
  if (e.burst.delay_s != 0) throw InputError(where + ": mw-fem starts the burst at t = 0 (the experiment delays it)");
  c.frequency_hz = e.burst.frequency_hz;
  c.cycles = e.burst.cycles;
  c.force_N = e.burst.amplitude_N;
  c.duration_s = e.record.duration_s;
  c.sample_dt_s = e.record.sample_interval_s;
  c.patch_radius_m = experiment::patch_disc_radius_m(a);  // the square PZT as the disc of the same area
  c.quantity = sensors.front()->quantity;
  const bool cylinder = e.specimen.shape == experiment::Specimen::Shape::cylinder;
  const double R = e.specimen.radius_m();
  c.probe_points.clear();
  for (const Transducer* s : sensors) {
    if (s->quantity != sensors.front()->quantity)
      throw InputError(where + ": sensor " + s->name + " records " + to_string(s->quantity) + ", " + sensors.front()->name +
                       " " + to_string(sensors.front()->quantity) + ": mw-fem records one quantity a run");
    if (s->component == "magnitude") throw InputError(where + ": sensor " + s->name + ": mw-fem records a component, not the magnitude");
    std::string component = s->component;
    std::array<double, 3> p = s->centre_m;
    if (cylinder) {
      if (component == "normal") component = s->face == "curved" ? "r" : s->face == "z+" ? "z" : "-z";
      else if (component != "z" && component != "-z")
        throw InputError(where + ": sensor " + s->name + " component " + component +
                         " breaks the axial symmetry of the cylinder's ring model (it records r and z: give normal or z)");
      p[0] -= R;
      p[1] -= R;
    }
    c.probe_points.push_back({s->name, p, component});
  }
  if (!cylinder) {
    c.body = FemCase::Body::box;
    c.size_m = e.specimen.size_m;
    c.source_m = a.centre_m;
    return;
  }
  const double off_axis = std::hypot(a.centre_m[0] - R, a.centre_m[1] - R);
  if (a.face != "z-" || off_axis > 1e-3 * units::mm)
    throw InputError(where + ": actuator " + a.name + " on face " + a.face + " at " + format_quantity(off_axis / units::mm, "mm") +
                     " from the axis: mw-fem models a cylinder with axisymmetric rings, which need the load on the axis of "
                     "the z- end (there is no 3D cylinder reference yet)");
  c.body = FemCase::Body::rod;
  c.rod_model = "axisymmetric";
  c.radius_m = R;
  c.length_m = e.specimen.length_m();
}

IsotropicMaterial material_of(std::optional<double> E_GPa, std::optional<double> nu, std::optional<double> density_kg_m3,
                              const experiment::Specimen* specimen) {
  const experiment::Specimen none;
  const experiment::Specimen& s = specimen ? *specimen : none;
  const auto need = [&](const std::optional<double>& of_specimen, const char* option) {
    if (!of_specimen)
      throw InputError(std::string("give ") + option + (specimen ? " (the experiment's specimen does not give it)" : ""));
    return *of_specimen;
  };
  return {E_GPa ? require_positive("--E-GPa", *E_GPa, "GPa") * units::GPa : need(s.E_Pa, "--E-GPa"),
          nu ? *nu : need(s.nu, "--nu"), density_kg_m3 ? *density_kg_m3 : need(s.density_kg_m3, "--density-kg-m3")};
}

experiment::Experiment rod_experiment(const experiment::Experiment& e, std::optional<double> radius_mm,
                                      std::optional<double> length_mm) {
  experiment::rod_of(e);  // a cylinder with its material, or the reason
  if (radius_mm) throw InputError("--experiment gives the rod's radius: no --radius-mm (--length-mm may shorten the rod)");
  if (!length_mm) return e;
  return experiment::with_length(e, require_positive("--length-mm", *length_mm, "mm") * units::mm);
}

void set_rod_size(FemCase& c, std::optional<double> radius_mm, std::optional<double> length_mm) {
  if (!radius_mm || !length_mm) throw InputError("mw-fem rod needs --radius-mm and --length-mm, or --experiment");
  c.radius_m = require_positive("--radius-mm", *radius_mm, "mm") * units::mm;
  c.length_m = require_positive("--length-mm", *length_mm, "mm") * units::mm;
}

FemSetup assemble_fem_case(const FemCase& spec) {
  validate(spec.material);
  const double h = require_positive("mesh size", spec.mesh_m / units::mm, "mm") * units::mm;
  const signal::HannBurst burst(spec.frequency_hz, spec.cycles, require_finite("force", spec.force_N, "N"));
  if (spec.patch_radius_m < 0 || !std::isfinite(spec.patch_radius_m))
    throw InputError("the load patch radius (" + format_quantity(spec.patch_radius_m / units::mm, "mm") + ") must be >= 0");
  FemModel model;
  std::vector<Probe> probes;
  std::optional<BurstLoad> load;
  std::optional<SpaceTimeRequest> spacetime;
  if (spec.body == FemCase::Body::rod) {
    const double R = require_positive("rod radius", spec.radius_m / units::mm, "mm") * units::mm;
    const double L = require_positive("rod length", spec.length_m / units::mm, "mm") * units::mm;
    if (spec.rod_model == "axisymmetric") model = rod_axisymmetric(spec.material, R, L, h);
    else if (spec.rod_model == "3d") model = rod_hexahedra(spec.material, R, L, h);
    else throw InputError("rod model " + spec.rod_model + " must be axisymmetric or 3d");
    const std::vector<ProbePoint> points =
        spec.probe_points.empty() ? std::vector<ProbePoint>{{"S", {0, 0, L}, ""}} : spec.probe_points;
    probes = make_probes(model, points, spec.quantity, "z");
    load = make_load(model, 2, 0.0, {0, 0, 0}, spec.patch_radius_m, 2, +1.0, burst);
    if (spec.spacetime_step_m)
      spacetime = rod_axis_line(model, *spec.spacetime_step_m > 0 ? *spec.spacetime_step_m : h, spec.quantity);
  } else {
    for (double a : spec.size_m) require_positive("box size", a / units::mm, "mm");
    model = box_hexahedra(spec.material, spec.size_m, h);
    const auto face = box_face_of(spec.source_m, spec.size_m, 1e-9);
    if (!face)
      throw InputError("the source point (" + format_number(spec.source_m[0] / units::mm) + ", " +
                       format_number(spec.source_m[1] / units::mm) + ", " + format_number(spec.source_m[2] / units::mm) +
                       " mm) must lie on a face of the box");
    const double value = face->second ? spec.size_m[std::size_t(face->first)] : 0.0;
    load = make_load(model, face->first, value, spec.source_m, spec.patch_radius_m, face->first,
                     face->second ? -1.0 : +1.0, burst);  // pushing into the body
    if (spec.probe_points.empty()) throw InputError("box: give at least one sensor (--sensor NAME=X,Y,Z)");
    probes = make_probes(model, spec.probe_points, spec.quantity, "normal", spec.size_m);
  }
  const Stepping stepping = choose_stepping(model, spec.duration_s, spec.sample_dt_s, spec.dt_s);
  return FemSetup{spec, std::move(model), std::move(*load), std::move(probes), stepping, std::move(spacetime)};
}

FemRun run_fem_case(const FemSetup& setup, const std::function<void(std::int64_t)>& progress) {
  const FemModel& model = setup.model;
  const Stepping& stepping = setup.stepping;
  ExplicitOptions opt;
  opt.dt_s = stepping.dt_s;
  opt.steps = stepping.steps;
  opt.sample_stride = stepping.stride;
  opt.alpha_damping_per_s = setup.spec.alpha_damping_per_s;
  opt.progress = progress;
  // A step synchronises the threads once per element colour: on a busy machine a
  // descheduled thread stalls the others, so the default leaves busy cores alone.
  FemRun run{{}, use_threads(setup.spec.threads, {model.element_count(), opt.min_elements_per_thread, "elements"}), {}};
  run.result = run_explicit(model, setup.load, setup.probes, opt, setup.spacetime ? &*setup.spacetime : nullptr);
  complete_fem_run(setup, run);
  return run;
}

void complete_fem_run(const FemSetup& setup, FemRun& run) {
  const FemModel& model = setup.model;
  const Stepping& stepping = setup.stepping;
  // The excitation, sampled like the signals, travels with them.
  const signal::HannBurst& burst = setup.load.burst;
  signal::Signal excitation;
  excitation.name = signal::kExcitationName;
  excitation.quantity = "force";
  excitation.unit = "N";
  excitation.dt_s = stepping.sample_dt_s;
  excitation.samples = burst.sample(stepping.sample_dt_s, run.result.signals.empty() ? 0 : run.result.signals[0].size());
  run.result.signals.push_back(excitation);
  run.attributes = {{"model", model.description},
                    {"solver", "mw-fem explicit central differences, lumped mass"},
                    {"mesh_mm", format_number(setup.spec.mesh_m / units::mm)},
                    {"dt_s", format_exact(stepping.dt_s)},
                    {"alpha_damping_per_s", format_number(setup.spec.alpha_damping_per_s)},
                    {"burst_frequency_Hz", format_exact(burst.centre_frequency_hz())},
                    {"burst_cycles", format_exact(burst.cycles())}};
}

nlohmann::ordered_json fem_report(const FemSetup& setup, const FemRun& run, double peak_rss_MiB,
                                  const std::filesystem::path& signals) {
  const FemModel& model = setup.model;
  const Stepping& stepping = setup.stepping;
  const ExplicitResult& result = run.result;
  nlohmann::ordered_json j;
  j["model"] = model.description;
  j["nodes"] = model.node_count();
  j["elements"] = model.element_count();
  j["mesh_mm"] = setup.spec.mesh_m / units::mm;
  j["stable_dt_us"] = model.stable_dt() / units::us;
  j["stable_dt_method"] = model.stable_dt_method;
  j["dt_us"] = stepping.dt_s / units::us;
  j["sample_dt_us"] = stepping.sample_dt_s / units::us;
  j["steps"] = stepping.steps;
  j["threads"] = result.threads;
  j["threads_reason"] = run.threads.reason;
  j["wall_s"] = result.wall_s;
  j["steps_per_s"] = double(stepping.steps) / result.wall_s;
  j["element_updates_per_s"] = double(stepping.steps) * double(model.element_count()) / result.wall_s;
  j["peak_rss_MiB"] = peak_rss_MiB;
  j["max_kinetic_energy_J"] = result.max_kinetic_energy_J;
  j["signals"] = signals.string();
  return j;
}

}  // namespace mesowave::fem
