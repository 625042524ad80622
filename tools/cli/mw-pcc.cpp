// mw-pcc - Pearson correlation coefficients between two sets of signals, per
// sensor (matched by name) and the mean over sensors: concrete paper Table 3
// (experimental vs numerical signals), for the signals and their envelopes.
//
//   mw-pcc experiment.h5 simulation.h5
//   mw-pcc --a exp-100kHz.csv --b sim-100kHz.h5 --sensors B,C,D --resample linear --csv pcc.csv --out pcc.json
//   mw-pcc experiment.h5 simulation.h5 --spectra spectra.csv --max-frequency-kHz 600
//   mw-pcc fem.h5 dem.h5 --resample linear --labels FEM,DEM --plot-signals signals.png --plot-envelopes env.png
#include <cmath>

#include "mesowave/app/tool.hpp"
#include "mesowave/core/check.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/io/csv.hpp"
#include "mesowave/io/sensor_panels.hpp"
#include "mesowave/io/signal_csv.hpp"
#include "mesowave/io/text_table.hpp"
#include "mesowave/signal/correlation.hpp"

using namespace mesowave;
using namespace mesowave::signal;
namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace {

std::vector<Signal> read_set(app::Run& run, const std::vector<fs::path>& files) {
  std::vector<Signal> all;
  for (const auto& f : files) {
    run.input(f);
    for (auto& s : io::read_signals(f)) all.push_back(std::move(s));
  }
  return all;
}

const Signal* find(std::span<const Signal> set, const std::string& name) {
  for (const auto& s : set)
    if (s.name == name) return &s;
  return nullptr;
}

io::Curve time_curve_us(const Signal& s) {
  io::Curve c;
  c.y = s.samples;
  c.x.resize(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) c.x[i] = s.time(i) / units::us;
  return c;
}

io::Curve spectrum_curve_kHz(const Spectrum& sp) {
  io::Curve c{sp.frequency_hz, sp.amplitude};
  for (auto& f : c.x) f /= units::kHz;
  return c;
}

std::string join(const std::vector<fs::path>& files) {
  std::string text;
  for (const auto& f : files) text += (text.empty() ? "" : " ") + f.string();
  return text;
}

}  // namespace

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
  std::vector<fs::path> files, set_a, set_b;
  std::vector<std::string> sensors;
  std::optional<std::string> resample_text;
  std::optional<double> begin_us, end_us;
  std::string detrend_text = "none", pad_text = "none";
  fs::path csv_out, spectra_out, out;
  std::optional<double> max_frequency_kHz;
  fs::path plot_signals, plot_envelopes, plot_spectra;
  std::vector<double> plot_window_us;
  std::vector<std::string> labels = {"a", "b"};
  std::string title;
  auto& cli = tool.cli();
  cli.add_option("files", files, "Two signal files (HDF5 .h5 or CSV .csv): the first set and the second");
  cli.add_option("--a", set_a, "The first set as one or more files (e.g. experiment)")->type_name("FILE ...");
  cli.add_option("--b", set_b, "The second set as one or more files (e.g. simulation)")->type_name("FILE ...");
  cli.add_option("--sensors", sensors, "Compare only these sensors (comma separated; default: every shared name)")
      ->delimiter(',');
  cli.add_option("--resample", resample_text,
                 "linear | cubic: interpolate the second set onto the first's samples where they overlap "
                 "(default: none, different time bases are an error)");
  cli.add_option("--window-begin-us", begin_us, "Compare from this time [us] (envelopes use the whole record)");
  cli.add_option("--window-end-us", end_us, "Compare up to this time [us]");
  cli.add_option("--detrend", detrend_text, "Envelopes: none | mean | linear")->capture_default_str();
  cli.add_option("--pad", pad_text, "Envelopes: none | double | pow2 | an FFT length")->capture_default_str();
  cli.add_option("--csv", csv_out, "Write the table as CSV (a last row 'mean')")->type_name("FILE");
  cli.add_option("--spectra", spectra_out,
                 "Also write the amplitude spectra of both sets (concrete paper Fig. 15) as CSV: f_kHz, then "
                 "'<sensor> a [unit]', '<sensor> b [unit]' per sensor")
      ->type_name("FILE");
  cli.add_option("--max-frequency-kHz", max_frequency_kHz, "--spectra, --plot-spectra: up to this frequency [kHz] only");
  cli.add_option("--plot-signals", plot_signals,
                 "Draw the signals (.png or .svg): one panel per sensor, both sets overlaid, each curve divided by its "
                 "largest |value| in the window, the PCC in the panel's title (concrete paper Figs. 12-13)")
      ->type_name("FILE");
  cli.add_option("--plot-envelopes", plot_envelopes,
                 "Draw the Hilbert envelopes the same way (concrete paper Fig. 14)")->type_name("FILE");
  cli.add_option("--plot-spectra", plot_spectra,
                 "Draw the amplitude spectra the same way (concrete paper Fig. 15; the spectra of --spectra)")
      ->type_name("FILE");
  cli.add_option("--plot-window-us", plot_window_us, "--plot-signals, --plot-envelopes: from,to [us] (default: all)")
      ->delimiter(',')
      ->expected(2);
  cli.add_option("--labels", labels, "Legend names of the two sets, comma separated (e.g. FEM,DEM)")
      ->delimiter(',')
      ->expected(2)
      ->capture_default_str();
  cli.add_option("--title", title, "Title of the figures (default: the two files)");
  app::add_out_option(cli, out, "the JSON result");

  return tool.run(argc, argv, [&](app::Run& run) {
    if (!files.empty()) {
      if (files.size() != 2) throw InputError("give two files (or --a and --b), got " + std::to_string(files.size()));
      if (!set_a.empty() || !set_b.empty()) throw InputError("give two files or --a and --b, not both");
      set_a = {files[0]};
      set_b = {files[1]};
    }
    if (set_a.empty() || set_b.empty()) throw InputError("need two signal files, or --a FILE... and --b FILE...");
    CorrelationOptions options;
    if (resample_text) options.resampling = parse_interpolation(*resample_text);
    if (begin_us) options.begin_s = require_finite("--window-begin-us", *begin_us, "us") * units::us;
    if (end_us) options.end_s = require_finite("--window-end-us", *end_us, "us") * units::us;
    if (begin_us && end_us && !(*end_us > *begin_us))
      throw InputError("--window-end-us (" + format_number(*end_us) + ") must exceed --window-begin-us (" +
                       format_number(*begin_us) + ")");
    options.envelope = {parse_detrend(detrend_text), Padding::parse(pad_text)};
    for (const auto* plot : {&plot_signals, &plot_envelopes, &plot_spectra}) {
      const auto ext = plot->extension();
      if (!plot->empty() && ext != ".png" && ext != ".svg")
        throw InputError("plot file " + plot->string() + " must end in .png or .svg");
    }
    std::optional<std::pair<double, double>> window;
    if (!plot_window_us.empty()) {
      if (!(plot_window_us[1] > plot_window_us[0]) || !std::isfinite(plot_window_us[0]) || !std::isfinite(plot_window_us[1]))
        throw InputError("--plot-window-us " + format_number(plot_window_us[0]) + "," + format_number(plot_window_us[1]) +
                         ": the end must exceed the start");
      window = std::pair{plot_window_us[0], plot_window_us[1]};
    }
    if (!spectra_out.empty() || !plot_spectra.empty()) options.spectra = SpectrumOptions{options.envelope.detrend, options.envelope.padding};
    if (max_frequency_kHz) require_positive("--max-frequency-kHz", *max_frequency_kHz, "kHz");

    const auto a = read_set(run, set_a), b = read_set(run, set_b);
    const auto table = correlate_sensors(a, b, options, sensors);

    const std::vector<std::string> header = {"sensor", "pcc_signal", "pcc_envelope", "samples", "from_us", "to_us"};
    std::vector<std::vector<std::string>> rows;
    json per_sensor = json::array();
    for (const auto& s : table.sensors) {
      rows.push_back({s.sensor, format_fixed(s.pcc_signal, 4), format_fixed(s.pcc_envelope, 4),
                      std::to_string(s.compared.count), format_number(s.compared.t0_s / units::us),
                      format_number(s.compared.end_s() / units::us)});
      per_sensor.push_back({{"sensor", s.sensor}, {"pcc_signal", s.pcc_signal}, {"pcc_envelope", s.pcc_envelope},
                            {"samples", s.compared.count}, {"from_us", s.compared.t0_s / units::us},
                            {"to_us", s.compared.end_s() / units::us}});
      run.metric("pcc_" + s.sensor, s.pcc_signal, "");
      run.metric("pcc_envelope_" + s.sensor, s.pcc_envelope, "");
    }
    rows.push_back({"mean", format_fixed(table.mean_pcc_signal, 4), format_fixed(table.mean_pcc_envelope, 4), "", "", ""});
    run.metric("pcc_mean", table.mean_pcc_signal, "");
    run.metric("pcc_envelope_mean", table.mean_pcc_envelope, "");

    auto& text = run.out();
    text << "a: " << join(set_a) << "\nb: " << join(set_b) << "\n" << io::format_text_table(header, rows);
    text << "resampling: " << table.resampling << "\nenvelopes: " << table.envelope_method << "\n";
    std::vector<std::string> unmatched;
    for (const auto& n : table.only_in_a) unmatched.push_back(n + " (only in a)");
    for (const auto& n : table.only_in_b) unmatched.push_back(n + " (only in b)");
    if (!unmatched.empty()) {
      std::string list;
      for (const auto& u : unmatched) list += (list.empty() ? "" : ", ") + u;
      text << "not compared: " << list << "\n";
    }
    if (!csv_out.empty()) run.write_text(csv_out, io::to_csv(header, rows));
    if (!spectra_out.empty()) {
      const auto& axis = table.sensors.front().spectrum_a;
      std::vector<std::string> spectra_header = {"f_kHz"};
      for (const auto& s : table.sensors) {
        for (const auto* sp : {&s.spectrum_a, &s.spectrum_b})
          if (sp->amplitude.size() != axis.amplitude.size() || sp->df_hz != axis.df_hz)
            throw InputError("sensor " + s.sensor + " has another frequency axis than " + table.sensors.front().sensor +
                             " (record length or sampling); write its spectra separately (mw-signal spectrum)");
        const auto unit_of = [&](std::span<const Signal> set) {
          for (const auto& sig : set)
            if (sig.name == s.sensor) return sig.unit;
          return std::string();
        };
        spectra_header.push_back(s.sensor + " a [" + s.spectrum_a.unit(unit_of(a)) + "]");
        spectra_header.push_back(s.sensor + " b [" + s.spectrum_b.unit(unit_of(b)) + "]");
      }
      std::vector<std::vector<std::string>> spectra_rows;
      for (std::size_t k = 0; k < axis.frequency_hz.size(); ++k) {
        if (max_frequency_kHz && axis.frequency_hz[k] > *max_frequency_kHz * units::kHz) break;
        std::vector<std::string> row = {format_exact(axis.frequency_hz[k] / units::kHz)};
        for (const auto& s : table.sensors) {
          row.push_back(format_exact(s.spectrum_a.amplitude[k]));
          row.push_back(format_exact(s.spectrum_b.amplitude[k]));
        }
        spectra_rows.push_back(std::move(row));
      }
      run.write_text(spectra_out, io::to_csv(spectra_header, spectra_rows));
    }
    // Figures: every compared sensor in the order of the first set, each set on its own time base.
    const std::string figure_title = title.empty() ? labels[0] + ": " + join(set_a) + "   " + labels[1] + ": " + join(set_b) : title;
    const auto figure = [&](const std::string& what, const std::string& x_label, const std::string& y_label) {
      io::SensorPanelsFigure f;
      f.title = figure_title + " - " + what;
      f.x_label = x_label;
      f.y_label = y_label;
      f.label_a = labels[0];
      f.label_b = labels[1];
      return f;
    };
    const auto panel_title = [](const SensorCorrelation& s) {
      return s.sensor + ": PCC " + format_fixed(s.pcc_signal, 3) + ", envelopes " + format_fixed(s.pcc_envelope, 3);
    };
    if (!plot_signals.empty() || !plot_envelopes.empty()) {
      auto signals = figure("signals", "t [us]", "signal / max |signal|");
      auto envelopes = figure("Hilbert envelopes", "t [us]", "envelope / max envelope");
      signals.x_range = envelopes.x_range = window;
      for (const auto& s : table.sensors) {
        const Signal &sa = *find(a, s.sensor), &sb = *find(b, s.sensor);
        signals.panels.push_back({panel_title(s), time_curve_us(sa), time_curve_us(sb)});
        if (!plot_envelopes.empty())
          envelopes.panels.push_back({panel_title(s), time_curve_us(envelope(sa, options.envelope)),
                                      time_curve_us(envelope(sb, options.envelope))});
      }
      if (!plot_signals.empty()) io::render_sensor_panels(signals, plot_signals, run.output(plot_signals));
      if (!plot_envelopes.empty()) io::render_sensor_panels(envelopes, plot_envelopes, run.output(plot_envelopes));
    }
    if (!plot_spectra.empty()) {
      auto spectra = figure("amplitude spectra", "f [kHz]", "amplitude / max amplitude");
      if (max_frequency_kHz) spectra.x_range = std::pair{0.0, *max_frequency_kHz};
      for (const auto& s : table.sensors)
        spectra.panels.push_back({panel_title(s), spectrum_curve_kHz(s.spectrum_a), spectrum_curve_kHz(s.spectrum_b)});
      io::render_sensor_panels(spectra, plot_spectra, run.output(plot_spectra));
    }
    if (!out.empty()) {
      json result;
      result["a"] = join(set_a);
      result["b"] = join(set_b);
      result["sensors"] = per_sensor;
      result["mean_pcc_signal"] = table.mean_pcc_signal;
      result["mean_pcc_envelope"] = table.mean_pcc_envelope;
      result["resampling"] = table.resampling;
      result["envelope_method"] = table.envelope_method;
      result["only_in_a"] = table.only_in_a;
      result["only_in_b"] = table.only_in_b;
      run.write_text(out, result.dump(2) + "\n");
    }
  });
}
