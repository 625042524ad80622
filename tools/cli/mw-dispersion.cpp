// mw-dispersion - dispersion curves of the steel-rod study (rod paper
// Section 2.1, Figure 9, Table 2).
//
//   mw-dispersion theory --E-GPa 208.72 --nu 0.3 --density-kg-m3 7850.66 --radius-mm 5.1
//       --f-max-kHz 500 --csv pc.csv --plot pc.png
//   mw-dispersion lattice --sphere-radius-mm 5.1 --particle-density-kg-m3 6044.37
//       --E-dem-GPa 660 --spacing-R 1.03 --csv chain103.csv
//   mw-dispersion measure --run fem50.h5 ... --method echo --distance-mm 2000 --E-GPa 208.72 ...
//   mw-dispersion bar-echo --record shpb.csv --column incident_bar_signal --path-mm 2036 ...
//
// theory: longitudinal modes L(0,n) of a solid rod from the Pochhammer-Chree
// equation (phase and group velocity, backward-wave branches with negative
// group velocity). lattice: the exact dispersion of the DEM chain (masses on
// springs), omega = 2 sqrt(K/m) |sin(k d/2)|. measure: group velocity of burst
// runs from Hilbert-envelope arrivals (or a space-time 2D FFT) and the RSS
// against theory (rod Table 2). bar-echo: bar velocity from a pulse-echo record.
#include <optional>

#include "mesowave/app/tool.hpp"
#include "mesowave/core/check.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/io/csv.hpp"
#include "mesowave/io/signal_csv.hpp"
#include "mesowave/io/signal_file.hpp"
#include "mesowave/wave/bar_echo.hpp"
#include "mesowave/wave/dispersion_output.hpp"

using namespace mesowave;
namespace fs = std::filesystem;

