#include "mesowave/lab/upv_report.hpp"

#include <tuple>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/lab/picker_study.hpp"
#include "mesowave/lab/pulse_velocity.hpp"

namespace mesowave::lab {

std::vector<PickedTrace> UpvReport::traces() const {
  std::vector<PickedTrace> traces;
  for (auto [pk, key, label, colour] : {std::tuple{&p_pick, "t_p", "P wave", "#1f4e9c"},
                                        std::tuple{&s_pick, "t_s", "S wave", "#c0392b"}})
    if (*pk) traces.push_back({&(*pk)->record, (*pk)->onset, (*pk)->delay_s, label, key, colour});
  return traces;
}

namespace {

// The S record's matched filter (picker xcorr) with the stated wavelet.
OnsetOptions with_s_wavelet(OnsetOptions o, const UpvMeasurement& m, WaveformReadOptions read) {
  if (!m.s_wavelet.empty() && !m.s_wavelet_burst.empty())
    throw InputError("give either --s-wavelet or --s-wavelet-burst-kHz, not both");
  o.picker = "xcorr";
  if (!m.s_wavelet_burst.empty()) {
    if (m.s_wavelet_burst.size() != 2 || !(m.s_wavelet_burst[0] > 0) || !(m.s_wavelet_burst[1] > 0))
      throw InputError("--s-wavelet-burst-kHz needs a positive frequency [kHz] and cycle count, e.g. 120,2");
    const double f = m.s_wavelet_burst[0] * units::kHz;
    o.wavelet = burst_wavelet(f, m.s_wavelet_burst[1], m.s_wavelet_derivative, 1 / (200 * f));  // resampled onto the record
    return o;
  }
  read.added_noise_snr_dB.reset();  // the wavelet is the reference, as recorded
  auto w = read_upv_waveform(m.s_wavelet, read, "S wavelet (" + m.s_wavelet.filename().string() + ")");
  // Its first motion is at its t = 0: the samples before it are not the wavelet.
  const auto first = std::size_t(std::max(0.0, std::ceil(-w.t0_s / w.dt_s - 1e-9)));
  if (first + 4 > w.size()) throw InputError("--s-wavelet " + m.s_wavelet.string() + ": fewer than 4 samples at t >= 0");
  w.samples.erase(w.samples.begin(), w.samples.begin() + std::ptrdiff_t(first));
  w.t0_s = 0;
  o.wavelet = std::move(w);
  return o;
}

}  // namespace

UpvReport upv_report(const UpvMeasurement& m) {
  if ((!m.s_wavelet.empty() || !m.s_wavelet_burst.empty()) && m.s_wave.empty())
    throw InputError("--s-wavelet and --s-wavelet-burst-kHz pick the S record: give --s-wave");
  if (m.s_wavelet_derivative && m.s_wavelet_burst.empty())
    throw InputError("--s-wavelet-derivative applies to --s-wavelet-burst-kHz (a record given by --s-wavelet is matched as it is)");
  require_positive("--path-mm", m.path_mm, "mm");
  if (m.t_p_us && !m.p_wave.empty()) throw InputError("give either --t-p-us or --p-wave, not both");
  if (m.t_s_us && !m.s_wave.empty()) throw InputError("give either --t-s-us or --s-wave, not both");
  if (!m.t_p_us && m.p_wave.empty()) throw InputError("need --t-p-us, or a P-wave record (--p-wave)");
  auto read = m.read;
  if (m.sample_interval_us)
    read.sample_interval_s = require_positive("--sample-interval-us", *m.sample_interval_us, "us") * units::us;
  auto pick = m.pick;
  pick.crosstalk_s = m.crosstalk_us * units::us;
  if (m.lowpass_kHz < 0 || (m.s_lowpass_kHz && *m.s_lowpass_kHz < 0))
    throw InputError("low-pass corners must not be negative");
  pick.lowpass_Hz = m.lowpass_kHz * units::kHz;
  pick.aic_after_s = require_positive("--aic-after-us", m.aic_after_us, "us") * units::us;
  if (!m.noise_us.empty()) pick.noise_begin_s = m.noise_us[0] * units::us, pick.noise_end_s = m.noise_us[1] * units::us;

  UpvReport report;
  auto t_p_us = m.t_p_us, t_s_us = m.t_s_us;
  auto windowed = [&](OnsetOptions o, const std::vector<double>& window) {
    if (!window.empty()) o.search_begin_s = window[0] * units::us, o.search_end_s = window[1] * units::us;
    return o;
  };
  if (!m.p_wave.empty()) {
    report.p_pick = pick_time_of_flight(m.p_wave, read, windowed(pick, m.p_search_us), m.delay_us * units::us, "P wave");
    t_p_us = report.p_pick->tof_s / units::us;
  }
  if (!m.s_wave.empty()) {
    const double d = m.s_delay_us.value_or(m.delay_us) * units::us;
    auto o = windowed(pick, m.s_search_us);
    if (m.s_lowpass_kHz) o.lowpass_Hz = *m.s_lowpass_kHz * units::kHz;
    if (t_p_us) o = shear_wave_options(o, *t_p_us * units::us + d, d);
    if (!m.s_locator.empty()) o.locator = m.s_locator;
    if (!m.s_wavelet.empty() || !m.s_wavelet_burst.empty()) o = with_s_wavelet(o, m, read);
    auto s_read = read;  // a second record: noise of its own, as a lab's two records have
    ++s_read.added_noise_seed;
    report.s_pick = pick_time_of_flight(m.s_wave, s_read, o, d, "S wave");
    t_s_us = report.s_pick->tof_s / units::us;
  }
  // The S chain after a P pick is a strategy of its own in the picker table.
  const std::string s_strategy = report.s_pick ? report.s_pick->onset.pick.method + (t_p_us ? "-after-p" : "") : "";
  nlohmann::ordered_json picks;
  if (read.added_noise_snr_dB && (report.p_pick || report.s_pick)) {
    picks["added_noise_snr_dB"] = *read.added_noise_snr_dB;
    picks["added_noise_seed"] = read.added_noise_seed;
  }
  for (auto [pk, key] : {std::pair{&report.p_pick, "t_p"}, std::pair{&report.s_pick, "t_s"}}) {
    if (!*pk) continue;
    describe_pick(picks, key, **pk);
    const bool p = pk == &report.p_pick;
    describe_bias(picks, key,
                  state_pick_bias((*pk)->record, (*pk)->onset, p ? "P" : "S", p ? (*pk)->onset.pick.method : s_strategy));
    report.warnings.insert(report.warnings.end(), (*pk)->onset.warnings.begin(), (*pk)->onset.warnings.end());
  }

  require_positive("--t-p-us", *t_p_us, "us");
  if (t_s_us) require_positive("--t-s-us", *t_s_us, "us");
  if (t_s_us && m.nu_assumed) throw InputError("give either an S wave (nu_d measured) or --nu-assumed, not both");
  if (!t_s_us && !m.nu_assumed && m.density_kg_m3)
    throw InputError("need --t-s-us, or --nu-assumed for a P-wave-only test");
  if (m.density_kg_m3) require_positive("--density-kg-m3", *m.density_kg_m3, "kg/m3");

  auto& result = report.summary;
  result["path_mm"] = m.path_mm;
  result["t_p_us"] = *t_p_us;
  if (t_s_us) result["t_s_us"] = *t_s_us;
  const double path = m.path_mm * units::mm;
  if (m.density_kg_m3) {
    const double density = *m.density_kg_m3;
    const auto moduli = t_s_us ? dynamic_moduli_from_p_and_s(path, *t_p_us * units::us, *t_s_us * units::us, density)
                               : dynamic_moduli_from_p_only(path, *t_p_us * units::us, density, *m.nu_assumed);
    result["density_kg_m3"] = density;
    result["v_p_m_s"] = moduli.v_p_m_s;
    result["v_s_m_s"] = moduli.v_s_m_s;
    result["nu_d"] = moduli.nu_d;
    result["nu_d_source"] = t_s_us ? "measured: Eq. (10) from v_p/v_s" : "assumed (--nu-assumed)";
    result["E_d_GPa"] = moduli.E_d_Pa / units::GPa;
    result["G_d_GPa"] = moduli.G_d_Pa / units::GPa;
    result["method"] = t_s_us ? "Eqs. (9)-(10): E_d = 2 rho v_s^2 (1 + nu_d)"
                              : "ASTM C597: E_d = rho v_p^2 (1 + nu)(1 - 2 nu)/(1 - nu)";
  } else {
    result["v_p_m_s"] = path / (*t_p_us * units::us);
    if (t_s_us) {
      result["v_s_m_s"] = path / (*t_s_us * units::us);
      result["nu_d"] = poisson_ratio_from_velocity_ratio(*t_s_us / *t_p_us);
      result["nu_d_source"] = "measured: Eq. (10) from v_p/v_s";
    }
    result["method"] = "velocities only (no --density-kg-m3)";
  }
  for (auto& [k, v] : picks.items()) result[k] = v;
  if (report.p_pick || report.s_pick) result["warnings"] = report.warnings;
  return report;
}

}  // namespace mesowave::lab
