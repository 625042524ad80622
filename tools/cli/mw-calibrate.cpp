// mw-calibrate - flowchart step 6: the DEM micro-parameters from the lab's
// macro-parameters, found with virtual tests, each one `mw-dem run` of a test
// scene; dem/calibration/calibration.hpp decides what to run next (CompressionCalibration,
// RodCalibration), dem/calibration/calibration_report.hpp what the trials and the result say.
#include <iostream>
#include <optional>

#include "mesowave/app/subprocess.hpp"
#include "mesowave/app/tool.hpp"
#include "mesowave/core/check.hpp"
#include "mesowave/dem/calibration/calibration.hpp"
#include "mesowave/dem/calibration/calibration_report.hpp"
#include "mesowave/dem/calibration/static_elastic.hpp"
#include "mesowave/dem/packing/packing_file.hpp"
#include "mesowave/dem/scene/scene.hpp"
#include "mesowave/io/gnuplot.hpp"

using namespace mesowave;
namespace fs = std::filesystem;

int main(int argc, char** argv) {
  app::Tool tool(
      "mw-calibrate",
      "Calibrate the DEM micro-parameters against the lab (concrete paper, flowchart step 6; rod paper, Table 1) "
      "with virtual tests, each one `mw-dem run` of a test scene, recorded in the provenance database.\n"
      "cube: E_dem, nu_dem and T (C = T by default) so that the virtual compression test gives E_st, nu_st and "
      "sigma_max within tolerance, as options or --from the static tests (static-test.toml) or mw-compress's JSON of the "
      "lab's own records (E_st_measured_GPa, sigma_max_MPa; nu_st then from a second file: the records have no lateral "
      "strain), or mw-upv's E_d and nu_d in their place (--E-d-GPa, --nu-d: the dynamic calibration); the result "
      "records each target's origin (file, entry, SHA-256; --targets-csv). Elastic trials (unbreakable bonds, to "
      "sigma_max / 3) fix E_dem (E_glob is proportional to it) and nu_dem (secant on nu_glob); failure trials (the full "
      "law) fix T (secant on the peak stress) and correct E_dem and nu_dem from the same runs (their modulus: the secant from "
      "10 % to 1/3 of the peak).\nrod: the contact modulus E_dem (K_n = E_dem R) so that the chain's tension test gives the "
      "rod's E (E_DEM = K_n d / (pi R^2), proportional to E_dem: one rescaled trial and a check); rho_p is the packing's (mw-pack line).\n\n"
      "  mw-calibrate cube --scene pipeline/concrete-cube/scenes/cube-compression.toml --from "
      "lab-data/concrete-cube/static-test.toml --start-E-dem-GPa 10 --start-nu-dem 0.1 --start-T-MPa 10 --work-dir "
      "calib --out calibration.json --trials trials.csv --plot-trajectory trajectory.png --plot-curves curves.png\n"
      "  mw-calibrate cube --scene pipeline/concrete-cube/scenes/cube-compression.toml --from lab-data/concrete-cube/"
      "static-test.toml --from raw-compress.json --work-dir calib --out calibration.json --targets-csv targets.csv\n"
      "  mw-dem run pipeline/concrete-cube/scenes/cube-wave.toml --from calibration.json --signals waves.h5\n"
      "  mw-calibrate rod --scene pipeline/steel-rod/scenes/rod-tension.toml --packing packing-1.05R.h5 --experiment "
      "lab-data/steel-rod/experiment.toml --work-dir calib-rod --out rod-1.05R.json");
  auto& cli = tool.cli();
  cli.require_subcommand(1);

  fs::path scene_path, packing_path, work_dir, out, trials_csv, targets_csv, plot_trajectory, plot_curves, mw_dem_path, experiment_path;
  int threads = 0, max_trials = 12;
  std::string elastic_trials = "dynamic";
  std::optional<std::string> static_preconditioner;
  auto common = [&](CLI::App* sub) {
    sub->add_option("--scene", scene_path, "The virtual test (TOML with a [test] table)")->required();
    sub->add_option("--packing", packing_path, "Packing instead of the scene's [packing] file");
    sub->add_option("--work-dir", work_dir, "Folder for the trials' files (trial-NN.json/.csv/.h5)")->required();
    sub->add_option("--max-trials", max_trials, "Give up after this many trials")->capture_default_str();
    sub->add_option("--threads", threads, "Threads for each mw-dem run (default: mw-dem's choice)");
    sub->add_option("--mw-dem", mw_dem_path, "The mw-dem to run (default: the one beside mw-calibrate)");
    app::add_out_option(*sub, out, "the calibrated parameters (JSON, read by mw-dem run --from)");
  };

  double E_st_GPa = 0, nu_st = 0, sigma_MPa = 0, tol_E_pct = 1, tol_nu = 0.01, tol_sigma_pct = 2, c_over_t = 1, tol_rod_pct = 0.5;
  std::optional<double> start_E, start_nu, start_T, friction_deg, E_rod_GPa, E_d_GPa, nu_d, elastic_velocity;
  auto* cube = cli.add_subcommand("cube", "Compression test of a packed specimen: E_dem, nu_dem, T = C");
  common(cube);
  cube->add_option("--E-st-measured-GPa", E_st_GPa, "Target: the static modulus E_st [GPa] (static-test.toml, mw-compress)")->required();
  cube->add_option("--nu-st", nu_st, "Target: the static Poisson ratio (the paper takes nu_d)")->required();
  cube->add_option("--sigma-max-MPa", sigma_MPa, "Target: the compressive strength [MPa]")->required();
  cube->add_option("--E-d-GPa", E_d_GPa, "Target instead of E_st: the dynamic modulus E_d [GPa] (mw-upv's JSON)");
  cube->add_option("--nu-d", nu_d, "Target instead of nu_st: the dynamic Poisson ratio (mw-upv's JSON)");
  cube->add_option("--start-E-dem-GPa", start_E, "First E_dem [GPa] (default: the scene's)");
  cube->add_option("--start-nu-dem", start_nu, "First nu_dem = K_s / K_n (default: the scene's)");
  cube->add_option("--start-T-MPa", start_T, "First T [MPa] (default: the scene's)");
  cube->add_option("--C-over-T", c_over_t, "Shear cohesion C as a multiple of T (the paper: T = C)")->capture_default_str();
  cube->add_option("--friction-angle-deg", friction_deg, "Friction angle mu [deg] (given, not calibrated; default: the scene's)");
  cube->add_option("--tolerance-E-pct", tol_E_pct, "Tolerance on E_glob [%]")->capture_default_str();
  cube->add_option("--tolerance-nu", tol_nu, "Tolerance on nu_glob")->capture_default_str();
  cube->add_option("--tolerance-sigma-pct", tol_sigma_pct, "Tolerance on the peak stress [%]")->capture_default_str();
  cube->add_option("--trials", trials_csv, "The trial log (CSV)");
  cube->add_option("--targets-csv", targets_csv, "CSV: each target, its tolerance, the calibrated value, where it was read from");
  cube->add_option("--plot-trajectory", plot_trajectory, "PNG: the trials against the targets");
  cube->add_option("--elastic-trials", elastic_trials, "dynamic: step the elastic trials (the linearised network to "
                   "sigma_max / 3); static: one linear solve each (mw-dem run --static, docs/calibration.md); failure "
                   "trials stay dynamic")->check(CLI::IsMember({"dynamic", "static"}))->capture_default_str();
  cube->add_option("--elastic-velocity-mm-s", elastic_velocity, "Stepped elastic trials: the walls' speed [mm/s] (default: "
                   "the scene's; their only rate effect is inertia, bounded by the test: docs/calibration.md)");
  cube->add_option("--static-preconditioner", static_preconditioner, "Solved elastic trials: the BiCGSTAB preconditioner "
                   "(mw-dem run --static-preconditioner; default: mw-dem's, jacobi)")->check(CLI::IsMember(dem::static_preconditioners()));
  cube->add_option("--plot-curves", plot_curves, "PNG: stress-strain curves of the calibrated test, with the moduli");

  auto* rod = cli.add_subcommand("rod", "Tension test of a chain: the contact modulus for the rod's E");
  common(rod);
  rod->add_option("--E-GPa", E_rod_GPa, "Target: the rod's Young modulus [GPa], or:");
  rod->add_option("--experiment", experiment_path, "Target: the E of this experiment's rod (lab-data/steel-rod/experiment.toml)");
  rod->add_option("--start-E-dem-GPa", start_E, "First contact modulus E_dem [GPa] (default: the scene's)");
  rod->add_option("--tolerance-E-pct", tol_rod_pct, "Tolerance on E_DEM [%]")->capture_default_str();

  return tool.run(argc, argv, [&](app::Run& run) {
    dem::Scene scene = dem::read_scene_file(scene_path);
    if (!scene.test.active()) throw InputError("--scene " + scene_path.string() + " has no [test] table: nothing to calibrate against");
    if (!packing_path.empty()) scene.packing_file = packing_path;
    run.input(scene_path), run.input(scene.packing_file);
    const dem::TrialCommand trial_command{mw_dem_path.empty() ? app::sibling_tool("mw-dem") : mw_dem_path, scene_path,
                                          packing_path, work_dir, tool.db_path(), threads};
    const auto run_trial = [&](int k, const std::vector<std::string>& options) {
      app::run_process_or_throw(trial_command.argv(k, options), trial_command.file(k, "").filename().string());
      run.input(trial_command.file(k, ".json"));
      return trial_command.file(k, ".json");
    };
    fs::create_directories(work_dir);
    const auto& m = scene.material;
    if (rod->parsed()) {
      if (scene.test.kind != dem::UniaxialTestSpec::Kind::tension) throw InputError("mw-calibrate rod needs a tension test scene");
      if (!experiment_path.empty()) run.input(experiment_path);
      dem::RodCalibration calibration(dem::rod_target_E_GPa(E_rod_GPa, experiment_path), tol_rod_pct / 100,
                                      require_positive("--start-E-dem-GPa", start_E.value_or(m.E_dem_Pa / 1e9), "GPa"), max_trials);
      const dem::Packing chain = dem::read_packing_file(scene.packing_file);
      dem::run_trials(calibration, run_trial, std::cerr);
      run.metric("E_DEM", calibration.result().E_DEM_GPa, "GPa"), run.metric("E_dem", calibration.result().E_dem_GPa, "GPa");
      run.emit_json(dem::rod_calibration_summary(calibration, chain, m), out);
      return;
    }

    const std::string E_option = E_d_GPa ? "--E-d-GPa" : "--E-st-measured-GPa", nu_option = nu_d ? "--nu-d" : "--nu-st";
    const dem::CalibrationTargets targets = dem::compression_targets(E_st_GPa, nu_st, sigma_MPa, E_d_GPa, nu_d);
    if (scene.test.kind != dem::UniaxialTestSpec::Kind::compression) throw InputError("mw-calibrate cube needs a compression test scene");
    const dem::DemParameters start = dem::compression_start(m, start_E, start_nu, start_T, c_over_t);
    const double mu_deg = friction_deg.value_or(m.friction_angle_deg());
    dem::CompressionCalibration calibration(targets, dem::compression_tolerances(tol_E_pct, tol_nu, tol_sigma_pct), start, max_trials);
    const dem::ElasticTrials elastic = dem::elastic_trials(elastic_trials == "static", elastic_velocity, static_preconditioner);
    dem::run_trials(calibration, run_trial, mu_deg, std::cerr, elastic, [&](int k) { return trial_command.file(k, "-intact.h5"); });
    const dem::CalibrationTrial& best = calibration.result();
    run.metric("E_glob", best.E_glob_Pa / 1e9, "GPa"), run.metric("nu_glob", best.nu_glob, "");
    run.metric("sigma_dem", best.peak_Pa / 1e6, "MPa"), run.metric("trials", double(calibration.trials().size()), "");
    if (!trials_csv.empty()) run.write_text(trials_csv, dem::calibration_trials_csv(calibration.trials()));
    if (!plot_trajectory.empty())
      io::run_gnuplot(dem::calibration_trajectory_script(calibration, run.output(plot_trajectory),
                                                         "Calibration of the DEM cube (mw-calibrate)"));
    if (!plot_curves.empty()) {
      run.input(fs::path(best.summary_file).replace_extension(".csv"));
      io::run_gnuplot(dem::stress_strain_script(dem::read_trial_curve(best.summary_file), targets.E_Pa, targets.nu,
                                                run.output(plot_curves), "Virtual compression test, calibrated parameters"));
    }
    auto summary = dem::calibration_summary(calibration, mu_deg, {run.origin(E_option), run.origin(nu_option),
                                            run.origin("--sigma-max-MPa")}, elastic);
    if (!targets_csv.empty()) run.write_text(targets_csv, dem::calibration_targets_csv(summary));
    // The five values the wave runs take (mw-dem --from calibration.json); the rest is the record.
    app::declare_products(summary, {"E_dem_GPa", "nu_dem", "T_MPa", "C_MPa", "friction_angle_deg"});
    run.emit_json(summary, out);
  });
}
