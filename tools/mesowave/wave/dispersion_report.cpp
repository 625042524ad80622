#include "mesowave/wave/dispersion_report.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <numbers>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/experiment/experiment.hpp"
#include "mesowave/io/csv.hpp"
#include "mesowave/signal/signal_csv.hpp"
#include "mesowave/wave/group_velocity.hpp"

namespace mesowave::wave {
namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace {

// "LO,HI" as two numbers; nullopt for "".
std::optional<std::pair<double, double>> parse_range(const std::string& text, const std::string& what) {
  if (text.empty()) return std::nullopt;
  const auto comma = text.find(',');
  if (comma == std::string::npos) throw InputError(what + " must read LO,HI");
  return std::make_pair(std::stod(text.substr(0, comma)), std::stod(text.substr(comma + 1)));
}

// The rod's values: those given, the rest from the experiment's rod (recorded as an input);
// `length_m`, if asked, gets the experiment's rod length.
RodOptions resolved(const RodOptions& given, std::vector<fs::path>& inputs, std::optional<double>* length_m = nullptr) {
  if (given.experiment.empty()) return given;
  inputs.push_back(given.experiment);
  const experiment::Rod rod = experiment::rod_of(experiment::read_experiment_file(given.experiment));
  RodOptions o = given;
  if (!o.E_GPa) o.E_GPa = rod.E_Pa / units::GPa;
  if (!o.nu) o.nu = rod.nu;
  if (!o.density_kg_m3) o.density_kg_m3 = rod.density_kg_m3;
  if (!o.radius_mm) o.radius_mm = rod.radius_m / units::mm;
  if (length_m) *length_m = rod.length_m;
  return o;
}

}  // namespace

TheoryReport theory_report(const TheoryRequest& request) {
  TheoryRequest q = request;
  std::vector<fs::path> inputs;
  q.rod = resolved(request.rod, inputs);
  if (!q.plot.empty()) io::require_plot_extension(q.plot);
  if (!q.rod.complete()) throw InputError("theory needs --E-GPa, --nu, --density-kg-m3 and --radius-mm (or --experiment)");
  const IsotropicMaterial material{require_positive("--E-GPa", *q.rod.E_GPa, "GPa") * units::GPa, *q.rod.nu,
                                   *q.rod.density_kg_m3};
  validate(material);
  TheoryReport r;
  r.inputs = inputs;
  const auto& pc = r.rod.emplace(material, require_positive("--radius-mm", *q.rod.radius_mm, "mm") * units::mm);
  TraceOptions opt;
  opt.f_max_Hz = require_positive("--f-max-kHz", q.f_max_kHz, "kHz") * units::kHz;
  opt.ka_step = require_positive("--ka-step", q.ka_step);
  if (q.max_modes < 0) throw InputError("--modes (" + std::to_string(q.max_modes) + ") must not be negative");
  std::vector<VelocityCurve> curves;
  for (const auto& o : q.overlays) {
    const auto eq = o.rfind('=');  // the label may hold '=' itself
    if (eq == std::string::npos || eq == 0) throw InputError("--overlay " + o + " must read LABEL=FILE.csv");
    r.inputs.push_back(o.substr(eq + 1));
    curves.push_back(read_velocity_curve(o.substr(eq + 1), o.substr(0, eq)));
  }
  auto trace = trace_longitudinal_modes(pc, opt);
  if (q.max_modes > 0) std::erase_if(trace.modes, [&](const ModeCurve& c) { return c.mode > q.max_modes; });
  const auto grid = frequency_grid(q.f_min_kHz.value_or(q.df_kHz) * units::kHz, opt.f_max_Hz, q.df_kHz * units::kHz);
  r.points = sample_at_frequencies(pc, trace, grid);
  r.csv = theory_csv(r.points, pc.radius_m());
  if (!q.plot.empty()) {
    auto spec = group_velocity_plot("Pochhammer-Chree, radius " + format_number(*q.rod.radius_mm) + " mm, nu = " +
                                        format_number(*q.rod.nu),
                                    r.points, {}, curves);
    spec.x_range = parse_range(q.plot_f_range, "--plot-f-range-kHz");
    spec.y_range = parse_range(q.plot_c_range, "--plot-c-range-m-s");
    for (char c : q.plot_key)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != ' ' && c != ',' && c != '.')
        throw InputError("--plot-key '" + q.plot_key + "' may hold only words and numbers");
    spec.key = q.plot_key;
    std::replace(spec.key.begin(), spec.key.end(), ',', ' ');  // "inside,bottom,left" reads as words
    r.plot = std::move(spec);
  }
  r.summary = theory_summary(pc, trace);
  r.summary["rows"] = r.points.size();
  for (const auto& m : r.summary["modes"])
    if (m["cutoff_kHz"].get<double>() > 0)
      r.metrics.push_back({m["mode"].get<std::string>() + " cut-off", m["cutoff_kHz"].get<double>(), "kHz"});
  r.metrics.push_back({"c0", pc.speeds().c0, "m/s"});
  if (r.summary.contains("L01_min_group_velocity_m_s"))
    r.metrics.push_back({"L(0,1) min group velocity", r.summary["L01_min_group_velocity_m_s"].get<double>(), "m/s"});
  return r;
}

