// mw-pcc - Pearson correlation coefficients between two sets of signals, per
// sensor (matched by name) and the mean over sensors: concrete paper Table 3
// (experimental vs numerical signals), for the signals and their envelopes.
// The correlation and what it reports live in signal/pcc_report.
//
//   mw-pcc experiment.h5 simulation.h5
//   mw-pcc --a exp-100kHz.csv --b sim-100kHz.h5 --sensors B,C,D --resample linear --csv pcc.csv --out pcc.json
//   mw-pcc experiment.h5 simulation.h5 --spectra spectra.csv --max-frequency-kHz 600
//   mw-pcc fem.h5 dem.h5 --resample linear --labels FEM,DEM --plot-signals signals.png --plot-envelopes env.png
#include "mesowave/app/tool.hpp"
#include "mesowave/signal/pcc_report.hpp"

using namespace mesowave;
namespace fs = std::filesystem;

int main(int argc, char** argv) {
  app::Tool tool("mw-pcc",
                 "Pearson correlation coefficient r = sum (a - mean a)(b - mean b) / sqrt(sum (a - mean a)^2 "
                 "sum (b - mean b)^2) between two sets of signals, sensor by sensor (matched by name), for the "
                 "signals and for their Hilbert envelopes, and the mean over sensors (concrete paper Table 3). "
                 "Signals must share their time base unless --resample names an interpolation; zero variance, "
                 "NaN, empty or unequal records are errors.\n\n"
                 "  mw-pcc experiment.h5 simulation.h5\n"
                 "  mw-pcc --a exp-B.csv exp-C.csv --b sim.h5 --sensors B,C --resample linear --csv pcc.csv\n"
                 "  mw-pcc experiment.h5 simulation.h5 --spectra spectra.csv --max-frequency-kHz 600");
  signal::PccRequest q;
  fs::path csv_out, spectra_out, out, plot_signals, plot_envelopes, plot_spectra;
  auto& cli = tool.cli();
  cli.add_option("files", q.files, "Two signal files (HDF5 .h5 or CSV .csv): the first set and the second");
  cli.add_option("--a", q.a, "The first set as one or more files (e.g. experiment)")->type_name("FILE ...");
  cli.add_option("--b", q.b, "The second set as one or more files (e.g. simulation)")->type_name("FILE ...");
  cli.add_option("--sensors", q.sensors, "Compare only these sensors (comma separated; default: every shared name but the load's record, 'excitation')")
      ->delimiter(',');
  cli.add_option("--resample", q.resampling,
                 "linear | cubic: interpolate the second set onto the first's samples where they overlap "
                 "(default: none, different time bases are an error)");
  cli.add_option("--window-begin-us", q.begin_us, "Compare from this time [us] (envelopes use the whole record)");
  cli.add_option("--window-end-us", q.end_us, "Compare up to this time [us]");
  cli.add_option("--detrend", q.detrend, "Envelopes: none | mean | linear")->capture_default_str();
  cli.add_option("--pad", q.pad, "Envelopes: none | double | pow2 | an FFT length")->capture_default_str();
  cli.add_option("--csv", csv_out,
                 "Write the table as CSV (a last row 'mean'), the coefficients to four decimals as printed; "
                 "--out's JSON holds them at full precision (the shortest text that reads back as the same double)")
      ->type_name("FILE");
  cli.add_option("--spectra", spectra_out,
                 "Also write the amplitude spectra of both sets (concrete paper Fig. 15) as CSV: f_kHz, then "
                 "'<sensor> a [unit]', '<sensor> b [unit]' per sensor")
      ->type_name("FILE");
  cli.add_option("--max-frequency-kHz", q.max_frequency_kHz, "--spectra, --plot-spectra: up to this frequency [kHz] only");
  cli.add_option("--plot-signals", plot_signals,
                 "Draw the signals (.png or .svg): one panel per sensor, both sets overlaid, each curve divided by its "
                 "largest |value| in the window, the PCC in the panel's title (concrete paper Figs. 12-13)")
      ->type_name("FILE");
  cli.add_option("--plot-envelopes", plot_envelopes,
                 "Draw the Hilbert envelopes the same way (concrete paper Fig. 14)")->type_name("FILE");
  cli.add_option("--plot-spectra", plot_spectra,
                 "Draw the amplitude spectra the same way (concrete paper Fig. 15; the spectra of --spectra)")
      ->type_name("FILE");
  cli.add_option("--plot-window-us", q.plot_window_us, "--plot-signals, --plot-envelopes: from,to [us] (default: all)")
      ->delimiter(',')
      ->expected(2);
  cli.add_option("--labels", q.labels, "Legend names of the two sets, comma separated (e.g. FEM,DEM)")
      ->delimiter(',')
      ->expected(2)
      ->capture_default_str();
  cli.add_option("--title", q.title, "Title of the figures (default: the two files)");
  cli.add_option("--arrival-relative", q.arrival_relative,
                 "Also compare arrivals and peaks, sensor by sensor: the arrival is the first crossing of this fraction "
                 "(e.g. 0.02) of the record's peak deviation from its first two samples (a simulated record starts at rest; "
                 "for a lab record's onset use mw-upv), the peak the largest |x| in the window; adds arrival_a_us, "
                 "arrival_b_us, arrival_shift_us (b - a) and peak_ratio (b / a) to the table, their mean |shift| and "
                 "mean |ratio - 1| to the mean row and the JSON (mean_abs_arrival_shift_us, mean_abs_peak_error)");
  app::add_out_option(cli, out, "the JSON result (every coefficient at full precision: it reads back bit for bit)");

  return tool.run(argc, argv, [&](app::Run& run) {
    q.spectra = !spectra_out.empty();
    q.plot_signals = !plot_signals.empty(), q.plot_envelopes = !plot_envelopes.empty(), q.plot_spectra = !plot_spectra.empty();
    for (const auto& p : {plot_signals, plot_envelopes, plot_spectra})
      if (!p.empty()) q.plots.push_back(p);
    const auto r = signal::pcc_report(q);
    for (const auto& f : r.inputs) run.input(f);
    for (const auto& m : r.metrics) run.metric(m.name, m.value, m.unit);
    run.out() << r.text;
    if (!csv_out.empty()) run.write_text(csv_out, r.csv);
    if (!spectra_out.empty()) run.write_text(spectra_out, r.spectra_csv);
    if (r.signals) io::render_sensor_panels(*r.signals, plot_signals, run.output(plot_signals));
    if (r.envelopes) io::render_sensor_panels(*r.envelopes, plot_envelopes, run.output(plot_envelopes));
    if (r.spectra) io::render_sensor_panels(*r.spectra, plot_spectra, run.output(plot_spectra));
    if (!out.empty()) run.write_text(out, r.summary.dump(2) + "\n");
  });
}
