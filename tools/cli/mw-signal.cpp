// mw-signal - the excitation burst and the analysis of recorded or simulated
// signals: Hilbert envelopes, amplitude spectra, times of flight, and
// conversion between the HDF5 and CSV signal files (docs/formats.md).
//
//   mw-signal burst --cycles 5 --frequency-kHz 100 --sampling-MHz 10 --duration-us 100 --out burst.h5
//   mw-signal envelope burst.h5 --pad double --out envelope.h5
//   mw-signal spectrum burst.h5 --pad 65536 --max-frequency-kHz 300 --out spectrum.csv
//   mw-signal tof upv.csv --method aic --window-end-us 60
//   mw-signal convert sensors.h5 sensors.csv
//   mw-signal convert B.csv C.csv D.csv experiment.h5
#include <cmath>
#include <optional>

#include "mesowave/app/tool.hpp"
#include "mesowave/core/check.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/io/csv.hpp"
#include "mesowave/io/signal_csv.hpp"
#include "mesowave/io/text_table.hpp"
#include "mesowave/signal/envelope.hpp"
#include "mesowave/signal/hann_burst.hpp"
#include "mesowave/signal/noise.hpp"
#include "mesowave/signal/select.hpp"
#include "mesowave/signal/spectrum.hpp"
#include "mesowave/signal/time_of_flight.hpp"

using namespace mesowave;
using namespace mesowave::signal;
namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace {

// What every analysing subcommand shares.
struct Input {
  fs::path file;
  std::vector<std::string> names;
  std::vector<Signal> read(app::Run& run) const {
    run.input(file);
    return select_signals(io::read_signals(file), names, file.string());
  }
};

void add_input(CLI::App* sub, Input& in) {
  sub->add_option("input", in.file, "Signal file: HDF5 (.h5) or CSV (.csv), see docs/formats.md")->required();
  sub->add_option("--signals", in.names, "Only these signals, by name (comma separated; default all)")->delimiter(',');
}

std::optional<double> us_to_s(const std::optional<double>& us, const char* name) {
  if (!us) return std::nullopt;
  return require_finite(name, *us, "us") * units::us;
}

// Writes signals to `path` in the format its extension names, through the run's staging.
void write_signal_output(app::Run& run, const fs::path& path, const std::vector<Signal>& signals,
                         const std::map<std::string, std::string>& attributes) {
  const auto format = io::signal_format_of(path);
  io::write_signals(run.output(path), format, signals, attributes);
}

}  // namespace

