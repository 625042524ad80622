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
#include <optional>
#include <tuple>

#include "mesowave/app/tool.hpp"
#include "mesowave/core/check.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/io/gnuplot.hpp"
#include "mesowave/lab/pulse_velocity.hpp"
#include "mesowave/lab/upv_waveform.hpp"

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
                 "receive, up to 3.5 t_p (nu < 0.45), located by its envelope peak. Without a density only velocities "
                 "and nu_d are given.\n\n"
                 "  mw-upv --path-mm 150 --t-p-us 35 --t-s-us 55.1 --density-kg-m3 2129.56\n"
                 "  mw-upv --from lab-data/concrete-cube/upv.toml --from results/concrete-cube/density.json\n"
                 "  mw-upv --path-mm 150 --p-wave raw/upv-p.csv --s-wave raw/upv-s.csv --density-kg-m3 2129.56 "
                 "--plot fig7.png");
  double path_mm = 0;
  std::optional<double> t_p_us, t_s_us, nu_assumed, density, s_delay_us, s_lowpass_kHz;
  std::filesystem::path out, p_wave, s_wave, plot;
  std::string title, s_locator;
  double delay_us = 0;
  lab::WaveformReadOptions read;
  lab::OnsetOptions pick;
  std::optional<double> sample_interval_us;
  double crosstalk_us = 0, aic_after_us = 10, lowpass_kHz = 0;
  std::vector<double> noise_us, p_search_us, s_search_us;
  auto& cli = tool.cli();
  cli.add_option("--path-mm", path_mm, "Distance between the transducers [mm]")->required();
  cli.add_option("--t-p-us", t_p_us, "Time of flight of the P (longitudinal) wave [us]");
  cli.add_option("--t-s-us", t_s_us, "Time of flight of the S (shear) wave [us]");
  cli.add_option("--density-kg-m3", density, "Density of the specimen [kg/m3] (e.g. from mw-specimen)");
  cli.add_option("--nu-assumed", nu_assumed, "Poisson ratio to assume when only the P wave was measured");
  auto* g = "waveforms";
  cli.add_option("--p-wave", p_wave, "P-wave record (CSV or WAV) to pick t_p on")->group(g)->type_name("FILE");
  cli.add_option("--s-wave", s_wave, "S-wave record (CSV or WAV) to pick t_s on")->group(g)->type_name("FILE");
  cli.add_option("--picker", pick.picker, "aic, threshold or envelope-peak")
      ->group(g)->check(CLI::IsMember({"aic", "threshold", "envelope-peak"}))->capture_default_str();
  cli.add_option("--threshold-factor", pick.threshold_factor, "Threshold = factor x pre-trigger noise RMS")
      ->group(g)->capture_default_str();
  cli.add_option("--locate-relative", pick.threshold_relative, "Arrival located where the record first reaches this "
                                                                "fraction of its peak (or the threshold factor)")
      ->group(g)->capture_default_str();
  cli.add_option("--s-locator", s_locator, "threshold or envelope-peak (default for S after a P pick)")
      ->group(g)->check(CLI::IsMember({"threshold", "envelope-peak"}));
  cli.add_option("--min-arrival-snr", pick.min_arrival_snr, "The located arrival's RMS over --aic-after-us must be at "
                                                             "least this many times the noise RMS")
      ->group(g)->capture_default_str();
  cli.add_option("--aic-after-us", aic_after_us, "AIC window reaches this far past the threshold crossing [us]")
      ->group(g)->capture_default_str();
  cli.add_option("--lowpass-kHz", lowpass_kHz, "Zero-phase low-pass before picking, corner [kHz] (0: none)")
      ->group(g)->capture_default_str();
  cli.add_option("--s-lowpass-kHz", s_lowpass_kHz, "Low-pass corner for the S record if it differs [kHz]")->group(g);
  cli.add_option("--crosstalk-us", crosstalk_us, "Electrical cross-talk after the trigger, not searched [us]")
      ->group(g)->capture_default_str();
  cli.add_option("--noise-window-us", noise_us, "Noise window begin,end [us] (default: the pre-trigger)")
      ->group(g)->delimiter(',')->expected(2);
  cli.add_option("--p-search-us", p_search_us, "P onset search window begin,end [us]")->group(g)->delimiter(',')->expected(2);
  cli.add_option("--s-search-us", s_search_us, "S onset search window begin,end [us] (default from 1.3 t_p)")
      ->group(g)->delimiter(',')->expected(2);
  cli.add_option("--delay-us", delay_us, "Transducer + couplant delay subtracted from the picks [us]")
      ->group(g)->capture_default_str();
  cli.add_option("--s-delay-us", s_delay_us, "Delay of the S transducers if it differs [us]")->group(g);
  cli.add_option("--time-column", read.time_column, "Time column: name, or 1-based index with --no-header")->group(g);
  cli.add_option("--amplitude-column", read.amplitude_column, "Amplitude column (default: the one after time)")->group(g);
  cli.add_flag("--no-header", read.no_header, "The CSV has no header row")->group(g);
  cli.add_option("--time-unit", read.time_unit, "Time unit of a headerless CSV: s, ms or us")->group(g);
  cli.add_option("--sample-interval-us", sample_interval_us, "WAV: the true sample interval [us]")->group(g);
  cli.add_option("--trigger-sample", read.trigger_sample, "WAV: 0-based sample at the trigger (t = 0)")->group(g);
  cli.add_option("--plot", plot, "PNG of the records with the picks marked (like Fig. 7)")->group(g)->type_name("FILE");
  cli.add_option("--title", title, "Plot title")->group(g);
  app::add_out_option(cli, out);

  return tool.run(argc, argv, [&](app::Run& run) {
    require_positive("--path-mm", path_mm, "mm");
    if (t_p_us && !p_wave.empty()) throw InputError("give either --t-p-us or --p-wave, not both");
    if (t_s_us && !s_wave.empty()) throw InputError("give either --t-s-us or --s-wave, not both");
    if (!t_p_us && p_wave.empty()) throw InputError("need --t-p-us, or a P-wave record (--p-wave)");
    if (sample_interval_us) read.sample_interval_s = require_positive("--sample-interval-us", *sample_interval_us, "us") * units::us;
    pick.crosstalk_s = crosstalk_us * units::us;
    if (lowpass_kHz < 0 || (s_lowpass_kHz && *s_lowpass_kHz < 0)) throw InputError("low-pass corners must not be negative");
    pick.lowpass_Hz = lowpass_kHz * units::kHz;
    pick.aic_after_s = require_positive("--aic-after-us", aic_after_us, "us") * units::us;
    if (!noise_us.empty()) pick.noise_begin_s = noise_us[0] * units::us, pick.noise_end_s = noise_us[1] * units::us;

    nlohmann::ordered_json picks;
    std::vector<std::string> warnings;
    std::optional<lab::TimeOfFlightPick> p_pick, s_pick;
    auto windowed = [&](lab::OnsetOptions o, const std::vector<double>& window) {
      if (!window.empty()) o.search_begin_s = window[0] * units::us, o.search_end_s = window[1] * units::us;
      return o;
    };
    if (!p_wave.empty()) {
      run.input(p_wave);
      p_pick = lab::pick_time_of_flight(p_wave, read, windowed(pick, p_search_us), delay_us * units::us, "P wave");
      t_p_us = p_pick->tof_s / units::us;
    }
    if (!s_wave.empty()) {
      run.input(s_wave);
      const double d = s_delay_us.value_or(delay_us) * units::us;
      auto o = windowed(pick, s_search_us);
      if (s_lowpass_kHz) o.lowpass_Hz = *s_lowpass_kHz * units::kHz;
      if (t_p_us) o = lab::shear_wave_options(o, *t_p_us * units::us + d, d);
      if (!s_locator.empty()) o.locator = s_locator;
      s_pick = lab::pick_time_of_flight(s_wave, read, o, d, "S wave");
      t_s_us = s_pick->tof_s / units::us;
    }
    std::vector<lab::PickedTrace> traces;
    for (auto [pk, key, label, colour] : {std::tuple{&p_pick, "t_p", "P wave", "#1f4e9c"},
                                          std::tuple{&s_pick, "t_s", "S wave", "#c0392b"}}) {
      if (!*pk) continue;
      lab::describe_pick(picks, key, **pk);
      warnings.insert(warnings.end(), (*pk)->onset.warnings.begin(), (*pk)->onset.warnings.end());
      traces.push_back({&(*pk)->record, (*pk)->onset, (*pk)->delay_s, label, key, colour});
    }

    require_positive("--t-p-us", *t_p_us, "us");
    if (t_s_us) require_positive("--t-s-us", *t_s_us, "us");
    if (t_s_us && nu_assumed) throw InputError("give either an S wave (nu_d measured) or --nu-assumed, not both");
    if (!t_s_us && !nu_assumed && density) throw InputError("need --t-s-us, or --nu-assumed for a P-wave-only test");
    if (density) require_positive("--density-kg-m3", *density, "kg/m3");
    for (const auto& w : warnings) std::cerr << "warning: " << w << "\n";

    nlohmann::ordered_json result;
    result["path_mm"] = path_mm;
    result["t_p_us"] = *t_p_us;
    if (t_s_us) result["t_s_us"] = *t_s_us;
    const double path = path_mm * units::mm;
    if (density) {
      const auto m = t_s_us ? lab::dynamic_moduli_from_p_and_s(path, *t_p_us * units::us, *t_s_us * units::us, *density)
                            : lab::dynamic_moduli_from_p_only(path, *t_p_us * units::us, *density, *nu_assumed);
      result["density_kg_m3"] = *density;
      result["v_p_m_s"] = m.v_p_m_s;
      result["v_s_m_s"] = m.v_s_m_s;
      result["nu_d"] = m.nu_d;
      result["nu_d_source"] = t_s_us ? "measured: Eq. (10) from v_p/v_s" : "assumed (--nu-assumed)";
      result["E_d_GPa"] = m.E_d_Pa / units::GPa;
      result["G_d_GPa"] = m.G_d_Pa / units::GPa;
      result["method"] = t_s_us ? "Eqs. (9)-(10): E_d = 2 rho v_s^2 (1 + nu_d)"
                                : "ASTM C597: E_d = rho v_p^2 (1 + nu)(1 - 2 nu)/(1 - nu)";
      run.metric("E_d", m.E_d_Pa / units::GPa, "GPa");
    } else {
      result["v_p_m_s"] = path / (*t_p_us * units::us);
      if (t_s_us) {
        result["v_s_m_s"] = path / (*t_s_us * units::us);
        result["nu_d"] = lab::poisson_ratio_from_velocity_ratio(*t_s_us / *t_p_us);
        result["nu_d_source"] = "measured: Eq. (10) from v_p/v_s";
      }
      result["method"] = "velocities only (no --density-kg-m3)";
    }
    run.metric("v_p", result["v_p_m_s"].get<double>(), "m/s");
    if (t_s_us) run.metric("v_s", result["v_s_m_s"].get<double>(), "m/s");
    if (result.contains("nu_d")) run.metric("nu_d", result["nu_d"].get<double>(), "");
    for (auto& [k, v] : picks.items()) result[k] = v;
    if (!traces.empty()) result["warnings"] = warnings;
    if (!plot.empty()) {
      if (traces.empty()) throw InputError("--plot needs a recorded waveform (--p-wave or --s-wave)");
      io::run_gnuplot(lab::upv_figure_script(traces, run.output(plot), title));
    }
    run.emit_json(result, out);
  });
}
