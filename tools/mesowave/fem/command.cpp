#include "mesowave/fem/command.hpp"

#include "mesowave/app/process_info.hpp"
#include "mesowave/app/progress.hpp"
#include "mesowave/app/superposition_options.hpp"
#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/experiment/experiment.hpp"
#include "mesowave/fem/case.hpp"
#include "mesowave/fem/superposition.hpp"
#include "mesowave/signal/signal_file.hpp"

namespace mesowave::fem {

namespace fs = std::filesystem;

void add_common_options(CLI::App& sub, FemCommandLine& v) {
  // The second names are mw-upv's: a wave test's continuum reference takes the dynamic moduli, and
  // `mw-fem --from upv.json box ...` fills them (and --density-kg-m3) from its E_d_GPa and nu_d.
  sub.add_option("--E-GPa,--E-d-GPa", v.E_GPa, "Young's modulus [GPa] (--from mw-upv's JSON fills it with E_d)");
  sub.add_option("--nu,--nu-d", v.nu, "Poisson ratio (-1 < nu < 0.5) (--from mw-upv's JSON fills it with nu_d)");
  sub.add_option("--density-kg-m3", v.rho, "Density [kg/m3] (these three: or the --experiment's specimen's)");
  sub.add_option("--mesh-mm", v.mesh_mm, "Element size [mm]")->capture_default_str();
  sub.add_option("--experiment", v.experiment_path, "The study's experiment (lab-data/<study>/experiment.toml): "
                 "specimen, transducers, burst and record; the options below beat its values");
  auto* one = sub.add_option("--frequency-kHz", v.f_kHz, "Centre frequency of the Hann burst [kHz] (100)");
  app::add_superposition_options(sub, one,
                                 {"unit-impulse run of the mesh by superposition (fem/superposition.hpp: exact to "
                                  "round-off)",
                                  "fem-{f}kHz.h5", "--out-pattern", "report"},
                                 v.frequencies_kHz, v.signals_pattern, v.out_pattern, v.check_kHz);
  sub.add_option("--cycles", v.cycles, "Cycles in the burst (5)");
  sub.add_option("--force-N", v.force_N, "Peak force amplitude [N] (1)");
  sub.add_option("--alpha-damping", v.alpha, "Rayleigh mass-proportional damping alpha [1/s] (rod paper: 2000)")
      ->capture_default_str();
  sub.add_option("--duration-ms", v.duration_ms, "Simulated time [ms] (1.5, or --experiment's record)");
  sub.add_option("--sample-dt-us", v.sample_dt_us, "Sampling interval of the signals [us] (0.1)");
  sub.add_option("--dt-us", v.dt_us, "Time step [us] (default: the largest that divides the sampling interval "
                                     "and stays below the stable step)");
  sub.add_option("--quantity", v.quantity, "Recorded quantity: displacement | velocity | acceleration (acceleration)");
  sub.add_option("--sensor", v.sensors, "NAME=X,Y,Z in mm, optionally /x|/y|/z|/r|/normal; repeatable");
  sub.add_option("--patch-radius-mm", v.patch_mm,
                 "Spread the force as a uniform traction over the face within this radius (0: point force)");
  sub.add_option("--signals", v.signals_path,
                 "Signal file to write (HDF5, mesowave signal layout); required without --frequencies-kHz");
  sub.add_option("--threads", v.threads,
                 "OpenMP threads (default: the cores the machine is not busy with; same bits for any count)");
  sub.add_flag("--quiet", v.quiet, "No progress bar");
  app::add_out_option(sub, v.out, "the JSON report (cost, stable step)");
}

void add_rod_options(CLI::App& rod, FemCommandLine& v) {
  rod.add_option("--radius-mm", v.radius_mm, "Rod radius [mm] (or --experiment's)");
  rod.add_option("--length-mm", v.length_mm, "Rod length [mm] (with --experiment: its rod at this length)");
  rod.add_option("--model", v.model_kind, "axisymmetric | 3d")->capture_default_str();
  rod.add_option("--spacetime", v.spacetime_path, "Also record the axial quantity along the axis (HDF5, for a 2D FFT)");
  rod.add_option("--spacetime-step-mm", v.st_step_mm, "Spacing of the space-time record [mm] (default: mesh size)");
}

void add_box_options(CLI::App& box, FemCommandLine& v) {
  box.add_option("--size-mm", v.size_text, "Edge length, or X,Y,Z [mm] (with --experiment: its box scaled to this edge X)");
  box.add_option("--source-mm", v.source_text, "Where the force acts, a point on a face X,Y,Z [mm] (or --experiment's actuator)");
}

namespace {

FemCase make_case(const FemCommandLine& v, FemBody body, app::Run& run) {
  FemCase c;
  std::optional<experiment::Experiment> lab;
  if (!v.experiment_path.empty()) {
    run.input(v.experiment_path);
    lab = experiment::read_experiment_file(v.experiment_path);
    if (body == FemBody::rod) lab = rod_experiment(*lab, v.radius_mm, v.length_mm);
    const double scale = v.size_text.empty() ? 1.0 : std::stod(v.size_text) / (lab->specimen.size_m[0] / units::mm);
    if (!v.source_text.empty() || !v.sensors.empty())
      throw InputError("--experiment places the transducers: no --source-mm, --sensor");
    apply_experiment(c, *lab, scale);
  } else if (body == FemBody::cylinder) {
    throw InputError("mw-fem cylinder needs --experiment (the cylinder and its transducers)");
  }
  c.material = material_of(v.E_GPa, v.nu, v.rho, lab ? &lab->specimen : nullptr);
  c.mesh_m = require_positive("--mesh-mm", v.mesh_mm, "mm") * units::mm;
  if (v.f_kHz) c.frequency_hz = require_positive("--frequency-kHz", *v.f_kHz, "kHz") * units::kHz;
  if (v.cycles) c.cycles = require_positive("--cycles", *v.cycles);
  if (v.force_N) c.force_N = require_finite("--force-N", *v.force_N, "N");
  if (v.patch_mm) c.patch_radius_m = *v.patch_mm * units::mm;
  c.alpha_damping_per_s = v.alpha;
  if (v.duration_ms) c.duration_s = require_positive("--duration-ms", *v.duration_ms, "ms") * units::ms;
  if (v.sample_dt_us) c.sample_dt_s = *v.sample_dt_us * units::us;
  if (v.dt_us) c.dt_s = *v.dt_us * units::us;
  if (v.quantity) c.quantity = experiment::parse_motion_quantity(*v.quantity, "--quantity");
  for (const auto& s : v.sensors) c.probe_points.push_back(parse_probe_point(s));
  c.threads = v.threads;
  if (body == FemBody::rod) {
    if (!lab) set_rod_size(c, v.radius_mm, v.length_mm);
    c.rod_model = v.model_kind;
    if (!v.spacetime_path.empty()) c.spacetime_step_m = v.st_step_mm * units::mm;
  } else if (v.experiment_path.empty()) {
    if (v.size_text.empty() || v.source_text.empty())
      throw InputError("mw-fem box needs --size-mm and --source-mm, or --experiment");
    c.body = FemCase::Body::box;
    if (v.size_text.find(',') == std::string::npos) c.size_m.fill(std::stod(v.size_text) * units::mm);
    else c.size_m = parse_point_mm(v.size_text, "--size-mm");
    c.source_m = parse_point_mm(v.source_text, "--source-mm");
  }
  return c;
}

double peak_rss_MiB() { return double(app::resource_usage().peak_rss_kib) / 1024.0; }

void run_direct(const FemCommandLine& v, const FemSetup& setup, app::Run& run) {
  if (v.signals_path.empty()) throw InputError("give --signals (or --frequencies-kHz with --signals-pattern)");
  app::Progress progress("mw-fem " + setup.model.description, setup.stepping.steps, "steps", !v.quiet);
  const FemRun fem = run_fem_case(setup, [&](std::int64_t n) { progress.update(n); });
  progress.finish();
  signal::write_signal_file(run.output(v.signals_path), fem.result.signals, fem.attributes);
  if (setup.spacetime)
    write_spacetime_file(run.output(v.spacetime_path), fem.result.spacetime, *setup.spacetime,
                         setup.stepping.sample_dt_s, "z", fem.attributes);
  const auto j = fem_report(setup, fem, peak_rss_MiB(), v.signals_path);
  run.metric("wall", fem.result.wall_s, "s");
  run.metric("steps per second", j["steps_per_s"], "1/s");
  run.metric("stable dt", j["stable_dt_us"], "us");
  run.metric("peak RSS", j["peak_rss_MiB"], "MiB");
  run.emit_json(j, v.out);
}

// A frequency's report: a direct run's (fem_report), its cost the impulse run's step loop, and the method.
nlohmann::ordered_json superposed_report(const FemSuperposedSet& set, const FemSuperposedFrequency& f,
                                         const fs::path& signals) {
  FemRun cost = f.run;
  cost.result.wall_s = set.impulse.result.wall_s;
  nlohmann::ordered_json j = fem_report(f.setup, cost, peak_rss_MiB(), signals);
  j["method"] = "superposition";
  j["superposition"] = superposition_json(set, f);
  return j;
}

void run_superposed(const FemCommandLine& v, const FemSetup& setup, app::Run& run) {
  if (!v.signals_path.empty() || !v.spacetime_path.empty())
    throw InputError("--frequencies-kHz writes --signals-pattern files: --signals and --spacetime are for one direct run");
  if (v.signals_pattern.empty()) throw InputError("--frequencies-kHz needs --signals-pattern (e.g. 'fem-{f}kHz.h5')");
  signal::frequency_path(v.signals_pattern, "--signals-pattern", 1);  // a pattern without {f} fails before the run
  if (!v.out_pattern.empty()) signal::frequency_path(v.out_pattern, "--out-pattern", 1);
  app::Progress progress("mw-fem " + setup.model.description + ", unit impulse", setup.stepping.steps, "steps", !v.quiet);
  const FemSuperposedSet set =
      run_fem_superposed(setup, v.frequencies_kHz, v.check_kHz, [&](std::int64_t n) { progress.update(n); });
  progress.finish();
  nlohmann::ordered_json per = nlohmann::ordered_json::array();
  for (const auto& f : set.frequencies) {
    const double hz = f.setup.spec.frequency_hz;
    const fs::path signals = signal::frequency_path(v.signals_pattern, "--signals-pattern", hz);
    signal::write_signal_file(run.output(signals), f.run.result.signals, f.run.attributes);
    if (!v.out_pattern.empty())
      run.write_text(signal::frequency_path(v.out_pattern, "--out-pattern", hz),
                     superposed_report(set, f, signals).dump(2) + "\n");
    per.push_back({{"frequency_kHz", hz / units::kHz}, {"signals", signals.string()},
                   {"convolution_s", f.run.result.wall_s}});
  }
  nlohmann::ordered_json j = superposed_report(set, set.frequencies.front(), "");
  j.erase("signals");
  j["superposition"].erase("check");
  j["superposition"]["convolution_s"] = nullptr;  // one per frequency: "frequencies"
  j["frequencies"] = per;
  run.param("method", "superposition");
  run.metric("wall", set.impulse.result.wall_s, "s");
  run.metric("steps per second", j["steps_per_s"], "1/s");
  run.metric("stable dt", j["stable_dt_us"], "us");
  run.metric("peak RSS", j["peak_rss_MiB"], "MiB");
  for (const auto& c : set.checks) {
    const std::string kHz = signal::frequency_text(c.frequency_hz);
    run.metric("superposition_min_pcc_" + kHz + "kHz", c.error.min_pcc, "");
    run.metric("superposition_max_diff_over_peak_" + kHz + "kHz", c.error.max_diff_over_peak_all, "");
  }
  run.emit_json(j, v.out);
}

}  // namespace

void run_fem_command(const FemCommandLine& v, FemBody body, app::Run& run) {
  const FemSetup setup = assemble_fem_case(make_case(v, body, run));
  if (v.frequencies_kHz.empty()) run_direct(v, setup, run);
  else run_superposed(v, setup, run);
}

}  // namespace mesowave::fem
