#include "mesowave/dem/engine/simulation.hpp"

#include <chrono>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <cmath>
#include <numbers>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/dem/loading/force_actuator.hpp"
#include "mesowave/dem/loading/sphere_selection.hpp"
#include "mesowave/dem/parallel/domain.hpp"

namespace mesowave::dem {
namespace {

// `line`: the packing's axis if its centres lie on one line (a patch on a face it crosses takes the end sphere).
std::vector<std::size_t> resolve(const SphereTarget& target, const SpherePart& s, const Box& box,
                                 const std::optional<Vec3>& line, const std::string& who) {
  switch (target.kind) {
    case SphereTarget::Kind::patch: return spheres_under_patch(s, box, target.patch, who, line);
    case SphereTarget::Kind::point: return {sphere_nearest(s, target.point_m)};
    case SphereTarget::Kind::end: return {sphere_at_end(s, target.last)};
  }
  return {};
}

std::string ns_text(double seconds) { return format_number(seconds * 1e9) + " ns"; }

std::int64_t whole_steps(double interval, double dt, const std::string& what) {
  const double ratio = interval / dt;
  const auto steps = std::int64_t(std::llround(ratio));
  if (steps < 1 || std::abs(ratio - double(steps)) > 1e-6 * ratio)
    throw InputError(what + " (" + ns_text(interval) + ") must be a whole number of time steps of " + ns_text(dt));
  return steps;
}

void add_boundary_stiffness(CriticalTimeStep& c, double stiffness_per_mass, double damping) {
  c.boundary_lambda = stiffness_per_mass;
  c.lambda_max += stiffness_per_mass;
  c.eigenvalue_s = 2.0 / std::sqrt(c.lambda_max);
  c.limit_s = c.eigenvalue_s / std::sqrt(1.0 + damping);
  const double gershgorin = 4.0 / (c.stiffness_bound_s * c.stiffness_bound_s) + stiffness_per_mass;
  c.stiffness_bound_s = 2.0 / std::sqrt(gershgorin);
}

// The loaded area (the bounding box across the load axis, or pi r^2 for a
// line of spheres), the mean sphere diameter and the particle density.
UniaxialTestSpecimen describe_specimen(double r_mean, const Box& box, const std::optional<Vec3>& line,
                                       const CohesiveFrictionalMaterial& m, const Scene& scene) {
  UniaxialTestSpecimen s;
  s.grain_diameter_m = 2 * r_mean;
  s.particle_density_kg_m3 = m.density_kg_m3;
  s.area_m2 = scene.test.area_m2;
  if (s.area_m2 > 0) return s;
  if (line) {
    s.area_m2 = std::numbers::pi * r_mean * r_mean;
    return s;
  }
  const SensorSpec* axial = nullptr;
  for (const auto& sensor : scene.sensors)
    if (sensor.name == scene.test.axial.front()) axial = &sensor;
  if (axial->component == "line") throw InputError("[test]: an extensometer along \"line\" needs a line of spheres");
  const int a = axial->component[0] - 'x';
  const int p = (a + 1) % 3, q = (a + 2) % 3;
  s.area_m2 = (box.upper[p] - box.lower[p]) * (box.upper[q] - box.lower[q]);
  return s;
}

// A copy of one default-constructed object, not a temporary: see the header.
const SimulationOptions& default_options() {
  static const SimulationOptions options;
  return options;
}

}  // namespace

Simulation::~Simulation() = default;

Simulation::Simulation(const Scene& scene, Packing packing) : Simulation(scene, std::move(packing), default_options()) {}

Simulation::Simulation(const Scene& scene, Packing packing, SimulationOptions options)
    : scene_(scene), options_(std::move(options)) {
  const auto start = std::chrono::steady_clock::now();
  CohesiveFrictionalMaterial& m = scene_.material;
  if (!scene_.density_given) {
    if (!(packing.particle_density_kg_m3 > 0))
      throw InputError("no particle density: the packing file has none, so set [material] density_kg_m3 in the scene");
    m.density_kg_m3 = packing.particle_density_kg_m3;
  }
  if (scene_.damping_law == "viscous") {
    // c = 4 alpha_d f_c: Eq. (7) on one oscillator loses 4 alpha_d of its energy per cycle (alpha_d x the
    // spring's energy in each quarter), viscous damping 4 pi zeta, so zeta = alpha_d / pi and c = 2 zeta w_c.
    double f_c = 0;
    for (const auto& a : scene_.actuators) {
      if (a.kind != "force" || !(a.frequency_hz > 0))
        throw InputError("[model] damping_law = \"viscous\" takes c = 4 alpha_d f_c from the bursts' centre frequency, "
                         "but actuator " + a.name + " is not a force burst");
      if (f_c != 0 && a.frequency_hz != f_c)
        throw InputError("[model] damping_law = \"viscous\" needs one centre frequency for every burst (actuator " +
                         a.name + ": " + format_number(a.frequency_hz / 1e3) + " kHz, another " +
                         format_number(f_c / 1e3) + " kHz)");
      f_c = a.frequency_hz;
    }
    if (f_c == 0) throw InputError("[model] damping_law = \"viscous\" needs a force burst (c = 4 alpha_d f_c)");
    m.viscous_damping_1_s = 4.0 * m.damping * f_c;
    notes_.push_back("damping_law viscous: the local damping alpha_d = " + format_number(m.damping) +
                     " is replaced by mass-proportional viscous damping c = 4 alpha_d f_c = " +
                     format_number(m.viscous_damping_1_s) + " 1/s (f_c = " + format_number(f_c / 1e3) +
                     " kHz): the same amplitude loss per cycle, 2 alpha_d, at the bursts' centre frequency, and linear");
    m.damping = 0;
  }
  Domain* domain = options_.domain && options_.domain->size() > 1 ? options_.domain : nullptr;
  // On several ranks `packing` is the rows this rank read, and the setup reads the rank's part of
  // the set (docs/mpi.md, stage 3 steps 10 and 11): its own spheres and a layer that holds every
  // bond's and step-0 overlap's other end.
  SpherePart spheres = domain ? SpherePart(packing, m.density_kg_m3, *domain, std::max(m.bond_factor, 1.0) * 2.0)
                              : SpherePart(make_sphere_set(packing, m.density_kg_m3));
  setup_rows_ = packing.size();
  packing = {};
  BondNetwork bonds = make_bond_network(spheres, m.bond_factor);
  const Box box = bounding_box(spheres);
  const double r_min = spheres.radius_min(), r_mean = spheres.radius_mean();

  const std::optional<Vec3> line = line_axis(spheres);
  std::vector<ResolvedLoad> loads;
  for (const auto& a : scene_.actuators) {
    const std::string who = "actuator " + a.name;
    loads.push_back({&a, resolve(a.target, spheres, box, line, who), direction_vector(a.direction, a.target, who, line)});
  }
  // The sphere groups of each sensor (its patch, an extensometer's two pads), as its kind lists them.
  std::vector<std::vector<std::vector<std::size_t>>> sensor_groups;
  for (const auto& sensor : scene_.sensors) {
    const std::string who = "sensor " + sensor.name;
    sensor_groups.emplace_back();
    for (const auto& [target, label] : sensor_kinds().get(sensor.kind, who).targets(sensor))
      sensor_groups.back().push_back(resolve(*target, spheres, box, line, who + label));
  }
  const std::string requested = options_.model != "auto" ? options_.model : scene_.model;
  choice_ = choose_model(requested, scene_, spheres, bonds, loads);
  if (choice_.model == "chain" && m.viscous_damping_1_s != 0)
    throw InputError("[model] damping_law = \"viscous\" is not implemented for the chain model; use --model linear");

  // Notes a user should see: second-neighbour bonds on a line (the rod at d < C_f R).
  if (line) {
    std::size_t far = 0;
    const std::vector<double> along = spheres.gathered([&](std::size_t l) { return dot(spheres.spheres().centre_m[l], *line); });
    std::vector<std::size_t> rank(along.size());
    {
      std::vector<std::size_t> idx(along.size());
      for (std::size_t k = 0; k < idx.size(); ++k) idx[k] = k;
      std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return along[a] < along[b]; });
      for (std::size_t r = 0; r < idx.size(); ++r) rank[idx[r]] = r;
    }
    for (std::size_t b = 0; b < bonds.size(); ++b)  // a rank counts the bonds whose first sphere is its own
      if (bonds.lists_all_of(bonds.first[b]) && std::llabs(std::int64_t(rank[bonds.first[b]]) - std::int64_t(rank[bonds.second[b]])) > 1) ++far;
    if (domain) far = std::size_t(domain->sum(far));
    if (far > 0)
      notes_.push_back(std::to_string(far) + " of " + std::to_string(bonds.total()) +
                       " bonds link spheres that are not neighbours on the line: at this spacing a sphere reaches its "
                       "second neighbours within C_f (r_i + r_j) = " + format_number(m.bond_factor) +
                       " (r_i + r_j), so they are bonded too (the rod paper's L_int < 2d would exclude them; a "
                       "bond_factor below (2 d)/(2 R) does)");
  }

  if (domain && options_.impulse_actuator >= 0)
    throw InputError("--frequencies-kHz (superposition) runs on one process only, not on several MPI ranks");
  // The actuators and sensors are made from the spheres at step 0, before the model: on several
  // ranks the model keeps only the spheres it holds once it is set up. Every rank takes the
  // statics of the spheres they read from their owners.
  {
    std::vector<std::size_t> resolved;
    for (const auto& load : loads) resolved.insert(resolved.end(), load.spheres.begin(), load.spheres.end());
    for (const auto& groups : sensor_groups)
      for (const auto& g : groups) resolved.insert(resolved.end(), g.begin(), g.end());
    spheres.fetch(std::move(resolved));
  }

  const double ratio = scene_.duration_s / scene_.dt_s;
  steps_ = std::int64_t(std::ceil(ratio - 1e-9));

  for (std::size_t i = 0; i < loads.size(); ++i) {
    const ActuatorSpec& a = *loads[i].spec;
    actuator_placements_.push_back({a.name, a.kind, packing_indices(spheres, loads[i].spheres), loads[i].direction,
                                    a.amplitude, a.frequency_hz, a.cycles, a.delay_s, {}});
    actuators_.push_back(actuator_kinds().get(a.kind, "actuator " + a.name).make(
        ActuatorSite{a, loads[i].spheres, loads[i].direction, spheres, box, m, scene_.duration_s}));
    if (options_.impulse_actuator >= 0) {
      if (a.kind != "force") throw InputError("actuator " + a.name + " is not a force actuator: no impulse response");
      const bool pushes = std::size_t(options_.impulse_actuator) == i;
      actuators_.back() = std::make_unique<ForceSeriesActuator>(a.name, loads[i].spheres, loads[i].direction,
                                                                pushes ? std::vector<double>{1.0} : std::vector<double>{});
    }
  }
  if (options_.impulse_actuator >= std::int64_t(actuators_.size()))
    throw InputError("no actuator number " + std::to_string(options_.impulse_actuator) + " for an impulse response");
  for (std::size_t i = 0; i < scene_.sensors.size(); ++i) {
    const SensorSpec& sensor = scene_.sensors[i];
    const std::string who = "sensor " + sensor.name;
    const std::int64_t every =
        sensor.sample_interval_s > 0 ? whole_steps(sensor.sample_interval_s, scene_.dt_s, who + " sample interval") : 1;
    sample_interval_steps_.push_back(every);
    Placement where{sensor.name, "", {}, {}, 0, 0, 0, 0, {}};
    sensors_.push_back(sensor_kinds().get(sensor.kind, who).make(
        SensorSite{sensor, spheres, sensor_groups[i], line, options_.impulse_actuator >= 0 ? 1 : every, actuators_},
        where));
    sensor_placements_.push_back(std::move(where));
  }
  if (options_.impulse_actuator >= 0)
    for (std::size_t i = 0; i < loads.size(); ++i)
      sensors_.push_back(std::make_unique<MotionSensor>("actuator " + loads[i].spec->name, loads[i].spheres,
                                                        MotionQuantity::velocity, (1.0 / norm(loads[i].direction)) * loads[i].direction,
                                                        "actuator direction", 1, Vec3{}));
  if (options_.impulse_actuator >= 0)
    for (std::size_t i = 0; i < scene_.sensors.size(); ++i) {
      SensorSpec twin = scene_.sensors[i];
      if (twin.kind != "motion") continue;  // superposition refuses other kinds
      twin.quantity = MotionQuantity::displacement;
      Placement unused{twin.name, "", {}, {}, 0, 0, 0, 0, {}};
      sensors_.push_back(sensor_kinds().get(twin.kind, "sensor " + twin.name)
                             .make(SensorSite{twin, spheres, sensor_groups[i], line, 1, actuators_}, unused));
    }
  // Every rank runs the actuators and sensors, so every rank holds the spheres they read; the
  // model keeps the accelerations of those only.
  std::vector<std::size_t> observed;
  for (const auto& a : actuators_) observed.insert(observed.end(), a->spheres().begin(), a->spheres().end());
  for (const auto& groups : sensor_groups)
    for (const auto& g : groups) observed.insert(observed.end(), g.begin(), g.end());
  setup_spheres_ = spheres.spheres().size();
  model_ = contact_laws()
               .get(scene_.contact_law, "[material].law")
               .make(choice_.model, std::move(spheres), std::move(bonds), LawInput{m, scene_.law_parameters, line, domain});
  model_->observe(observed);
  if (domain) model_->distribute(*domain, observed);
