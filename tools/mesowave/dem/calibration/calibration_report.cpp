#include "mesowave/dem/calibration/calibration_report.hpp"

#include <cmath>
#include <fstream>
#include <ostream>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/dem/contact/material_parameters.hpp"
#include "mesowave/dem/engine/vec3.hpp"
#include "mesowave/io/csv.hpp"
#include "mesowave/io/gnuplot.hpp"

namespace mesowave::dem {

std::filesystem::path TrialCommand::file(int k, const std::string& extension) const {
  return work_dir / ("trial-" + std::string(k < 10 ? "0" : "") + std::to_string(k) + extension);
}

std::vector<std::string> TrialCommand::argv(int k, const std::vector<std::string>& options) const {
  std::vector<std::string> a = {mw_dem.string(), "run", scene.string(), "--quiet", "--signals", file(k, ".h5"),
                                "--curves", file(k, ".csv"), "--summary", file(k, ".json")};
  if (!packing.empty()) a.insert(a.end(), {"--packing", packing.string()});
  if (!db.empty()) a.insert(a.end(), {"--db", db});
  if (threads > 0) a.insert(a.end(), {"--threads", std::to_string(threads)});
  a.insert(a.end(), options.begin(), options.end());
  return a;
}

DemParameters compression_start(const CohesiveFrictionalMaterial& scene, std::optional<double> E_dem_GPa,
                                std::optional<double> nu_dem, std::optional<double> T_MPa, double c_over_t) {
  const double T = T_MPa ? *T_MPa * units::MPa : scene.tensile_strength_Pa;
  if (!std::isfinite(T)) throw InputError("the scene's bonds never break (no T_MPa): give --start-T-MPa");
  return {E_dem_GPa ? *E_dem_GPa * units::GPa : scene.E_dem_Pa, nu_dem.value_or(scene.stiffness_ratio), T, c_over_t};
}

ElasticTrials elastic_trials(bool static_solve, std::optional<double> velocity_mm_s,
                             std::optional<std::string> preconditioner) {
  if (velocity_mm_s) {
    require_positive("--elastic-velocity-mm-s", *velocity_mm_s, "mm/s");
    if (static_solve) throw InputError("--elastic-velocity-mm-s is the speed of stepped elastic trials: --elastic-trials static has none");
  }
  if (preconditioner && !static_solve)
    throw InputError("--static-preconditioner " + *preconditioner +
                     " is for solved elastic trials: give --elastic-trials static, or leave it out");
  return {static_solve, velocity_mm_s, preconditioner};
}

std::vector<std::string> compression_trial_options(const CalibrationTrial& t, const CalibrationTargets& targets,
                                                   double friction_deg, const ElasticTrials& elastic) {
  const auto& p = t.parameters;
  const auto option = [](const char* key) { return material_parameter(key).option; };
  std::vector<std::string> options = {option("E_dem_GPa"), format_exact(p.E_dem_Pa / 1e9), option("nu_dem"),
                                      format_exact(p.nu_dem), option("friction_angle_deg"), format_exact(friction_deg)};
  if (t.kind == CalibrationTrial::Kind::elastic) {
    // The linearised network is valid there (the scene's linear_validity_bound says how far).
    const double b = 0.1 * targets.sigma_Pa / 1e6, a = targets.sigma_Pa / 3 / 1e6;
    options.insert(options.end(), {"--unbreakable-bonds", "--model", "linear", "--modulus-levels-MPa",
                                   format_exact(b) + "," + format_exact(a), "--stop-at-MPa", format_exact(1.02 * a)});
    if (elastic.static_solve) {
      options.push_back("--static");
      if (elastic.preconditioner) options.insert(options.end(), {"--static-preconditioner", *elastic.preconditioner});
    } else if (elastic.velocity_mm_s) options.insert(options.end(), {"--velocity-mm-s", format_exact(*elastic.velocity_mm_s)});
  } else {
    options.insert(options.end(), {"--T-MPa", format_exact(p.T_Pa / 1e6), "--C-MPa", format_exact(p.c_over_t * p.T_Pa / 1e6)});
  }
  return options;
}

namespace {
nlohmann::ordered_json read_json(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError("cannot read " + file.string());
  return nlohmann::ordered_json::parse(in);
}
}  // namespace

CalibrationTrial with_results(CalibrationTrial t, const std::filesystem::path& summary_file) {
  const nlohmann::ordered_json s = read_json(summary_file);
  const auto& test = s.at("test");
  t.E_glob_Pa = test.at("E_glob_GPa").get<double>() * 1e9;
  t.nu_glob = test.at("nu_glob").is_number() ? test.at("nu_glob").get<double>() : NAN;
  t.peak_Pa = test.at("peak_stress_MPa").get<double>() * 1e6;
  t.peak_reached = test.at("peak_reached").get<bool>();
  t.wall_s = s.at("wall_s").get<double>();
  t.shared_prefix_steps = s.value("restarted_stronger_at_step", std::int64_t(0));
  t.model = s.at("model").get<std::string>();
  t.method = s.contains("method") ? s.at("method").get<std::string>() : "dynamic";
  t.summary_file = summary_file.string();
  return t;
}

RodTrial with_results(RodTrial t, const std::filesystem::path& summary_file) {
  const nlohmann::ordered_json s = read_json(summary_file);
  t.E_DEM_GPa = s.at("test").at("E_fit_GPa").get<double>();
  t.wall_s = s.at("wall_s").get<double>();
  t.summary_file = summary_file.string();
  return t;
}

std::string describe(const CalibrationTrial& t) {
  const auto& p = t.parameters;
  const bool failure = t.kind == CalibrationTrial::Kind::failure;
  std::string line = "trial " + std::to_string(t.number) + " (" + t.kind_name() + "): E_dem " +
                     format_number(std::round(p.E_dem_Pa / 1e7) / 100) + " GPa, nu_dem " +
                     format_number(std::round(p.nu_dem * 1e4) / 1e4);
  if (failure) line += ", T " + format_number(std::round(p.T_Pa / 1e4) / 100) + " MPa";
  line += " -> E_glob " + format_number(std::round(t.E_glob_Pa / 1e7) / 100) + " GPa, nu_glob " +
          format_number(std::round(t.nu_glob * 1e4) / 1e4);
  if (failure) line += ", peak " + format_number(std::round(t.peak_Pa / 1e4) / 100) + " MPa";
  const std::string prefix = t.prefix_of_trial > 0 ? ", the first " + std::to_string(t.shared_prefix_steps) +
                                                         " steps from trial " + std::to_string(t.prefix_of_trial) : "";
  return line + " (" + t.model + " model" + (t.method == "static" ? ", static solve" : "") + ", " +
         format_number(std::round(t.wall_s * 10) / 10) + " s" + prefix + ")";
}

namespace {
// The earlier failure trial whose intact checkpoint `t` may start from (nullptr: none).
const CalibrationTrial* prefix_donor(const CalibrationTrial& t, const std::vector<CalibrationTrial>& done,
                                     const IntactCheckpointFile& intact_file) {
  const CalibrationTrial* best = nullptr;
  const auto& p = t.parameters;
  for (const auto& d : done) {
    const auto& q = d.parameters;
    if (d.kind != CalibrationTrial::Kind::failure || q.E_dem_Pa != p.E_dem_Pa || q.nu_dem != p.nu_dem ||
        !(q.T_Pa <= p.T_Pa) || !(q.c_over_t * q.T_Pa <= p.c_over_t * p.T_Pa) || !std::filesystem::exists(intact_file(d.number)))
      continue;
    if (!best || q.T_Pa > best->parameters.T_Pa) best = &d;
  }
  return best;
}
}  // namespace

std::vector<std::string> shared_prefix_options(const CalibrationTrial& t, const std::vector<CalibrationTrial>& done,
                                               const IntactCheckpointFile& intact_file) {
  if (t.kind != CalibrationTrial::Kind::failure || !intact_file) return {};
  std::vector<std::string> options = {"--intact-checkpoint", intact_file(t.number).string()};
  if (const CalibrationTrial* d = prefix_donor(t, done, intact_file))
    options.insert(options.end(), {"--restart-stronger", intact_file(d->number).string()});
  return options;
}

void run_trials(CompressionCalibration& c, const TrialRunner& run, double friction_deg, std::ostream& log,
                const ElasticTrials& elastic, const IntactCheckpointFile& intact_file) {
  while (auto trial = c.next()) {
    auto options = compression_trial_options(*trial, c.targets(), friction_deg, elastic);
    const auto shared = shared_prefix_options(*trial, c.trials(), intact_file);
    options.insert(options.end(), shared.begin(), shared.end());
    auto done = with_results(*trial, run(trial->number, options));
    if (const CalibrationTrial* d = prefix_donor(*trial, c.trials(), intact_file); d && done.shared_prefix_steps > 0)
      done.prefix_of_trial = d->number;
    log << "mw-calibrate: " << describe(done) << "\n";
    c.record(done);
  }
}

void run_trials(RodCalibration& c, const TrialRunner& run, std::ostream& log) {
  while (auto t = c.next()) {
    t = with_results(*t, run(t->number, {"--E-dem-GPa", format_exact(t->E_dem_GPa)}));
    log << "mw-calibrate rod: trial " << t->number << ": E_dem " << format_number(t->E_dem_GPa) << " GPa -> E_DEM "
        << format_number(t->E_DEM_GPa) << " GPa\n";
    c.record(*t);
  }
}

nlohmann::ordered_json calibration_summary(const CompressionCalibration& c, double friction_deg,
                                           const TargetOrigins& origins, const ElasticTrials& elastic) {
  const CalibrationTrial& best = c.result();
  const auto& p = best.parameters;
  const auto& targets = c.targets();
  double total_wall = 0;
  for (const auto& t : c.trials()) total_wall += t.wall_s;
  nlohmann::ordered_json j;
  j["E_dem_GPa"] = p.E_dem_Pa / 1e9;
  j["nu_dem"] = p.nu_dem;
  j["T_MPa"] = p.T_Pa / 1e6;
  j["C_MPa"] = p.c_over_t * p.T_Pa / 1e6;
  j["friction_angle_deg"] = friction_deg;
  j["E_glob_GPa"] = best.E_glob_Pa / 1e9;
  j["nu_glob"] = best.nu_glob;
  j["sigma_dem_MPa"] = best.peak_Pa / 1e6;
  j[targets.E_name + "_target_GPa"] = targets.E_Pa / 1e9;
  j[targets.nu_name + "_target"] = targets.nu;
  j["sigma_max_target_MPa"] = targets.sigma_Pa / 1e6;
  j["E_error_pct"] = 100 * (best.E_glob_Pa / targets.E_Pa - 1);
  j["nu_error"] = best.nu_glob - targets.nu;
  j["sigma_error_pct"] = 100 * (best.peak_Pa / targets.sigma_Pa - 1);
  j["trial_count"] = c.trials().size();
  j["calibrated_by_trial"] = best.summary_file;
  j["trials_wall_s"] = total_wall;
  j["elastic_trials"] = elastic.static_solve ? "static" : "dynamic";  // stepped, or one solve of the linearised network
  if (!elastic.static_solve && elastic.velocity_mm_s) j["elastic_trials_velocity_mm_s"] = *elastic.velocity_mm_s;
  if (elastic.static_solve && elastic.preconditioner) j["elastic_trials_preconditioner"] = *elastic.preconditioner;
  const auto& tol = c.tolerances();
  const auto target = [](double value, const char* unit, const std::string& tolerance, double calibrated,
                         const nlohmann::ordered_json& origin) {
    nlohmann::ordered_json t = {{"value", value}, {"unit", unit}, {"tolerance", tolerance}, {"calibrated", calibrated}};
    if (origin.is_object()) t.update(origin);
    return t;
  };
  j["targets"] = {
      {targets.E_name, target(targets.E_Pa / 1e9, "GPa", format_number(100 * tol.E_relative) + " %", best.E_glob_Pa / 1e9,
                      origins.E)},
      {targets.nu_name, target(targets.nu, "", format_number(tol.nu_absolute), best.nu_glob, origins.nu)},
      {"sigma_max", target(targets.sigma_Pa / 1e6, "MPa", format_number(100 * tol.sigma_relative) + " %",
                           best.peak_Pa / 1e6, origins.sigma_max)}};
  return j;
}

std::string calibration_targets_csv(const nlohmann::ordered_json& summary) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& [name, t] : summary.at("targets").items()) {
    const auto text = [&t](const char* key) { return t.contains(key) ? t.at(key).get<std::string>() : std::string(); };
    const std::string sha = text("sha256");
    rows.push_back({name, format_exact(t.at("value").get<double>()), text("unit"), text("tolerance"),
                    format_significant(t.at("calibrated").get<double>(), 6), t.contains("file") ? text("file") : text("given"),
                    text("entry"), text("source"), text("cite"), sha.substr(0, 12)});
  }
  return io::to_csv({"target", "value", "unit", "tolerance", "calibrated", "read_from", "entry", "source", "cite",
                     "sha256_prefix"},
                    rows);
}

