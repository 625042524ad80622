// mw-signal - the excitation burst, envelopes, spectra, times of flight and HDF5 <-> CSV conversion of
// signal files (docs/formats.md; examples in --help). The analyses' reports live in signal/signal_report.
#include "mesowave/app/tool.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/signal/signal_csv.hpp"
#include "mesowave/signal/signal_report.hpp"

using namespace mesowave;
using namespace mesowave::signal;
namespace fs = std::filesystem;

namespace {

void add_input(CLI::App* sub, SignalSource& in) {
  sub->add_option("input", in.file, "Signal file: HDF5 (.h5) or CSV (.csv), see docs/formats.md")->required();
  sub->add_option("--signals", in.names, "Only these signals, by name (comma separated; default all)")->delimiter(',');
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
  fs::path json_out, out;
  auto add_json = [&](CLI::App* sub) {
    sub->add_option("--json", json_out, "Also write the JSON summary (printed on stdout) to FILE")->type_name("FILE");
  };

  auto* burst = cli.add_subcommand("burst", "An n-cycle Hann-windowed sine (the papers' excitation)");
  BurstRequest bq;
  burst->add_option("--frequency-kHz", bq.frequency_kHz, "Centre frequency f_c [kHz]")->required();
  burst->add_option("--cycles", bq.cycles, "Number of cycles n")->capture_default_str();
  burst->add_option("--amplitude", bq.amplitude, "Peak amplitude A of the sine, in --unit")->capture_default_str();
  burst->add_option("--delay-us", bq.delay_us, "Start of the burst [us]")->capture_default_str();
  burst->add_option("--sampling-MHz", bq.sampling_MHz, "Sampling rate [MHz] (dt = 1/rate)")->capture_default_str();
  burst->add_option("--duration-us", bq.duration_us, "Record length [us] (default: up to the end of the burst)");
  burst->add_option("--noise-rms", bq.noise_rms, "Add white Gaussian noise of this RMS (in --unit): test data")->capture_default_str();
  burst->add_option("--seed", bq.seed, "Seed of the noise (same seed, same samples)")->capture_default_str();
  burst->add_option("--name", bq.name, "Signal name")->capture_default_str();
  burst->add_option("--quantity", bq.quantity, "What the samples are (force, displacement, voltage, ...)")->capture_default_str();
  burst->add_option("--unit", bq.unit, "Unit of the samples")->capture_default_str();
  burst->add_option("--out", out, "Signal file to write (.h5 or .csv)")->required()->type_name("FILE");
  add_json(burst);

  auto* env = cli.add_subcommand("envelope", "Hilbert envelopes |x + i H{x}| of every (or the chosen) signal");
  SignalSource env_in;
  std::string detrend = "none", pad = "none";
  add_input(env, env_in);
  env->add_option("--detrend", detrend, "none | mean | linear: removed before the transform")->capture_default_str();
  env->add_option("--pad", pad, "none (as scipy.signal.hilbert) | double (>= 2n) | pow2 | an FFT length: zero padding "
                                "that keeps a burst near one end from wrapping onto the other")->capture_default_str();
  env->add_option("--out", out, "Envelope signals to write (.h5 or .csv)")->required()->type_name("FILE");
  add_json(env);

  auto* spec = cli.add_subcommand("spectrum", "One-sided amplitude spectra, one CSV column per signal");
  SignalSource spec_in;
  SpectrumRequest sq;
  add_input(spec, spec_in);
  spec->add_option("--detrend", sq.detrend, "none | mean | linear")->capture_default_str();
  spec->add_option("--pad", sq.pad, "none | double | pow2 | an FFT length (finer frequency grid)")->capture_default_str();
  spec->add_option("--scaling", sq.scaling, "amplitude (2|X_k|/n: a sine of amplitude a reads a) | density (|X_k| dt, "
                                            "the continuous transform's magnitude) | raw (|X_k|)")->capture_default_str();
  spec->add_option("--max-frequency-kHz", sq.max_frequency_kHz, "Write frequencies up to this [kHz] only");
  spec->add_option("--out", out, "Spectrum CSV to write: f_kHz, then one column per signal")->required()->type_name("FILE");
  add_json(spec);

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
  SignalSource tof_in;
  TofRequest tq;
  add_input(tof, tof_in);
  tof->add_option("--method", tq.method, "threshold | aic | envelope-peak")
      ->check(CLI::IsMember({"threshold", "aic", "envelope-peak"}))->capture_default_str();
  tof->add_option("--window-begin-us", tq.begin_us, "Pick no earlier than this [us]");
  tof->add_option("--window-end-us", tq.end_us,
                  "Pick no later than this [us] (aim AIC at the first arrival; default for AIC: the largest |x|)");
  tof->add_option("--noise-begin-us", tq.noise_begin_us, "threshold: start of the pre-trigger noise window [us]");
  tof->add_option("--noise-end-us", tq.noise_end_us, "threshold: end of the noise window [us] (default 0, the trigger)");
  tof->add_option("--factor", tq.factor, "threshold: multiple of the noise RMS")->capture_default_str();
  tof->add_option("--relative", tq.relative, "threshold: or this fraction of the peak, whichever is larger")->capture_default_str();
  tof->add_option("--detrend", tq.detrend, "aic, envelope-peak: none | mean | linear (default none | mean)");
  tof->add_option("--pad", tq.pad, "envelope-peak: padding of the envelope's FFT")->capture_default_str();
  tof->add_option("--out", out, "Also write the picks as CSV")->type_name("FILE");
  tof->add_option("--json", json_out, "Also write the picks as JSON to FILE")->type_name("FILE");

  auto* conv = cli.add_subcommand("convert", "Signal files HDF5 <-> CSV (by the extensions); several inputs merge");
  std::vector<fs::path> conv_files;
  std::vector<std::string> conv_names;
  signal::SignalCsvDefaults csv_defaults;
  conv->add_option("files", conv_files, "IN... OUT: signal files to read (.h5 or .csv, their signals gathered in "
                                        "order), then the file to write (.h5 or .csv)")->required()->expected(2, -1);
  conv->add_option("--signals", conv_names, "Only these signals, by name (comma separated; default all)")->delimiter(',');
  conv->add_option("--unit", csv_defaults.unit, "CSV input: unit of columns whose header has no [unit]");
  conv->add_option("--quantity", csv_defaults.quantity, "CSV input: quantity of signals without a '# signal' line");
  add_json(conv);

  return tool.run(argc, argv, [&](app::Run& run) {
    const auto emit = [&](const SignalReport& r) {
      for (const auto& f : r.inputs) run.input(f);
      if (!r.signals.empty()) signal::write_signals(run.output(out), signal::signal_format_of(out), r.signals, r.attributes);
      for (const auto& m : r.metrics) run.metric(m.name, m.value, m.unit);
      run.emit_json(r.summary, json_out);
    };
    if (burst->parsed()) {
      bq.output = out.string();
      emit(burst_report(bq));
    } else if (env->parsed()) {
      emit(envelope_report(env_in, out.string(), detrend, pad));
    } else if (spec->parsed()) {
      const auto r = spectrum_report(spec_in, out.string(), sq);
      run.write_text(out, r.csv);
      emit(r);
    } else if (tof->parsed()) {
      const auto r = tof_report(tof_in, tq);
      run.input(tof_in.file);
      for (const auto& m : r.metrics) run.metric(m.name, m.value, m.unit);
      run.out() << r.text;  // a table here, the JSON only with --json
      if (!out.empty()) run.write_text(out, r.csv);
      if (!json_out.empty()) run.write_text(json_out, r.summary.dump(2) + "\n");
    } else if (conv->parsed()) {
      if (conv_files.size() < 2) throw InputError("convert needs an input file and an output file");
      out = conv_files.back();
      signal::signal_format_of(out);  // refuse a bad output name before reading
      emit(convert_report({conv_files.begin(), conv_files.end() - 1}, conv_names, csv_defaults, out.string()));
    }
  });
}