int main(int argc, char** argv) {
  app::Tool tool("mw-signal",
                 "Excitation bursts and signal analysis. burst: an n-cycle sine in a Hann window, "
                 "f(t) = A sin(2 pi f_c t) (1 - cos(2 pi f_c t / n)) / 2 for 0 <= t <= n / f_c (after a delay). "
                 "envelope: |x + i H{x}|, the Hilbert transform by the FFT exactly as scipy.signal.hilbert "
                 "(optionally detrended and zero padded, which is stated in the output). spectrum: one-sided "
                 "amplitude spectrum 2|X_k|/n at f_k = k/(M dt). tof: time of flight by a threshold over the "
                 "pre-trigger noise, Maeda's AIC picker or the envelope peak, each with a quality measure. "
                 "convert: HDF5 <-> CSV.\n\n"
                 "  mw-signal burst --cycles 5 --frequency-kHz 100 --sampling-MHz 10 --duration-us 100 --out burst.h5\n"
                 "  mw-signal envelope burst.h5 --pad double --out envelope.h5\n"
                 "  mw-signal spectrum burst.h5 --pad 65536 --max-frequency-kHz 300 --out spectrum.csv\n"
                 "  mw-signal tof upv.csv --method aic --window-end-us 60\n"
                 "  mw-signal convert sensors.h5 sensors.csv\n"
                 "  mw-signal convert B.csv C.csv D.csv experiment.h5");
  auto& cli = tool.cli();
  cli.require_subcommand(1);
  fs::path json_out;
  auto add_json = [&](CLI::App* sub) {
    sub->add_option("--json", json_out, "Also write the JSON summary (printed on stdout) to FILE")->type_name("FILE");
  };

  // burst
  auto* burst = cli.add_subcommand("burst", "An n-cycle Hann-windowed sine (the papers' excitation)");
  double frequency_kHz = 0, cycles = 5, amplitude = 1, delay_us = 0, sampling_MHz = 10;
  std::optional<double> duration_us;
  double noise_rms = 0;
  std::uint64_t seed = 1;
  std::string burst_name = "excitation", quantity = "force", unit = "N";
  fs::path burst_out;
  burst->add_option("--frequency-kHz", frequency_kHz, "Centre frequency f_c [kHz]")->required();
  burst->add_option("--cycles", cycles, "Number of cycles n")->capture_default_str();
  burst->add_option("--amplitude", amplitude, "Peak amplitude A of the sine, in --unit")->capture_default_str();
  burst->add_option("--delay-us", delay_us, "Start of the burst [us]")->capture_default_str();
  burst->add_option("--sampling-MHz", sampling_MHz, "Sampling rate [MHz] (dt = 1/rate)")->capture_default_str();
  burst->add_option("--duration-us", duration_us, "Record length [us] (default: up to the end of the burst)");
  burst->add_option("--noise-rms", noise_rms, "Add white Gaussian noise of this RMS (in --unit): synthetic test data")
      ->capture_default_str();
  burst->add_option("--seed", seed, "Seed of the noise (same seed, same samples)")->capture_default_str();
  burst->add_option("--name", burst_name, "Signal name")->capture_default_str();
  burst->add_option("--quantity", quantity, "What the samples are (force, displacement, voltage, ...)")->capture_default_str();
  burst->add_option("--unit", unit, "Unit of the samples")->capture_default_str();
  burst->add_option("--out", burst_out, "Signal file to write (.h5 or .csv)")->required()->type_name("FILE");
  add_json(burst);

  // envelope
  auto* env = cli.add_subcommand("envelope", "Hilbert envelopes |x + i H{x}| of every (or the chosen) signal");
  Input env_in;
  std::string detrend_text = "none", pad_text = "none";
  fs::path env_out;
  add_input(env, env_in);
  env->add_option("--detrend", detrend_text, "none | mean | linear: removed before the transform")->capture_default_str();
  env->add_option("--pad", pad_text,
                  "none (as scipy.signal.hilbert) | double (>= 2n) | pow2 | an FFT length: zero padding that keeps "
                  "a burst near one end from wrapping onto the other")
      ->capture_default_str();
  env->add_option("--out", env_out, "Envelope signals to write (.h5 or .csv)")->required()->type_name("FILE");
  add_json(env);

  // spectrum
  auto* spec = cli.add_subcommand("spectrum", "One-sided amplitude spectra, one CSV column per signal");
  Input spec_in;
  std::string spec_detrend = "none", spec_pad = "none", scaling_text = "amplitude";
  std::optional<double> max_frequency_kHz;
  fs::path spec_out;
  add_input(spec, spec_in);
  spec->add_option("--detrend", spec_detrend, "none | mean | linear")->capture_default_str();
  spec->add_option("--pad", spec_pad, "none | double | pow2 | an FFT length (finer frequency grid)")->capture_default_str();
  spec->add_option("--scaling", scaling_text,
                   "amplitude (2|X_k|/n: a sine of amplitude a reads a) | density (|X_k| dt, the continuous "
                   "transform's magnitude) | raw (|X_k|)")
      ->capture_default_str();
  spec->add_option("--max-frequency-kHz", max_frequency_kHz, "Write frequencies up to this [kHz] only");
  spec->add_option("--out", spec_out, "Spectrum CSV to write: f_kHz, then one column per signal")
      ->required()
      ->type_name("FILE");
  add_json(spec);

  // tof
  auto* tof = cli.add_subcommand("tof", "Time of flight of every (or the chosen) signal, with a quality measure");
  tof->footer(
      "\nthreshold: the first sample whose "
      "deviation from the pre-trigger mean reaches max(factor x noise RMS, relative x peak), refined between "
      "samples (quality snr_dB). aic: Maeda's picker, the minimum of AIC(k) = k log var(x[1..k]) + (N-k-1) log "
      "var(x[k+1..N]) over the window, by default from the start to the largest |x| (quality aic_sd_us: the spread "
      "of the pick under the Akaike weights). envelope-peak: the maximum of the Hilbert envelope, the group "
      "arrival (quality peak_ratio: over the next highest packet).\n\n"
      "  mw-signal tof upv.csv --method threshold --noise-end-us 0\n"
      "  mw-signal tof sensors.h5 --method envelope-peak --window-begin-us 20 --window-end-us 120");
  Input tof_in;
  std::string method = "aic";
  std::optional<std::string> tof_detrend;
  std::string tof_pad = "double";
  std::optional<double> begin_us, end_us, noise_begin_us, noise_end_us;
  double factor = 5, relative = 0;
  fs::path tof_out;
  add_input(tof, tof_in);
  tof->add_option("--method", method, "threshold | aic | envelope-peak")
      ->check(CLI::IsMember({"threshold", "aic", "envelope-peak"}))
      ->capture_default_str();
  tof->add_option("--window-begin-us", begin_us, "Pick no earlier than this [us]");
  tof->add_option("--window-end-us", end_us,
                  "Pick no later than this [us] (aim AIC at the first arrival; default for AIC: the largest |x|)");
  tof->add_option("--noise-begin-us", noise_begin_us, "threshold: start of the pre-trigger noise window [us]");
  tof->add_option("--noise-end-us", noise_end_us, "threshold: end of the noise window [us] (default 0, the trigger)");
  tof->add_option("--factor", factor, "threshold: multiple of the noise RMS")->capture_default_str();
  tof->add_option("--relative", relative, "threshold: or this fraction of the peak, whichever is larger")
      ->capture_default_str();
  tof->add_option("--detrend", tof_detrend, "aic, envelope-peak: none | mean | linear (default none for aic, mean "
                                            "for envelope-peak)");
  tof->add_option("--pad", tof_pad, "envelope-peak: padding of the envelope's FFT")->capture_default_str();
  tof->add_option("--out", tof_out, "Also write the picks as CSV")->type_name("FILE");
  tof->add_option("--json", json_out, "Also write the picks as JSON to FILE")->type_name("FILE");

  // convert
  auto* conv = cli.add_subcommand("convert", "Signal files HDF5 <-> CSV (by the extensions); several inputs merge");
  std::vector<fs::path> conv_files;
  std::vector<std::string> conv_names;
  std::string csv_unit, csv_quantity;
  conv->add_option("files", conv_files, "IN... OUT: signal files to read (.h5 or .csv, their signals gathered in "
                                        "order), then the file to write (.h5 or .csv)")
      ->required()
      ->expected(2, -1);
  conv->add_option("--signals", conv_names, "Only these signals, by name (comma separated; default all)")->delimiter(',');
  conv->add_option("--unit", csv_unit, "CSV input: unit of columns whose header has no [unit]");
  conv->add_option("--quantity", csv_quantity, "CSV input: quantity of signals without a '# signal' line");
  add_json(conv);

  return tool.run(argc, argv, [&](app::Run& run) {
    json result;
    if (burst->parsed()) {
      require_positive("--sampling-MHz", sampling_MHz, "MHz");
      require_finite("--delay-us", delay_us, "us");
      const HannBurst b(frequency_kHz * units::kHz, cycles, amplitude, delay_us * units::us);
      const double dt = 1.0 / (sampling_MHz * units::MHz);
      const double duration = duration_us ? require_positive("--duration-us", *duration_us, "us") * units::us
                                          : b.end_s() + dt;
      const auto count = std::size_t(std::llround(duration / dt));
      if (count < 1 || count > (std::size_t(1) << 31))
        throw InputError("--duration-us (" + format_number(duration / units::us) + " us) gives " +
                         std::to_string(count) + " samples at " + format_number(sampling_MHz) + " MHz");
      Signal s{burst_name, quantity, unit, "", 0.0, dt, b.sample(dt, count), std::nullopt};
      if (noise_rms != 0) {
        const auto noise = gaussian_noise(count, noise_rms, seed);
        for (std::size_t i = 0; i < count; ++i) s.samples[i] += noise[i];
      }
      write_signal_output(run, burst_out, {s}, {{"generator", "mw-signal burst"}});
      result["output"] = burst_out.string();
      result["name"] = burst_name;
      result["samples"] = count;
      result["dt_ns"] = 1e3 / sampling_MHz;
      result["duration_us"] = double(count) * dt / units::us;
      result["frequency_kHz"] = frequency_kHz;
      result["cycles"] = cycles;
      result["burst_start_us"] = delay_us;
      result["burst_end_us"] = b.end_s() / units::us;
      result["main_lobe_kHz"] = json::array({frequency_kHz * (1 - 2 / cycles), frequency_kHz * (1 + 2 / cycles)});
      if (noise_rms != 0) {
        result["noise_rms"] = noise_rms;
        result["seed"] = seed;
      }
      if (b.end_s() > s.time(count - 1)) result["note"] = "the record ends before the burst does";
    } else if (env->parsed()) {
      const HilbertOptions options{parse_detrend(detrend_text), Padding::parse(pad_text)};
      const auto signals = env_in.read(run);
      std::vector<Signal> envelopes;
      json peaks = json::object();
      for (const auto& s : signals) {
        envelopes.push_back(envelope(s, options));
        const auto p = envelope_peak_pick(s, {{}, options});
        peaks[s.name] = {{"peak", envelopes.back().samples[p.index]}, {"unit", s.unit},
                         {"peak_time_us", p.time_s / units::us}};
        run.metric("envelope_peak_time_" + s.name, p.time_s / units::us, "us");
      }
      const std::string described = options.describe(signals.front().size());
      write_signal_output(run, env_out, envelopes,
                          {{"envelope_of", env_in.file.string()}, {"envelope_method", described}});
      result["input"] = env_in.file.string();
      result["output"] = env_out.string();
      result["method"] = "|x + i H{x}|, H by the FFT with scipy.signal.hilbert's definition";
      result["detrend"] = std::string(to_string(options.detrend));
      result["padding"] = options.padding.name();
      result["fft_length"] = options.padding.fft_length(signals.front().size());
      result["envelopes"] = peaks;
    } else if (spec->parsed()) {
      const SpectrumOptions options{parse_detrend(spec_detrend), Padding::parse(spec_pad),
                                    parse_spectrum_scaling(scaling_text)};
      const auto signals = spec_in.read(run);
      if (max_frequency_kHz) require_positive("--max-frequency-kHz", *max_frequency_kHz, "kHz");
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
        run.metric("peak_frequency_" + s.name, f_peak / units::kHz, "kHz");
      }
      const auto& axis = spectra.front().frequency_hz;
      std::vector<std::vector<std::string>> rows;
      for (std::size_t k = 0; k < axis.size(); ++k) {
        if (max_frequency_kHz && axis[k] > *max_frequency_kHz * units::kHz) break;
        std::vector<std::string> row = {format_exact(axis[k] / units::kHz)};
        for (const auto& sp : spectra) row.push_back(format_exact(sp.amplitude[k]));
        rows.push_back(std::move(row));
      }
      run.write_text(spec_out, io::to_csv(header, rows));
      result["input"] = spec_in.file.string();
      result["output"] = spec_out.string();
      result["scaling"] = std::string(to_string(options.scaling));
      result["detrend"] = std::string(to_string(options.detrend));
      result["padding"] = options.padding.name();
      result["fft_length"] = spectra.front().fft_length;
      result["df_kHz"] = spectra.front().df_hz / units::kHz;
      result["resolution_kHz"] = 1.0 / (double(spectra.front().samples) * signals.front().dt_s) / units::kHz;
      result["rows"] = rows.size();
      result["spectra"] = peaks;
    } else if (tof->parsed()) {
      const auto signals = tof_in.read(run);
      const TimeWindow window{us_to_s(begin_us, "--window-begin-us"), us_to_s(end_us, "--window-end-us")};
      std::vector<std::vector<std::string>> rows;
      json picks = json::object();
      for (const auto& s : signals) {
        Pick p;
        if (method == "threshold") {
          ThresholdOptions o;
          o.noise_begin_s = us_to_s(noise_begin_us, "--noise-begin-us");
          o.noise_end_s = us_to_s(noise_end_us, "--noise-end-us");
          o.factor = factor;
          o.relative = relative;
          o.search = window;
          p = threshold_pick(s, o);
        } else if (method == "aic") {
          p = aic_pick(s, {window, parse_detrend(tof_detrend.value_or("none"))});
        } else {
          p = envelope_peak_pick(s, {window, {parse_detrend(tof_detrend.value_or("mean")), Padding::parse(tof_pad)}});
        }
        const bool in_seconds = p.quality_name.ends_with("_s");
        const double quality = in_seconds ? p.quality / units::us : p.quality;
        const std::string quality_name = in_seconds ? p.quality_name.substr(0, p.quality_name.size() - 2) + "_us"
                                                    : p.quality_name;
        rows.push_back({s.name, p.method, format_fixed(p.time_s / units::us, 4), format_number(quality), quality_name});
        picks[s.name] = {{"t_us", p.time_s / units::us}, {"sample", p.index}, {quality_name, quality}};
        run.metric("tof_" + s.name, p.time_s / units::us, "us");
      }
      const std::vector<std::string> header = {"signal", "method", "t_us", "quality", "quality_name"};
      run.out() << io::format_text_table(header, rows);  // a table here, the JSON only with --json
      if (!tof_out.empty()) run.write_text(tof_out, io::to_csv(header, rows));
      result["input"] = tof_in.file.string();
      result["method"] = method;
      result["picks"] = picks;
      if (!json_out.empty()) run.write_text(json_out, result.dump(2) + "\n");
      return;
    } else if (conv->parsed()) {
      if (conv_files.size() < 2) throw InputError("convert needs an input file and an output file");
      const std::vector<fs::path> conv_in(conv_files.begin(), conv_files.end() - 1);
      const fs::path conv_out = conv_files.back();
      io::signal_format_of(conv_out);  // refuse a bad output name before reading
      std::vector<Signal> all;
      std::string from;
      for (const auto& file : conv_in) {
        run.input(file);
        for (auto& s : io::read_signals(file, {csv_unit, csv_quantity})) all.push_back(std::move(s));
        from += (from.empty() ? "" : " ") + file.string();
      }
      const auto signals = select_signals(all, conv_names, from);
      write_signal_output(run, conv_out, signals, {{"converted_from", from}});
      result["inputs"] = from;
      result["output"] = conv_out.string();
      json names = json::array();
      for (const auto& s : signals) names.push_back(s.name);
      result["signals"] = names;
    }
    run.emit_json(result, json_out);
  });
}