nlohmann::ordered_json rod_calibration_summary(const RodCalibration& c, const Packing& chain,
                                               const CohesiveFrictionalMaterial& material) {
  const RodTrial& best = c.result();
  const double R = chain.radii_m.front();
  auto centre = [&](std::size_t i) {
    const auto& x = chain.centres_m[i];
    return Vec3{x[0], x[1], x[2]};
  };
  const double d = norm(centre(1) - centre(0));
  CohesiveFrictionalMaterial calibrated = material;
  calibrated.E_dem_Pa = best.E_dem_GPa * 1e9;
  nlohmann::ordered_json trials = nlohmann::ordered_json::array();
  for (const auto& t : c.trials())
    trials.push_back({{"trial", t.number}, {"E_dem_GPa", t.E_dem_GPa}, {"E_DEM_GPa", t.E_DEM_GPa}, {"wall_s", t.wall_s}});
  nlohmann::ordered_json j;
  j["spheres"] = chain.size();
  j["sphere_radius_mm"] = R * 1e3;
  j["spacing_mm"] = d * 1e3;
  j["spacing_R"] = d / R;
  j["rho_p_kg_m3"] = chain.particle_density_kg_m3;
  j["E_dem_GPa"] = best.E_dem_GPa;
  j["Kn_N_m"] = normal_stiffness(calibrated, R, R);  // Eq. (3): E_dem R for equal spheres
  j["E_DEM_GPa"] = best.E_DEM_GPa;
  j["E_target_GPa"] = c.target_GPa();
  j["E_dem_start_GPa"] = c.trials().front().E_dem_GPa;
  j["E_DEM_at_start_GPa"] = c.trials().front().E_DEM_GPa;
  j["trials"] = trials;
  return j;
}