DispersionReport lattice_report(const LatticeRequest& q) {
  MassSpringChain chain;
  const bool direct = q.mass_kg || q.stiffness_N_m;
  const bool dem = q.sphere_radius_mm || q.particle_density_kg_m3 || q.E_dem_GPa || q.spacing_R;
  if (direct && dem) throw InputError("give either --mass-kg/--stiffness-N-m or the sphere description, not both");
  if (direct) {
    if (!q.mass_kg || !q.stiffness_N_m || !q.spacing_mm)
      throw InputError("--mass-kg, --stiffness-N-m and --spacing-mm are needed together");
    chain = {*q.mass_kg, *q.stiffness_N_m, *q.spacing_mm * units::mm};
  } else {
    if (!q.sphere_radius_mm || !q.particle_density_kg_m3 || !q.E_dem_GPa)
      throw InputError("need --sphere-radius-mm, --particle-density-kg-m3 and --E-dem-GPa "
                       "(or --mass-kg, --stiffness-N-m, --spacing-mm)");
    if (q.spacing_mm.has_value() == q.spacing_R.has_value())
      throw InputError("give exactly one of --spacing-mm and --spacing-R");
    const double R = require_positive("--sphere-radius-mm", *q.sphere_radius_mm, "mm") * units::mm;
    const double d = q.spacing_mm ? *q.spacing_mm * units::mm : require_positive("--spacing-R", *q.spacing_R) * R;
    chain = dem_chain(R, *q.particle_density_kg_m3,
                      require_positive("--E-dem-GPa", *q.E_dem_GPa, "GPa") * units::GPa, d);
  }
  validate(chain);
  const auto grid = frequency_grid(q.df_kHz * units::kHz, q.f_max_kHz * units::kHz, q.df_kHz * units::kHz);
  const auto curve = lattice_curve(q.label, chain, grid);
  DispersionReport r;
  r.csv = lattice_csv(curve);
  auto& j = r.summary;
  j["model"] = q.label;
  j["mass_kg"] = chain.mass_kg;
  j["stiffness_N_m"] = chain.stiffness_N_m;
  j["spacing_mm"] = chain.spacing_m / units::mm;
  j["long_wave_speed_m_s"] = long_wave_speed(chain);
  j["cutoff_kHz"] = cutoff_omega(chain) / (2 * std::numbers::pi) / units::kHz;
  j["rows"] = curve.points.size();
  r.metrics.push_back({"long-wave speed", j["long_wave_speed_m_s"].get<double>(), "m/s"});
  r.metrics.push_back({"lattice cut-off", j["cutoff_kHz"].get<double>(), "kHz"});
  return r;
}

