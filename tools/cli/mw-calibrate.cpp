// mw-calibrate - flowchart step 6: the DEM micro-parameters from the lab's
// macro-parameters, found with virtual tests. Every trial is one `mw-dem run`
// of a test scene (recorded in the provenance database by mw-dem itself);
// mw-calibrate decides what to run next (dem/calibration.hpp) and writes the
// calibrated parameters as JSON that `mw-dem run --from` reads.
//
//   mw-calibrate cube --scene pipeline/concrete-cube/scenes/cube-compression.toml
//       --from lab-data/concrete-cube/static-test.toml --work-dir results/concrete-cube/calibration
//       --out results/concrete-cube/calibration.json
//   mw-calibrate rod --scene pipeline/steel-rod/scenes/rod-tension.toml
//       --packing results/steel-rod/packing-1.05R.h5 --E-GPa 208.72 --out rod-1.05R.json
#include <cmath>
#include <fstream>
#include <iostream>
#include <optional>

#include "mesowave/app/subprocess.hpp"
#include "mesowave/app/tool.hpp"
#include "mesowave/core/check.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/dem/calibration.hpp"
#include "mesowave/dem/calibration_report.hpp"
#include "mesowave/dem/material.hpp"
#include "mesowave/dem/material_parameters.hpp"
#include "mesowave/dem/packing_file.hpp"
#include "mesowave/dem/scene.hpp"
#include "mesowave/dem/vec3.hpp"
#include "mesowave/io/csv.hpp"
#include "mesowave/io/gnuplot.hpp"

using namespace mesowave;
namespace fs = std::filesystem;
using nlohmann::ordered_json;

namespace {

// One virtual test: `mw-dem run SCENE` with the trial's parameters, its
// summary, curves and signals in the work folder.
struct TrialRunner {
  fs::path mw_dem, scene, packing, work_dir;
  std::string db;
  int threads = 0;

