// mw-pickers - how far mw-upv's pickers land from the true onset (issue 19,
// item 1): the picker table of docs/upv-pickers.md on synthetic records with a
// ringing transducer response, a P precursor on the shear channel and noise.
//
//   mw-pickers                            # the Markdown table, default grid (30 seeds per point)
//   mw-pickers --seeds 10 --cells cells.csv --out table.json
#include "mesowave/app/tool.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/io/gnuplot.hpp"
#include "mesowave/lab/picker_study.hpp"

using namespace mesowave;

int main(int argc, char** argv) {
  app::Tool tool("mw-pickers",
                 "The picker table: median and MAD of (pick - true onset), in periods of the transducer frequency, "
                 "for mw-upv's pickers (threshold, aic, envelope-peak on the P and S channels; aic-after-p and "
                 "envelope-peak-after-p, mw-upv's S chain; xcorr-after-p, its matched filter) on synthetic record pairs (lab/transducer_record.hpp: a "
                 "pair of damped resonators, rise over --rise-periods, P precursor at --precursor-fractions of the S "
                 "peak, a slow rise under the S onset at --slow-rise-fractions of it, noise at --snr-dB; t_p = 35 us, t_s = 55.1 us as the paper's cube). Prints the Markdown table "
                 "of docs/upv-pickers.md.\n\n"
                 "  mw-pickers --cells cells.csv --out table.json");
  lab::PickerStudyGrid grid;
  std::vector<double> frequency_kHz{30, 45, 60};
  std::filesystem::path out, cells, table_cpp, plot, point_force_csv;
  auto& cli = tool.cli();
  cli.add_option("--seeds", grid.seeds, "Noise realisations per grid point")->capture_default_str();
  cli.add_option("--frequency-kHz", frequency_kHz, "Transducer frequencies [kHz]")->delimiter(',')->capture_default_str();
  cli.add_option("--rise-periods", grid.rise_periods, "Envelope rise to its peak [periods]")->delimiter(',')->capture_default_str();
  cli.add_option("--precursor-fractions", grid.precursor_fraction, "P precursor peak / S peak on the S channel")
      ->delimiter(',')->capture_default_str();
  cli.add_option("--snr-dB", grid.snr_dB, "Signal-to-noise ratios [dB]")->delimiter(',')->capture_default_str();
  cli.add_option("--slow-rise-fractions", grid.slow_rise_fraction, "Slow rise under the S onset, peak / S peak "
                 "(a Hann lobe from 0.35 periods before the onset, one period long; 0 must be among them: the pooled "
                 "rows)")->delimiter(',')->capture_default_str();
  cli.add_option("--cells", cells, "CSV of every grid point's statistics")->type_name("FILE");
  cli.add_option("--point-force-csv", point_force_csv, "CSV of the point-force rows (with each row's first refusal)")
      ->type_name("FILE");
  cli.add_option("--table-cpp", table_cpp, "The pooled rows as C++ initialisers (lab/picker_bias_table.inc)")
      ->type_name("FILE");
  cli.add_option("--plot", plot, "PNG of an example pair (40 kHz, rise 1.5 periods, precursor 0.3, 30 dB) with the "
                                 "true onsets and every picker's pick")->type_name("FILE");
  app::add_out_option(cli, out);

  return tool.run(argc, argv, [&](app::Run& run) {
    grid.frequency_Hz.clear();
    for (double f : frequency_kHz) grid.frequency_Hz.push_back(f * units::kHz);
    const auto study = lab::run_picker_study(grid);
    const auto point_force = lab::run_point_force_study(grid.snr_dB, grid.seeds);
    run.out() << lab::picker_bias_markdown(study.pooled) << "\nBy precursor fraction (S channel):\n\n";
    std::vector<lab::PickerBiasRow> s_rows;
    for (const auto& r : study.by_fraction)
      if (r.arrival == "S") s_rows.push_back(r);
    run.out() << lab::picker_bias_markdown(s_rows) << "\nBy slow rise under the S onset (S channel):\n\n"
              << lab::picker_bias_markdown(study.by_slow_rise)
              << "\nPoint-force records (Stokes' solution, the DEM's UPV geometry: 50 mm, 120 kHz S, 162 kHz P; "
                 "both calibrations' speeds; periods of 120 kHz):\n\n"
              << lab::picker_bias_markdown(point_force);
    if (!point_force_csv.empty()) run.write_text(point_force_csv, lab::picker_bias_csv(point_force));
    if (!cells.empty()) run.write_text(cells, lab::picker_bias_csv(study.cells));
    if (!plot.empty())
      io::run_gnuplot(lab::picker_example_figure_script(lab::study_record_pair(grid, 40e3, 1.5, 0.3, 30, 1),
                                                        run.output(plot), "Synthetic pair: 40 kHz, rise 1.5 periods, "
                                                                          "P precursor 0.3 of S, 30 dB"));
    if (!table_cpp.empty()) run.write_text(table_cpp, lab::picker_bias_cpp(study.pooled));
    nlohmann::ordered_json j;
    j["seeds"] = grid.seeds;
    j["t_p_us"] = grid.t_p_s * 1e6;
    j["t_s_us"] = grid.t_s_s * 1e6;
    for (const auto& r : study.pooled) {
      nlohmann::ordered_json row = {{"arrival", r.arrival}, {"picker", r.picker}, {"snr_dB", r.snr_dB},
                                    {"records", r.records}, {"refused", r.refused}, {"flagged", r.flagged},
                                    {"median_error_periods", r.median_periods}, {"mad_error_periods", r.mad_periods},
                                    {"p90_abs_error_periods", r.p90_abs_periods}};
      j["pooled"].push_back(row);
    }
    if (!out.empty()) run.write_text(out, j.dump(2) + "\n");
  });
}
