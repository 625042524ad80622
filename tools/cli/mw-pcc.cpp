// mw-pcc - Pearson correlation coefficients between two sets of signals, per
// sensor (matched by name) and the mean over sensors: concrete paper Table 3
// (experimental vs numerical signals), for the signals and their envelopes.
//
//   mw-pcc experiment.h5 simulation.h5
//   mw-pcc --a exp-100kHz.csv --b sim-100kHz.h5 --sensors B,C,D --resample linear --csv pcc.csv --out pcc.json
#include "mesowave/app/tool.hpp"
#include "mesowave/core/check.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/io/csv.hpp"
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
                 "  mw-pcc --a exp-B.csv exp-C.csv --b sim.h5 --sensors B,C --resample linear --csv pcc.csv");
  std::vector<fs::path> files, set_a, set_b;
  std::vector<std::string> sensors;
  std::optional<std::string> resample_text;
  std::optional<double> begin_us, end_us;
  std::string detrend_text = "none", pad_text = "none";
  fs::path csv_out, out;
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