  ordered_json run(const std::string& name, std::vector<std::string> options) const {
    const fs::path summary = work_dir / (name + ".json");
    std::vector<std::string> argv = {mw_dem.string(), "run", scene.string(), "--quiet",
                                     "--signals", (work_dir / (name + ".h5")).string(),
                                     "--curves", (work_dir / (name + ".csv")).string(),
                                     "--summary", summary.string()};
    if (!packing.empty()) argv.insert(argv.end(), {"--packing", packing.string()});
    if (!db.empty()) argv.insert(argv.end(), {"--db", db});
    if (threads > 0) argv.insert(argv.end(), {"--threads", std::to_string(threads)});
    argv.insert(argv.end(), options.begin(), options.end());
    const app::ProcessResult r = app::run_process(argv);
    if (r.exit_status != 0) {
      std::string why = r.stderr_text;
      while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
      if (const auto nl = why.rfind('\n'); nl != std::string::npos) why = why.substr(nl + 1);
      throw InputError(name + " (mw-dem, exit " + std::to_string(r.exit_status) + ") failed: " + why);
    }
    std::ifstream in(summary);
    return ordered_json::parse(in);
  }
};

// trial-01, trial-02, ...: the files of one trial in the work folder.
std::string trial_name(int k) { return "trial-" + std::string(k < 10 ? "0" : "") + std::to_string(k); }

dem::CalibrationTrial run_compression_trial(const TrialRunner& runner, dem::CalibrationTrial t,
                                            const dem::CalibrationTargets& targets, double friction_deg) {
  const auto& p = t.parameters;
  const auto option = [](const char* key) { return dem::material_parameter(key).option; };
  std::vector<std::string> options = {option("E_dem_GPa"), format_exact(p.E_dem_Pa / 1e9), option("nu_dem"),
                                      format_exact(p.nu_dem), option("friction_angle_deg"), format_exact(friction_deg)};
  if (t.kind == dem::CalibrationTrial::Kind::elastic) {
    // The elastic response alone, read where the lab reads it: between 10 % and
    // 1/3 of the target strength (EN 12390-13), the run ending just above; the
    // linearised network is valid there (the scene's linear_validity_bound says how far).
    const double b = 0.1 * targets.sigma_Pa / 1e6, a = targets.sigma_Pa / 3 / 1e6;
    options.insert(options.end(), {"--unbreakable-bonds", "--model", "linear", "--modulus-levels-MPa",
                                   format_exact(b) + "," + format_exact(a), "--stop-at-MPa", format_exact(1.02 * a)});
  } else {
    options.insert(options.end(), {"--T-MPa", format_exact(p.T_Pa / 1e6), "--C-MPa", format_exact(p.c_over_t * p.T_Pa / 1e6)});
  }
  const std::string name = trial_name(t.number);
  const ordered_json s = runner.run(name, options);
  const auto& test = s.at("test");
  t.E_glob_Pa = test.at("E_glob_GPa").get<double>() * 1e9;
  t.nu_glob = test.at("nu_glob").is_number() ? test.at("nu_glob").get<double>() : NAN;
  t.peak_Pa = test.at("peak_stress_MPa").get<double>() * 1e6;
  t.peak_reached = test.at("peak_reached").get<bool>();
  t.wall_s = s.at("wall_s").get<double>();
  t.model = s.at("model").get<std::string>();
  t.summary_file = (runner.work_dir / (name + ".json")).string();
  return t;
}

std::string describe(const dem::CalibrationTrial& t) {
  const auto& p = t.parameters;
  std::string line = "trial " + std::to_string(t.number) + " (" + t.kind_name() + "): E_dem " +
                     format_number(std::round(p.E_dem_Pa / 1e7) / 100) + " GPa, nu_dem " +
                     format_number(std::round(p.nu_dem * 1e4) / 1e4);
  if (t.kind == dem::CalibrationTrial::Kind::failure) line += ", T " + format_number(std::round(p.T_Pa / 1e4) / 100) + " MPa";
  line += " -> E_glob " + format_number(std::round(t.E_glob_Pa / 1e7) / 100) + " GPa, nu_glob " +
          format_number(std::round(t.nu_glob * 1e4) / 1e4);
  if (t.kind == dem::CalibrationTrial::Kind::failure) line += ", peak " + format_number(std::round(t.peak_Pa / 1e4) / 100) + " MPa";
  return line + " (" + t.model + " model, " + format_number(std::round(t.wall_s * 10) / 10) + " s)";
}

dem::StressStrainCurve read_curve(const fs::path& csv, const ordered_json& test) {
  const io::CsvTable t = io::read_csv(csv);
  dem::StressStrainCurve c;
  const std::size_t s = t.column("stress_MPa"), a = t.column("axial_strain"), l = t.column("lateral_strain");
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    c.stress_Pa.push_back(t.number(i, s) * 1e6);
    c.axial.push_back(t.number(i, a));
    if (!t.text(i, l).empty()) c.lateral.push_back(t.number(i, l));
  }
  c.E_glob_Pa = test.at("E_glob_GPa").get<double>() * 1e9;
  c.nu_glob = test.at("nu_glob").is_number() ? test.at("nu_glob").get<double>() : 0;
  c.sigma_b_Pa = test.at("modulus_levels_MPa")[0].get<double>() * 1e6;
  c.sigma_a_Pa = test.at("modulus_levels_MPa")[1].get<double>() * 1e6;
  c.eps_b = test.at("strains_at_levels")[0].get<double>();
  c.eps_a = test.at("strains_at_levels")[1].get<double>();
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  app::Tool tool(
      "mw-calibrate",
      "Calibrate the DEM micro-parameters against the lab (concrete paper, flowchart step 6; rod paper, Table 1) "
      "with virtual tests, each one `mw-dem run` of a test scene, recorded in the provenance database.\n"
      "cube: E_dem, nu_dem and T (C = T by default) so that the virtual compression test gives E_st, nu_st and "
      "sigma_max within tolerance. Elastic trials (unbreakable bonds, loaded to sigma_max / 3) fix E_dem and nu_dem: "
      "E_glob is proportional to E_dem (rescaled exactly) and nu_glob falls with nu_dem (secant, started from the "
      "random-packing estimate (1 - a)/(4 + a)). Failure trials (the full law to failure) fix T: the peak stress does "
      "not depend on the stiffness scale and grows about proportionally with T (secant); E_dem and nu_dem are "
      "corrected from the same runs, whose modulus is the secant between 10 % and 1/3 of their peak.\n"
      "rod: the contact modulus E_dem (K_n = E_dem R) so that the tension test of the chain gives the rod's E "
      "(E_DEM = K_n d / (pi R^2) is proportional to E_dem: one rescaled trial and a check); the particle density is "
      "the packing's (mw-pack line chose it from the rod's mass).\n\n"
      "  mw-calibrate cube --scene pipeline/concrete-cube/scenes/cube-compression.toml --from "
      "lab-data/concrete-cube/static-test.toml --start-E-dem-GPa 10 --start-nu-dem 0.1 --start-T-MPa 10 --work-dir "
      "calib --out calibration.json --trials trials.csv --plot-trajectory trajectory.png --plot-curves curves.png\n"
      "  mw-dem run pipeline/concrete-cube/scenes/cube-wave.toml --from calibration.json --signals waves.h5\n"
      "  mw-calibrate rod --scene pipeline/steel-rod/scenes/rod-tension.toml --packing packing-1.05R.h5 --E-GPa "
      "208.72 --work-dir calib-rod --out rod-1.05R.json");
  auto& cli = tool.cli();
  cli.require_subcommand(1);

