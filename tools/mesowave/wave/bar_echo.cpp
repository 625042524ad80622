#include "mesowave/wave/bar_echo.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "mesowave/core/check.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/io/csv.hpp"
#include "mesowave/signal/signal_csv.hpp"
#include "mesowave/signal/spectrum.hpp"
#include "mesowave/signal/time_of_flight.hpp"
#include "mesowave/signal/envelope.hpp"
#include "mesowave/signal/fft.hpp"

namespace mesowave::wave {

namespace {

// Signed sample of largest magnitude in [a, b].
double extreme_in(const signal::Signal& s, double a, double b) {
  double best = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double t = s.time(i);
    if (t >= a && t <= b && std::abs(s.samples[i]) > std::abs(best)) best = s.samples[i];
  }
  return best;
}

// First crossing of `level` searching forward in [a, b], linear between samples.
double crossing(const signal::Signal& s, double level, double a, double b) {
  for (std::size_t i = 1; i < s.size(); ++i) {
    const double ta = s.time(i - 1), tb = s.time(i);
    if (ta < a) continue;
    if (tb > b) break;
    const double ya = s.samples[i - 1] - level, yb = s.samples[i] - level;
    if ((ya < 0) != (yb < 0)) return ta + s.dt_s * ya / (ya - yb);
  }
  throw InputError("record " + s.name + ": no edge crossing " + format_number(level) + " between " +
                   format_quantity(a / units::us, "us") + " and " + format_quantity(b / units::us, "us"));
}

}  // namespace

signal::Signal signal_from_csv(const std::string& path, const std::string& column) {
  const auto t = io::read_csv(path);
  std::optional<std::size_t> col;
  for (std::size_t c = 0; c < t.header.size(); ++c) {
    const auto& h = t.header[c];
    if (h == column || h.substr(0, h.find('/')) == column) col = c;
  }
  if (!col) throw InputError(path + " has no column " + column);
  const std::size_t n = t.rows.size();
  if (n < 16) throw InputError(path + " has fewer than 16 rows");
  // Least-squares line t_i = t0 + i dt through every printed time: the rounding
  // of single entries averages out (two endpoints alone can be off by a digit).
  double si = 0, st = 0, sii = 0, sit = 0, tmax = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double ti = t.number(i, 0), x = double(i);
    si += x;
    st += ti;
    sii += x * x;
    sit += x * ti;
    tmax = std::max(tmax, std::abs(ti));
  }
  const double m = double(n);
  const double dt = (sit - si * st / m) / (sii - si * si / m);
  const double t0 = (st - dt * si) / m;
  if (!(dt > 0)) throw InputError(path + ": the time column does not increase");
  for (std::size_t i = 0; i < n; ++i) {
    // Three significant digits print a time to within half a unit of its last digit,
    // at most 0.5 % of the largest |t|.
    if (std::abs(t.number(i, 0) - (t0 + double(i) * dt)) > 5e-3 * tmax + dt)
      throw InputError(path + " line " + std::to_string(t.row_lines[i]) +
                       ": the time is not on a uniform grid (cannot rebuild the time base)");
  }
  signal::Signal s;
  s.name = column;
  s.quantity = "strain";
  s.unit = "";
  s.t0_s = t0;
  s.dt_s = dt;
  for (std::size_t i = 0; i < n; ++i) s.samples.push_back(t.number(i, *col));
  return s;
}

signal::Signal propagate_l01(const signal::Signal& pulse, const PochhammerChree& pc, double distance,
                             double f_max) {
  require_positive("propagation distance", distance, "m");
  // Long enough for the slowest L(0,1) content kept (c_group >= 0.3 c0) to arrive.
  const double delay = distance / (0.3 * pc.speeds().c0);
  const std::size_t n = signal::fast_fft_length(pulse.size() + std::size_t(delay / pulse.dt_s) + 16);
  auto X = signal::rfft(pulse.samples, n);
  std::vector<double> f;
  for (std::size_t j = 1; j < X.size(); ++j) {
    const double fj = double(j) / (double(n) * pulse.dt_s);
    if (fj >= f_max) break;
    f.push_back(fj);
  }
  TraceOptions opt;
  opt.f_max_Hz = f_max;
  // Coarser steps than the defaults: only L(0,1) is used, and the roots are refined
  // to full precision at every point whatever the step.
  opt.ka_step = 0.04;
  opt.scan_step = 0.04;
  const auto pts = sample_at_frequencies(pc, trace_longitudinal_modes(pc, opt), f);
  std::vector<double> k;
  for (const auto& p : pts)
    if (p.mode == 1) k.push_back(p.k_rad_m);
  if (k.size() != f.size()) throw std::logic_error("L(0,1) not found at every frequency");
  // A cosine taper from f_max / 2 to f_max: a brick-wall cut would ring ahead of the front.
  for (std::size_t j = 1; j < X.size(); ++j) {
    if (j - 1 >= k.size()) {
      X[j] = 0;
      continue;
    }
    const double x = std::clamp(2 * f[j - 1] / f_max - 1, 0.0, 1.0);
    X[j] *= std::polar(0.5 * (1 + std::cos(std::numbers::pi * x)), -k[j - 1] * distance);
  }
  signal::Signal out = pulse;
  out.samples = signal::irfft(X, n);
  return out;
}