StressStrainCurve read_trial_curve(const std::filesystem::path& summary_file) {
  const nlohmann::ordered_json test = read_json(summary_file).at("test");
  const io::CsvTable t = io::read_csv(std::filesystem::path(summary_file).replace_extension(".csv"));
  StressStrainCurve c;
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

std::string calibration_trials_csv(const std::vector<CalibrationTrial>& trials) {
  // Six significant digits: a log for people (the tolerances are 1 %, 0.01 and 2 %); each
  // trial's summary file has its numbers in full.
  auto n = [](double v) { return format_significant(v, 6); };
  std::vector<std::vector<std::string>> rows;
  for (const auto& t : trials) {
    const auto& p = t.parameters;
    const bool failure = t.kind == CalibrationTrial::Kind::failure;
    rows.push_back({std::to_string(t.number), t.kind_name(), t.model, n(p.E_dem_Pa / 1e9), n(p.nu_dem),
                    failure ? n(p.T_Pa / 1e6) : "", failure ? n(p.c_over_t * p.T_Pa / 1e6) : "", n(t.E_glob_Pa / 1e9),
                    n(t.nu_glob), failure ? n(t.peak_Pa / 1e6) : "", failure ? (t.peak_reached ? "yes" : "no") : "",
                    format_fixed(t.wall_s, 1), t.summary_file});
  }
  return io::to_csv({"trial", "kind", "model", "E_dem_GPa", "nu_dem", "T_MPa", "C_MPa", "E_glob_GPa", "nu_glob", "peak_MPa",
                     "peak_reached", "wall_s", "summary"},
                    rows);
}

std::string calibration_trajectory_script(const CompressionCalibration& c, const std::filesystem::path& png,
                                          const std::string& title) {
  const auto& tg = c.targets();
  const auto& tol = c.tolerances();
  std::vector<double> n, e, nu, en, enu, fn, fs;
  for (const auto& t : c.trials()) {
    const double k = t.number;
    (t.kind == CalibrationTrial::Kind::elastic ? en : fn).push_back(k);
    if (t.kind == CalibrationTrial::Kind::elastic) {
      e.push_back(100 * (t.E_glob_Pa / tg.E_Pa - 1));
      enu.push_back(t.nu_glob);
    } else {
      n.push_back(100 * (t.E_glob_Pa / tg.E_Pa - 1));
      nu.push_back(t.nu_glob);
      fs.push_back(100 * (t.peak_Pa / tg.sigma_Pa - 1));
    }
  }
  const double last = double(c.trials().size()) + 0.5;
  std::string s = "set terminal pngcairo size 1500,480 font 'Sans,11'\nset output " + io::gnuplot_quote(png) + "\n";
  s += io::gnuplot_datablock("el", {en, e, enu});
  s += io::gnuplot_datablock("fa", {fn, n, nu, fs});
  s += "set grid\nset xrange [0.5:" + format_number(last) + "]\nset xtics 1\nset xlabel 'trial'\n"
       "set style fill transparent solid 0.15 noborder\n";
  s += "set multiplot layout 1,3 title '" + title + "'\n";
  auto band = [&](double lo, double hi) {
    return "'+' using 1:(" + format_number(lo) + "):(" + format_number(hi) + ") with filledcurves lc rgb '#2e8b57' title 'tolerance', ";
  };
  const double te = 100 * tol.E_relative, ts = 100 * tol.sigma_relative;
  // Keys where the trials seldom go: the last trials sit at the targets (E: bottom right is
  // free), the first failure trial is never trial 1 (strength: bottom left), nu_glob starts
  // far from its band at most in trial 1 (top right).
  s += "set key bottom right\nset title 'E_{glob} against E_{st} = " + format_number(std::round(tg.E_Pa / 1e7) / 100) + " GPa'\n"
       "set ylabel 'E_{glob} / E_{st} - 1 [%]'\n"
       "plot " + band(-te, te) + "$el using 1:2 with linespoints pt 7 ps 1.4 lc rgb '#1f4e9c' title 'elastic trials', "
       "$fa using 1:2 with linespoints pt 5 ps 1.4 lc rgb '#c0392b' title 'failure trials'\n";
  s += "set key top right\nset title '{/Symbol n}_{glob} against {/Symbol n}_{st} = " + format_number(tg.nu) + "'\n"
       "set ylabel '{/Symbol n}_{glob}'\n"
       "plot " + band(tg.nu - tol.nu_absolute, tg.nu + tol.nu_absolute) +
       "$el using 1:3 with linespoints pt 7 ps 1.4 lc rgb '#1f4e9c' title 'elastic trials', "
       "$fa using 1:3 with linespoints pt 5 ps 1.4 lc rgb '#c0392b' title 'failure trials'\n";
  s += "set key bottom left\nset title '{/Symbol s}_{peak} against {/Symbol s}_{max} = " + format_number(std::round(tg.sigma_Pa / 1e4) / 100) +
       " MPa'\nset ylabel '{/Symbol s}_{peak} / {/Symbol s}_{max} - 1 [%]'\n"
       "plot " + band(-ts, ts) + "$fa using 1:4 with linespoints pt 5 ps 1.4 lc rgb '#c0392b' title 'failure trials'\n";
  s += "unset multiplot\n";
  return s;
}

std::string stress_strain_script(const StressStrainCurve& c, double E_target_Pa, double nu_target,
                                 const std::filesystem::path& png, const std::string& title) {
  std::vector<double> ax, lat, sig;
  for (std::size_t i = 0; i < c.stress_Pa.size(); ++i) {
    ax.push_back(c.axial[i] * 1e3);
    lat.push_back(c.lateral.empty() ? NAN : -c.lateral[i] * 1e3);
    sig.push_back(c.stress_Pa[i] / 1e6);
  }
  std::string s = "set terminal pngcairo size 1000,720 font 'Sans,11'\nset output " + io::gnuplot_quote(png) + "\n";
  s += io::gnuplot_datablock("c", {ax, lat, sig});
  // Lines through the lower reading (eps_b, sigma_b): slope E (axial) and E / nu (lateral).
  auto line = [&](double E, double nu, bool lateral) {
    const std::string slope = format_exact(lateral ? -E / nu / 1e9 : E / 1e9);  // MPa per 1e-3
    const std::string x0 = format_exact((lateral ? -c.eps_b * nu : c.eps_b) * 1e3);
    std::string expr = "(";
    expr.append(format_exact(c.sigma_b_Pa / 1e6)).append(" + ").append(slope).append(" * (x - ").append(x0).append("))");
    return expr;
  };
  // Each line from zero stress to just above the upper reading, on its own side of the strain axis.
  const std::string top = format_exact(1.05 * c.sigma_a_Pa / 1e6);
  auto segment = [&](double E, double nu, bool lateral) {
    const std::string f = line(E, nu, lateral);
    std::string expr = lateral ? "((x <= 0" : "((x >= 0";
    expr.append(" && ").append(f).append(" >= 0 && ").append(f).append(" <= ").append(top).append(") ? ").append(f).append(" : 1/0)");
    return expr;
  };
  auto gpa = [](double pa) { return format_number(std::round(pa / 1e7) / 100); };
  s += "set datafile missing 'nan'\nset grid\nset xlabel 'strain [10^{-3}] (lateral < 0 < axial)'\n"
       "set ylabel 'stress [MPa]'\nset yrange [0:*]\nset key below maxrows 4\nset title '" + title + "'\nset samples 800\n";
  s += "plot $c using 1:3 with lines lw 2 lc rgb '#1f4e9c' title 'axial strain', "
       "$c using 2:3 with lines lw 2 lc rgb '#8e44ad' title 'lateral strain', " +
       segment(c.E_glob_Pa, c.nu_glob, false) + " with lines dt 2 lw 2 lc rgb '#c0392b' title 'E_{glob} = " +
       gpa(c.E_glob_Pa) + " GPa (calibrated)', " + segment(E_target_Pa, nu_target, false) +
       " with lines dt 3 lw 2 lc rgb '#2e8b57' title 'E_{st} = " + gpa(E_target_Pa) + " GPa (target)', " +
       segment(c.E_glob_Pa, c.nu_glob, true) + " with lines dt 2 lw 2 lc rgb '#c0392b' title 'E_{glob} / {/Symbol n}_{glob}, {/Symbol n}_{glob} = " +
       format_number(std::round(c.nu_glob * 1000) / 1000) + "', " + segment(E_target_Pa, nu_target, true) +
       " with lines dt 3 lw 2 lc rgb '#2e8b57' title 'E_{st} / {/Symbol n}_{st}, {/Symbol n}_{st} = " + format_number(nu_target) + "', "
       "'+' using (" + format_exact(c.eps_b * 1e3) + "):(" + format_exact(c.sigma_b_Pa / 1e6) +
       ") with points pt 7 ps 1.5 lc rgb 'black' notitle, "
       "'+' using (" + format_exact(c.eps_a * 1e3) + "):(" + format_exact(c.sigma_a_Pa / 1e6) +
       ") with points pt 7 ps 1.5 lc rgb 'black' title 'secant readings (10 % and 1/3 of the peak)'\n";
  return s;
}

}  // namespace mesowave::dem