  fs::path scene_path, packing_path, work_dir, out, trials_csv, plot_trajectory, plot_curves, mw_dem_path;
  int threads = 0, max_trials = 12;
  auto common = [&](CLI::App* sub) {
    sub->add_option("--scene", scene_path, "The virtual test (TOML with a [test] table)")->required();
    sub->add_option("--packing", packing_path, "Packing instead of the scene's [packing] file");
    sub->add_option("--work-dir", work_dir, "Folder for the trials' files (trial-NN.json/.csv/.h5)")->required();
    sub->add_option("--max-trials", max_trials, "Give up after this many trials")->capture_default_str();
    sub->add_option("--threads", threads, "Threads for each mw-dem run (default: mw-dem's choice)");
    sub->add_option("--mw-dem", mw_dem_path, "The mw-dem to run (default: the one beside mw-calibrate)");
    app::add_out_option(*sub, out, "the calibrated parameters (JSON, read by mw-dem run --from)");
  };

  double E_st_GPa = 0, nu_st = 0, sigma_MPa = 0, tol_E_pct = 1, tol_nu = 0.01, tol_sigma_pct = 2, c_over_t = 1;
  std::optional<double> start_E, start_nu, start_T, friction_deg;
  auto* cube = cli.add_subcommand("cube", "Compression test of a packed specimen: E_dem, nu_dem, T = C");
  common(cube);
  cube->add_option("--E-st-measured-GPa", E_st_GPa, "Target: the static modulus E_st [GPa] (static-test.toml)")->required();
  cube->add_option("--nu-st", nu_st, "Target: the static Poisson ratio (the paper takes nu_d)")->required();
  cube->add_option("--sigma-max-MPa", sigma_MPa, "Target: the compressive strength [MPa]")->required();
  cube->add_option("--start-E-dem-GPa", start_E, "First E_dem [GPa] (default: the scene's)");
  cube->add_option("--start-nu-dem", start_nu, "First nu_dem = K_s / K_n (default: the scene's)");
  cube->add_option("--start-T-MPa", start_T, "First T [MPa] (default: the scene's)");
  cube->add_option("--C-over-T", c_over_t, "Shear cohesion C as a multiple of T (the paper: T = C)")->capture_default_str();
  cube->add_option("--friction-angle-deg", friction_deg, "Friction angle mu [deg] (given, not calibrated; default: the scene's)");
  cube->add_option("--tolerance-E-pct", tol_E_pct, "Tolerance on E_glob [%]")->capture_default_str();
  cube->add_option("--tolerance-nu", tol_nu, "Tolerance on nu_glob")->capture_default_str();
  cube->add_option("--tolerance-sigma-pct", tol_sigma_pct, "Tolerance on the peak stress [%]")->capture_default_str();
  cube->add_option("--trials", trials_csv, "The trial log (CSV)");
  cube->add_option("--plot-trajectory", plot_trajectory, "PNG: the trials against the targets");
  cube->add_option("--plot-curves", plot_curves, "PNG: stress-strain curves of the calibrated test, with the moduli");

