#include "mesowave/signal/signal_report.hpp"

#include <cmath>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/io/csv.hpp"
#include "mesowave/io/text_table.hpp"
#include "mesowave/signal/envelope.hpp"
#include "mesowave/signal/hann_burst.hpp"
#include "mesowave/signal/noise.hpp"
#include "mesowave/signal/select.hpp"
#include "mesowave/signal/spectrum.hpp"
#include "mesowave/signal/time_of_flight.hpp"

namespace mesowave::signal {
using json = nlohmann::ordered_json;

namespace {

std::optional<double> us_to_s(const std::optional<double>& us, const char* name) {
  if (!us) return std::nullopt;
  return require_finite(name, *us, "us") * units::us;
}

}  // namespace

SignalReport burst_report(const BurstRequest& q) {
  require_positive("--sampling-MHz", q.sampling_MHz, "MHz");
  require_finite("--delay-us", q.delay_us, "us");
  const HannBurst b(q.frequency_kHz * units::kHz, q.cycles, q.amplitude, q.delay_us * units::us);
  const double dt = 1.0 / (q.sampling_MHz * units::MHz);
  const double duration =
      q.duration_us ? require_positive("--duration-us", *q.duration_us, "us") * units::us : b.end_s() + dt;
  const auto count = std::size_t(std::llround(duration / dt));
  if (count < 1 || count > (std::size_t(1) << 31))
    throw InputError("--duration-us (" + format_number(duration / units::us) + " us) gives " + std::to_string(count) +
                     " samples at " + format_number(q.sampling_MHz) + " MHz");
  SignalReport r;
  r.attributes = {{"generator", "mw-signal burst"}};
  Signal& s = r.signals.emplace_back();
  s = {q.name, q.quantity, q.unit, "", 0.0, dt, b.sample(dt, count), std::nullopt};
  if (q.noise_rms != 0) {
    const auto noise = gaussian_noise(count, q.noise_rms, q.seed);
    for (std::size_t i = 0; i < count; ++i) s.samples[i] += noise[i];
  }
  auto& j = r.summary;
  j["output"] = q.output;
  j["name"] = q.name;
  j["samples"] = count;
  j["dt_ns"] = 1e3 / q.sampling_MHz;
  j["duration_us"] = double(count) * dt / units::us;
  j["frequency_kHz"] = q.frequency_kHz;
  j["cycles"] = q.cycles;
  j["burst_start_us"] = q.delay_us;
  j["burst_end_us"] = b.end_s() / units::us;
  j["main_lobe_kHz"] = json::array({q.frequency_kHz * (1 - 2 / q.cycles), q.frequency_kHz * (1 + 2 / q.cycles)});
  if (q.noise_rms != 0) {
    j["noise_rms"] = q.noise_rms;
    j["seed"] = q.seed;
  }
  if (b.end_s() > s.time(count - 1)) j["note"] = "the record ends before the burst does";
  return r;
}

std::vector<Signal> read_source(const SignalSource& source) {
  return select_signals(signal::read_signals(source.file), source.names, source.file.string());
}

SignalReport envelope_report(const SignalSource& source, const std::string& output, const std::string& detrend,
                             const std::string& pad) {
  const HilbertOptions options{parse_detrend(detrend), Padding::parse(pad)};
  const auto signals = read_source(source);
  const std::string input = source.file.string();
  SignalReport r;
  r.inputs = {source.file};
  json peaks = json::object();
  for (const auto& s : signals) {
    r.signals.push_back(envelope(s, options));
    const auto p = envelope_peak_pick(s, {{}, options});
    peaks[s.name] = {{"peak", r.signals.back().samples[p.index]}, {"unit", s.unit},
                     {"peak_time_us", p.time_s / units::us}};
    r.metrics.push_back({"envelope_peak_time_" + s.name, p.time_s / units::us, "us"});
  }
  r.attributes = {{"envelope_of", input}, {"envelope_method", options.describe(signals.front().size())}};
  auto& j = r.summary;
  j["input"] = input;
  j["output"] = output;
  j["method"] = "|x + i H{x}|, H by the FFT with scipy.signal.hilbert's definition";
  j["detrend"] = std::string(to_string(options.detrend));
  j["padding"] = options.padding.name();
  j["fft_length"] = options.padding.fft_length(signals.front().size());
  j["envelopes"] = peaks;
  return r;
}

SignalReport spectrum_report(const SignalSource& source, const std::string& output, const SpectrumRequest& q) {
  const SpectrumOptions options{parse_detrend(q.detrend), Padding::parse(q.pad), parse_spectrum_scaling(q.scaling)};
  const auto signals = read_source(source);
  const std::string input = source.file.string();
  if (q.max_frequency_kHz) require_positive("--max-frequency-kHz", *q.max_frequency_kHz, "kHz");
  SignalReport r;
  r.inputs = {source.file};
  std::vector<Spectrum> spectra;
  std::vector<std::string> header = {"f_kHz"};
  json peaks = json::object();
  for (const auto& s : signals) {
    spectra.push_back(amplitude_spectrum(s, options));
    if (spectra.back().frequency_hz.size() != spectra.front().frequency_hz.size() ||
        spectra.back().df_hz != spectra.front().df_hz)
      throw InputError("signals " + signals.front().name + " and " + s.name +
                       " give different frequency axes (length or sampling); choose one with --signals");
    header.push_back(s.name + " [" + spectra.back().unit(s.unit) + "]");
    const double f_peak = peak_frequency_hz(spectra.back(), spectra.back().df_hz);
    peaks[s.name] = {{"peak_frequency_kHz", f_peak / units::kHz}};
    r.metrics.push_back({"peak_frequency_" + s.name, f_peak / units::kHz, "kHz"});
  }
  const auto& axis = spectra.front().frequency_hz;
  std::vector<std::vector<std::string>> rows;
  for (std::size_t k = 0; k < axis.size(); ++k) {
    if (q.max_frequency_kHz && axis[k] > *q.max_frequency_kHz * units::kHz) break;
    std::vector<std::string> row = {format_exact(axis[k] / units::kHz)};
    for (const auto& sp : spectra) row.push_back(format_exact(sp.amplitude[k]));
    rows.push_back(std::move(row));
  }
  r.csv = io::to_csv(header, rows);
  auto& j = r.summary;
  j["input"] = input;
  j["output"] = output;
  j["scaling"] = std::string(to_string(options.scaling));
  j["detrend"] = std::string(to_string(options.detrend));
  j["padding"] = options.padding.name();
  j["fft_length"] = spectra.front().fft_length;
  j["df_kHz"] = spectra.front().df_hz / units::kHz;
  j["resolution_kHz"] = 1.0 / (double(spectra.front().samples) * signals.front().dt_s) / units::kHz;
  j["rows"] = rows.size();
  j["spectra"] = peaks;
  return r;
}

SignalReport tof_report(const SignalSource& source, const TofRequest& q) {
  if (q.method != "threshold" && q.method != "aic" && q.method != "envelope-peak")
    throw InputError("--method " + q.method + " must be threshold, aic or envelope-peak");
  const auto signals = read_source(source);
  const TimeWindow window{us_to_s(q.begin_us, "--window-begin-us"), us_to_s(q.end_us, "--window-end-us")};
  SignalReport r;
  r.inputs = {source.file};
  std::vector<std::vector<std::string>> rows;
  json picks = json::object();
  for (const auto& s : signals) {
    Pick p;
    if (q.method == "threshold") {
      ThresholdOptions o;
      o.noise_begin_s = us_to_s(q.noise_begin_us, "--noise-begin-us");
      o.noise_end_s = us_to_s(q.noise_end_us, "--noise-end-us");
      o.factor = q.factor;
      o.relative = q.relative;
      o.search = window;
      p = threshold_pick(s, o);
    } else if (q.method == "aic") {
      p = aic_pick(s, {window, parse_detrend(q.detrend.value_or("none"))});
    } else {
      p = envelope_peak_pick(s, {window, {parse_detrend(q.detrend.value_or("mean")), Padding::parse(q.pad)}});
    }
    // Qualities in seconds are reported in us, as the times.
    const bool in_seconds = p.quality_name.ends_with("_s");
    const double quality = in_seconds ? p.quality / units::us : p.quality;
    const std::string quality_name =
        in_seconds ? p.quality_name.substr(0, p.quality_name.size() - 2) + "_us" : p.quality_name;
    rows.push_back({s.name, p.method, format_fixed(p.time_s / units::us, 4), format_number(quality), quality_name});
    picks[s.name] = {{"t_us", p.time_s / units::us}, {"sample", p.index}, {quality_name, quality}};
    r.metrics.push_back({"tof_" + s.name, p.time_s / units::us, "us"});
  }
  const std::vector<std::string> header = {"signal", "method", "t_us", "quality", "quality_name"};
  r.text = io::format_text_table(header, rows);
  r.csv = io::to_csv(header, rows);
  r.summary["input"] = source.file.string();
  r.summary["method"] = q.method;
  r.summary["picks"] = picks;
  return r;
}

SignalReport convert_report(const std::vector<std::filesystem::path>& inputs, const std::vector<std::string>& names,
                            const signal::SignalCsvDefaults& defaults, const std::string& output) {
  std::vector<Signal> all;
  std::string from;
  for (const auto& file : inputs) {
    for (auto& s : signal::read_signals(file, defaults)) all.push_back(std::move(s));
    from += (from.empty() ? "" : " ") + file.string();
  }
  SignalReport r;
  r.inputs = inputs;
  r.signals = select_signals(all, names, from);
  r.attributes = {{"converted_from", from}};
  r.summary["inputs"] = from;
  r.summary["output"] = output;
  r.summary["signals"] = json::array();
  for (const auto& s : r.signals) r.summary["signals"].push_back(s.name);
  return r;
}

}  // namespace mesowave::signal
