// mw-dem - wave propagation (and any loading) in a DEM packing: Yade's
// cohesive-frictional sphere model (concrete paper Eqs. 1-7), run on the
// cheapest model that is valid for the scene.
//
//   mw-dem info pipeline/concrete-cube/scenes/cube-wave.toml
//   mw-dem run pipeline/concrete-cube/scenes/cube-wave.toml --frequency-kHz 100
//       --signals results/concrete-cube/dem-100kHz.h5 --summary results/concrete-cube/dem-100kHz.json
//   mw-dem run pipeline/concrete-cube/scenes/cube-wave.toml --frequencies-kHz 100,300,500
//       --signals-pattern 'dem-{f}kHz.h5' --summary-pattern 'dem-{f}kHz.json'   (one run, every frequency)
//   mw-dem run ... --checkpoint run.ckpt.h5 --checkpoint-every-steps 10000   (and on SIGTERM/SIGINT)
//   mw-dem run ... --restart run.ckpt.h5      (the same options: continues to the same bits)
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>

#include "mesowave/app/interrupt.hpp"
#include "mesowave/app/progress.hpp"
#include "mesowave/app/tool.hpp"
#include "mesowave/core/threads.hpp"
#include "mesowave/dem/calibration/static_elastic.hpp"
#include "mesowave/dem/packing/packing_file.hpp"
#include "mesowave/dem/engine/run_report.hpp"
#include "mesowave/dem/scene/scene.hpp"
#include "mesowave/dem/scene/scene_overrides.hpp"
#include "mesowave/dem/engine/simulation.hpp"
#include "mesowave/dem/engine/snapshot.hpp"
#include "mesowave/dem/engine/superposition.hpp"
#include "mesowave/signal/signal_file.hpp"

using namespace mesowave;
namespace fs = std::filesystem;