#ifdef __GLIBC__
  // The setup's buffers are freed, but in the heap's middle: hand those pages back before the
  // critical step's Lanczos, the run's peak (docs/mpi.md, stage 3 step 11: the resident peak of a
  // rank of two otherwise held 10-35 MB of them, at the same heap peak).
  malloc_trim(0);
#endif
  dt_cr_ = critical_time_step(*model_, r_min, m.density_kg_m3, m.E_dem_Pa, m.damping);
  // Walls add a contact spring to the spheres they touch: by Weyl's inequality
  // lambda_max(K + D) <= lambda_max(K) + max D, D the largest k_w / m.
  double boundary = 0;
  for (const auto& a : actuators_) boundary = std::max(boundary, a->added_stiffness_per_mass());
  if (boundary > 0) add_boundary_stiffness(dt_cr_, boundary, m.damping);
  if (options_.refuse_unstable_dt && !(scene_.dt_s <= dt_cr_.limit_s))
    throw InputError("time step dt = " + ns_text(scene_.dt_s) + " exceeds the stable limit of this packing, " +
                     ns_text(dt_cr_.limit_s) + " = 2/sqrt((1 + alpha_d) lambda_max) with lambda_max of the bonded "
                     "network (the paper's estimate min R sqrt(rho/E) is " + ns_text(dt_cr_.paper_estimate_s) +
                     "); choose dt_ns <= " + format_number(std::floor(dt_cr_.limit_s * 1e9 * 1000) / 1000));

  if (scene_.test.active()) test_specimen_ = describe_specimen(r_mean, box, line, m, scene_);
  setup_s_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

