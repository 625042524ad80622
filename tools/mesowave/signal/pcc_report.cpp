#include "mesowave/signal/pcc_report.hpp"

#include <cmath>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/io/csv.hpp"
#include "mesowave/io/gnuplot.hpp"
#include "mesowave/signal/signal_csv.hpp"
#include "mesowave/io/text_table.hpp"
#include "mesowave/signal/envelope.hpp"
#include "mesowave/signal/time_of_flight.hpp"

namespace mesowave::signal {
namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace {

std::vector<Signal> read_set(const std::vector<fs::path>& files, std::vector<fs::path>& inputs) {
  std::vector<Signal> all;
  for (const auto& f : files) {
    inputs.push_back(f);
    for (auto& s : signal::read_signals(f)) all.push_back(std::move(s));
  }
  return all;
}

const Signal& find(std::span<const Signal> set, const std::string& name) {
  for (const auto& s : set)
    if (s.name == name) return s;
  throw InputError("no signal " + name);  // the table holds only names of both sets
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

// f_kHz, then both sets' amplitude per sensor, up to max_frequency_kHz.
std::string spectra_table(const CorrelationTable& table, std::span<const Signal> a, std::span<const Signal> b,
                          const std::optional<double>& max_frequency_kHz) {
  const auto& axis = table.sensors.front().spectrum_a;
  std::vector<std::string> header = {"f_kHz"};
  for (const auto& s : table.sensors) {
    for (const auto* sp : {&s.spectrum_a, &s.spectrum_b})
      if (sp->amplitude.size() != axis.amplitude.size() || sp->df_hz != axis.df_hz)
        throw InputError("sensor " + s.sensor + " has another frequency axis than " + table.sensors.front().sensor +
                         " (record length or sampling); write its spectra separately (mw-signal spectrum)");
    header.push_back(s.sensor + " a [" + s.spectrum_a.unit(find(a, s.sensor).unit) + "]");
    header.push_back(s.sensor + " b [" + s.spectrum_b.unit(find(b, s.sensor).unit) + "]");
  }
  std::vector<std::vector<std::string>> rows;
  for (std::size_t k = 0; k < axis.frequency_hz.size(); ++k) {
    if (max_frequency_kHz && axis.frequency_hz[k] > *max_frequency_kHz * units::kHz) break;
    std::vector<std::string> row = {format_exact(axis.frequency_hz[k] / units::kHz)};
    for (const auto& s : table.sensors) {
      row.push_back(format_exact(s.spectrum_a.amplitude[k]));
      row.push_back(format_exact(s.spectrum_b.amplitude[k]));
    }
    rows.push_back(std::move(row));
  }
  return io::to_csv(header, rows);
}

// Where and how large: the arrival (PccRequest::arrival_relative) and the peak |x| of one record
// in the compared window [begin_s, end_s] (unset: the record's end).
struct ArrivalAndPeak {
  double arrival_s = 0, peak = 0;
};

ArrivalAndPeak arrival_and_peak(const Signal& s, double relative, const std::optional<double>& begin_s,
                                const std::optional<double>& end_s) {
  ThresholdOptions t;
  t.noise_begin_s = s.t0_s;
  t.noise_end_s = s.t0_s + 1.5 * s.dt_s;  // the first two samples (the fewest the picker takes): the rest level
  t.factor = 1;  // times their RMS, 0 at rest: the relative level decides
  t.relative = relative;
  ArrivalAndPeak r;
  r.arrival_s = threshold_pick(s, t).time_s;
  for (std::size_t i = 0; i < s.size(); ++i)
    if ((!begin_s || s.time(i) >= *begin_s) && (!end_s || s.time(i) <= *end_s)) r.peak = std::max(r.peak, std::abs(s.samples[i]));
  return r;
}

}  // namespace

PccReport pcc_report(const PccRequest& request) {
  auto q = request;
  if (!q.files.empty()) {
    if (q.files.size() != 2) throw InputError("give two files (or --a and --b), got " + std::to_string(q.files.size()));
    if (!q.a.empty() || !q.b.empty()) throw InputError("give two files or --a and --b, not both");
    q.a = {q.files[0]};
    q.b = {q.files[1]};
  }
  if (q.a.empty() || q.b.empty()) throw InputError("need two signal files, or --a FILE... and --b FILE...");
  CorrelationOptions options;
  if (q.resampling) options.resampling = parse_interpolation(*q.resampling);
  if (q.begin_us) options.begin_s = require_finite("--window-begin-us", *q.begin_us, "us") * units::us;
  if (q.end_us) options.end_s = require_finite("--window-end-us", *q.end_us, "us") * units::us;
  if (q.begin_us && q.end_us && !(*q.end_us > *q.begin_us))
    throw InputError("--window-end-us (" + format_number(*q.end_us) + ") must exceed --window-begin-us (" +
                     format_number(*q.begin_us) + ")");
  options.envelope = {parse_detrend(q.detrend), Padding::parse(q.pad)};
  for (const auto& plot : q.plots) io::require_plot_extension(plot);
  std::optional<std::pair<double, double>> window;
  if (!q.plot_window_us.empty()) {
    const double from = q.plot_window_us.at(0), to = q.plot_window_us.at(1);
    if (!(to > from) || !std::isfinite(from) || !std::isfinite(to))
      throw InputError("--plot-window-us " + format_number(from) + "," + format_number(to) +
                       ": the end must exceed the start");
    window = std::pair{from, to};
  }
  if (q.spectra || q.plot_spectra) options.spectra = SpectrumOptions{options.envelope.detrend, options.envelope.padding};
  if (q.max_frequency_kHz) require_positive("--max-frequency-kHz", *q.max_frequency_kHz, "kHz");

  if (q.arrival_relative && !(*q.arrival_relative > 0 && *q.arrival_relative < 1))
    throw InputError("--arrival-relative (" + format_number(*q.arrival_relative) +
                     ") must lie in (0, 1): the arrival is where a record first reaches that fraction of its peak");

  PccReport r;
  const auto a = read_set(q.a, r.inputs), b = read_set(q.b, r.inputs);
  r.table = correlate_sensors(a, b, options, q.sensors);
  const auto& table = r.table;

  std::vector<std::string> header = {"sensor", "pcc_signal", "pcc_envelope", "samples", "from_us", "to_us"};
  if (q.arrival_relative)
    for (const char* h : {"arrival_a_us", "arrival_b_us", "arrival_shift_us", "peak_ratio"}) header.push_back(h);
  std::vector<std::vector<std::string>> rows;
  json per_sensor = json::array();
  double sum_abs_shift_s = 0, sum_abs_peak_error = 0;
  for (const auto& s : table.sensors) {
    rows.push_back({s.sensor, format_fixed(s.pcc_signal, 4), format_fixed(s.pcc_envelope, 4),
                    std::to_string(s.compared.count), format_number(s.compared.t0_s / units::us),
                    format_number(s.compared.end_s() / units::us)});
    per_sensor.push_back({{"sensor", s.sensor}, {"pcc_signal", s.pcc_signal}, {"pcc_envelope", s.pcc_envelope},
                          {"samples", s.compared.count}, {"from_us", s.compared.t0_s / units::us},
                          {"to_us", s.compared.end_s() / units::us}});
    r.metrics.push_back({"pcc_" + s.sensor, s.pcc_signal, ""});
    r.metrics.push_back({"pcc_envelope_" + s.sensor, s.pcc_envelope, ""});
    if (!q.arrival_relative) continue;
    const auto pa = arrival_and_peak(find(a, s.sensor), *q.arrival_relative, options.begin_s, options.end_s);
    const auto pb = arrival_and_peak(find(b, s.sensor), *q.arrival_relative, options.begin_s, options.end_s);
    if (!(pa.peak > 0)) throw InputError("sensor " + s.sensor + " of the first set is zero in the compared window: it has no peak to compare");
    const double shift_s = pb.arrival_s - pa.arrival_s, ratio = pb.peak / pa.peak;
    sum_abs_shift_s += std::abs(shift_s), sum_abs_peak_error += std::abs(ratio - 1);
    for (const double us : {pa.arrival_s, pb.arrival_s, shift_s}) rows.back().push_back(format_fixed(us / units::us, 4));
    rows.back().push_back(format_fixed(ratio, 4));
    per_sensor.back().update({{"arrival_a_us", pa.arrival_s / units::us}, {"arrival_b_us", pb.arrival_s / units::us},
                              {"arrival_shift_us", shift_s / units::us}, {"peak_a", pa.peak}, {"peak_b", pb.peak},
                              {"peak_ratio", ratio}});
    r.metrics.push_back({"arrival_shift_" + s.sensor, shift_s / units::us, "us"});
    r.metrics.push_back({"peak_ratio_" + s.sensor, ratio, ""});
  }
  rows.push_back({"mean", format_fixed(table.mean_pcc_signal, 4), format_fixed(table.mean_pcc_envelope, 4), "", "", ""});
  r.metrics.push_back({"pcc_mean", table.mean_pcc_signal, ""});
  r.metrics.push_back({"pcc_envelope_mean", table.mean_pcc_envelope, ""});
  const double n = double(table.sensors.size());
  const double mean_abs_shift_us = sum_abs_shift_s / n / units::us, mean_abs_peak_error = sum_abs_peak_error / n;
  if (q.arrival_relative) {
    // The mean row holds the means of |shift| and |ratio - 1| (signs would cancel between sensors).
    for (const auto& text : {std::string(), std::string(), format_fixed(mean_abs_shift_us, 4), format_fixed(mean_abs_peak_error, 4)})
      rows.back().push_back(text);
    r.metrics.push_back({"arrival_shift_mean_abs", mean_abs_shift_us, "us"});
    r.metrics.push_back({"peak_error_mean_abs", mean_abs_peak_error, ""});
  }

  r.text = "a: " + join(q.a) + "\nb: " + join(q.b) + "\n" + io::format_text_table(header, rows) +
           "resampling: " + table.resampling + "\nenvelopes: " + table.envelope_method + "\n" +
           (q.arrival_relative ? "arrivals: first crossing of " + format_number(*q.arrival_relative) +
                                     " x the record's peak; mean row: mean |shift|, mean |peak ratio - 1|\n"
                               : "");
  std::string unmatched;
  for (const auto& n : table.only_in_a) unmatched += (unmatched.empty() ? "" : ", ") + n + " (only in a)";
  for (const auto& n : table.only_in_b) unmatched += (unmatched.empty() ? "" : ", ") + n + " (only in b)";
  if (table.excitation_left_out)
    unmatched += (unmatched.empty() ? "" : ", ") + std::string(kExcitationName) + " (the load, not a sensor; --sensors names it)";
  if (!unmatched.empty()) r.text += "not compared: " + unmatched + "\n";
  r.csv = io::to_csv(header, rows);
  if (q.spectra) r.spectra_csv = spectra_table(table, a, b, q.max_frequency_kHz);

  // Figures: every compared sensor in the order of the first set, each set on its own time base.
  const std::string figure_title =
      q.title.empty() ? q.labels[0] + ": " + join(q.a) + "   " + q.labels[1] + ": " + join(q.b) : q.title;
  const auto figure = [&](const std::string& what, const std::string& x_label, const std::string& y_label) {
    io::SensorPanelsFigure f;
    f.title = figure_title + " - " + what;
    f.x_label = x_label;
    f.y_label = y_label;
    f.label_a = q.labels[0];
    f.label_b = q.labels[1];
    return f;
  };
  const auto panel_title = [](const SensorCorrelation& s) {
    return s.sensor + ": PCC " + format_fixed(s.pcc_signal, 3) + ", envelopes " + format_fixed(s.pcc_envelope, 3);
  };
  if (q.plot_signals || q.plot_envelopes) {
    auto signals = figure("signals", "t [us]", "signal / max |signal|");
    auto envelopes = figure("Hilbert envelopes", "t [us]", "envelope / max envelope");
    signals.x_range = envelopes.x_range = window;
    for (const auto& s : table.sensors) {
      const Signal &sa = find(a, s.sensor), &sb = find(b, s.sensor);
      signals.panels.push_back({panel_title(s), time_curve_us(sa), time_curve_us(sb)});
      if (q.plot_envelopes)
        envelopes.panels.push_back({panel_title(s), time_curve_us(envelope(sa, options.envelope)),
                                    time_curve_us(envelope(sb, options.envelope))});
    }
    if (q.plot_signals) r.signals = std::move(signals);
    if (q.plot_envelopes) r.envelopes = std::move(envelopes);
  }
  if (q.plot_spectra) {
    auto spectra = figure("amplitude spectra", "f [kHz]", "amplitude / max amplitude");
    if (q.max_frequency_kHz) spectra.x_range = std::pair{0.0, *q.max_frequency_kHz};
    for (const auto& s : table.sensors)
      spectra.panels.push_back({panel_title(s), spectrum_curve_kHz(s.spectrum_a), spectrum_curve_kHz(s.spectrum_b)});
    r.spectra = std::move(spectra);
  }

  auto& j = r.summary;
  j["a"] = join(q.a);
  j["b"] = join(q.b);
  j["sensors"] = per_sensor;
  j["mean_pcc_signal"] = table.mean_pcc_signal;
  j["mean_pcc_envelope"] = table.mean_pcc_envelope;
  j["resampling"] = table.resampling;
  j["envelope_method"] = table.envelope_method;
  j["only_in_a"] = table.only_in_a;
  j["only_in_b"] = table.only_in_b;
  j["excitation_left_out"] = table.excitation_left_out;
  if (q.arrival_relative) {
    j["arrival_relative"] = *q.arrival_relative;
    j["mean_abs_arrival_shift_us"] = mean_abs_shift_us;
    j["mean_abs_peak_error"] = mean_abs_peak_error;
  }
  return r;
}

}  // namespace mesowave::signal