DispersionReport measure_report(const MeasureReportRequest& request) {
  DispersionReport r;
  MeasureReportRequest q = request;
  std::optional<double> rod_length_m;
  q.rod = resolved(request.rod, r.inputs, &rod_length_m);
  // The echo at the far end of the experiment's rod: two packets 2 L apart.
  if (q.method == "echo" && q.distance_mm == 0 && rod_length_m) q.distance_mm = 2 * *rod_length_m / units::mm;
  std::vector<GroupVelocityPoint> points;
  if (!q.spacetime.empty()) {
    if (!q.runs.empty()) throw InputError("give either --run files or --spacetime, not both");
    r.inputs.push_back(q.spacetime);
    const auto ridge =
        spacetime_ridge(read_spacetime_file(q.spacetime), q.f_min_kHz * units::kHz, q.f_max_kHz * units::kHz);
    for (const auto& p : ridge)
      points.push_back({q.label.empty() ? q.spacetime.filename().string() : q.label, p.f_Hz, "spacetime", 0, 0, 0,
                        p.c_group_m_s});
  } else {
    if (q.runs.empty()) throw InputError("give at least one --run FILE (or FREQ_kHz=FILE) or --spacetime FILE");
    const MeasureRequest req{q.method, q.stations.empty() ? std::vector<std::string>{"S"} : q.stations,
                             q.distance_mm * units::mm, q.cycles};
    if (q.distance_mm < 0) throw InputError("--distance-mm must not be negative");
    for (const auto& run : q.runs) {
      const auto eq = run.find('=');
      const fs::path file = eq == std::string::npos ? fs::path(run) : fs::path(run.substr(eq + 1));
      r.inputs.push_back(file);
      double f = 0;
      if (eq != std::string::npos) {
        f = std::stod(run.substr(0, eq)) * units::kHz;
      } else {
        const auto a = signal_file_attribute(file, "burst_frequency_Hz");
        if (!a) throw InputError(file.string() + " does not record its burst frequency: give FREQ_kHz=" + run);
        f = std::stod(*a);
      }
      auto p = measure_run(signal::read_signals(file), f, req);
      p.run = q.label.empty() ? file.filename().string() : q.label;
      points.push_back(p);
    }
  }
  std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) { return a.f_Hz < b.f_Hz; });
  std::function<double(double)> theory;
  if (q.rod.any() && !q.theory_csv.empty()) throw InputError("give either the material or --theory-csv, not both");
  if (q.rod.any()) {
    if (!q.rod.complete()) throw InputError("theory needs --E-GPa, --nu, --density-kg-m3 and --radius-mm together");
    const PochhammerChree pc({require_positive("--E-GPa", *q.rod.E_GPa, "GPa") * units::GPa, *q.rod.nu,
                              *q.rod.density_kg_m3},
                             require_positive("--radius-mm", *q.rod.radius_mm, "mm") * units::mm);
    std::vector<double> f_Hz;
    for (const auto& p : points) f_Hz.push_back(p.f_Hz);
    const auto cg = l01_group_velocity(pc, f_Hz);
    theory = [f_Hz, cg](double f) {
      for (std::size_t i = 0; i < f_Hz.size(); ++i)
        if (f_Hz[i] == f) return cg[i];
      return 0.0;
    };
  } else if (!q.theory_csv.empty()) {
    r.inputs.push_back(q.theory_csv);
    theory = theory_from_csv(q.theory_csv);
  }
  double lo = points.empty() ? 0 : points.front().f_Hz, hi = points.empty() ? 0 : points.back().f_Hz;
  if (const auto band = parse_range(q.band_kHz, "--band-kHz")) {
    lo = band->first * units::kHz;
    hi = band->second * units::kHz;
  }
  auto& j = r.summary;
  j["points"] = points.size();
  std::optional<ResidualSummary> rss;
  if (theory) {
    rss = residual_sum_of_squares(points, theory, lo, hi);
    j["band_kHz"] = {lo / units::kHz, hi / units::kHz};
    j["points_in_band"] = rss->points;
    j["rss_m2_s2"] = rss->rss_m2_s2;
    j["rms_m_s"] = rss->rms_m_s;
    j["max_abs_residual_m_s"] = rss->max_abs_m_s;
    r.metrics.push_back({"RSS", rss->rss_m2_s2, "m^2/s^2"});
  }
  std::vector<std::vector<std::string>> rows;
  auto list = json::array();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    const bool in = rss && rss->in_band[i];
    const std::string th = in ? format_exact(rss->theory_m_s[i]) : "";
    const std::string res = in ? format_exact(p.c_group_m_s - rss->theory_m_s[i]) : "";
    rows.push_back({p.run, format_number(p.f_Hz / units::kHz), p.method, format_exact(p.t1_s / units::us),
                    format_exact(p.t2_s / units::us), format_exact(p.distance_m / units::mm),
                    format_exact(p.c_group_m_s), th, res, in ? "1" : "0"});
    list.push_back({{"f_kHz", p.f_Hz / units::kHz}, {"c_group_m_s", p.c_group_m_s}});
  }
  j["measured"] = list;
  r.csv = io::to_csv({"run", "f_kHz", "method", "t1_us", "t2_us", "distance_mm", "c_group_m_s", "theory_c_group_m_s",
                      "residual_m_s", "in_band"},
                     rows);
  return r;
}