  double E_rod_GPa = 0, tol_rod_pct = 0.5;
  auto* rod = cli.add_subcommand("rod", "Tension test of a chain: the contact modulus for the rod's E");
  common(rod);
  rod->add_option("--E-GPa", E_rod_GPa, "Target: the rod's Young modulus [GPa] (the rod paper: 208.72)")->required();
  rod->add_option("--start-E-dem-GPa", start_E, "First contact modulus E_dem [GPa] (default: the scene's)");
  rod->add_option("--tolerance-E-pct", tol_rod_pct, "Tolerance on E_DEM [%]")->capture_default_str();

  return tool.run(argc, argv, [&](app::Run& run) {
    dem::Scene scene = dem::read_scene_file(scene_path);
    run.input(scene_path);
    if (!scene.test.active()) throw InputError("--scene " + scene_path.string() + " has no [test] table: nothing to calibrate against");
    if (!packing_path.empty()) scene.packing_file = packing_path;
    run.input(scene.packing_file);
    TrialRunner runner{mw_dem_path.empty() ? app::sibling_tool("mw-dem") : mw_dem_path, scene_path, packing_path,
                       work_dir, tool.db_path(), threads};
    fs::create_directories(work_dir);
    const auto& m = scene.material;

    if (rod->parsed()) {
      if (scene.test.kind != dem::UniaxialTestSpec::Kind::tension) throw InputError("mw-calibrate rod needs a tension test scene");
      const double target = require_positive("--E-GPa", E_rod_GPa, "GPa");
      double E_dem = require_positive("--start-E-dem-GPa", start_E.value_or(m.E_dem_Pa / 1e9), "GPa");
      const dem::Packing packing = dem::read_packing_file(scene.packing_file);
      ordered_json trials = ordered_json::array();
      double E_start_result = 0, E_result = 0;
      for (int k = 1;; ++k) {
        if (k > max_trials) throw InputError("the rod calibration did not reach " + format_number(target) + " GPa within " + std::to_string(max_trials) + " trials");
        const std::string name = trial_name(k);
        const ordered_json s = runner.run(name, {"--E-dem-GPa", format_exact(E_dem)});
        E_result = s.at("test").at("E_fit_GPa").get<double>();
        if (k == 1) E_start_result = E_result;
        trials.push_back({{"trial", k}, {"E_dem_GPa", E_dem}, {"E_DEM_GPa", E_result}, {"wall_s", s.at("wall_s")}});
        run.input(work_dir / (name + ".json"));
        std::cerr << "mw-calibrate rod: trial " << k << ": E_dem " << format_number(E_dem) << " GPa -> E_DEM "
                  << format_number(E_result) << " GPa\n";
        if (std::abs(E_result / target - 1) <= tol_rod_pct / 100) break;
        E_dem *= target / E_result;  // E_DEM = E_dem R d / (pi R^2): proportional to E_dem
      }
      const double R = packing.radii_m.front();
      auto centre = [&](std::size_t i) {
        const auto& c = packing.centres_m[i];
        return dem::Vec3{c[0], c[1], c[2]};
      };
      const double d = dem::norm(centre(1) - centre(0));
      dem::CohesiveFrictionalMaterial calibrated = m;
      calibrated.E_dem_Pa = E_dem * 1e9;
      ordered_json j;
      j["spheres"] = packing.size();
      j["sphere_radius_mm"] = R * 1e3;
      j["spacing_mm"] = d * 1e3;
      j["spacing_R"] = d / R;
      j["rho_p_kg_m3"] = packing.particle_density_kg_m3;
      j["E_dem_GPa"] = E_dem;
      j["Kn_N_m"] = dem::normal_stiffness(calibrated, R, R);  // Eq. (3): E_dem R for equal spheres
      j["E_DEM_GPa"] = E_result;
      j["E_target_GPa"] = target;
      j["E_dem_start_GPa"] = trials.front().at("E_dem_GPa");
      j["E_DEM_at_start_GPa"] = E_start_result;
      j["trials"] = trials;
      run.metric("E_DEM", E_result, "GPa");
      run.metric("E_dem", E_dem, "GPa");
      run.emit_json(j, out);
      return;
    }

    const dem::CalibrationTargets targets{require_positive("--E-st-measured-GPa", E_st_GPa, "GPa") * units::GPa, nu_st,
                                          require_positive("--sigma-max-MPa", sigma_MPa, "MPa") * units::MPa};
    const dem::CalibrationTolerances tolerances{require_positive("--tolerance-E-pct", tol_E_pct, "%") / 100,
                                                require_positive("--tolerance-nu", tol_nu),
                                                require_positive("--tolerance-sigma-pct", tol_sigma_pct, "%") / 100};
    if (scene.test.kind != dem::UniaxialTestSpec::Kind::compression) throw InputError("mw-calibrate cube needs a compression test scene");
    const double T0 = start_T ? *start_T * units::MPa : m.tensile_strength_Pa;
    if (!std::isfinite(T0)) throw InputError("the scene's bonds never break (no T_MPa): give --start-T-MPa");
    const dem::DemParameters start{start_E ? *start_E * units::GPa : m.E_dem_Pa, start_nu.value_or(m.stiffness_ratio), T0, c_over_t};
    const double mu_deg = friction_deg.value_or(m.friction_angle_rad * 180 / 3.141592653589793);
    dem::CompressionCalibration calibration(targets, tolerances, start, max_trials);

    while (auto trial = calibration.next()) {
      const dem::CalibrationTrial done = run_compression_trial(runner, *trial, targets, mu_deg);
      run.input(done.summary_file);
      std::cerr << "mw-calibrate: " << describe(done) << "\n";
      calibration.record(done);
    }
    const dem::CalibrationTrial& best = calibration.result();
    const auto& p = best.parameters;
    double total_wall = 0;
    for (const auto& t : calibration.trials()) total_wall += t.wall_s;

    // Flat keys that mw-dem run --from reads (E_dem_GPa, nu_dem, T_MPa, C_MPa, friction_angle_deg), then the results.
    ordered_json j;
    j["E_dem_GPa"] = p.E_dem_Pa / 1e9;
    j["nu_dem"] = p.nu_dem;
    j["T_MPa"] = p.T_Pa / 1e6;
    j["C_MPa"] = p.c_over_t * p.T_Pa / 1e6;
    j["friction_angle_deg"] = mu_deg;
    j["E_glob_GPa"] = best.E_glob_Pa / 1e9;
    j["nu_glob"] = best.nu_glob;
    j["sigma_dem_MPa"] = best.peak_Pa / 1e6;
    j["E_st_target_GPa"] = targets.E_Pa / 1e9;
    j["nu_st_target"] = targets.nu;
    j["sigma_max_target_MPa"] = targets.sigma_Pa / 1e6;
    j["E_error_pct"] = 100 * (best.E_glob_Pa / targets.E_Pa - 1);
    j["nu_error"] = best.nu_glob - targets.nu;
    j["sigma_error_pct"] = 100 * (best.peak_Pa / targets.sigma_Pa - 1);
    j["trial_count"] = calibration.trials().size();
    j["calibrated_by_trial"] = best.summary_file;
    j["trials_wall_s"] = total_wall;
    run.metric("E_glob", best.E_glob_Pa / 1e9, "GPa");
    run.metric("nu_glob", best.nu_glob, "");
    run.metric("sigma_dem", best.peak_Pa / 1e6, "MPa");
    run.metric("trials", double(calibration.trials().size()), "");
    if (!trials_csv.empty()) run.write_text(trials_csv, dem::calibration_trials_csv(calibration.trials()));
    if (!plot_trajectory.empty())
      io::run_gnuplot(dem::calibration_trajectory_script(calibration, run.output(plot_trajectory),
                                                         "Calibration of the DEM cube (mw-calibrate)"));
    if (!plot_curves.empty()) {
      std::ifstream in(best.summary_file);
      const ordered_json summary = ordered_json::parse(in);
      fs::path csv = best.summary_file;
      csv.replace_extension(".csv");
      run.input(csv);
      io::run_gnuplot(dem::stress_strain_script(read_curve(csv, summary.at("test")), targets.E_Pa, targets.nu,
                                                run.output(plot_curves), "Virtual compression test, calibrated parameters"));
    }
    run.emit_json(j, out);
  });
}
