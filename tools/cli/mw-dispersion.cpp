// mw-dispersion - dispersion of longitudinal waves in the steel-rod study (rod
// paper Section 2.1, Figure 9, Table 2): Pochhammer-Chree theory, the DEM chain
// lattice, measured group velocities with their RSS, and the bar-echo velocity.
// The analyses and what they report live in wave/dispersion_report.
#include "mesowave/app/tool.hpp"
#include "mesowave/signal/signal_csv.hpp"
#include "mesowave/wave/dispersion_report.hpp"

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
  fs::path csv, h5, signals, out;
  // The rod's material and radius: `what` says what they serve.
  const auto add_rod = [](CLI::App* sub, wave::RodOptions& rod, const std::string& what) {
    sub->add_option("--E-GPa", rod.E_GPa, what + "Young's modulus [GPa]");
    sub->add_option("--nu", rod.nu, what + "Poisson ratio (-1 < nu < 0.5)");
    sub->add_option("--density-kg-m3", rod.density_kg_m3, what + "density [kg/m3]");
    sub->add_option("--radius-mm", rod.radius_mm, what + "radius [mm]");
    sub->add_option("--experiment", rod.experiment, what + "the four not given from the experiment's rod (lab-data TOML)");
  };

  auto* theory = cli.add_subcommand("theory", "Pochhammer-Chree longitudinal modes of a solid rod");
  wave::TheoryRequest tq;
  add_rod(theory, tq.rod, "Rod: ");
  theory->add_option("--f-max-kHz", tq.f_max_kHz, "Highest frequency [kHz]")->capture_default_str();
  theory->add_option("--f-min-kHz", tq.f_min_kHz, "Lowest frequency of the table [kHz] (default: the step)");
  theory->add_option("--df-kHz", tq.df_kHz, "Frequency step of the table [kHz]")->capture_default_str();
  theory->add_option("--ka-step", tq.ka_step, "Tracing step in k a (halved automatically where needed)")
      ->capture_default_str();
  theory->add_option("--modes", tq.max_modes, "Only the first N modes (0: every mode below --f-max-kHz)")
      ->capture_default_str();
  theory->add_option("--csv", csv, "Table: mode, branch, direction, f_kHz, k_rad_m, ka, c_phase_m_s, c_group_m_s");
  theory->add_option("--h5", h5, "The same table in HDF5 (/theory)");
  theory->add_option("--plot", tq.plot, "Group velocity against frequency (.png or .svg)");
  theory->add_option("--overlay", tq.overlays,
                     "LABEL=FILE.csv: add a curve (columns f_kHz, c_group_m_s; e.g. a lattice or measure table) to "
                     "the plot; repeatable");
  theory->add_option("--plot-f-range-kHz", tq.plot_f_range, "LO,HI: frequency axis of the plot [kHz]");
  theory->add_option("--plot-c-range-m-s", tq.plot_c_range, "LO,HI: velocity axis of the plot [m/s]");
  theory->add_option("--plot-key", tq.plot_key, "Where the legend goes (gnuplot words, spaces or commas: inside,bottom,left)")
      ->capture_default_str();
  app::add_out_option(*theory, out, "the JSON summary");

  auto* lattice = cli.add_subcommand("lattice", "Exact dispersion of the DEM chain (1D mass-spring lattice)");
  wave::LatticeRequest lq;
  lattice->add_option("--mass-kg", lq.mass_kg, "Particle mass m [kg]");
  lattice->add_option("--stiffness-N-m", lq.stiffness_N_m, "Bond stiffness K [N/m]");
  lattice->add_option("--spacing-mm", lq.spacing_mm, "Distance d between particle centres [mm]");
  lattice->add_option("--sphere-radius-mm", lq.sphere_radius_mm, "Sphere radius R [mm] (m = rho_p 4/3 pi R^3, K = E_dem R)");
  lattice->add_option("--particle-density-kg-m3", lq.particle_density_kg_m3, "Particle density rho_p [kg/m3] (rod Table 1)");
  lattice->add_option("--E-dem-GPa", lq.E_dem_GPa, "Contact modulus E_dem [GPa] (the K_n column of rod Table 1)");
  lattice->add_option("--spacing-R", lq.spacing_R, "Spacing d as a multiple of the sphere radius (1.03 for 1.03R)");
  lattice->add_option("--f-max-kHz", lq.f_max_kHz, "Highest frequency [kHz]")->capture_default_str();
  lattice->add_option("--df-kHz", lq.df_kHz, "Frequency step [kHz]")->capture_default_str();
  lattice->add_option("--label", lq.label, "Name of the model in the table")->capture_default_str();
  lattice->add_option("--csv", csv, "Table: model, f_kHz, k_rad_m, kd, c_phase_m_s, c_group_m_s");
  app::add_out_option(*lattice, out, "the JSON summary");

  auto* measure = cli.add_subcommand("measure", "Group velocity of simulated or measured signals, RSS against theory");
  wave::MeasureReportRequest mq;
  measure->add_option("--run", mq.runs, "A burst run: FILE (an mw-fem signal file, which records its burst frequency) "
                                        "or FREQ_kHz=FILE; repeatable, one per centre frequency");
  measure->add_option("--spacetime", mq.spacetime, "A space-time record (mw-fem rod --spacetime): 2D FFT ridge instead");
  measure->add_option("--method", mq.method,
                      "echo: two successive packets at one station, distance = round trip (2 L, by default the "
                      "--experiment rod's; the rod paper's peak to peak); two-stations: first packets at two stations; source: burst centre to first "
                      "packet")
      ->capture_default_str();
  measure->add_option("--station", mq.stations, "Signal name(s) to use (one, or two for two-stations)");
  measure->add_option("--distance-mm", mq.distance_mm,
                      "Path length [mm] (echo: the round trip; two-stations: default from the positions)");
  measure->add_option("--cycles", mq.cycles, "Cycles in the bursts")->capture_default_str();
  add_rod(measure, mq.rod, "Theory: rod's ");
  measure->add_option("--theory-csv", mq.theory_csv, "Theory: a table from mw-dispersion theory --csv instead");
  measure->add_option("--band-kHz", mq.band_kHz, "LO,HI: frequency band of the RSS [kHz] (default: every point)");
  measure->add_option("--f-min-kHz", mq.f_min_kHz, "Space-time ridge: lowest frequency [kHz]")->capture_default_str();
  measure->add_option("--f-max-kHz", mq.f_max_kHz, "Space-time ridge: highest frequency [kHz]")->capture_default_str();
  measure->add_option("--label", mq.label, "Name of the model in the table (default: the file names)");
  measure->add_option("--csv", csv, "Table: run, f_kHz, method, t1_us, t2_us, distance_mm, c_group_m_s, "
                                    "theory_c_group_m_s, residual_m_s, in_band");
  app::add_out_option(*measure, out, "the JSON summary (RSS)");

  auto* bar = cli.add_subcommand("bar-echo", "Bar velocity from a pulse and its echo at one gauge (split Hopkinson bar record)");
  wave::BarEchoRequest bq;
  bar->add_option("--record", bq.record, "Signal file (HDF5 or mesowave CSV) or a plain CSV table whose first column is "
                                         "time in s (printed with few digits is fine: the time base is rebuilt)")
      ->required();
  bar->add_option("--column", bq.column, "Column (CSV; the header up to '/' is enough) or signal name")->required();
  bar->add_option("--path-mm", bq.path_mm, "Round-trip path between the two passes [mm] (2 x gauge to bar end)")->required();
  bar->add_option("--path-uncertainty-mm", bq.path_uncertainty_mm, "Standard uncertainty of that path [mm]")
      ->capture_default_str();
  add_rod(bar, bq.rod, "Bar (E, density: c0; all four: theory): ");
  bar->add_option("--csv", csv, "Table of the picks: method, t1_us, t2_us, delay_us, c_m_s");
  bar->add_option("--signals", signals,
                  "Write the record and the theory's echo (needs the material) as a signal file (.h5 or .csv)");
  app::add_out_option(*bar, out, "the JSON result");

  return tool.run(argc, argv, [&](app::Run& run) {
    const auto emit = [&](const wave::DispersionReport& r) {
      for (const auto& f : r.inputs) run.input(f);
      if (!csv.empty()) run.write_text(csv, r.csv);
      for (const auto& m : r.metrics) run.metric(m.name, m.value, m.unit);
      run.emit_json(r.summary, out);
    };
    if (bar->parsed()) {
      const auto r = wave::bar_echo_report(bq);
      if (!signals.empty()) {
        const auto written = wave::bar_echo_signals(r);
        signal::write_signals(run.output(signals), signal::signal_format_of(signals), written);
      }
      emit(r);
    } else if (measure->parsed()) {
      emit(wave::measure_report(mq));
    } else if (theory->parsed()) {
      const auto r = wave::theory_report(tq);
      if (!h5.empty()) wave::write_dispersion_h5(run.output(h5), *r.rod, r.points);
      if (r.plot) io::render_plot(*r.plot, tq.plot, run.output(tq.plot));
      emit(r);
    } else {
      emit(wave::lattice_report(lq));
    }
  });
}