signal::Signal read_record(const std::filesystem::path& path, const std::string& name) {
  bool mesowave_layout = path.extension() != ".csv";
  if (!mesowave_layout) {
    // The signal toolkit's CSV names its time column t_s, t_ms, ... or "t [us]".
    const auto t = io::read_csv(path);
    const std::string first = t.header.empty() ? "" : t.header.front();
    mesowave_layout = first.rfind("t_", 0) == 0 || first.rfind("t [", 0) == 0 || first.rfind("time [", 0) == 0;
  }
  if (!mesowave_layout) return signal_from_csv(path.string(), name);
  for (const auto& s : signal::read_signals(path))
    if (s.name == name) return s;
  throw InputError(path.string() + " has no signal " + name);
}

BarEchoResult analyse_bar_echo(const signal::Signal& s, const BarEchoOptions& opt) {
  require_positive("round-trip path", opt.path_m, "m");
  require_positive("edge search", opt.edge_search_s, "s");
  if (s.size() < 16) throw InputError("record " + s.name + " has fewer than 16 samples");
  // Pulses: stretches where |x| reaches 30 % of the record's largest |x|, stretches
  // less than a third of the edge search apart merged (a long pulse's plateau may
  // dip). A Hilbert envelope would split a long flat pulse at its two edges.
  double top = 0;
  for (double x : s.samples) top = std::max(top, std::abs(x));
  if (!(top > 0)) throw InputError("record " + s.name + " is zero");
  struct Stretch {
    double begin, end;
  };
  std::vector<Stretch> pulses;
  const double gap = opt.edge_search_s / 3;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (std::abs(s.samples[i]) < 0.3 * top) continue;
    const double t = s.time(i);
    if (!pulses.empty() && t - pulses.back().end <= gap) pulses.back().end = t;
    else pulses.push_back({t, t});
  }
  if (pulses.size() < 2)
    throw InputError("record " + s.name + " holds " + std::to_string(pulses.size()) + " pulse(s), two are needed");
  const Stretch p1 = pulses[0], p2 = pulses[1];
  BarEchoResult r;
  r.first_pulse_extreme = extreme_in(s, p1.begin, p1.end);
  r.second_pulse_extreme = extreme_in(s, p2.begin, p2.end);
  const auto add = [&](const std::string& m, double t1, double t2) {
    if (!(t2 > t1)) throw InputError(m + ": the echo is not later than the pulse");
    r.picks.push_back({m, t1, t2, opt.path_m / (t2 - t1)});
  };
  const auto edge = [&](const Stretch& p, double extreme, double level) {
    return crossing(s, level * extreme, p.begin - opt.edge_search_s, 0.5 * (p.begin + p.end));
  };
  for (double level : {0.25, 0.5, 0.75})
    add("edge-" + format_number(level), edge(p1, r.first_pulse_extreme, level),
        edge(p2, r.second_pulse_extreme, level));
  // Onset pickers on each leading edge, the noise taken before it.
  const double e1 = edge(p1, r.first_pulse_extreme, 0.5), e2 = edge(p2, r.second_pulse_extreme, 0.5);
  // The pickers look from `back` before the edge; the noise is what precedes that.
  const auto onset = [&](double e, double noise_from, bool aic) {
    const double back = std::min(opt.edge_search_s, 0.5 * (e - noise_from));
    const signal::TimeWindow search{e - back, e + 0.25 * opt.edge_search_s};
    if (aic) {
      signal::AicOptions o;
      o.search = search;
      return signal::aic_pick(s, o).time_s;
    }
    signal::ThresholdOptions o;
    o.noise_begin_s = noise_from;
    o.noise_end_s = e - back;
    o.relative = 0.1;
    o.search = search;
    return signal::threshold_pick(s, o).time_s;
  };
  const double noise1 = std::max(s.t0_s, e1 - 4 * opt.edge_search_s);
  const double noise2 = std::max(p1.end + gap, e2 - 4 * opt.edge_search_s);
  add("threshold", onset(e1, noise1, false), onset(e2, noise2, false));
  add("aic", onset(e1, noise1, true), onset(e2, noise2, true));
  // The Hilbert-envelope peak of each pulse (what mw-dispersion measure uses for bursts).
  const signal::HilbertOptions ho{signal::Detrend::mean, signal::Padding{signal::Padding::Mode::double_length, 0}};
  const auto env = signal::envelope(std::span<const double>(s.samples), ho);
  const auto env_peak = [&](const Stretch& p) {
    std::size_t best = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const double t = s.time(i);
      if (t >= p.begin - opt.edge_search_s && t <= p.end && env[i] > env[best]) best = i;
    }
    return s.time(best);
  };
  add("envelope", env_peak(p1), env_peak(p2));
  // The first pulse alone (from an edge search before it to one after it).
  std::vector<double> first;
  double first_t0 = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.time(i) >= p1.begin - opt.edge_search_s && s.time(i) <= p1.end + opt.edge_search_s) {
      if (first.empty()) first_t0 = s.time(i);
      first.push_back(s.samples[i]);
    }
  if (opt.theory) {
    // Theory's echo: the first pulse carried over the path, scaled by the echo ratio
    // (the reflection), its leading edge picked like the measured echo's.
    signal::Signal pulse = s;
    pulse.t0_s = first_t0;
    pulse.samples = first;
    auto echo = propagate_l01(pulse, *opt.theory, opt.path_m, opt.theory_f_max_Hz);
    const double ratio = r.second_pulse_extreme / r.first_pulse_extreme;
    for (double& x : echo.samples) x *= ratio;
    double etop = 0;
    for (double x : echo.samples) etop = std::max(etop, std::abs(x));
    Stretch q{0, 0};
    for (std::size_t i = 0; i < echo.size(); ++i)
      if (std::abs(echo.samples[i]) >= 0.3 * etop) {
        q = {echo.time(i), echo.time(i)};
        for (std::size_t j = i; j < echo.size() && std::abs(echo.samples[j]) >= 0.3 * etop; ++j) q.end = echo.time(j);
        break;
      }
    const double ext = extreme_in(echo, q.begin, q.end);
    double sum_theory = 0, sum_measured = 0, lo = 1e300, hi = 0;
    for (double level : {0.25, 0.5, 0.75}) {
      const double t1 = edge(p1, r.first_pulse_extreme, level);
      const double t2 = crossing(echo, level * ext, q.begin - opt.edge_search_s, 0.5 * (q.begin + q.end));
      add("theory-edge-" + format_number(level), t1, t2);
      const double measured = edge(p2, r.second_pulse_extreme, level) - t1;
      sum_theory += t2 - t1;
      sum_measured += measured;
      lo = std::min(lo, (t2 - t1) / measured);
      hi = std::max(hi, (t2 - t1) / measured);
    }
    r.theory_echo = s;
    r.theory_echo.name = "theory echo";
    const auto offset = std::size_t(std::llround((first_t0 - s.t0_s) / s.dt_s));
    for (std::size_t i = 0; i < s.size(); ++i)
      r.theory_echo.samples[i] = i >= offset && i - offset < echo.size() ? echo.samples[i - offset] : 0.0;
    const double fit = sum_theory / sum_measured;
    r.fitted_c0_m_s = opt.theory->speeds().c0 * fit;
    r.fitted_c0_relative_spread = 0.5 * (hi - lo) / fit;
  }
  // Frequency content of the first pulse.
  r.pulse_window_s = double(first.size()) * s.dt_s;
  signal::SpectrumOptions so;
  so.detrend = signal::Detrend::none;
  so.scaling = signal::SpectrumScaling::raw;
  so.padding = signal::Padding{signal::Padding::Mode::to_length, 16 * first.size()};
  const auto spec = signal::amplitude_spectrum(first, s.dt_s, so);
  double total = 0;
  for (double a : spec.amplitude) total += a * a;
  double acc = 0;
  for (std::size_t k = 0; k < spec.amplitude.size(); ++k) {
    acc += spec.amplitude[k] * spec.amplitude[k];
    if (r.f50_Hz == 0 && acc >= 0.5 * total) r.f50_Hz = spec.frequency_hz[k];
    if (r.f90_Hz == 0 && acc >= 0.9 * total) r.f90_Hz = spec.frequency_hz[k];
  }
  return r;
}