RunReport Simulation::describe() const {
  RunReport r;
  r.scene = scene_.name;
  r.choice = choice_;
  r.material = scene_.material;
  r.contact_law = scene_.contact_law;
  r.law_parameters = scene_.law_parameters;
  r.actuator_placements = actuator_placements_;
  r.sensor_placements = sensor_placements_;
  r.spheres = model_->sphere_count();
  r.bonds = model_->bond_count();
  r.contacts = model_->contact_count();
  r.broken_bonds = model_->broken_bond_count();
  r.degrees_of_freedom = model_->degrees_of_freedom();
  r.threads = model_->threads();
  r.distribution = model_->distribution();
  if (!r.distribution.empty())
    r.distribution += "; setup: " + std::to_string(setup_rows_) + " packing rows read, " + std::to_string(setup_spheres_) +
                      " spheres of its part (own, layer, observed)";
  r.dt_s = scene_.dt_s;
  r.duration_s = double(steps_) * scene_.dt_s;
  r.steps = steps_;
  r.dt_cr = dt_cr_;
  std::size_t sensor_bytes = 0;
  for (std::size_t i = 0; i < sensors_.size(); ++i) sensor_bytes += std::size_t(steps_ + 1) * sizeof(double);
  r.memory_bytes = model_->memory_bytes() + sensor_bytes;
  for (const auto& a : actuators_) r.actuators.push_back(a->name() + ": " + a->description());
  for (const auto& s : sensors_) r.sensors.push_back(s->name() + ": " + s->description());
  r.notes = notes_;
  r.setup_s = setup_s_;
  r.sample_interval_steps = sample_interval_steps_;
  return r;
}

