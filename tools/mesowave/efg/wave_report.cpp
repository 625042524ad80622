#include "mesowave/efg/wave_report.hpp"

#include <cmath>

#include "mesowave/core/check.hpp"

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
  o.triangular = {peak_MPa * 1e6, rise_us * 1e-6, fall_us * 1e-6, start_us * 1e-6};
  o.friedlander = {peak_MPa * 1e6, positive_us * 1e-6, decay, start_us * 1e-6};
  for (double x : sensor_mm) o.sensor_x_m.push_back(x * 1e-3);
  if (!std::isfinite(duration_us) || duration_us < 0)
    throw InputError("--duration-us (" + format_number(duration_us) + ") must be >= 0 (0: the wave to the far end and 10 % more)");
  o.dynamics.duration_s = duration_us * 1e-6;
  o.dynamics.dt_s = dt_us * 1e-6;
  o.dynamics.dt_fraction = dt_fraction;
  o.dynamics.alpha_damping_per_s = alpha_per_s;
  o.dynamics.stiffness_check_every = stiffness_check_every;
  o.dynamics.sample_stride = sample_stride;
  o.dynamics.snapshot_stride = !snapshots.empty() && snapshot_stride == 0 ? 50 : snapshot_stride;
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
                                     "--positive-us, --decay)")->capture_default_str();
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
}

WaveOutputs wave_strip_outputs(const WaveStripOptions& o, const WaveStripResult& r) {
  WaveOutputs w;
  const DynamicsResult& d = r.run;
  nlohmann::ordered_json sensors = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < r.sensors.size(); ++k)
    sensors.push_back({{"name", r.sensors[k].name},
                       {"x_mm", r.sensors[k].x.x() * 1e3},
                       {"peak_time_us", r.peak_time_s[k] * 1e6},
                       {"expected_peak_time_us", (r.sensors[k].x.x() / r.c_p_m_s + r.pulse_peak_time_s) * 1e6},
                       {"peak_compression_MPa", r.peak_stress_Pa[k] * 1e-6}});
  nlohmann::ordered_json dispersion = nlohmann::ordered_json::array();
  for (const DispersionPoint& p : stencil_dispersion(o, {M_PI / 16, M_PI / 8, M_PI / 4, M_PI / 2, M_PI}, d.dt_first_s))
    dispersion.push_back({{"kh", p.kh}, {"phase_speed_over_c_p", p.phase_speed_ratio}, {"with_time_step", p.with_time_step}});
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
      {"max_constraint_violation_m", d.max_constraint_violation_m},
      {"P_modulus_GPa", r.P_modulus_Pa * 1e-9},
      {"c_p_m_s", r.c_p_m_s},
      {"peak_speed_m_s", r.peak_speed_m_s},
      {"peak_speed_error", r.peak_speed_error},
      {"sensors", sensors},
      {"stencil_dispersion", dispersion},
      {"setup_s", r.setup_s},
      {"wall_s", d.wall_s},
      {"wall_per_step_us", d.steps > 0 ? d.wall_s / double(d.steps) * 1e6 : 0.0},
      {"threads_used", d.threads}};
  w.metrics = {{"c_p", r.c_p_m_s, "m/s"},       {"peak_speed_error", r.peak_speed_error, ""},
               {"energy_drift", d.energy_drift, ""}, {"dt", d.dt_first_s * 1e6, "us"},
               {"stable_dt", d.stable.dt_critical_s * 1e6, "us"}, {"wall", d.wall_s, "s"}};
  w.history_header = {"t_us"};
  for (const Sensor& s : r.sensors)
    for (const char* q : {"_sigma_xx_MPa", "_sigma_yy_MPa", "_v_x_m_s", "_v_y_m_s"}) w.history_header.push_back(s.name + q);
  for (std::size_t i = 0; i < d.sample_t_s.size(); ++i) {
    std::vector<std::string> row{format_significant(d.sample_t_s[i] * 1e6, 10)};
    for (std::size_t k = 0; k < r.sensors.size(); ++k) {
      const SensorSample& s = d.sensors[k][i];
      row.push_back(format_significant(s.stress_Pa[0] * 1e-6, 10));
      row.push_back(format_significant(s.stress_Pa[1] * 1e-6, 10));
      row.push_back(format_significant(s.velocity_m_s[0], 10));
      row.push_back(format_significant(s.velocity_m_s[1], 10));
    }
    w.history_rows.push_back(std::move(row));
  }
  return w;
}

}  // namespace mesowave::efg
