#include "mesowave/efg/wave_report.hpp"

#include <algorithm>
#include <cmath>

#include "mesowave/core/check.hpp"
#include "mesowave/efg/viscosity_command.hpp"

namespace mesowave::efg {

WaveStripOptions WaveCommandLine::resolve() const {
  WaveStripOptions o;
  o.length_m = length_mm * 1e-3, o.width_m = width_mm * 1e-3, o.spacing_m = spacing_mm * 1e-3;
  o.thickness_m = thickness_mm * 1e-3;
  o.E_Pa = E_GPa * 1e9, o.nu = nu, o.density_kg_m3 = density_kg_m3;
  o.mls.basis = parse_basis(basis);
  o.mls.weight = parse_weight_kind(weight);
  o.support_scale = require_positive("--support-scale", support_scale);
  o.gauss = gauss;
  o.rollers = !free_sides;
  o.pulse = pulse;
  if (pulse == "hann")  // the burst of mw-fem's and mw-dem's runs, so that --fem-reference loads both alike
    o.custom = signal::HannBurst(require_positive("--frequency-kHz", frequency_kHz) * 1e3, require_positive("--cycles", cycles),
                                 peak_MPa * 1e6);
  if (fem_reference && pulse != "hann") throw InputError("--fem-reference needs --pulse hann (mw-fem's only load is a Hann burst)");
  o.triangular = {peak_MPa * 1e6, rise_us * 1e-6, fall_us * 1e-6, start_us * 1e-6};
  o.friedlander = {peak_MPa * 1e6, positive_us * 1e-6, decay, start_us * 1e-6};
  for (double x : sensor_mm) o.sensor_x_m.push_back(x * 1e-3);
  if (!std::isfinite(duration_us) || duration_us < 0)
    throw InputError("--duration-us (" + format_number(duration_us) + ") must be >= 0 (0: the wave to the far end and 10 % more)");
  o.dynamics.duration_s = duration_us * 1e-6;
  o.dynamics.dt_s = dt_us * 1e-6;
  o.dynamics.dt_fraction = dt_fraction;
  o.dynamics.alpha_damping_per_s = alpha_per_s;
  o.dynamics.viscosity = {viscosity_quadratic, viscosity_linear};
  o.dynamics.viscosity.validate();
  o.dynamics.stiffness_check_every = stiffness_check_every;
  o.dynamics.sample_stride = sample_stride;
  // the profiles pick the snapshot nearest each time: every other step keeps that within one step
  o.dynamics.snapshot_stride = snapshot_stride > 0       ? snapshot_stride
                               : !profiles.empty()      ? 2
                               : !snapshots.empty()     ? 50
                                                        : 0;
  if (!profiles.empty() && profile_us.empty()) throw InputError("--profiles needs the times: --profile-us T (repeatable)");
  for (double t : profile_us)
    if (!std::isfinite(t) || t < 0) throw InputError("--profile-us (" + format_number(t) + ") must be >= 0");
  if (unloading != 0 && unloading != 1) throw InputError("--unloading (" + std::to_string(unloading) + ") must be 1 (Eq. 27) or 0");
  return o;
}

void add_wave_options(CLI::App& app, WaveCommandLine& v) {
  app.add_option("--length-mm", v.length_mm, "Strip length L (pressure on x = 0, x = L free)")->capture_default_str();
  app.add_option("--width-mm", v.width_mm, "Strip width W (rollers v = 0 on y = 0 and y = W)")->capture_default_str();
  app.add_option("--spacing-mm", v.spacing_mm, "Node spacing (cells round(L/s) x round(W/s), their corners the nodes)")
      ->capture_default_str();
  app.add_option("--thickness-mm", v.thickness_mm, "Out-of-plane thickness (plane strain)")->capture_default_str();
  app.add_option("--E-GPa", v.E_GPa, "Young's modulus")->capture_default_str();
  app.add_option("--nu", v.nu, "Poisson's ratio")->capture_default_str();
  app.add_option("--density-kg-m3", v.density_kg_m3, "Density")->capture_default_str();
  app.add_option("--pulse", v.pulse, "triangular (--peak-MPa, --rise-us, --fall-us) | friedlander (--peak-MPa, "
                                     "--positive-us, --decay) | hann (--peak-MPa, --frequency-kHz, --cycles)")->capture_default_str();
  app.add_option("--frequency-kHz", v.frequency_kHz, "Hann burst: centre frequency")->capture_default_str();
  app.add_option("--cycles", v.cycles, "Hann burst: cycles")->capture_default_str();
  app.add_flag("--fem-reference", v.fem_reference, "Run mw-fem's explicit solver on the same bar (--pulse hann): v_x beside "
                                                   "the history, rms errors against the closed form in the summary");
  app.add_option("--peak-MPa", v.peak_MPa, "Peak pressure on x = 0")->capture_default_str();
  app.add_option("--rise-us", v.rise_us, "Triangular: rise time")->capture_default_str();
  app.add_option("--fall-us", v.fall_us, "Triangular: fall time")->capture_default_str();
  app.add_option("--positive-us", v.positive_us, "Friedlander: positive-phase duration t_d")->capture_default_str();
  app.add_option("--decay", v.decay, "Friedlander: decay coefficient b, p = p_s (1 - t/t_d) exp(-b t/t_d)")->capture_default_str();
  app.add_option("--start-us", v.start_us, "When the pulse starts (Friedlander: the arrival time)")->capture_default_str();
  app.add_option("--duration-us", v.duration_us, "Simulated time (0: the wave to x = L and 10 % more)")->capture_default_str();
  app.add_option("--dt-us", v.dt_us, "Time step (0: --dt-fraction x the stable step; above the stable step: refused)")
      ->capture_default_str();
  app.add_option("--dt-fraction", v.dt_fraction, "Fraction of the stable step 2/omega_max, in (0, 1]")->capture_default_str();
  app.add_option("--alpha-damping", v.alpha_per_s, "Mass-proportional damping alpha [1/s] (0: none)")->capture_default_str();
  add_viscosity_options(app, v.viscosity_quadratic, v.viscosity_linear);
  app.add_option("--stiffness-check", v.stiffness_check_every, "Steps between re-reading the law's stiffening")->capture_default_str();
  app.add_option("--sensor-mm", v.sensor_mm, "Sensor x on the centre line, repeatable (default L/4, L/2, 3L/4)");
  app.add_option("--sample-stride", v.sample_stride, "Steps between the history's rows")->capture_default_str();
  app.add_option("--basis", v.basis, "MLS basis: linear | quadratic, Eq. (2)")->capture_default_str();
  app.add_option("--weight", v.weight, "MLS weight: quartic-spline (Eq. 12) | cubic-spline")->capture_default_str();
  app.add_option("--support-scale", v.support_scale, "Support radius over the spacing, Eq. (10)")->capture_default_str();
  app.add_option("--gauss", v.gauss, "Gauss points per cell direction (the paper: 2)")->capture_default_str();
  app.add_flag("--free-sides", v.free_sides, "No rollers: the long sides free (no longer uniaxial strain)");
  app.add_option("--history", v.history, "Sensor histories CSV: t_us, per sensor sigma_xx/yy [MPa], v_x/y [m/s]");
  app.add_option("--snapshots", v.snapshots, "Folder for ParaView files of the nodes (wave.pvd), with --snapshot-stride");
  app.add_option("--snapshot-stride", v.snapshot_stride, "Steps between snapshots (default: 50 with --snapshots)");
  app.add_option("--threads", v.threads, "Threads (0: the cores the machine is not busy with, core/threads.hpp)");
  app.add_option("--law", v.law, "The strip's law: " + strip_law_names() + " (efg/strip_law.hpp)")->capture_default_str();
  app.add_option("--beta", v.law_parameters.beta, "quadratic: p = M s (1 + beta s)")->capture_default_str();
  HugoniotParameters& h = v.law_parameters.hugoniot;
  app.add_option("--e-v-th", h.e_v_th, "hugoniot: threshold volumetric strain, Eq. (26)")->capture_default_str();
  app.add_option("--e-v", h.e_v, "hugoniot: e_v, Eq. (26)")->capture_default_str();
  app.add_option("--a-v", h.a_v, "hugoniot: a_v, Eq. (26)")->capture_default_str();
  app.add_option("--b-v", h.b_v, "hugoniot: b_v, Eq. (26)")->capture_default_str();
  app.add_option("--unloading", v.unloading, "hugoniot: 1 unloads by Eq. (27), 0 on Eq. (25) (Section 4.2's test)")
      ->capture_default_str();
  app.add_option("--profiles", v.profiles, "CSV of -sigma_xx along the centre line at the --profile-us times");
  app.add_option("--profile-us", v.profile_us, "A time of --profiles (repeatable; the nearest snapshot's)");
  app.add_option("--fronts", v.fronts, "CSV of the front's width per sensor against the simple wave (a stiffening law)");
}

WaveCommandRun run_wave_command(const WaveCommandLine& cl) {
  WaveCommandRun w;
  w.options = cl.resolve();
  StripLawParameters p = cl.law_parameters;
  p.hugoniot.unloading = cl.unloading == 1;
  const WaveStripOptions& o = w.options;
  w.law = make_strip_law(cl.law, {o.E_Pa, o.nu, o.thickness_m, o.density_kg_m3, PlaneState::plane_strain}, p);
  w.options.material = w.law.point.get();
  w.result = run_wave_strip(w.options);
  if (cl.fem_reference)
    w.fem = fem_bar_reference(w.options, signal::HannBurst(cl.frequency_kHz * 1e3, cl.cycles, cl.peak_MPa * 1e6), w.result);
  std::vector<double> profile_s;
  for (double t : cl.profile_us) profile_s.push_back(t * 1e-6);
  w.outputs = wave_strip_outputs(w.options, w.result, &w.law, profile_s, w.fem ? &*w.fem : nullptr);
  w.outputs.summary["law"] = cl.law;
  return w;
}

namespace {

// The sensor's -sigma_xx in the linear continuum: the pulse and its reflection from the free end
// x = L (sign reversed), exact until that reflection comes back from the loaded end.
double continuum_sigma_xx(const WaveStripOptions& o, const WaveStripResult& r, double x, double t) {
  const PressureHistory p = o.pressure();
  const double c = r.c_p_m_s;
  const auto at = [&](double tau) { return tau < 0 ? 0.0 : p(tau); };
  return -at(t - x / c) + at(t - (2 * o.length_m - x) / c);
}

nlohmann::ordered_json front_json(const ShockFrontComparison& c) {
  const auto num = [](double v) { return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr); };
  nlohmann::ordered_json fronts = nlohmann::ordered_json::array();
  for (const FrontWidth& f : c.fronts)
    fronts.push_back({{"x_mm", f.x_m * 1e3},
                      {"width_us", num(f.width_s * 1e6)},
                      {"simple_wave_width_us", f.simple_wave_width_s * 1e6},
                      {"before_breaking", f.before_breaking}});
  return {{"shock_forms", c.formation.forms},
          {"breaks_on", c.formation.loading ? "rise" : "fall"},
          {"formation_distance_mm", c.formation.distance_m * 1e3},
          {"formation_time_us", c.formation.time_s * 1e6},
          {"breaking_compression", c.formation.compression},
          {"c_0_m_s", c.c_0_m_s},
          {"p_lo_MPa", c.p_lo_Pa * 1e-6},
          {"p_hi_MPa", c.p_hi_Pa * 1e-6},
          {"c_lo_m_s", c.c_lo_m_s},
          {"c_hi_m_s", c.c_hi_m_s},
          {"fronts", fronts},
          {"meet_distance_mm", num(c.meet_distance_m * 1e3)},
          {"meet_time_us", num(c.meet_time_s * 1e6)},
          {"measured_meet_distance_mm", num(c.measured_meet_distance_m * 1e3)},
          {"measured_meet_time_us", num(c.measured_meet_time_s * 1e6)},
          {"fitted_sensors", c.fitted_sensors},
          {"speed_level_MPa", c.speed_level_Pa * 1e-6},
          {"shock_speed_m_s", num(c.shock_speed_m_s)},
          {"jump_speed_m_s", c.jump_speed_m_s},
          {"shock_speed_over_jump", num(c.shock_speed_m_s / c.jump_speed_m_s)},
          {"bar_1d_spacing_mm", c.bar_spacing_m * 1e3},
          {"bar_1d_speed_m_s", num(c.bar_speed_m_s)},
          {"shock_speed_over_bar", num(c.shock_speed_m_s / c.bar_speed_m_s)}};
}

}  // namespace