int main(int argc, char** argv) {
  app::Tool tool(
      "mw-dem",
      "Simulate a DEM scene (TOML: packing, material, time step, actuators, sensors) with Yade's cohesive-frictional "
      "contact law: F_n = K_n (u - u_0) (Eq. 1), incremental shear F_s = F_s,prev + K_s dX_s rotated with the contact "
      "(Eq. 2), K_n = E_dem 2 R_A R_B/(R_A + R_B), K_s = nu_dem K_n (Eq. 3), Mohr-Coulomb with strengths T R^2, C R^2 "
      "(Eqs. 4-6), local damping alpha_d (Eq. 7), leapfrog as Yade's NewtonIntegrator. The model is chosen for the "
      "scene and the summary says why: chain (a line of spheres loaded axially), linear (small-amplitude waves: "
      "peak bond force / strength below the bound, checked after the run) or full (contact detection, breakage, "
      "friction). A time step above the stable limit 2/sqrt((1 + alpha_d) lambda_max) is refused. With "
      "--frequencies-kHz the linear model runs once per actuator with a unit force impulse and each frequency's "
      "signals are the burst convolved with that response (superposition: exact to round-off without damping; "
      "the local damping is not additive, so its error is measured: --check-kHz).\n\n"
      "  mw-dem info pipeline/concrete-cube/scenes/cube-wave.toml\n"
      "  mw-dem run pipeline/concrete-cube/scenes/cube-wave.toml --frequency-kHz 250 --signals cube-250kHz.h5\n"
      "  mw-dem run pipeline/concrete-cube/scenes/cube-wave.toml --frequencies-kHz 100,300,500 "
      "--signals-pattern 'cube-{f}kHz.h5' --summary-pattern 'cube-{f}kHz.json' --check-kHz 300\n"
      "  mw-dem run pipeline/steel-rod/scenes/rod-wave.toml --model full --signals rod-full.h5 --summary rod-full.json\n"
      "  mw-dem run pipeline/concrete-cube/scenes/cube-wave.toml --from calibration.json --signals cube.h5   "
      "(E_dem_GPa, nu_dem, T_MPa, C_MPa, friction_angle_deg from mw-calibrate)\n"
      "  mw-dem run pipeline/concrete-cube/scenes/cube-compression.toml --signals c.h5 --curves c.csv   "
      "(a virtual compression test: E_glob, nu_glob, peak stress)\n"
      "  mw-dem run pipeline/concrete-cube/scenes/cube-compression.toml --unbreakable-bonds --modulus-levels-MPa 5,16.67 "
      "--static --signals e.h5   (its elastic part as one static solve of the linearised network)");
  auto& cli = tool.cli();
  cli.require_subcommand(1);

  std::vector<double> frequencies_kHz;
  std::string signals_pattern, summary_pattern;
  std::vector<double> check_kHz;
  fs::path scene_path, signals_path, summary_path, snapshot_dir, csv_path, curves_path, checkpoint_path, restart_path;
  std::int64_t checkpoint_every = 0, resumed_at = 0;
  std::string model = "auto";
  int threads = 0;
  bool quiet = false, static_solve = false;
  dem::SceneOverrides overrides;

  auto common = [&](CLI::App* sub) {
    sub->add_option("scene", scene_path, "Scene file (TOML; see docs/formats.md)")->required();
    sub->add_option("--model", model, "auto (default: the scene's choice, else the rules) | full | linear | chain")
        ->check(CLI::IsMember({"auto", "full", "linear", "chain"}));
    dem::add_override_options(*sub, overrides);
    sub->add_option("--threads", threads,
                    "OpenMP threads (default: the cores the machine is not busy with; the results are the same bits "
                    "for any count)");
  };
  auto* info = cli.add_subcommand("info", "Counts, critical time step, the model it would choose and a memory estimate, without running");
  common(info);
  auto* run_cmd = cli.add_subcommand("run", "Run the scene and write the sensor signals");
  common(run_cmd);
  run_cmd->add_option("--signals", signals_path, "Sensor signals (HDF5, docs/formats.md); required without --frequencies-kHz");
  auto* many = run_cmd->add_option("--frequencies-kHz", frequencies_kHz,
                                   "Burst centre frequencies [kHz] (comma-separated) from one run by superposition "
                                   "(dem/engine/superposition.hpp): linear model, force actuators, motion sensors")
                   ->delimiter(',')
                   ->excludes(run_cmd->get_option("--frequency-kHz"));
  run_cmd->add_option("--signals-pattern", signals_pattern,
                      "With --frequencies-kHz: each frequency's signals, {f} the frequency in kHz ('dem-{f}kHz.h5')")
      ->needs(many);
  run_cmd->add_option("--summary-pattern", summary_pattern, "With --frequencies-kHz: each frequency's summary (JSON), {f} as above")
      ->needs(many);
  run_cmd->add_option("--check-kHz", check_kHz,
                      "With --frequencies-kHz: also run these of them directly (comma-separated) and record the "
                      "superposition's PCC and largest difference / peak against each in the summaries")
      ->delimiter(',')
      ->needs(many);
  run_cmd->add_option("--summary", summary_path, "Run summary (JSON; also printed)");
  run_cmd->add_option("--signals-csv", csv_path, "The signals also as CSV (t_s and one column per sensor)");
  run_cmd->add_option("--snapshots", snapshot_dir, "Folder for ParaView snapshots (.vtp per instant + snapshots.pvd)");
  run_cmd->add_option("--snapshot-interval-us", overrides.snapshot_us, "Time between snapshots [us] (default: the scene's)");
  run_cmd->add_flag("--quiet", quiet, "No progress bar");
  run_cmd->add_flag("--static", static_solve,
                    "A compression [test]'s elastic part as one static solve of the linearised network instead of "
                    "stepping (dem/calibration/static_elastic.hpp): E_glob and nu_glob between --modulus-levels-MPa, "
                    "walls as one-sided springs, the same extensometers; --signals and --curves get the two levels");
  run_cmd->add_option("--curves", curves_path,
                      "A [test]'s stress-strain curves as CSV (t_s, stress_MPa, axial_strain, lateral_strain, "
                      "broken_bonds); the signal file holds them too (test.stress, test.axial_strain, ...)");
  auto* checkpoint_opt = run_cmd->add_option("--checkpoint", checkpoint_path,
                                             "Checkpoint (HDF5, written whole) on SIGTERM/SIGINT before the run stops, "
                                             "and every --checkpoint-every-steps steps");
  run_cmd->add_option("--checkpoint-every-steps", checkpoint_every, "Steps between checkpoints")
      ->check(CLI::PositiveNumber)->needs(checkpoint_opt);
  run_cmd->add_option("--restart", restart_path,
                      "Continue from this checkpoint, to the same bits as a run never stopped; the scene, packing "
                      "and options must be the checkpoint's")->check(CLI::ExistingFile);

  return tool.run(argc, argv, [&](app::Run& run) {
    const std::string threads_reason = use_threads(threads).reason;
    dem::Scene scene = dem::read_scene_file(scene_path);
    run.input(scene_path);
    if (!scene.experiment_file.empty()) run.input(scene.experiment_file);
    overrides.curves = !curves_path.empty();
    dem::apply_overrides(scene, overrides);
    const dem::Packing packing = dem::read_packing_file(scene.packing_file);
    run.input(scene.packing_file);
    if (static_solve) {
      if (!info->parsed() && (!snapshot_dir.empty() || !csv_path.empty()))
        throw InputError("--static solves for equilibrium: it has no --snapshots or --signals-csv");
      if (model != "auto" && model != "linear") throw InputError("--static solves the linearised network, not --model " + model);
      const dem::StaticElasticResult r = dem::static_compression_test(scene, packing);
      if (!curves_path.empty()) run.write_text(curves_path, dem::uniaxial_curves_csv(r.test));
      signal::write_signal_file(run.output(signals_path), dem::uniaxial_curve_signals(r.test),
                                {{"scene", scene.name}, {"model", "linear"}, {"method", "static"},
                                 {"packing", scene.packing_file.string()}});
      run.param("model_chosen", "linear");
      run.param("method", "static");
      run.metric("E_glob", r.E_glob_Pa / 1e9, "GPa");
      if (r.nu_glob) run.metric("nu_glob", *r.nu_glob, "");
      run.metric("wall", r.wall_s, "s");
      auto summary = dem::to_json(r);
      summary["scene"] = scene.name;
      summary["threads_reason"] = threads_reason;
      run.emit_json(summary, summary_path);
      return;
    }

    dem::SimulationOptions options;
    options.model = model;
    std::vector<std::pair<double, std::string>> snapshots;
    if (run_cmd->parsed() && !snapshot_dir.empty()) {
      if (!(scene.snapshot_interval_s > 0)) throw InputError("--snapshots needs --snapshot-interval-us or [output] snapshot_interval_us");
      options.on_snapshot = [&](const dem::Model& m, double t, std::int64_t index) {
        const std::string name = "snapshot-" + std::to_string(index) + ".vtp";
        dem::write_vtp(run.output(snapshot_dir / name), m, t);
        snapshots.emplace_back(t, name);
      };
    }
    std::optional<app::Progress> progress;
    options.on_progress = [&](std::int64_t done, std::int64_t total) {
      if (!progress) progress.emplace("mw-dem " + scene.name, total, "steps", !quiet, resumed_at);
      progress->update(done);
    };
    if (!frequencies_kHz.empty()) {
      if (!signals_path.empty() || !csv_path.empty() || !snapshot_dir.empty() || !curves_path.empty() ||
          !checkpoint_path.empty() || !restart_path.empty())
        throw InputError("--frequencies-kHz writes --signals-pattern files: --signals, --signals-csv, --snapshots, "
                         "--curves, --checkpoint and --restart are for one direct run");
      if (signals_pattern.empty()) throw InputError("--frequencies-kHz needs --signals-pattern (e.g. 'dem-{f}kHz.h5')");
      const dem::SuperposedSet set = dem::run_superposed(scene, packing, options, frequencies_kHz, check_kHz);
      if (progress) progress->finish();
      for (const auto& f : set.frequencies) {
        const std::string kHz = dem::frequency_text(f.run.frequency_hz);
        signal::write_signal_file(run.output(dem::frequency_path(signals_pattern, "--signals-pattern", f.run.frequency_hz)),
                                  f.run.signals, {{"scene", scene.name}, {"model", set.responses.report.choice.model},
                                                  {"packing", scene.packing_file.string()}, {"method", "superposition"}});
        if (!summary_pattern.empty())
          run.write_text(dem::frequency_path(summary_pattern, "--summary-pattern", f.run.frequency_hz), f.summary.dump(2) + "\n");
        run.metric("peak_force_ratio_bound_" + kHz + "kHz", f.run.peak_force_ratio_bound, "");
      }
      run.param("model_chosen", set.responses.report.choice.model);
      run.param("method", "superposition");
      run.metric("wall", set.responses.wall_s, "s");
      for (const auto& c : set.checks) {
        const std::string kHz = dem::frequency_text(c.frequency_hz);
        run.metric("superposition_min_pcc_" + kHz + "kHz", c.error.min_pcc, "");
        run.metric("superposition_max_diff_over_peak_" + kHz + "kHz", c.error.max_diff_over_peak_all, "");
      }
      auto summary = set.summary;
      summary["threads_reason"] = threads_reason;
      run.emit_json(summary, summary_path);
      return;
    }
    if (!checkpoint_path.empty() || !restart_path.empty()) {
      const auto written = [&](std::int64_t step) {
        run.param("checkpoint_step", step);  // recorded also when the run is interrupted
        if (app::interrupt_signal())
          std::cerr << "mw-dem: " << checkpoint_path.string() << " holds step " << step << "; continue with --restart\n";
      };
      options.checkpoint = {checkpoint_path, checkpoint_every, [] { return app::interrupt_signal() != 0; },
                            dem::run_identity(scene_path, scene, overrides, model), written};
    }
    dem::Simulation sim(scene, packing, options);
    if (info->parsed()) {
      auto j = dem::to_json(sim.describe());
      j["threads_reason"] = threads_reason;
      run.emit_json(j);
      return;
    }
    if (signals_path.empty()) throw InputError("run needs --signals (or --frequencies-kHz with --signals-pattern)");
    if (!restart_path.empty()) {
      run.input(restart_path);
      sim.restore(restart_path, options.checkpoint.identity);
      resumed_at = sim.steps_done();
      run.param("restarted_at_step", resumed_at);
    }
    const dem::RunReport report = sim.run();
    if (progress) progress->finish();

    std::map<std::string, std::string> attributes = {{"scene", scene.name},
                                                     {"model", report.choice.model},
                                                     {"packing", scene.packing_file.string()}};
    std::vector<signal::Signal> signals = report.signals;
    if (report.test) {
      for (auto& s : dem::uniaxial_curve_signals(*report.test)) signals.push_back(std::move(s));
      if (!curves_path.empty()) run.write_text(curves_path, dem::uniaxial_curves_csv(*report.test));
      run.metric("E_glob", report.test->E_secant_Pa / 1e9, "GPa");
      if (report.test->nu_secant) run.metric("nu_glob", *report.test->nu_secant, "");
      run.metric("peak_stress", report.test->peak_stress_Pa / 1e6, "MPa");
      run.metric("inertial_number_max", report.test->inertial_number_max, "");
    }
    signal::write_signal_file(run.output(signals_path), signals, attributes);
    if (!csv_path.empty()) run.write_text(csv_path, dem::signals_csv(report.signals));
    if (!snapshots.empty()) dem::write_pvd(run.output(snapshot_dir / "snapshots.pvd"), snapshots);
    run.param("model_chosen", report.choice.model);
    run.metric("steps_per_s", report.steps_per_s, "1/s");
    run.metric("wall", report.wall_s, "s");
    run.metric("dt_limit", report.dt_cr.limit_s, "s");
    run.metric("peak_force_ratio", report.peak_force_ratio, "");
    run.metric("ns_per_contact_step", report.ns_per_contact_step, "ns");
    auto summary = dem::to_json(report);
    summary["threads_reason"] = threads_reason;
    run.emit_json(summary, summary_path);
  });
}