BarEchoVelocity bar_echo_velocity(const BarEchoResult& result, double dt_s, double relative_path_uncertainty) {
  double sum = 0, lo = 1e300, hi = 0, delay = 0;
  int onsets = 0;
  for (const auto& p : result.picks) {
    if (p.method != "threshold" && p.method != "aic") continue;
    sum += p.velocity_m_s;
    delay += (p.t2_s - p.t1_s) / 2;  // the mean delay of the two pickers
    lo = std::min(lo, p.velocity_m_s);
    hi = std::max(hi, p.velocity_m_s);
    ++onsets;
  }
  if (onsets == 0) throw InputError("the bar-echo analysis holds no threshold or AIC pick");
  BarEchoVelocity v;
  v.velocity_m_s = sum / onsets;
  v.relative_uncertainty_method = 0.5 * (hi - lo) / v.velocity_m_s;
  v.relative_uncertainty_sampling = std::sqrt(0.5) * dt_s / delay;
  v.relative_uncertainty_path = relative_path_uncertainty;
  const double u_method = v.relative_uncertainty_method, u_time = v.relative_uncertainty_sampling,
               u_path = relative_path_uncertainty;
  v.velocity_uncertainty_m_s = v.velocity_m_s * std::sqrt(u_method * u_method + u_time * u_time + u_path * u_path);
  if (result.fitted_c0_m_s > 0) {
    const double u_fit = result.fitted_c0_relative_spread;
    v.fitted_c0_uncertainty_m_s = result.fitted_c0_m_s * std::sqrt(u_fit * u_fit + u_time * u_time + u_path * u_path);
  }
  return v;
}

}  // namespace mesowave::wave