int main(int argc, char** argv) {
  app::Tool tool(
      "mw-dispersion",
      "Dispersion of longitudinal waves in a rod: Pochhammer-Chree theory and the DEM chain lattice.\n\n"
      "theory: roots of the Pochhammer-Chree frequency equation (rod paper Eq. 1)\n"
      "  (2a/r)(b^2+k^2) J1(ar) J1(br) - (b^2-k^2)^2 J0(ar) J1(br) - 4 k^2 a b J1(ar) J0(br) = 0,\n"
      "  a^2 = w^2/cP^2 - k^2, b^2 = w^2/cS^2 - k^2 (r the radius; modified Bessel functions where a^2 or\n"
      "  b^2 < 0), traced in wavenumber from each k = 0 cut-off; group velocity c_g = dw/dk = -F_k/F_w.\n"
      "  Rows per mode L(0,n) and branch; a backward-wave branch (c_g < 0) is reported beside the forward one.\n"
      "lattice: the DEM chain of spheres on bonds, w = 2 sqrt(K/m) |sin(k d/2)|, c_g = d sqrt(K/m) cos(k d/2).\n"
      "measure: group velocity at each burst centre frequency from Hilbert-envelope peaks (echo: two packets at\n"
      "  one sensor 2 L apart, the rod paper's peak to peak; two-stations; source), or from the ridge of the 2D FFT of\n"
      "  a space-time record; RSS = sum (c_measured - c_theory)^2 over a band (rod Table 2).\n"
      "bar-echo: bar velocity from a long pulse and its echo at one gauge (Hopkinson bar): onset and edge picks, and\n"
      "  the c0 for which the Pochhammer-Chree-propagated pulse's edges meet the echo's.\n\n"
      "  mw-dispersion theory --E-GPa 208.72 --nu 0.3 --density-kg-m3 7850.66 --radius-mm 5.1 --csv pc.csv --plot "
      "pc.png\n"
      "  mw-dispersion lattice --sphere-radius-mm 5.1 --particle-density-kg-m3 6044.37 --E-dem-GPa 660 "
      "--spacing-R 1.03 --csv chain.csv\n"
      "  mw-dispersion theory ... --overlay 1.03R=chain.csv --plot figure9.png\n"
      "  mw-dispersion measure --run fem50.h5 --run fem100.h5 --method echo --distance-mm 2000 --E-GPa 208.72 --nu 0.3 "
      "--density-kg-m3 7850.66 --radius-mm 5.1 --band-kHz 50,150\n"
      "  mw-dispersion bar-echo --record shpb.csv --column incident_bar_signal --path-mm 2036 --E-GPa 210 --nu 0.3 "
      "--density-kg-m3 7800 --radius-mm 10");
  auto& cli = tool.cli();
  cli.require_subcommand(1);

  // theory
  auto* theory = cli.add_subcommand("theory", "Pochhammer-Chree longitudinal modes of a solid rod");
  double E_GPa = 0, nu = 0, rho = 0, radius_mm = 0, f_max_kHz = 500, df_kHz = 1;
  std::optional<double> f_min_kHz;
  double ka_step = 0.01;
  int max_modes = 0;
  fs::path csv, h5, plot, out;
  std::vector<std::string> overlays;
  theory->add_option("--E-GPa", E_GPa, "Young's modulus [GPa]")->required();
  theory->add_option("--nu", nu, "Poisson ratio (-1 < nu < 0.5)")->required();
  theory->add_option("--density-kg-m3", rho, "Density [kg/m3]")->required();
  theory->add_option("--radius-mm", radius_mm, "Rod radius [mm]")->required();
  theory->add_option("--f-max-kHz", f_max_kHz, "Highest frequency [kHz]")->capture_default_str();
  theory->add_option("--f-min-kHz", f_min_kHz, "Lowest frequency of the table [kHz] (default: the step)");
  theory->add_option("--df-kHz", df_kHz, "Frequency step of the table [kHz]")->capture_default_str();
  theory->add_option("--ka-step", ka_step, "Tracing step in k a (halved automatically where needed)")
      ->capture_default_str();
  theory->add_option("--modes", max_modes, "Only the first N modes (0: every mode below --f-max-kHz)")
      ->capture_default_str();
  theory->add_option("--csv", csv, "Table: mode, branch, direction, f_kHz, k_rad_m, ka, c_phase_m_s, c_group_m_s");
  theory->add_option("--h5", h5, "The same table in HDF5 (/theory)");
  theory->add_option("--plot", plot, "Group velocity against frequency (.png or .svg)");
  theory->add_option("--overlay", overlays,
                     "LABEL=FILE.csv: add a curve (columns f_kHz, c_group_m_s; e.g. a lattice or measure table) to "
                     "the plot; repeatable");
  std::string plot_f_range, plot_c_range, plot_key = "outside right top";
  theory->add_option("--plot-f-range-kHz", plot_f_range, "LO,HI: frequency axis of the plot [kHz]");
  theory->add_option("--plot-c-range-m-s", plot_c_range, "LO,HI: velocity axis of the plot [m/s]");
  theory->add_option("--plot-key", plot_key, "Where the legend goes (gnuplot words, spaces or commas: inside,bottom,left)")
      ->capture_default_str();
  app::add_out_option(*theory, out, "the JSON summary");

  // lattice
  auto* lattice = cli.add_subcommand("lattice", "Exact dispersion of the DEM chain (1D mass-spring lattice)");
  std::optional<double> mass_kg, stiffness, spacing_mm, sphere_mm, rho_p, E_dem_GPa, spacing_R;
  double l_f_max_kHz = 500, l_df_kHz = 1;
  std::string label = "chain";
  fs::path l_csv, l_out;
  lattice->add_option("--mass-kg", mass_kg, "Particle mass m [kg]");
  lattice->add_option("--stiffness-N-m", stiffness, "Bond stiffness K [N/m]");
  lattice->add_option("--spacing-mm", spacing_mm, "Distance d between particle centres [mm]");
  lattice->add_option("--sphere-radius-mm", sphere_mm, "Sphere radius R [mm] (m = rho_p 4/3 pi R^3, K = E_dem R)");
  lattice->add_option("--particle-density-kg-m3", rho_p, "Particle density rho_p [kg/m3] (rod Table 1)");
  lattice->add_option("--E-dem-GPa", E_dem_GPa, "Contact modulus E_dem [GPa] (the K_n column of rod Table 1)");
  lattice->add_option("--spacing-R", spacing_R, "Spacing d as a multiple of the sphere radius (1.03 for 1.03R)");
  lattice->add_option("--f-max-kHz", l_f_max_kHz, "Highest frequency [kHz]")->capture_default_str();
  lattice->add_option("--df-kHz", l_df_kHz, "Frequency step [kHz]")->capture_default_str();
  lattice->add_option("--label", label, "Name of the model in the table")->capture_default_str();
  lattice->add_option("--csv", l_csv, "Table: model, f_kHz, k_rad_m, kd, c_phase_m_s, c_group_m_s");
  app::add_out_option(*lattice, l_out, "the JSON summary");

  // measure
  auto* measure = cli.add_subcommand("measure", "Group velocity of simulated or measured signals, RSS against theory");
  std::vector<std::string> runs, stations;
  std::string method = "echo", band_text, m_label;
  double m_distance_mm = 0, m_cycles = 5, m_f_min_kHz = 10, m_f_max_kHz = 300;
  std::optional<double> m_E, m_nu, m_rho, m_radius;
  fs::path m_theory_csv, m_csv, m_out, m_spacetime;
  measure->add_option("--run", runs,
                      "A burst run: FILE (an mw-fem signal file, which records its burst frequency) or "
                      "FREQ_kHz=FILE; repeatable, one per centre frequency");
  measure->add_option("--spacetime", m_spacetime, "A space-time record (mw-fem rod --spacetime): 2D FFT ridge instead");
  measure->add_option("--method", method,
                      "echo: two successive packets at one station, distance = round trip (2 L; the rod paper's "
                      "peak to peak); two-stations: first packets at two stations; source: burst centre to first "
                      "packet")
      ->capture_default_str();
  measure->add_option("--station", stations, "Signal name(s) to use (one, or two for two-stations)");
  measure->add_option("--distance-mm", m_distance_mm,
                      "Path length [mm] (echo: the round trip; two-stations: default from the positions)");
  measure->add_option("--cycles", m_cycles, "Cycles in the bursts")->capture_default_str();
  measure->add_option("--E-GPa", m_E, "Theory: Young's modulus [GPa]");
  measure->add_option("--nu", m_nu, "Theory: Poisson ratio");
  measure->add_option("--density-kg-m3", m_rho, "Theory: density [kg/m3]");
  measure->add_option("--radius-mm", m_radius, "Theory: rod radius [mm]");
  measure->add_option("--theory-csv", m_theory_csv, "Theory: a table from mw-dispersion theory --csv instead");
  measure->add_option("--band-kHz", band_text, "LO,HI: frequency band of the RSS [kHz] (default: every point)");
  measure->add_option("--f-min-kHz", m_f_min_kHz, "Space-time ridge: lowest frequency [kHz]")->capture_default_str();
  measure->add_option("--f-max-kHz", m_f_max_kHz, "Space-time ridge: highest frequency [kHz]")->capture_default_str();
  measure->add_option("--label", m_label, "Name of the model in the table (default: the file names)");
  measure->add_option("--csv", m_csv, "Table: run, f_kHz, method, t1_us, t2_us, distance_mm, c_group_m_s, "
                                      "theory_c_group_m_s, residual_m_s, in_band");
  app::add_out_option(*measure, m_out, "the JSON summary (RSS)");

  // bar-echo
  auto* bar = cli.add_subcommand("bar-echo",
                                 "Bar velocity from a pulse and its echo at one gauge (split Hopkinson bar record)");
  std::string b_column;
  fs::path b_record, b_csv, b_out;
  double b_path_mm = 0, b_path_unc_mm = 0;
  std::optional<double> b_E, b_nu, b_rho, b_radius;
  bar->add_option("--record", b_record,
                  "Signal file (HDF5 or mesowave CSV) or a plain CSV table whose first column is time in s "
                  "(printed with few digits is fine: the time base is rebuilt)")
      ->required();
  bar->add_option("--column", b_column, "Column (CSV; the header up to '/' is enough) or signal name")->required();
  bar->add_option("--path-mm", b_path_mm, "Round-trip path between the two passes [mm] (2 x gauge to bar end)")
      ->required();
  bar->add_option("--path-uncertainty-mm", b_path_unc_mm, "Standard uncertainty of that path [mm]")
      ->capture_default_str();
  bar->add_option("--E-GPa", b_E, "Bar Young's modulus [GPa] (for c0 and theory)");
  bar->add_option("--nu", b_nu, "Bar Poisson ratio (for theory)");
  bar->add_option("--density-kg-m3", b_rho, "Bar density [kg/m3]");
  bar->add_option("--radius-mm", b_radius, "Bar radius [mm] (for theory)");
  bar->add_option("--csv", b_csv, "Table of the picks: method, t1_us, t2_us, delay_us, c_m_s");
  fs::path b_signals;
  bar->add_option("--signals", b_signals,
                  "Write the record and the theory's echo (needs the material) as a signal file (.h5 or .csv)");
  app::add_out_option(*bar, b_out, "the JSON result");

  return tool.run(argc, argv, [&](app::Run& run) {
    if (bar->parsed()) {
      run.input(b_record);
      const auto record = wave::read_record(b_record, b_column);
      wave::BarEchoOptions bo;
      bo.path_m = require_positive("--path-mm", b_path_mm, "mm") * units::mm;
      std::optional<wave::PochhammerChree> pc;
      if (b_E && b_nu && b_rho && b_radius) {
        pc.emplace(wave::IsotropicMaterial{*b_E * units::GPa, *b_nu, *b_rho}, *b_radius * units::mm);
        bo.theory = &*pc;
      }
      const auto r = wave::analyse_bar_echo(record, bo);
      nlohmann::ordered_json j;
      j["record"] = b_record.filename().string();
      j["samples"] = record.size();
      j["dt_ns"] = record.dt_s / units::ns;
      j["path_mm"] = b_path_mm;
      auto picks = nlohmann::ordered_json::array();
      std::vector<std::vector<std::string>> rows;
      // The pulse front (onset pickers) travels at the bar's low-frequency velocity; the
      // edge crossings lag more the higher the level as dispersion widens the front.
      double sum = 0, lo = 1e300, hi = 0, delay = 0;
      int onsets = 0;
      for (const auto& p : r.picks) {
        picks.push_back({{"method", p.method}, {"t1_us", p.t1_s / units::us}, {"t2_us", p.t2_s / units::us},
                         {"delay_us", (p.t2_s - p.t1_s) / units::us}, {"c_m_s", p.velocity_m_s}});
        rows.push_back({p.method, format_exact(p.t1_s / units::us), format_exact(p.t2_s / units::us),
                        format_exact((p.t2_s - p.t1_s) / units::us), format_exact(p.velocity_m_s)});
        if (p.method == "threshold" || p.method == "aic") {
          sum += p.velocity_m_s;
          delay += (p.t2_s - p.t1_s) / 2;
          lo = std::min(lo, p.velocity_m_s);
          hi = std::max(hi, p.velocity_m_s);
          ++onsets;
        }
      }
      const double primary = sum / onsets;
      j["picks"] = picks;
      // Uncertainty: half the spread of the two onset pickers, half a sample on each of
      // the two times, and the path's own; combined in quadrature.
      const double u_method = 0.5 * (hi - lo) / primary;
      const double u_time = std::sqrt(0.5) * record.dt_s / delay;
      const double u_path = b_path_unc_mm / b_path_mm;
      j["velocity_m_s"] = primary;
      j["velocity_method"] = "pulse front: mean of the threshold and AIC onset picks (a dispersed front rises "
                             "ahead of z/c0, so this reads high by up to ~1 %)";
      j["relative_uncertainty_method"] = u_method;
      j["relative_uncertainty_sampling"] = u_time;
      j["relative_uncertainty_path"] = u_path;
      j["velocity_uncertainty_m_s"] = primary * std::sqrt(u_method * u_method + u_time * u_time + u_path * u_path);
      if (r.fitted_c0_m_s > 0) {
        // The dispersion-corrected bar velocity: Pochhammer-Chree edges matched to the echo's.
        const double u = std::sqrt(r.fitted_c0_relative_spread * r.fitted_c0_relative_spread + u_time * u_time +
                                   u_path * u_path);
        j["fitted_c0_m_s"] = r.fitted_c0_m_s;
        j["fitted_c0_uncertainty_m_s"] = r.fitted_c0_m_s * u;
        j["fitted_c0_method"] = "c0 for which the Pochhammer-Chree echo's edges (0.25/0.5/0.75) meet the measured ones";
        run.metric("fitted bar velocity c0", r.fitted_c0_m_s, "m/s");
      }
      j["echo_over_pulse_amplitude"] = r.second_pulse_extreme / r.first_pulse_extreme;
      j["f50_kHz"] = r.f50_Hz / units::kHz;
      j["f90_kHz"] = r.f90_Hz / units::kHz;
      if (b_E && b_rho) {
        const double c0 = std::sqrt(*b_E * units::GPa / *b_rho);
        j["c0_m_s"] = c0;
        j["velocity_over_c0"] = primary / c0;
        if (pc) {
          const auto cg = wave::l01_group_velocity(*pc, {r.f50_Hz, r.f90_Hz});
          j["theory_c_group_at_f50_m_s"] = cg[0];
          j["theory_c_group_at_f90_m_s"] = cg[1];
        }
      }
      run.metric("bar velocity", primary, "m/s");
      if (!b_csv.empty()) run.write_text(b_csv, io::to_csv({"method", "t1_us", "t2_us", "delay_us", "c_m_s"}, rows));
      if (!b_signals.empty()) {
        if (!pc) throw InputError("--signals needs the bar's --E-GPa, --nu, --density-kg-m3 and --radius-mm");
        io::write_signals(run.output(b_signals), io::signal_format_of(b_signals), {record, r.theory_echo});
      }
      run.emit_json(j, b_out);
    } else if (measure->parsed()) {
      std::vector<wave::GroupVelocityPoint> points;
      if (!m_spacetime.empty()) {
        if (!runs.empty()) throw InputError("give either --run files or --spacetime, not both");
        run.input(m_spacetime);
        const auto ridge = wave::spacetime_ridge(wave::read_spacetime_file(m_spacetime), m_f_min_kHz * units::kHz,
                                                 m_f_max_kHz * units::kHz);
        for (const auto& r : ridge)
          points.push_back({m_label.empty() ? m_spacetime.filename().string() : m_label, r.f_Hz, "spacetime", 0, 0, 0,
                            r.c_group_m_s});
      } else {
        if (runs.empty()) throw InputError("give at least one --run FILE (or FREQ_kHz=FILE) or --spacetime FILE");
        wave::MeasureRequest req{method, stations.empty() ? std::vector<std::string>{"S"} : stations,
                                 m_distance_mm * units::mm, m_cycles};
        if (m_distance_mm < 0) throw InputError("--distance-mm must not be negative");
        for (const auto& r : runs) {
          const auto eq = r.find('=');
          fs::path file = eq == std::string::npos ? fs::path(r) : fs::path(r.substr(eq + 1));
          run.input(file);
          double f = 0;
          if (eq != std::string::npos) {
            f = std::stod(r.substr(0, eq)) * units::kHz;
          } else {
            const auto a = wave::signal_file_attribute(file, "burst_frequency_Hz");
            if (!a) throw InputError(file.string() + " does not record its burst frequency: give FREQ_kHz=" + r);
            f = std::stod(*a);
          }
          auto p = wave::measure_run(io::read_signals(file), f, req);
          p.run = m_label.empty() ? file.filename().string() : m_label;
          points.push_back(p);
        }
      }
      std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) { return a.f_Hz < b.f_Hz; });
      std::function<double(double)> theory;
      const bool material = m_E || m_nu || m_rho || m_radius;
      if (material && !m_theory_csv.empty()) throw InputError("give either the material or --theory-csv, not both");
      if (material) {
        if (!m_E || !m_nu || !m_rho || !m_radius)
          throw InputError("theory needs --E-GPa, --nu, --density-kg-m3 and --radius-mm together");
        const wave::PochhammerChree pc({require_positive("--E-GPa", *m_E, "GPa") * units::GPa, *m_nu, *m_rho},
                                       require_positive("--radius-mm", *m_radius, "mm") * units::mm);
        std::vector<double> fs_;
        for (const auto& p : points) fs_.push_back(p.f_Hz);
        const auto cg = wave::l01_group_velocity(pc, fs_);
        theory = [fs_, cg](double f) {
          for (std::size_t i = 0; i < fs_.size(); ++i)
            if (fs_[i] == f) return cg[i];
          return 0.0;
        };
      } else if (!m_theory_csv.empty()) {
        run.input(m_theory_csv);
        theory = wave::theory_from_csv(m_theory_csv);
      }
      double lo = points.empty() ? 0 : points.front().f_Hz, hi = points.empty() ? 0 : points.back().f_Hz;
      if (!band_text.empty()) {
        const auto comma = band_text.find(',');
        if (comma == std::string::npos) throw InputError("--band-kHz must read LO,HI");
        lo = std::stod(band_text.substr(0, comma)) * units::kHz;
        hi = std::stod(band_text.substr(comma + 1)) * units::kHz;
      }
      nlohmann::ordered_json j;
      j["points"] = points.size();
      std::optional<wave::ResidualSummary> rss;
      if (theory) {
        rss = wave::residual_sum_of_squares(points, theory, lo, hi);
        j["band_kHz"] = {lo / units::kHz, hi / units::kHz};
        j["points_in_band"] = rss->points;
        j["rss_m2_s2"] = rss->rss_m2_s2;
        j["rms_m_s"] = rss->rms_m_s;
        j["max_abs_residual_m_s"] = rss->max_abs_m_s;
        run.metric("RSS", rss->rss_m2_s2, "m^2/s^2");
      }
      std::vector<std::vector<std::string>> rows;
      auto list = nlohmann::ordered_json::array();
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
      if (!m_csv.empty())
        run.write_text(m_csv, io::to_csv({"run", "f_kHz", "method", "t1_us", "t2_us", "distance_mm", "c_group_m_s",
                                          "theory_c_group_m_s", "residual_m_s", "in_band"},
                                         rows));
      run.emit_json(j, m_out);
    } else if (theory->parsed()) {
      if (!plot.empty()) wave::require_plot_extension(plot);
      const wave::IsotropicMaterial material{require_positive("--E-GPa", E_GPa, "GPa") * units::GPa, nu, rho};
      wave::validate(material);
      const wave::PochhammerChree pc(material, require_positive("--radius-mm", radius_mm, "mm") * units::mm);
      wave::TraceOptions opt;
      opt.f_max_Hz = require_positive("--f-max-kHz", f_max_kHz, "kHz") * units::kHz;
      opt.ka_step = require_positive("--ka-step", ka_step);
      if (max_modes < 0) throw InputError("--modes (" + std::to_string(max_modes) + ") must not be negative");
      std::vector<wave::VelocityCurve> curves;
      for (const auto& o : overlays) {
        const auto eq = o.rfind('=');  // the label may hold '=' itself
        if (eq == std::string::npos || eq == 0)
          throw InputError("--overlay " + o + " must read LABEL=FILE.csv");
        run.input(o.substr(eq + 1));
        curves.push_back(wave::read_velocity_curve(o.substr(eq + 1), o.substr(0, eq)));
      }
      auto trace = wave::trace_longitudinal_modes(pc, opt);
      if (max_modes > 0)
        std::erase_if(trace.modes, [&](const wave::ModeCurve& c) { return c.mode > max_modes; });
      const auto grid = wave::frequency_grid(f_min_kHz.value_or(df_kHz) * units::kHz, opt.f_max_Hz, df_kHz * units::kHz);
      const auto points = wave::sample_at_frequencies(pc, trace, grid);

      if (!csv.empty()) run.write_text(csv, wave::theory_csv(points, pc.radius_m()));
      if (!h5.empty()) wave::write_dispersion_h5(run.output(h5), pc, points);
      if (!plot.empty()) {
        auto spec = wave::group_velocity_plot("Pochhammer-Chree, radius " + format_number(radius_mm) + " mm, nu = " +
                                                  format_number(nu),
                                              points, {}, curves);
        const auto range = [](const std::string& text, const char* what) -> std::optional<std::pair<double, double>> {
          if (text.empty()) return std::nullopt;
          const auto comma = text.find(',');
          if (comma == std::string::npos) throw InputError(std::string(what) + " must read LO,HI");
          return std::make_pair(std::stod(text.substr(0, comma)), std::stod(text.substr(comma + 1)));
        };
        spec.x_range = range(plot_f_range, "--plot-f-range-kHz");
        spec.y_range = range(plot_c_range, "--plot-c-range-m-s");
        for (char c : plot_key)
          if (!std::isalnum(static_cast<unsigned char>(c)) && c != ' ' && c != ',' && c != '.')
            throw InputError("--plot-key '" + plot_key + "' may hold only words and numbers");
        spec.key = plot_key;
        std::replace(spec.key.begin(), spec.key.end(), ',', ' ');  // "inside,bottom,left" reads as words
        wave::render_plot(spec, plot, run.output(plot));
      }
      auto summary = wave::theory_summary(pc, trace);
      summary["rows"] = points.size();
      for (const auto& m : summary["modes"])
        if (m["cutoff_kHz"].get<double>() > 0) run.metric(m["mode"].get<std::string>() + " cut-off", m["cutoff_kHz"], "kHz");
      run.metric("c0", pc.speeds().c0, "m/s");
      if (summary.contains("L01_min_group_velocity_m_s"))
        run.metric("L(0,1) min group velocity", summary["L01_min_group_velocity_m_s"], "m/s");
      run.emit_json(summary, out);
    } else {
      wave::MassSpringChain chain;
      const bool direct = mass_kg || stiffness;
      const bool dem = sphere_mm || rho_p || E_dem_GPa || spacing_R;
      if (direct && dem) throw InputError("give either --mass-kg/--stiffness-N-m or the sphere description, not both");
      if (direct) {
        if (!mass_kg || !stiffness || !spacing_mm)
          throw InputError("--mass-kg, --stiffness-N-m and --spacing-mm are needed together");
        chain = {*mass_kg, *stiffness, *spacing_mm * units::mm};
      } else {
        if (!sphere_mm || !rho_p || !E_dem_GPa)
          throw InputError("need --sphere-radius-mm, --particle-density-kg-m3 and --E-dem-GPa "
                           "(or --mass-kg, --stiffness-N-m, --spacing-mm)");
        if (spacing_mm.has_value() == spacing_R.has_value())
          throw InputError("give exactly one of --spacing-mm and --spacing-R");
        const double R = require_positive("--sphere-radius-mm", *sphere_mm, "mm") * units::mm;
        const double d = spacing_mm ? *spacing_mm * units::mm : require_positive("--spacing-R", *spacing_R) * R;
        chain = wave::dem_chain(R, *rho_p, require_positive("--E-dem-GPa", *E_dem_GPa, "GPa") * units::GPa, d);
      }
      wave::validate(chain);
      const auto grid = wave::frequency_grid(l_df_kHz * units::kHz, l_f_max_kHz * units::kHz, l_df_kHz * units::kHz);
      const auto curve = wave::lattice_curve(label, chain, grid);
      if (!l_csv.empty()) run.write_text(l_csv, wave::lattice_csv(curve));
      nlohmann::ordered_json j;
      j["model"] = label;
      j["mass_kg"] = chain.mass_kg;
      j["stiffness_N_m"] = chain.stiffness_N_m;
      j["spacing_mm"] = chain.spacing_m / units::mm;
      j["long_wave_speed_m_s"] = wave::long_wave_speed(chain);
      j["cutoff_kHz"] = wave::cutoff_omega(chain) / (2 * std::numbers::pi) / units::kHz;
      j["rows"] = curve.points.size();
      run.metric("long-wave speed", j["long_wave_speed_m_s"], "m/s");
      run.metric("lattice cut-off", j["cutoff_kHz"], "kHz");
      run.emit_json(j, l_out);
    }
  });
}