BarEchoReport bar_echo_report(const BarEchoRequest& request) {
  BarEchoReport r;
  BarEchoRequest q = request;
  q.rod = resolved(request.rod, r.inputs);
  r.inputs.push_back(q.record);
  r.record = read_record(q.record, q.column);
  BarEchoOptions bo;
  bo.path_m = require_positive("--path-mm", q.path_mm, "mm") * units::mm;
  std::optional<PochhammerChree> pc;
  if (q.rod.complete()) {
    pc.emplace(IsotropicMaterial{*q.rod.E_GPa * units::GPa, *q.rod.nu, *q.rod.density_kg_m3},
               *q.rod.radius_mm * units::mm);
    bo.theory = &*pc;
  }
  r.result = analyse_bar_echo(r.record, bo);
  const auto& a = r.result;
  auto& j = r.summary;
  j["record"] = q.record.filename().string();
  j["samples"] = r.record.size();
  j["dt_ns"] = r.record.dt_s / units::ns;
  j["path_mm"] = q.path_mm;
  auto picks = json::array();
  std::vector<std::vector<std::string>> rows;
  for (const auto& p : a.picks) {
    picks.push_back({{"method", p.method}, {"t1_us", p.t1_s / units::us}, {"t2_us", p.t2_s / units::us},
                     {"delay_us", (p.t2_s - p.t1_s) / units::us}, {"c_m_s", p.velocity_m_s}});
    rows.push_back({p.method, format_exact(p.t1_s / units::us), format_exact(p.t2_s / units::us),
                    format_exact((p.t2_s - p.t1_s) / units::us), format_exact(p.velocity_m_s)});
  }
  r.csv = io::to_csv({"method", "t1_us", "t2_us", "delay_us", "c_m_s"}, rows);
  const auto v = bar_echo_velocity(a, r.record.dt_s, q.path_uncertainty_mm / q.path_mm);
  j["picks"] = picks;
  j["velocity_m_s"] = v.velocity_m_s;
  j["velocity_method"] = "pulse front: mean of the threshold and AIC onset picks (a dispersed front rises "
                         "ahead of z/c0, so this reads high by up to ~1 %)";
  j["relative_uncertainty_method"] = v.relative_uncertainty_method;
  j["relative_uncertainty_sampling"] = v.relative_uncertainty_sampling;
  j["relative_uncertainty_path"] = v.relative_uncertainty_path;
  j["velocity_uncertainty_m_s"] = v.velocity_uncertainty_m_s;
  if (a.fitted_c0_m_s > 0) {
    // The dispersion-corrected bar velocity: Pochhammer-Chree edges matched to the echo's.
    j["fitted_c0_m_s"] = a.fitted_c0_m_s;
    j["fitted_c0_uncertainty_m_s"] = v.fitted_c0_uncertainty_m_s;
    j["fitted_c0_method"] = "c0 for which the Pochhammer-Chree echo's edges (0.25/0.5/0.75) meet the measured ones";
    r.metrics.push_back({"fitted bar velocity c0", a.fitted_c0_m_s, "m/s"});
  }
  j["echo_over_pulse_amplitude"] = a.second_pulse_extreme / a.first_pulse_extreme;
  j["f50_kHz"] = a.f50_Hz / units::kHz;
  j["f90_kHz"] = a.f90_Hz / units::kHz;
  if (q.rod.E_GPa && q.rod.density_kg_m3) {
    const double c0 = std::sqrt(*q.rod.E_GPa * units::GPa / *q.rod.density_kg_m3);
    j["c0_m_s"] = c0;
    j["velocity_over_c0"] = v.velocity_m_s / c0;
    if (pc) {
      const auto cg = l01_group_velocity(*pc, {a.f50_Hz, a.f90_Hz});
      j["theory_c_group_at_f50_m_s"] = cg[0];
      j["theory_c_group_at_f90_m_s"] = cg[1];
    }
  }
  r.metrics.push_back({"bar velocity", v.velocity_m_s, "m/s"});
  return r;
}

std::vector<signal::Signal> bar_echo_signals(const BarEchoReport& report) {
  if (report.result.theory_echo.samples.empty())
    throw InputError("--signals needs the bar's --E-GPa, --nu, --density-kg-m3 and --radius-mm");
  return {report.record, report.result.theory_echo};
}

}  // namespace mesowave::wave