WaveOutputs wave_strip_outputs(const WaveStripOptions& o, const WaveStripResult& r, const StripLaw* law,
                               const std::vector<double>& profile_s, const FemBarReference* fem) {
  WaveOutputs w;
  const DynamicsResult& d = r.run;
  nlohmann::ordered_json sensors = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < r.sensors.size(); ++k)
    sensors.push_back({{"name", r.sensors[k].name},
                       {"x_mm", r.sensors[k].x.x() * 1e3},
                       {"peak_time_us", r.peak_time_s[k] * 1e6},
                       {"expected_peak_time_us", (r.sensors[k].x.x() / r.c_p_m_s + r.pulse_peak_time_s) * 1e6},
                       {"peak_compression_MPa", r.peak_stress_Pa[k] * 1e-6}});
  nlohmann::ordered_json dispersion = nlohmann::ordered_json::array(), by_kh = nlohmann::ordered_json::object();
  const char* kh_names[] = {"pi_16", "pi_8", "pi_4", "pi_2", "pi"};
  int kh_index = 0;
  for (const DispersionPoint& p : stencil_dispersion(o, {M_PI / 16, M_PI / 8, M_PI / 4, M_PI / 2, M_PI}, d.dt_first_s)) {
    dispersion.push_back({{"kh", p.kh}, {"phase_speed_over_c_p", p.phase_speed_ratio}, {"with_time_step", p.with_time_step}});
    // the same keyed by k h (a table's column reads a key path, not an array index)
    by_kh[std::string("kh_") + kh_names[kh_index++]] = {{"phase_speed_over_c_p", p.phase_speed_ratio},
                                                         {"with_time_step", p.with_time_step}};
  }
  w.summary = {
      {"tool_summary", "explicit EFG wave in a strip (plane strain" + std::string(o.rollers ? ", rollers: uniaxial strain)" : ", free sides)")},
      {"nodes", r.nodes},
      {"gauss_points", r.points},
      {"steps", d.steps},
      {"t_end_us", d.t_end_s * 1e6},
      {"dt_us", d.dt_first_s * 1e6},
      {"dt_min_us", d.dt_min_s * 1e6},
      {"stable_dt_us", d.stable.dt_critical_s * 1e6},
      {"stable_dt_method", d.stable.method},
      {"lanczos_iterations", d.stable.iterations},
      {"max_modulus_scale", d.max_modulus_scale},
      {"energy_drift", d.energy_drift},
      {"external_work_J", d.energy.empty() ? 0.0 : d.energy.back().external_work_J},
      {"damping_work_J", d.energy.empty() ? 0.0 : d.energy.back().damping_J},
      {"viscosity", viscosity_summary(o.dynamics.viscosity, d)},
      {"max_constraint_violation_m", d.max_constraint_violation_m},
      {"P_modulus_GPa", r.P_modulus_Pa * 1e-9},
      {"c_p_m_s", r.c_p_m_s},
      {"peak_speed_m_s", r.peak_speed_m_s},
      {"peak_speed_error", r.peak_speed_error},
      {"sensors", sensors},
      {"stencil_dispersion", dispersion},
      {"stencil_dispersion_by_kh", by_kh},
      {"setup_s", r.setup_s},
      {"wall_s", d.wall_s},
      {"wall_per_step_us", d.steps > 0 ? d.wall_s / double(d.steps) * 1e6 : 0.0},
      {"threads_used", d.threads}};
  w.metrics = {{"c_p", r.c_p_m_s, "m/s"},       {"peak_speed_error", r.peak_speed_error, ""},
               {"energy_drift", d.energy_drift, ""}, {"dt", d.dt_first_s * 1e6, "us"},
               {"stable_dt", d.stable.dt_critical_s * 1e6, "us"}, {"wall", d.wall_s, "s"}};
  const bool linear = !law || !law->nonlinear;
  if (!linear && o.pulse == "triangular" && !o.custom && o.triangular.start_s == 0) {
    // the 1D bar of the same law: the shock speed's reference (shock_front.hpp), not for a law that unloads
    const BarShockSpeedOptions bar;
    const ShockFrontComparison c = compare_front_with_characteristics(o, r, *law->compression, law->unloads ? nullptr : &bar);
    w.summary["characteristics"] = front_json(c);
    w.front_header = {"sensor", "x_mm", "width_us", "simple_wave_width_us", "before_breaking"};
    const auto cell = [](double v) { return std::isfinite(v) ? format_significant(v, 4) : std::string(); };  // "": not reached
    for (std::size_t k = 0; k < c.fronts.size(); ++k)
      w.front_rows.push_back({r.sensors[k].name, format_significant(c.fronts[k].x_m * 1e3, 10), cell(c.fronts[k].width_s * 1e6),
                              format_significant(c.fronts[k].simple_wave_width_s * 1e6, 4),
                              c.fronts[k].before_breaking ? "yes" : "no"});
    w.metrics.emplace_back("formation_distance", w.summary["characteristics"]["formation_distance_mm"].get<double>(), "mm");
  }
  w.history_header = {"t_us"};
  for (const Sensor& s : r.sensors)
    for (const char* q : {"_sigma_xx_MPa", "_sigma_yy_MPa", "_v_x_m_s", "_v_y_m_s"}) w.history_header.push_back(s.name + q);
  // the linear law's closed form beside the run (the continuum the peak speed is measured against)
  if (linear)
    for (const Sensor& s : r.sensors) w.history_header.push_back(s.name + "_sigma_xx_continuum_MPa");
  if (fem) {
    nlohmann::ordered_json per_sensor = nlohmann::ordered_json::object();
    for (std::size_t k = 0; k < r.sensors.size(); ++k) {
      w.history_header.push_back(r.sensors[k].name + "_v_x_fem_m_s");
      w.history_header.push_back(r.sensors[k].name + "_v_x_continuum_m_s");
      per_sensor[r.sensors[k].name] = {{"x_mm", fem->sensor_x_m[k] * 1e3},
                                       {"efg_rms_error", fem->efg_error[k]},
                                       {"fem_rms_error", fem->fem_error[k]},
                                       {"efg_fem_rms_difference", fem->efg_fem_difference[k]}};
    }
    w.summary["fem_reference"] = {{"what", "mw-fem explicit (fem::run_explicit), one row of hexahedra, u_y = u_z held; v_x, "
                                           "rms over the record / the closed form's peak"},
                                  {"elements", fem->elements},
                                  {"dt_us", fem->dt_s * 1e6},
                                  {"wall_s", fem->wall_s},
                                  {"sensors", per_sensor}};
  }
  for (std::size_t i = 0; i < d.sample_t_s.size(); ++i) {
    std::vector<std::string> row{format_significant(d.sample_t_s[i] * 1e6, 10)};
    for (std::size_t k = 0; k < r.sensors.size(); ++k) {
      const SensorSample& s = d.sensors[k][i];
      row.push_back(format_significant(s.stress_Pa[0] * 1e-6, 10));
      row.push_back(format_significant(s.stress_Pa[1] * 1e-6, 10));
      row.push_back(format_significant(s.velocity_m_s[0], 10));
      row.push_back(format_significant(s.velocity_m_s[1], 10));
    }
    if (linear)
      for (const Sensor& s : r.sensors)
        row.push_back(format_significant(continuum_sigma_xx(o, r, s.x.x(), d.sample_t_s[i]) * 1e-6, 10));
    if (fem)
      for (std::size_t k = 0; k < r.sensors.size(); ++k) {
        const double v = fem->v_x_m_s[k][i];
        row.push_back(std::isfinite(v) ? format_significant(v, 10) : std::string());  // "": past the FEM's record
        row.push_back(format_significant(continuum_velocity_m_s(o, r.c_p_m_s, fem->sensor_x_m[k], d.sample_t_s[i]), 10));
      }
    w.history_rows.push_back(std::move(row));
  }
  if (!profile_s.empty()) {
    if (d.snapshots.empty()) throw InputError("--profiles: the run kept no snapshots (--snapshot-stride)");
    nlohmann::ordered_json taken = nlohmann::ordered_json::array();
    std::vector<const NodeSnapshot*> picked;
    w.profile_header = {"x_mm"};
    for (double t : profile_s) {
      std::size_t best = 0;
      for (std::size_t i = 1; i < d.snapshots.size(); ++i)
        if (std::abs(d.snapshots[i].first - t) < std::abs(d.snapshots[best].first - t)) best = i;
      picked.push_back(&d.snapshots[best].second);
      w.profile_header.push_back("p_MPa_at_" + format_significant(t * 1e6, 9) + "us");  // 30, not 30.000000000000004
      taken.push_back({{"requested_us", t * 1e6}, {"snapshot_us", d.snapshots[best].first * 1e6}});
    }
    w.summary["profiles"] = taken;
    // the node row nearest the centre line, in x order (the grid's nodes run x fastest or y
    // fastest: sorting by x makes the file the same either way)
    const NodeSnapshot& first = *picked.front();
    double y_row = first.positions_m.at(0).y();
    for (const auto& x : first.positions_m)
      if (std::abs(x.y() - 0.5 * o.width_m) < std::abs(y_row - 0.5 * o.width_m)) y_row = x.y();
    std::vector<std::size_t> row_nodes;
    for (std::size_t n = 0; n < first.positions_m.size(); ++n)
      if (std::abs(first.positions_m[n].y() - y_row) < 1e-9 * o.width_m) row_nodes.push_back(n);
    std::sort(row_nodes.begin(), row_nodes.end(),
              [&](std::size_t a, std::size_t b) { return first.positions_m[a].x() < first.positions_m[b].x(); });
    for (std::size_t n : row_nodes) {
      std::vector<std::string> row{format_significant(first.positions_m[n].x() * 1e3, 10)};
      for (const NodeSnapshot* s : picked) row.push_back(format_significant(-s->stress_Pa.at(n)(0) * 1e-6, 10));
      w.profile_rows.push_back(std::move(row));
    }
  }
  return w;
}

}  // namespace mesowave::efg
