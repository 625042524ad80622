// mw-dem - wave propagation (and any loading) in a DEM packing: Yade's
// cohesive-frictional sphere model (concrete paper Eqs. 1-7), run on the
// cheapest model that is valid for the scene.
//
//   mw-dem info pipeline/concrete-cube/scenes/cube-wave.toml
//   mw-dem run pipeline/concrete-cube/scenes/cube-wave.toml --frequency-kHz 100
//       --signals results/concrete-cube/dem-100kHz.h5 --summary results/concrete-cube/dem-100kHz.json
#include <algorithm>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>

#include "mesowave/app/progress.hpp"
#include "mesowave/app/tool.hpp"
#include "mesowave/core/check.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/dem/packing_file.hpp"
#include "mesowave/dem/plugins.hpp"
#include "mesowave/dem/run_report.hpp"
#include "mesowave/dem/scene.hpp"
#include "mesowave/dem/simulation.hpp"
#include "mesowave/dem/snapshot.hpp"
#include "mesowave/io/signal_file.hpp"

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
      "friction). A time step above the stable limit 2/sqrt((1 + alpha_d) lambda_max) is refused.\n\n"
      "  mw-dem info pipeline/concrete-cube/scenes/cube-wave.toml\n"
      "  mw-dem run pipeline/concrete-cube/scenes/cube-wave.toml --frequency-kHz 250 --signals cube-250kHz.h5\n"
      "  mw-dem run pipeline/steel-rod/scenes/rod-wave.toml --model full --signals rod-full.h5 --summary rod-full.json\n"
      "  mw-dem run pipeline/concrete-cube/scenes/cube-wave.toml --from calibration.json --signals cube.h5   "
      "(E_dem_GPa, nu_dem, T_MPa, C_MPa, friction_angle_deg from mw-calibrate)\n"
      "  mw-dem run pipeline/concrete-cube/scenes/cube-compression.toml --signals c.h5 --curves c.csv   "
      "(a virtual compression test: E_glob, nu_glob, peak stress)");
  auto& cli = tool.cli();
  cli.require_subcommand(1);

  fs::path scene_path, packing_path, signals_path, summary_path, snapshot_dir;
  std::string model = "auto";
  double frequency_kHz = 0, dt_ns = 0, duration_ms = 0, snapshot_us = -1;
  int threads = 0;
  bool quiet = false;
  std::map<std::string, double> material_values;  // [material] key -> value given on the command line
  std::map<std::string, std::string> material_option_names;
  bool unbreakable = false;
  double stop_at_MPa = 0, velocity_mm_s = 0;
  std::vector<double> levels_MPa;

  auto common = [&](CLI::App* sub) {
    sub->add_option("scene", scene_path, "Scene file (TOML; see docs/formats.md)")->required();
    sub->add_option("--packing", packing_path, "Packing file to use instead of the scene's [packing] file");
    sub->add_option("--model", model, "auto (default: the scene's choice, else the rules) | full | linear | chain")
        ->check(CLI::IsMember({"auto", "full", "linear", "chain"}));
    sub->add_option("--frequency-kHz", frequency_kHz, "Centre frequency of every actuator's burst [kHz]");
    sub->add_option("--dt-ns", dt_ns, "Time step instead of the scene's [ns]");
    sub->add_option("--duration-ms", duration_ms, "Duration instead of the scene's [ms]");
    for (const auto& [key, what] : std::vector<std::pair<std::string, std::string>>{
             {"E_dem_GPa", "Contact modulus E_dem of Eq. (3) [GPa]"},
             {"nu_dem", "Stiffness ratio nu_dem = K_s / K_n (Eq. 3)"},
             {"friction_angle_deg", "Friction angle mu of Eqs. (4)-(5) [deg]"},
             {"T_MPa", "Normal (tensile) bond strength T of Eq. (6) [MPa]"},
             {"C_MPa", "Shear cohesion C of Eq. (6) [MPa]"},
             {"damping", "Local damping alpha_d of Eq. (7)"},
             {"bond_factor", "Detection factor C_f: pairs within C_f (r_i + r_j) are bonded at step 0"}}) {
      std::string option = "--" + key;
      std::replace(option.begin(), option.end(), '_', '-');
      sub->add_option_function<double>(option, [&, key = key](double v) { material_values[key] = v; },
                                       what + " (beats the scene's [material]; --from mw-calibrate's JSON fills it)");
      material_option_names[key] = option;
    }
    sub->add_flag("--unbreakable-bonds", unbreakable,
                  "Bonds never break (no T, C): the elastic response (mw-calibrate's elastic trials)");
    sub->add_option("--stop-at-MPa", stop_at_MPa, "A [test] ends once its stress reaches this [MPa]");
    sub->add_option("--velocity-mm-s", velocity_mm_s,
                    "Every moving platen or wall (velocity, wall actuators with a velocity) at this speed instead [mm/s]");
    sub->add_option("--modulus-levels-MPa", levels_MPa,
                    "A [test]'s secant modulus between these two stresses [MPa] instead of the scene's levels")
        ->expected(2)->delimiter(',');
    sub->add_option("--threads", threads,
                    "OpenMP threads (default: the cores the machine is not busy with; the results are the same bits "
                    "for any count)");
  };
  auto* info = cli.add_subcommand("info", "Counts, critical time step, the model it would choose and a memory estimate, without running");
  common(info);
  auto* run_cmd = cli.add_subcommand("run", "Run the scene and write the sensor signals");
  common(run_cmd);
  run_cmd->add_option("--signals", signals_path, "Sensor signals (HDF5, docs/formats.md)")->required();
  run_cmd->add_option("--summary", summary_path, "Run summary (JSON; also printed)");
  fs::path csv_path;
  run_cmd->add_option("--signals-csv", csv_path, "The signals also as CSV (t_s and one column per sensor)");
  run_cmd->add_option("--snapshots", snapshot_dir, "Folder for ParaView snapshots (.vtp per instant + snapshots.pvd)");
  run_cmd->add_option("--snapshot-interval-us", snapshot_us, "Time between snapshots [us] (default: the scene's)");
  run_cmd->add_flag("--quiet", quiet, "No progress bar");
  fs::path curves_path;
  run_cmd->add_option("--curves", curves_path,
                      "A [test]'s stress-strain curves as CSV (t_s, stress_MPa, axial_strain, lateral_strain, "
                      "broken_bonds); the signal file holds them too (test.stress, test.axial_strain, ...)");

  return tool.run(argc, argv, [&](app::Run& run) {
    std::string threads_reason;
    dem::set_thread_count(dem::choose_thread_count(threads, &threads_reason));
    dem::Scene scene = dem::read_scene_file(scene_path);
    run.input(scene_path);
    if (!packing_path.empty()) scene.packing_file = packing_path;
    for (const auto& [key, value] : material_values)
      dem::set_material_value(scene, key, value, material_option_names.at(key));
    if (velocity_mm_s != 0) {
      require_positive("--velocity-mm-s", velocity_mm_s, "mm/s");
      for (auto& a : scene.actuators)
        if (dem::actuator_kinds().get(a.kind, "actuator " + a.name).moving && a.amplitude != 0) a.amplitude = velocity_mm_s * units::mm;
    }
    if (unbreakable)
      scene.material.tensile_strength_Pa = scene.material.cohesion_Pa = std::numeric_limits<double>::infinity();
    if ((stop_at_MPa != 0 || !levels_MPa.empty()) && !scene.test.active())
      throw InputError("--stop-at-MPa and --modulus-levels-MPa need a scene with a [test] table");
    if (stop_at_MPa != 0) scene.test.stop_at_Pa = require_positive("--stop-at-MPa", stop_at_MPa, "MPa") * units::MPa;
    if (!levels_MPa.empty()) {
      if (!(levels_MPa[0] >= 0 && levels_MPa[1] > levels_MPa[0]))
        throw InputError("--modulus-levels-MPa (" + format_number(levels_MPa[0]) + ", " + format_number(levels_MPa[1]) +
                         ") must rise from a lower to an upper stress");
      scene.test.levels_absolute = true;
      scene.test.levels[0] = levels_MPa[0] * units::MPa;
      scene.test.levels[1] = levels_MPa[1] * units::MPa;
    }
    if (frequency_kHz != 0)
      for (auto& a : scene.actuators) a.frequency_hz = require_positive("--frequency-kHz", frequency_kHz, "kHz") * units::kHz;
    if (dt_ns != 0) scene.dt_s = require_positive("--dt-ns", dt_ns, "ns") * units::ns;
    if (duration_ms != 0) scene.duration_s = require_positive("--duration-ms", duration_ms, "ms") * units::ms;
    if (snapshot_us >= 0) scene.snapshot_interval_s = snapshot_us * units::us;
    if (!curves_path.empty() && !scene.test.active())
      throw InputError("--curves needs a scene with a [test] table (a compression or tension test)");
    const dem::Packing packing = dem::read_packing_file(scene.packing_file);
    run.input(scene.packing_file);

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
      if (!progress) progress.emplace("mw-dem " + scene.name, total, "steps", !quiet);
      progress->update(done);
    };
    dem::Simulation sim(scene, packing, options);
    if (info->parsed()) {
      auto j = dem::to_json(sim.describe());
      j["threads_reason"] = threads_reason;
      run.emit_json(j);
      return;
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
    io::write_signal_file(run.output(signals_path), signals, attributes);
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