RunReport Simulation::run() {
  Model& model = *model_;
  const double dt = scene_.dt_s;
  for (auto& s : sensors_) s->prepare(steps_);
  const std::int64_t energy_every = scene_.energy_check_steps;
  const std::int64_t snapshot_every =
      scene_.snapshot_interval_s > 0 && options_.on_snapshot
          ? whole_steps(scene_.snapshot_interval_s, dt, "snapshot interval")
          : 0;
  const std::int64_t first = loop_.done;  // 0, or the step a checkpoint restored
  // Snapshot k is at step k * snapshot_every; a restarted run takes up the numbering after its step.
  std::int64_t snapshot_index = first > 0 && snapshot_every > 0 ? first / snapshot_every + 1 : 0;
  // A distributed model holds other ranks' spheres only as ghosts: a snapshot collects them first.
  const auto snapshot = [&](double t_s) {
    model.collect_state();
    options_.on_snapshot(model, t_s, snapshot_index++);
  };
  if (snapshot_every > 0 && first == 0) snapshot(0.0);

  // A test's stop rule reads the load sensors whenever they have a new sample.
  std::optional<UniaxialTestMonitor> monitor;
  std::vector<const Sensor*> loads;
  if (test_specimen_) {
    monitor.emplace(scene_.test, test_specimen_->area_m2);
    monitor->resume(loop_.test_peak_Pa);
    for (const auto& name : scene_.test.load)
      for (const auto& s : sensors_)
        if (s->name() == name) loads.push_back(s.get());
  }
  std::vector<double> latest(loads.size());
  std::size_t seen = loads.empty() ? 0 : loads.front()->samples().size();
  std::string stop_reason;

  const CheckpointOptions& checkpoint = options_.checkpoint;
  const CheckpointOptions& intact = options_.intact_checkpoint;
  bool request_served = false, intact_over = intact.file.empty() || intact.every_steps <= 0;
  const auto start = std::chrono::steady_clock::now();
  for (std::int64_t n = first; n < steps_; ++n) {
    const double t = double(n) * dt;
    for (auto& a : actuators_) a->before_step(model, t, dt);
    const bool energy_step = n % energy_every == 0 || n + 1 == steps_;
    model.step(dt, energy_step);
    for (auto& a : actuators_) a->after_step(model, t, dt);
    for (auto& s : sensors_) s->record(model, n);
    if (energy_step) {
      const EnergyAccount e = model.energy();
      const double stored = e.stored();
      if (!std::isfinite(stored) || model.has_non_finite_state())
        throw InputError("the state became non-finite at step " + std::to_string(n) + " (t = " +
                         format_number(t * 1e6) + " us): the run is unstable; nothing was written");
      if (n == 0) loop_.initial_stored_J = std::max(stored, 0.0);
      loop_.max_work_J = std::max(loop_.max_work_J, e.external_work_J);
      loop_.peak_stored_J = std::max(loop_.peak_stored_J, stored);
      const double allowed = 4.0 * (loop_.initial_stored_J + loop_.max_work_J);
      if (stored > allowed && stored > 1e-300)
        throw InputError("energy blow-up at step " + std::to_string(n) + " (t = " + format_number(t * 1e6) +
                         " us): stored energy " + format_number(stored) + " J exceeds 4x the energy put in (" +
                         format_number(loop_.initial_stored_J + loop_.max_work_J) + " J); the time step " + ns_text(dt) +
                         " is too large for this packing (stable limit " + ns_text(dt_cr_.limit_s) +
                         ") or the model is unstable; nothing was written");
    }
    if (snapshot_every > 0 && (n + 1) % snapshot_every == 0) snapshot(double(n + 1) * dt);
    loop_.done = n + 1;
    if (monitor && loads.front()->samples().size() > seen) {
      seen = loads.front()->samples().size();
      for (std::size_t i = 0; i < loads.size(); ++i) latest[i] = loads[i]->samples().back();
      const bool stop = monitor->stop_after(latest);
      loop_.test_peak_Pa = monitor->peak_Pa();
      if (stop) {
        stop_reason = monitor->reason();
        break;
      }
    }
    // A checkpoint when one is due, before the progress report (which ends an interrupted run).
    if (!checkpoint.file.empty()) {
      const bool due = checkpoint.every_steps > 0 && loop_.done % checkpoint.every_steps == 0;
      const bool asked = !request_served && checkpoint.requested && checkpoint.requested();
      if (due || asked) {
        save_checkpoint(checkpoint.file, checkpoint.identity);
        if (checkpoint.on_written) checkpoint.on_written(loop_.done);
      }
      request_served = request_served || asked;
    }
    if (!intact_over && loop_.done % intact.every_steps == 0) {
      intact_over = model.broken_bond_count() > 0;
      if (!intact_over) {
        save_checkpoint(intact.file, intact.identity);
        if (intact.on_written) intact.on_written(loop_.done);
      }
    }
    if (options_.on_progress) options_.on_progress(loop_.done, steps_);
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::int64_t done = loop_.done, stepped = done - first;  // this process's steps (all but a restart's)

  RunReport r = describe();
  r.ran = true;
  r.steps = done;
  r.duration_s = double(done) * dt;
  r.stop_reason = stop_reason;
  r.wall_s = wall;
  r.steps_per_s = wall > 0 ? double(stepped) / wall : 0;
  r.ns_per_contact_step = stepped > 0 && r.contacts > 0 ? wall * 1e9 / (double(stepped) * double(r.contacts)) : 0;
  model.collect_energy();  // a stop after a step without energies: the damping of every rank's blocks
  r.energy = model.energy();
  r.peak_stored_J = loop_.peak_stored_J;
  r.peak_force_ratio = model.peak_force_ratio();
  r.broken_bonds = model.broken_bond_count();
  if (options_.impulse_actuator >= 0) {
    // superposition.hpp checks the bound for the burst the response is convolved with.
  } else if (choice_.model == "linear") {
    r.validity_bound = scene_.linear_validity_bound;
    if (!(r.peak_force_ratio < r.validity_bound))
      throw InputError("the linearised network is not valid for this run: the peak bond force / strength reached " +
                       format_number(r.peak_force_ratio) + ", above the validity bound " +
                       format_number(r.validity_bound) + " (linear_validity_bound); rerun with --model full");
  } else if (choice_.model == "chain" && scene_.material.breakable()) {
    r.validity_bound = 1.0;
    if (!(r.peak_force_ratio < 1.0))
      throw InputError("the chain model is not valid for this run: a bond reached its strength (peak bond force / "
                       "strength " + format_number(r.peak_force_ratio) + " >= 1) and would break; rerun with --model full");
  }
  for (const auto& s : sensors_) r.signals.push_back(s->signal(dt));
  if (test_specimen_) r.test = analyse_uniaxial_test(r.signals, scene_.test, *test_specimen_);
  return r;
}

// The run's checkpoint (checkpoint.hpp): the loop's state, then each part's own. Distributed,
// every rank takes part (the model gathers its state to rank 0 as it writes the file; the
// actuators and sensors run alike on every rank, so rank 0's state is theirs).
void Simulation::save_checkpoint(const std::filesystem::path& file, const CheckpointIdentity& identity) {
  model_->collect_energy();
  const auto body = [&](StateGroup& root) {
    StateGroup run = root.create("run");
    run.write("steps_done", loop_.done);
    run.write("steps", steps_);
    run.write("dt_s", scene_.dt_s);
    run.write("initial_stored_J", loop_.initial_stored_J);
    run.write("max_work_J", loop_.max_work_J);
    run.write("peak_stored_J", loop_.peak_stored_J);
    run.write("test_peak_Pa", loop_.test_peak_Pa);
    StateGroup model = root.create("model");
    model_->save_state(model);
    StateGroup actuators = root.create("actuators");
    for (std::size_t i = 0; i < actuators_.size(); ++i) {
      StateGroup g = actuators.create(std::to_string(i));
      g.write_text("name", actuators_[i]->name());
      actuators_[i]->save_state(g);
    }
    StateGroup sensors = root.create("sensors");
    for (std::size_t i = 0; i < sensors_.size(); ++i) {
      StateGroup g = sensors.create(std::to_string(i));
      g.write_text("name", sensors_[i]->name());
      sensors_[i]->save_state(g);
    }
  };
  if (options_.domain && options_.domain->rank() != 0) {
    StateGroup nowhere = StateGroup::nowhere();
    return body(nowhere);
  }
  write_checkpoint_file(file, identity, body);
}

void Simulation::restore(const std::filesystem::path& file, const CheckpointIdentity& identity) {
  restore(file, identity, false);
}

void Simulation::restore_stronger(const std::filesystem::path& file, const CheckpointIdentity& identity) {
  // The linearised network and the chain never break: no prefix to share, and their state is not the full law's.
  if (choice_.model != "full")
    throw InputError("a restart with stronger bonds is for the full law (bonds that break); this run's model is " +
                     choice_.model);
  restore(file, identity, true);
  if (const std::size_t broken = model_->broken_bond_count(); broken > 0)
    throw InputError("checkpoint " + file.string() + " holds " + std::to_string(broken) + " broken bonds at step " +
                     std::to_string(loop_.done) + ": only an intact one (--intact-checkpoint) starts a run with "
                     "stronger bonds");
}

void Simulation::restore(const std::filesystem::path& file, const CheckpointIdentity& identity, bool stronger_bonds) {
  read_checkpoint_file(file, identity, [&](const StateGroup& root) {
    const StateGroup run = root.open("run");
    // The identity covers the inputs and options; these are what they determine, checked once more.
    if (run.read_int64("steps") != steps_ || run.read_double("dt_s") != scene_.dt_s)
      throw InputError("checkpoint " + file.string() + " is of a run of another time step or duration");
    const std::int64_t done = run.read_int64("steps_done");
    if (done < 0 || done > steps_)
      throw InputError("checkpoint " + file.string() + " holds step " + std::to_string(done) + " of a " +
                       std::to_string(steps_) + "-step run");
    model_->load_state(root.open("model"));
    const StateGroup actuators = root.open("actuators"), sensors = root.open("sensors");
    for (std::size_t i = 0; i < actuators_.size(); ++i) {
      const StateGroup g = actuators.open(std::to_string(i));
      g.expect_text("name", actuators_[i]->name());
      actuators_[i]->load_state(g);
    }
    for (std::size_t i = 0; i < sensors_.size(); ++i) {
      const StateGroup g = sensors.open(std::to_string(i));
      g.expect_text("name", sensors_[i]->name());
      sensors_[i]->load_state(g);
    }
    loop_.done = done;
    loop_.initial_stored_J = run.read_double("initial_stored_J");
    loop_.max_work_J = run.read_double("max_work_J");
    loop_.peak_stored_J = run.read_double("peak_stored_J");
    loop_.test_peak_Pa = run.read_double("test_peak_Pa");
  }, stronger_bonds);
}

}  // namespace mesowave::dem
