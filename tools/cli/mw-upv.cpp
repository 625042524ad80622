// mw-upv - flowchart step 3 (dynamic route): elastic constants from the
// ultrasonic pulse velocity test, concrete paper Eqs. (8)-(10).
//
//   mw-upv --path-mm 150 --t-p-us 35 --t-s-us 55.1 --density-kg-m3 2129.56
//   mw-upv --path-mm 150 --t-p-us 35 --nu-assumed 0.2 --density-kg-m3 2129.56
//   mw-upv --path-mm 150 --p-wave p.csv --s-wave s.csv --density-kg-m3 2129.56 --plot fig7.png
//
// With both times of flight the Poisson ratio is measured (Eq. 10) and E_d
// follows from the shear wave (Eq. 9). With the P wave alone the Poisson ratio
// must be assumed (ASTM C597: E_d = rho v_p^2 (1+nu)(1-2nu)/(1-nu)); the
// result records that it was. Times of flight come from the command line or
// are picked on the recorded waveforms (lab/upv_waveform.hpp), minus the
// transducer/couplant delay.
#include <iostream>

#include "mesowave/app/tool.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/io/gnuplot.hpp"
#include "mesowave/lab/upv_report.hpp"

using namespace mesowave;

int main(int argc, char** argv) {
  app::Tool tool("mw-upv",
                 "Dynamic modulus E_d and Poisson ratio nu_d from the ultrasonic pulse velocity test (concrete paper "
                 "Eqs. 8-10): v = path / time of flight; nu_d = (0.5 r^2 - 1)/(r^2 - 1) with r = v_p/v_s; "
                 "E_d = 2 rho v_s^2 (1 + nu_d). With --nu-assumed and no S wave, the ASTM C597 P-wave relation.\n"
                 "Times of flight are given (--t-p-us, --t-s-us) or picked on the recorded waveforms (--p-wave, "
                 "--s-wave: CSV time + amplitude, or WAV) by --picker: aic (default; Maeda's AIC around the first "
                 "threshold crossing), threshold (--threshold-factor x pre-trigger noise RMS) or envelope-peak (group "
                 "arrival), after the --crosstalk-us window, minus --delay-us (transducers + couplant). A zero-phase "
                 "--lowpass-kHz at about 4x the transducer frequency removes the noise that hides the first "
                 "half-cycle. The S wave is "
                 "searched from 1.3 t_p on (v_s < v_p / sqrt(2) for nu > 0), past the P energy S transducers also "
                 "receive, up to 3.5 t_p (nu < 0.45), located by its envelope peak; with --s-wavelet or --s-wavelet-burst-kHz its "
                 "onset is the matched filter's (xcorr: the lag where the record best matches the known wavelet), "
                 "which a slow rise under the burst's first half-cycle does not pull to the first large one. Without a density only velocities "
                 "and nu_d are given. Each pick states its picker's remaining bias (t_p_pick_bias_us: the median of pick - true "
                 "onset on synthetic records at the record's SNR, docs/upv-pickers.md; not subtracted).\n\n"
                 "  mw-upv --path-mm 150 --t-p-us 35 --t-s-us 55.1 --density-kg-m3 2129.56\n"
                 "  mw-upv --from lab-data/concrete-cube/upv.toml --from results/concrete-cube/density.json\n"
                 "  mw-upv --path-mm 150 --p-wave raw/upv-p.csv --s-wave raw/upv-s.csv --density-kg-m3 2129.56 "
                 "--plot fig7.png");
  lab::UpvMeasurement m;
  std::filesystem::path out, plot;
  std::string title;
  auto& cli = tool.cli();
  cli.add_option("--path-mm", m.path_mm, "Distance between the transducers [mm]")->required();
  cli.add_option("--t-p-us", m.t_p_us, "Time of flight of the P (longitudinal) wave [us]");
  cli.add_option("--t-s-us", m.t_s_us, "Time of flight of the S (shear) wave [us]");
  cli.add_option("--density-kg-m3", m.density_kg_m3, "Density of the specimen [kg/m3] (e.g. from mw-specimen)");
  cli.add_option("--nu-assumed", m.nu_assumed, "Poisson ratio to assume when only the P wave was measured");
  auto* g = "waveforms";
  cli.add_option("--p-wave", m.p_wave, "P-wave record (CSV or WAV) to pick t_p on")->group(g)->type_name("FILE");
  cli.add_option("--s-wave", m.s_wave, "S-wave record (CSV or WAV) to pick t_s on")->group(g)->type_name("FILE");
  cli.add_option("--picker", m.pick.picker, "aic, threshold or envelope-peak")
      ->group(g)->check(CLI::IsMember({"aic", "threshold", "envelope-peak"}))->capture_default_str();
  cli.add_option("--threshold-factor", m.pick.threshold_factor, "Threshold = factor x pre-trigger noise RMS")
      ->group(g)->capture_default_str();
  cli.add_option("--locate-relative", m.pick.threshold_relative, "Arrival located where the record first reaches this "
                                                                "fraction of its peak (or the threshold factor)")
      ->group(g)->capture_default_str();
  cli.add_option("--s-locator", m.s_locator, "threshold or envelope-peak (default for S after a P pick)")
      ->group(g)->check(CLI::IsMember({"threshold", "envelope-peak"}));
  cli.add_option("--s-wavelet", m.s_wavelet, "S onset by the matched filter (picker xcorr) with this wavelet record "
                 "(CSV or WAV, the S record's column options; its first motion at its t = 0): a face-to-face record "
                 "of the S transducers, or a model's load as its receiver records it. For an S burst that rides on "
                 "a slow rise (a near field), where AIC picks its first large half-cycle (docs/upv-pickers.md)")
      ->group(g)->type_name("FILE");
  cli.add_option("--s-wavelet-burst-kHz", m.s_wavelet_burst, "The same with a Hann burst as the wavelet: frequency "
                 "[kHz],cycles (a model's load, e.g. 120,2 for upv50-s.toml)")
      ->group(g)->delimiter(',')->expected(2)->type_name("KHZ,CYCLES");
  cli.add_flag("--s-wavelet-derivative", m.s_wavelet_derivative, "Match the burst's time derivative: the record is "
               "the velocity of a force load (the DEM's UPV records)")->group(g);
  cli.add_option("--min-arrival-snr", m.pick.min_arrival_snr, "The located arrival's RMS over --aic-after-us must be at "
                                                             "least this many times the noise RMS")
      ->group(g)->capture_default_str();
  cli.add_option("--aic-after-us", m.aic_after_us, "AIC window reaches this far past the threshold crossing [us]")
      ->group(g)->capture_default_str();
  cli.add_option("--lowpass-kHz", m.lowpass_kHz, "Zero-phase low-pass before picking, corner [kHz] (0: none)")
      ->group(g)->capture_default_str();
  cli.add_option("--s-lowpass-kHz", m.s_lowpass_kHz, "Low-pass corner for the S record if it differs [kHz]")->group(g);
  cli.add_option("--crosstalk-us", m.crosstalk_us, "Electrical cross-talk after the trigger, not searched [us]")
      ->group(g)->capture_default_str();
  cli.add_option("--noise-window-us", m.noise_us, "Noise window begin,end [us] (default: the pre-trigger)")
      ->group(g)->delimiter(',')->expected(2);
  cli.add_option("--p-search-us", m.p_search_us, "P onset search window begin,end [us]")->group(g)->delimiter(',')->expected(2);
  cli.add_option("--s-search-us", m.s_search_us, "S onset search window begin,end [us] (default from 1.3 t_p)")
      ->group(g)->delimiter(',')->expected(2);
  cli.add_option("--delay-us", m.delay_us, "Transducer + couplant delay subtracted from the picks [us]")
      ->group(g)->capture_default_str();
  cli.add_option("--s-delay-us", m.s_delay_us, "Delay of the S transducers if it differs [us]")->group(g);
  cli.add_option("--time-column", m.read.time_column, "Time column: name, or 1-based index with --no-header")->group(g);
  cli.add_option("--amplitude-column", m.read.amplitude_column, "Amplitude column (default: the one after time)")->group(g);
  cli.add_flag("--no-header", m.read.no_header, "The CSV has no header row")->group(g);
  cli.add_option("--time-unit", m.read.time_unit, "Time unit of a headerless CSV: s, ms or us")->group(g);
  cli.add_option("--sample-interval-us", m.sample_interval_us, "WAV: the true sample interval [us]")->group(g);
  cli.add_option("--trigger-sample", m.read.trigger_sample, "WAV: 0-based sample at the trigger (t = 0)")->group(g);
  cli.add_option("--add-noise-snr-dB", m.read.added_noise_snr_dB, "Add white Gaussian noise at this SNR = 20 log10(peak / "
                 "noise RMS) to the records before picking (a model's noise-free record made like a lab's)")->group(g);
  cli.add_option("--add-noise-seed", m.read.added_noise_seed, "Seed of the added noise (the S record's: seed + 1)")
      ->group(g)->capture_default_str();
  cli.add_option("--plot", plot, "PNG of the records with the picks marked (like Fig. 7)")->group(g)->type_name("FILE");
  cli.add_option("--title", title, "Plot title")->group(g);
  app::add_out_option(cli, out);

  return tool.run(argc, argv, [&](app::Run& run) {
    for (const auto* record : {&m.p_wave, &m.s_wave})
      if (!record->empty()) run.input(*record);
    const auto report = lab::upv_report(m);
    for (const auto& w : report.warnings) std::cerr << "warning: " << w << "\n";
    auto j = report.summary;
    if (j.contains("E_d_GPa")) run.metric("E_d", j["E_d_GPa"].get<double>(), "GPa");
    run.metric("v_p", j["v_p_m_s"].get<double>(), "m/s");
    if (j.contains("t_s_us")) run.metric("v_s", j["v_s_m_s"].get<double>(), "m/s");
    if (j.contains("nu_d")) run.metric("nu_d", j["nu_d"].get<double>(), "");
    if (!plot.empty()) {
      if (report.traces().empty()) throw InputError("--plot needs a recorded waveform (--p-wave or --s-wave)");
      io::run_gnuplot(lab::upv_figure_script(report.traces(), run.output(plot), title));
    }
    // What the next steps read (mw-estatic, mw-fem); the rest is there for the reader.
    // Without a density (velocities only) there is nothing for them.
    std::vector<std::string> products;
    for (const char* k : {"E_d_GPa", "density_kg_m3"})
      if (j.contains(k)) products.push_back(k);
    app::declare_products(j, products);
    run.emit_json(j, out);
  });
}
