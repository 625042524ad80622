#include "mesowave/dem/command/run_command.hpp"

#include <iostream>
#include <map>
#include <optional>

#include "mesowave/app/interrupt.hpp"
#include "mesowave/app/progress.hpp"
#include "mesowave/app/superposition_options.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/dem/calibration/static_elastic.hpp"
#include "mesowave/dem/engine/run_report.hpp"
#include "mesowave/dem/engine/simulation.hpp"
#include "mesowave/dem/engine/snapshot.hpp"
#include "mesowave/dem/engine/superposition.hpp"
#include "mesowave/dem/parallel/domain.hpp"
#include "mesowave/dem/packing/packing_file.hpp"
#include "mesowave/dem/scene/scene.hpp"
#include "mesowave/signal/signal_file.hpp"

namespace mesowave::dem {

void add_scene_options(CLI::App& sub, RunCommandLine& v) {
  sub.add_option("scene", v.scene_path, "Scene file (TOML; see docs/formats.md)")->required();
  sub.add_option("--model", v.model, "auto (default: the scene's choice, else the rules) | full | linear | chain")
      ->check(CLI::IsMember({"auto", "full", "linear", "chain"}));
  add_override_options(sub, v.overrides);
}

void add_run_options(CLI::App& run_cmd, RunCommandLine& v) {
  run_cmd.add_option("--signals", v.signals_path, "Sensor signals (HDF5, docs/formats.md); required without --frequencies-kHz");
  auto* many = app::add_superposition_options(
      run_cmd, run_cmd.get_option("--frequency-kHz"),
      {"run by superposition (dem/engine/superposition.hpp): linear model, force actuators, motion sensors",
       "dem-{f}kHz.h5", "--summary-pattern", "summary"},
      v.frequencies_kHz, v.signals_pattern, v.summary_pattern, v.check_kHz);
  run_cmd.add_flag("--check-unproven", v.check_unproven,
                   "With --frequencies-kHz: also run directly each frequency whose bound on the peak bond force / "
                   "strength does not prove the linear model valid (instead of refusing it); the records say which")
      ->needs(many);
  run_cmd.add_option("--summary", v.summary_path, "Run summary (JSON; also printed)");
  run_cmd.add_option("--signals-csv", v.csv_path, "The signals also as CSV (t_s and one column per sensor)");
  run_cmd.add_option("--snapshots", v.snapshot_dir, "Folder for ParaView snapshots (.vtp per instant + snapshots.pvd)");
  run_cmd.add_option("--snapshot-interval-us", v.overrides.snapshot_us, "Time between snapshots [us] (default: the scene's)");
  run_cmd.add_flag("--quiet", v.quiet, "No progress bar");
  auto* static_opt = run_cmd.add_flag(
      "--static", v.static_solve,
      "A compression [test]'s elastic part as one static solve of the linearised network instead of "
      "stepping (dem/calibration/static_elastic.hpp): E_glob and nu_glob between --modulus-levels-MPa, "
      "walls as one-sided springs, the same extensometers; --signals and --curves get the two levels");
  run_cmd.add_option("--static-preconditioner", v.static_preconditioner,
                     "--static's BiCGSTAB preconditioner: jacobi | ilut (incomplete LU) | amg (hypre's BoomerAMG, "
                     "systems AMG over the spheres' 6 DOFs; docs/calibration.md, \"Elastic trials as a static solve\")")
      ->check(CLI::IsMember(static_preconditioners()))
      ->needs(static_opt)
      ->capture_default_str();
  run_cmd.add_option("--curves", v.curves_path,
                     "A [test]'s stress-strain curves as CSV (t_s, stress_MPa, axial_strain, lateral_strain, "
                     "broken_bonds); the signal file holds them too (test.stress, test.axial_strain, ...)");
  auto* checkpoint_opt = run_cmd.add_option("--checkpoint", v.checkpoint_path,
                                            "Checkpoint (HDF5, written whole) on SIGTERM/SIGINT before the run stops, "
                                            "and every --checkpoint-every-steps steps; a restart may run on any "
                                            "MPI rank count");
  run_cmd.add_option("--checkpoint-every-steps", v.checkpoint_every, "Steps between checkpoints")
      ->check(CLI::PositiveNumber)
      ->needs(checkpoint_opt);
  run_cmd.add_option("--restart", v.restart_path,
                     "Continue from this checkpoint, to the same bits as a run never stopped; the scene, packing "
                     "and options must be the checkpoint's")
      ->check(CLI::ExistingFile);
  auto* intact_opt = run_cmd.add_option(
      "--intact-checkpoint", v.intact_checkpoint_path,
      "Checkpoint (HDF5) every --intact-checkpoint-every-steps steps while no bond is broken: the last one holds "
      "the state before the first break, from which a run with stronger bonds starts (--restart-stronger)");
  run_cmd.add_option("--intact-checkpoint-every-steps", v.intact_checkpoint_every, "Steps between intact checkpoints")
      ->check(CLI::PositiveNumber)
      ->needs(intact_opt)
      ->capture_default_str();
  run_cmd.add_option("--restart-stronger", v.restart_stronger_path,
                     "Start from an --intact-checkpoint of a run with weaker bonds: the scene, packing and options "
                     "the checkpoint's but T and C, each at least its; while every bond holds the strengths do not "
                     "enter the law, so the run is the same bits as one from step 0 (docs/calibration.md)")
      ->check(CLI::ExistingFile)
      ->excludes(run_cmd.get_option("--restart"));
}

namespace {

struct Inputs {
  Scene scene;
  Packing packing;
};

// On several ranks each reads its part of the packing's rows (the setup sorts them: docs/mpi.md).
Inputs read_inputs(RunCommandLine& v, app::Run& run, const Domain* domain = nullptr) {
  Scene scene = read_scene_file(v.scene_path);
  run.input(v.scene_path);
  if (!scene.experiment_file.empty()) run.input(scene.experiment_file);
  v.overrides.curves = !v.curves_path.empty();
  apply_overrides(scene, v.overrides);
  Packing packing = domain && domain->size() > 1 ? read_packing_file(scene.packing_file, domain->rank(), domain->size())
                                                 : read_packing_file(scene.packing_file);
  run.input(scene.packing_file);
  return {std::move(scene), std::move(packing)};
}

void run_static(const RunCommandLine& v, const Inputs& in, app::Run& run, const std::string& threads_reason) {
  if (!v.snapshot_dir.empty() || !v.csv_path.empty())
    throw InputError("--static solves for equilibrium: it has no --snapshots or --signals-csv");
  if (v.model != "auto" && v.model != "linear") throw InputError("--static solves the linearised network, not --model " + v.model);
  StaticElasticOptions options;
  options.preconditioner = v.static_preconditioner;
  const StaticElasticResult r = static_compression_test(in.scene, in.packing, options);
  if (!v.curves_path.empty()) run.write_text(v.curves_path, uniaxial_curves_csv(r.test));
  signal::write_signal_file(run.output(v.signals_path), uniaxial_curve_signals(r.test),
                            {{"scene", in.scene.name}, {"model", "linear"}, {"method", "static"},
                             {"packing", in.scene.packing_file.string()}});
  run.param("model_chosen", "linear");
  run.param("method", "static");
  run.metric("E_glob", r.E_glob_Pa / 1e9, "GPa");
  if (r.nu_glob) run.metric("nu_glob", *r.nu_glob, "");
  run.metric("wall", r.wall_s, "s");
  auto summary = to_json(r);
  summary["scene"] = in.scene.name;
  summary["threads_reason"] = threads_reason;
  run.emit_json(summary, v.summary_path);
}

void run_superposed_set(const RunCommandLine& v, const Inputs& in, const SimulationOptions& options,
                        std::optional<app::Progress>& progress, app::Run& run, const std::string& threads_reason) {
  if (!v.signals_path.empty() || !v.csv_path.empty() || !v.snapshot_dir.empty() || !v.curves_path.empty() ||
      !v.checkpoint_path.empty() || !v.restart_path.empty() || !v.intact_checkpoint_path.empty() ||
      !v.restart_stronger_path.empty())
    throw InputError("--frequencies-kHz writes --signals-pattern files: --signals, --signals-csv, --snapshots, "
                     "--curves, --checkpoint, --restart and their intact forms are for one direct run");
  if (v.signals_pattern.empty()) throw InputError("--frequencies-kHz needs --signals-pattern (e.g. 'dem-{f}kHz.h5')");
  const SuperposedSet set = run_superposed(in.scene, in.packing, options, v.frequencies_kHz, v.check_kHz, v.check_unproven);
  if (progress) progress->finish();
  for (const auto& f : set.frequencies) {
    const std::string kHz = frequency_text(f.run.frequency_hz);
    signal::write_signal_file(run.output(frequency_path(v.signals_pattern, "--signals-pattern", f.run.frequency_hz)),
                              f.run.signals, {{"scene", in.scene.name}, {"model", set.responses.report.choice.model},
                                              {"packing", in.scene.packing_file.string()}, {"method", "superposition"}});
    if (!v.summary_pattern.empty()) {
      auto summary = f.summary;
      summary["threads_reason"] = threads_reason;
      run.write_text(frequency_path(v.summary_pattern, "--summary-pattern", f.run.frequency_hz), summary.dump(2) + "\n");
    }
    run.metric("peak_force_ratio_bound_" + kHz + "kHz", f.run.peak_force_ratio_bound, "");
  }
  run.param("model_chosen", set.responses.report.choice.model);
  run.param("method", "superposition");
  run.metric("wall", set.responses.wall_s, "s");
  for (const auto& c : set.checks) {
    const std::string kHz = frequency_text(c.frequency_hz);
    run.metric("superposition_min_pcc_" + kHz + "kHz", c.error.min_pcc, "");
    run.metric("superposition_max_diff_over_peak_" + kHz + "kHz", c.error.max_diff_over_peak_all, "");
  }
  auto summary = set.summary;
  summary["threads_reason"] = threads_reason;
  run.emit_json(summary, v.summary_path);
}

void write_direct_run(const RunCommandLine& v, const Scene& scene, const RunReport& report,
                      const std::vector<std::pair<double, std::string>>& snapshots, app::Run& run,
                      const std::string& threads_reason, std::int64_t stronger_at_step) {
  std::map<std::string, std::string> attributes = {
      {"scene", scene.name}, {"model", report.choice.model}, {"packing", scene.packing_file.string()}};
  std::vector<signal::Signal> signals = report.signals;
  if (report.test) {
    for (auto& s : uniaxial_curve_signals(*report.test)) signals.push_back(std::move(s));
    if (!v.curves_path.empty()) run.write_text(v.curves_path, uniaxial_curves_csv(*report.test));
    run.metric("E_glob", report.test->E_secant_Pa / 1e9, "GPa");
    if (report.test->nu_secant) run.metric("nu_glob", *report.test->nu_secant, "");
    run.metric("peak_stress", report.test->peak_stress_Pa / 1e6, "MPa");
    run.metric("inertial_number_max", report.test->inertial_number_max, "");
  }
  signal::write_signal_file(run.output(v.signals_path), signals, attributes);
  if (!v.csv_path.empty()) run.write_text(v.csv_path, signals_csv(report.signals));
  if (!snapshots.empty()) write_pvd(run.output(v.snapshot_dir / "snapshots.pvd"), snapshots);
  run.param("model_chosen", report.choice.model);
  run.metric("steps_per_s", report.steps_per_s, "1/s");
  run.metric("wall", report.wall_s, "s");
  run.metric("dt_limit", report.dt_cr.limit_s, "s");
  run.metric("peak_force_ratio", report.peak_force_ratio, "");
  run.metric("ns_per_contact_step", report.ns_per_contact_step, "ns");
  auto summary = to_json(report);
  summary["threads_reason"] = threads_reason;
  // Its wall_s covers the steps after it; the prefix's peak_force_ratio is the weaker run's (a bound).
  if (stronger_at_step > 0) summary["restarted_stronger_at_step"] = stronger_at_step;
  run.emit_json(summary, v.summary_path);
}

}  // namespace

void run_info_command(RunCommandLine v, app::Run& run, const std::string& threads_reason) {
  Inputs in = read_inputs(v, run);
  SimulationOptions options;
  options.model = v.model;
  const Simulation sim(in.scene, std::move(in.packing), options);
  auto j = to_json(sim.describe());
  j["threads_reason"] = threads_reason;
  run.emit_json(j);
}

void run_run_command(RunCommandLine v, app::Run& run, const std::string& threads_reason, Domain* domain) {
  Inputs in = read_inputs(v, run, domain);
  const bool root = !domain || domain->rank() == 0;
  const bool intact_files = !v.intact_checkpoint_path.empty() || !v.restart_stronger_path.empty();
  if (v.static_solve && intact_files) throw InputError("--static steps nothing: --intact-checkpoint and --restart-stronger are for a stepped run");
  if (domain && (v.static_solve || !v.frequencies_kHz.empty()))
    throw InputError("on several MPI ranks mw-dem runs the scene directly: --static and --frequencies-kHz run on one "
                     "process (docs/mpi.md)");
  if (v.static_solve) return run_static(v, in, run, threads_reason);

  SimulationOptions options;
  options.model = v.model;
  options.domain = domain;
  if (!root) v.quiet = true;  // rank 0 reports and writes
  std::vector<std::pair<double, std::string>> snapshots;
  if (!v.snapshot_dir.empty()) {
    if (!(in.scene.snapshot_interval_s > 0))
      throw InputError("--snapshots needs --snapshot-interval-us or [output] snapshot_interval_us");
    options.on_snapshot = [&, root](const Model& m, double t, std::int64_t index) {
      if (!root) return;  // the simulation collected every sphere on every rank; rank 0 writes them
      const std::string name = "snapshot-" + std::to_string(index) + ".vtp";
      write_vtp(run.output(v.snapshot_dir / name), m, t);
      snapshots.emplace_back(t, name);
    };
  }
  // A signal stops the run after a step, a checkpoint written first if one is asked for. Each
  // rank of several sees it at its own step: with a checkpoint they agree on it after each step
  // (the largest signal number over the ranks, one small reduction a step) before the
  // checkpoint's poll and the progress update read it, so that all write the checkpoint and stop
  // after the same step, whichever caught it (docs/mpi.md). Without one, the first rank to stop
  // ends the others (MPI_Abort).
  const bool agree = domain && !v.checkpoint_path.empty();
  std::optional<int> stop;  // this step's signal, once read (0: none)
  const auto stop_signal = [&] {
    if (!stop) {
      stop = app::interrupt_signal();
      if (agree) stop = int(domain->max(double(*stop)));
      if (*stop != 0) app::interrupt_as(*stop);
    }
    return *stop;
  };
  std::optional<app::Progress> progress;
  std::int64_t resumed_at = 0;
  options.on_progress = [&](std::int64_t done, std::int64_t total) {
    if (!progress) progress.emplace("mw-dem " + in.scene.name, total, "steps", !v.quiet, resumed_at);
    const int signal = stop_signal();
    stop.reset();  // the next step reads it anew
    progress->update(done, signal);
  };
  if (!v.frequencies_kHz.empty()) return run_superposed_set(v, in, options, progress, run, threads_reason);

  // Hashes the scene, packing and experiment files: only for a run that writes or reads a checkpoint.
  const bool checkpoints = !v.checkpoint_path.empty() || !v.restart_path.empty() || !v.intact_checkpoint_path.empty() ||
                           !v.restart_stronger_path.empty();
  const CheckpointIdentity identity = checkpoints ? run_identity(v.scene_path, in.scene, v.overrides, v.model) : CheckpointIdentity{};
  if (!v.checkpoint_path.empty() || !v.restart_path.empty()) {
    const auto written = [&](std::int64_t step) {
      run.param("checkpoint_step", step);  // recorded also when the run is interrupted
      run.keep_on_interrupt(v.checkpoint_path, "a checkpoint at step " + std::to_string(step));
      if (app::interrupt_signal() && root)
        std::cerr << "mw-dem: " << v.checkpoint_path.string() << " holds step " << step << "; continue with --restart\n";
    };
    options.checkpoint = {v.checkpoint_path, v.checkpoint_every, [&] { return stop_signal() != 0; }, identity, written};
  }
  if (!v.intact_checkpoint_path.empty()) {
    const auto written = [&](std::int64_t step) { run.param("intact_checkpoint_step", step); };
    options.intact_checkpoint = {v.intact_checkpoint_path, v.intact_checkpoint_every, {}, identity, written};
  }
  Simulation sim(in.scene, std::move(in.packing), options);
  if (v.signals_path.empty()) throw InputError("run needs --signals (or --frequencies-kHz with --signals-pattern)");
  if (!v.restart_path.empty()) {
    run.input(v.restart_path);
    sim.restore(v.restart_path, identity);
    resumed_at = sim.steps_done();
    run.param("restarted_at_step", resumed_at);
  }
  if (!v.restart_stronger_path.empty()) {
    run.input(v.restart_stronger_path);
    sim.restore_stronger(v.restart_stronger_path, identity);
    resumed_at = sim.steps_done();
    run.param("restarted_stronger_at_step", resumed_at);
  }
  const RunReport report = sim.run();
  if (progress && report.stop_reason.empty()) progress->finish();
  else if (progress) progress->finish_early(report.steps, report.stop_reason);
  if (!root) return;
  write_direct_run(v, in.scene, report, snapshots, run, threads_reason,
                   v.restart_stronger_path.empty() ? 0 : resumed_at);
}

}  // namespace mesowave::dem
