#include "mesowave/lab/compression_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"

namespace mesowave::lab {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// A channel whose strain changes by more than this between two samples, beyond
// what the stress change explains at a modulus of 5 GPa (softer than any
// concrete), was zeroed, re-clamped or slipped there.
constexpr double kJumpModulusPa = 5e9;

double median(std::vector<double> v) {
  if (v.empty()) return kNaN;
  const std::size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(mid), v.end());
  double m = v[mid];
  if (v.size() % 2 == 0) m = 0.5 * (m + *std::max_element(v.begin(), v.begin() + std::ptrdiff_t(mid)));
  return m;
}

// Noise SD from second differences (ramps and holds have none): 1.4826 MAD / sqrt(6).
double noise_sd(const std::vector<double>& x) {
  std::vector<double> d2;
  for (std::size_t i = 1; i + 1 < x.size(); ++i)
    if (std::isfinite(x[i - 1]) && std::isfinite(x[i]) && std::isfinite(x[i + 1]))
      d2.push_back(std::abs(x[i + 1] - 2 * x[i] + x[i - 1]));
  return d2.empty() ? 0.0 : 1.4826 * median(d2) / std::sqrt(6.0);
}

std::string mpa(double pa) { return format_fixed(pa / 1e6, 2) + " MPa"; }
std::string gpa(double pa) { return format_fixed(pa / 1e9, 2) + " GPa"; }
std::string sec(double s) { return format_fixed(s, 1) + " s"; }

struct Excursion {
  std::size_t start, peak, end;
};

// Per-channel strain of one sample range (NaN if any sample lacks a reading).
std::vector<double> channel_means(const CompressionRecord& rec, std::size_t first, std::size_t last, double gauge) {
  std::vector<double> out;
  for (const auto& ch : rec.extensometer_m) {
    double sum = 0;
    bool ok = true;
    for (std::size_t i = first; i <= last; ++i) {
      if (!std::isfinite(ch[i])) ok = false;
      sum += ch[i];
    }
    out.push_back(ok ? sum / double(last - first + 1) / gauge : kNaN);
  }
  return out;
}

Reading make_reading(const CompressionRecord& rec, std::size_t run_first, std::size_t run_last, bool hold,
                     double window_s, double gauge) {
  Reading r;
  r.hold = hold;
  r.hold_s = rec.t_s[run_last] - rec.t_s[run_first];
  r.last = run_last;
  r.first = run_last;
  if (hold)
    while (r.first > run_first && rec.t_s[run_last] - rec.t_s[r.first - 1] <= window_s + 1e-9) --r.first;
  r.t0_s = rec.t_s[r.first];
  r.t1_s = rec.t_s[r.last];
  double s = 0;
  for (std::size_t i = r.first; i <= r.last; ++i) s += rec.stress_Pa[i];
  r.stress_Pa = s / double(r.last - r.first + 1);
  r.strain = channel_means(rec, r.first, r.last, gauge);
  return r;
}

// A level is "held" when it lasts at least 2 s and 3 samples.
bool is_hold(const CompressionRecord& rec, std::size_t a, std::size_t b) {
  return b >= a + 2 && rec.t_s[b] - rec.t_s[a] >= 2.0;
}

// First sample index where channel `c` jumps within [a, b), or npos.
std::size_t find_jump(const CompressionRecord& rec, std::size_t c, std::size_t a, std::size_t b, double gauge,
                      double strain_noise) {
  const auto& ch = rec.extensometer_m[c];
  for (std::size_t i = a; i < b; ++i) {
    if (!std::isfinite(ch[i]) || !std::isfinite(ch[i + 1])) continue;
    const double d_eps = std::abs(ch[i + 1] - ch[i]) / gauge;
    const double d_sigma = std::abs(rec.stress_Pa[i + 1] - rec.stress_Pa[i]);
    if (d_eps > d_sigma / kJumpModulusPa + 10 * strain_noise + 1e-5) return i;
  }
  return std::string::npos;
}

double fit_slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = double(x.size());
  const double mx = std::accumulate(x.begin(), x.end(), 0.0) / n, my = std::accumulate(y.begin(), y.end(), 0.0) / n;
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
  }
  return sxx > 0 ? sxy / sxx : kNaN;
}

}  // namespace

CyclicResult analyse_cyclic_test(const CompressionRecord& rec, const CyclicOptions& opt) {
  if (!(opt.gauge_length_m > 0)) throw InputError("the extensometer gauge length must be positive");
  if (opt.evaluated_cycle < 1) throw InputError("the evaluated cycle must be 1 or later");
  if (rec.extensometer_m.empty()) throw InputError(rec.origin + ": the cyclic test has no extensometer channel");
  const auto& s = rec.stress_Pa;
  const std::size_t n = s.size();
  CyclicResult res;
  res.evaluated_cycle = opt.evaluated_cycle;
  res.stress_noise_Pa = noise_sd(s);

  // Levels: the top, and the base the cycles return to (the lowest stress
  // between the first and the last time the top is approached).
  const std::size_t i_hi = std::size_t(std::max_element(s.begin(), s.end()) - s.begin());
  const double hi = s[i_hi];
  std::size_t first_high = n, last_high = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (s[i] > 0.9 * hi) first_high = std::min(first_high, i), last_high = i;
  double base = *std::min_element(s.begin(), s.begin() + std::ptrdiff_t(first_high) + 1);
  if (last_high > first_high) {
    const double between = *std::min_element(s.begin() + std::ptrdiff_t(first_high), s.begin() + std::ptrdiff_t(last_high) + 1);
    if (between < 0.8 * hi) base = between;
  }
  const double range = hi - base;
  if (!(range > 10 * res.stress_noise_Pa) || !(hi > 0))
    throw InputError(rec.origin + ": no load cycles (the stress hardly varies)");
  const double enter = base + 0.7 * range, leave = base + 0.3 * range;

  std::vector<Excursion> exc;
  bool above = false;
  for (std::size_t i = 0; i < n; ++i) {
    if (!above && s[i] > enter) {
      std::size_t start = i;
      while (start > 0 && s[start - 1] > leave) --start;
      exc.push_back({start, i, n - 1});
      above = true;
    } else if (above && s[i] < leave) {
      exc.back().end = i - 1;
      above = false;
    }
    if (above && s[i] > s[exc.back().peak]) exc.back().peak = i;
  }
  if (int(exc.size()) < opt.evaluated_cycle)
    throw InputError(rec.origin + ": found " + std::to_string(exc.size()) + " load cycle" + (exc.size() == 1 ? "" : "s") +
                     " to the upper stress, but the stabilized modulus is read on cycle " +
                     std::to_string(opt.evaluated_cycle) +
                     " (EN 12390-13, 8.2): the record misses a cycle or was cut short (--cycle N reads another)");

  const double band0 = std::max(0.02 * range, 4 * res.stress_noise_Pa);
  const double band1 = std::max(0.005 * range, 4 * res.stress_noise_Pa);
  const double gauge = opt.gauge_length_m;
  std::size_t prev_end = std::string::npos;
  for (std::size_t k = 0; k < exc.size(); ++k) {
    const auto& e = exc[k];
    LoadCycle c;
    c.number = int(k + 1);
    c.start = e.start;
    c.peak = e.peak;
    c.end = e.end;
    // Upper reading: the plateau around the peak.
    {
      std::size_t a = e.peak, b = e.peak;
      while (a > e.start && s[a - 1] >= s[e.peak] - band0) --a;
      while (b < e.end && s[b + 1] >= s[e.peak] - band0) ++b;
      std::vector<double> run(s.begin() + std::ptrdiff_t(a), s.begin() + std::ptrdiff_t(b) + 1);
      const double level = median(run);
      a = b = e.peak;
      while (a > e.start && s[a - 1] >= level - band1) --a;
      while (b < e.end && s[b + 1] >= level - band1) ++b;
      const bool hold = is_hold(rec, a, b);
      c.upper = hold ? make_reading(rec, a, b, true, opt.reading_window_s, gauge)
                     : make_reading(rec, e.peak, e.peak, false, 0, gauge);
    }
    // Lower reading: the last plateau before this cycle's ramp (a sample is on
    // a plateau when the stress over the 2 s before it stays within 2 band1);
    // without one, the turning point (lowest sample) between the cycles.
    const std::size_t r0 = prev_end == std::string::npos ? 0 : prev_end + 1;
    if (e.start > r0) {
      const std::size_t r1 = e.start - 1;
      auto flat = [&](std::size_t i) {
        std::size_t j = i;
        double lo = s[i], hi = s[i];
        while (j > r0 && rec.t_s[i] - rec.t_s[j - 1] <= 2.0 + 1e-9) --j, lo = std::min(lo, s[j]), hi = std::max(hi, s[j]);
        return i >= j + 2 && rec.t_s[i] - rec.t_s[j] >= 2.0 - 1e-9 && hi - lo <= 2 * band1;
      };
      std::size_t q = r1 + 1;
      while (q > r0 && !flat(q - 1)) --q;
      if (q > r0) {
        --q;  // last plateau sample
        std::size_t a = q;
        while (a > r0 && (flat(a - 1) || rec.t_s[q] - rec.t_s[a - 1] <= 2.0)) --a;
        std::vector<double> run(s.begin() + std::ptrdiff_t(a), s.begin() + std::ptrdiff_t(q) + 1);
        const double level = median(run);
        while (a < q && std::abs(s[a] - level) > band1) ++a;
        c.lower = make_reading(rec, a, q, is_hold(rec, a, q), opt.reading_window_s, gauge);
      } else {
        const std::size_t turn =
            std::size_t(std::min_element(s.begin() + std::ptrdiff_t(r0), s.begin() + std::ptrdiff_t(r1) + 1) - s.begin());
        c.lower = make_reading(rec, turn, turn, false, 0, gauge);
      }
    } else {
      c.note = "the record starts inside this cycle: no lower reading before it";
    }
    // Loading rate: the ramp between 20 and 80 % of its rise.
    if (c.lower) {
      std::vector<double> t, y;
      const double from = c.lower->stress_Pa, rise = c.upper.stress_Pa - c.lower->stress_Pa;
      for (std::size_t i = c.lower->last; i <= e.peak; ++i)
        if (s[i] >= from + 0.2 * rise && s[i] <= from + 0.8 * rise) {
          t.push_back(rec.t_s[i]);
          y.push_back(s[i]);
        }
      if (t.size() >= 3) c.loading_rate_Pa_s = fit_slope(t, y);
    }
    res.cycles.push_back(std::move(c));
    prev_end = e.end;
  }

  // Channels: judged on the evaluated cycle.
  LoadCycle& ev = res.cycles[std::size_t(opt.evaluated_cycle - 1)];
  if (!ev.lower)
    throw InputError(rec.origin + ": cycle " + std::to_string(ev.number) + " has no lower reading before it");
  const std::size_t nch = rec.extensometer_m.size();
  std::vector<double> delta(nch, kNaN);
  for (std::size_t c = 0; c < nch; ++c) {
    ChannelVerdict v;
    v.name = rec.extensometer_names[c];
    v.used = true;
    const double d = ev.upper.strain[c] - ev.lower->strain[c];
    v.delta_strain = d;
    if (!std::isfinite(d)) {
      v.used = false;
      v.reason = "no readings in cycle " + std::to_string(ev.number) + " (channel dropped out)";
    } else {
      const double eps_noise = noise_sd(rec.extensometer_m[c]) / gauge;
      const std::size_t j = find_jump(rec, c, ev.lower->first, ev.upper.last, gauge, eps_noise);
      if (j != std::string::npos) {
        v.used = false;
        v.reason = "jumps by " + format_fixed((rec.extensometer_m[c][j + 1] - rec.extensometer_m[c][j]) * 1e3, 4) +
                   " mm at t = " + sec(rec.t_s[j + 1]) + " (zeroed, re-clamped or slipped)";
      } else {
        delta[c] = d;
      }
    }
    res.channels.push_back(v);
  }
  {
    std::vector<double> finite;
    for (double d : delta)
      if (std::isfinite(d)) finite.push_back(d);
    const double med = median(finite);
    for (std::size_t c = 0; c < nch; ++c) {
      auto& v = res.channels[c];
      if (!v.used) continue;
      if (!(delta[c] > 0) || (finite.size() >= 2 && med > 0 && delta[c] < 0.2 * med)) {
        v.used = false;
        v.reason = "no response: strain change " + format_fixed(delta[c] * 1e6, 1) + " um/m over cycle " +
                   std::to_string(ev.number) + " (stuck or detached)";
      } else if (finite.size() >= 3 && std::abs(delta[c] / med - 1) > opt.channel_tolerance) {
        v.used = false;
        v.reason = "reads " + format_fixed(100 * (delta[c] / med - 1), 0) + " % from the median of the channels";
      }
    }
  }
  std::vector<std::size_t> used;
  for (std::size_t c = 0; c < nch; ++c)
    if (res.channels[c].used) used.push_back(c);
    else res.warnings.push_back("extensometer '" + res.channels[c].name + "' not used: " + res.channels[c].reason);
  if (used.size() < opt.min_extensometers)
    throw InputError(rec.origin + ": only " + std::to_string(used.size()) + " usable extensometer channel" +
                     (used.size() == 1 ? "" : "s") + " in cycle " + std::to_string(ev.number) + " (need " +
                     std::to_string(opt.min_extensometers) + " to average out bending; " +
                     (res.warnings.empty() ? std::string("none responds") : res.warnings.front()) +
                     "; --min-extensometers 1 accepts a single one)");
  if (used.size() == 2) {
    const double a = delta[used[0]], b = delta[used[1]];
    const double spread = std::abs(a - b) / (0.5 * (a + b));
    if (spread > opt.channel_tolerance)
      res.warnings.push_back("the two extensometers differ by " + format_fixed(100 * spread, 0) +
                             " % in cycle " + std::to_string(ev.number) +
                             " (eccentric loading or a faulty channel); E uses their mean");
  }
  if (used.size() == 1) res.warnings.push_back("E from a single extensometer: bending is not averaged out");

  // Secant modulus of every cycle on the used channels.
  auto mean_used = [&](const std::vector<double>& strain) {
    double sum = 0;
    for (std::size_t c : used) sum += strain[c];
    return sum / double(used.size());
  };
  for (auto& c : res.cycles) {
    if (!c.lower) continue;
    bool jumped = false;
    for (std::size_t ch : used)
      if (find_jump(rec, ch, c.lower->first, c.upper.last, gauge, noise_sd(rec.extensometer_m[ch]) / gauge) !=
          std::string::npos)
        jumped = true;
    const double d_eps = mean_used(c.upper.strain) - mean_used(c.lower->strain);
    const double d_sigma = c.upper.stress_Pa - c.lower->stress_Pa;
    if (jumped) c.note = "an extensometer jumps during this cycle (zeroed or slipped): not evaluated";
    else if (!std::isfinite(d_eps)) c.note = "an extensometer has no reading in this cycle: not evaluated";
    else if (!(d_eps > 0)) c.note = "the strain does not rise with the stress: not evaluated";
    else c.E_Pa = d_sigma / d_eps;
    {
      std::vector<double> x, y;
      const double from = c.lower->stress_Pa, rise = c.upper.stress_Pa - c.lower->stress_Pa;
      std::size_t first = c.upper.first, last = c.lower->last;
      for (std::size_t i = c.lower->last; i <= c.peak; ++i)
        if (s[i] >= from + 0.2 * rise && s[i] <= from + 0.8 * rise) {
          std::vector<double> strain;
          for (const auto& ch : rec.extensometer_m) strain.push_back(ch[i] / gauge);
          x.push_back(mean_used(strain));
          y.push_back(s[i]);
          first = std::min(first, i), last = std::max(last, i);
        }
      bool ramp_jump = false;
      for (std::size_t ch : used)
        if (x.size() >= 3 && find_jump(rec, ch, first, last, gauge, noise_sd(rec.extensometer_m[ch]) / gauge) !=
                                 std::string::npos)
          ramp_jump = true;
      if (x.size() >= 3 && !ramp_jump && std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); })) {
        const double slope = fit_slope(x, y);
        if (slope > 0) c.E_ramp_Pa = slope;
      }
    }
    if (c.E_Pa && (!c.lower->hold || !c.upper.hold))
      c.note = std::string("read at a turning point (") + (!c.lower->hold ? "no lower hold" : "") +
               (!c.lower->hold && !c.upper.hold ? ", " : "") + (!c.upper.hold ? "no upper hold" : "") + ")";
  }
  if (!ev.E_Pa) throw InputError(rec.origin + ": cycle " + std::to_string(ev.number) + ": " + ev.note);
  res.E_st_Pa = *ev.E_Pa;
  res.sigma_a_Pa = ev.upper.stress_Pa;
  res.sigma_b_Pa = ev.lower->stress_Pa;
  res.eps_a = mean_used(ev.upper.strain);
  res.eps_b = mean_used(ev.lower->strain);

  // What a person should look at.
  if (!ev.upper.hold)
    res.warnings.push_back("cycle " + std::to_string(ev.number) +
                           " is not held at the upper stress: read at the peak sample, not during a hold");
  if (!ev.lower->hold)
    res.warnings.push_back("the lower stress before cycle " + std::to_string(ev.number) +
                           " is not held: read at the turning point, not during a hold");
  {
    std::vector<double> uppers;
    for (const auto& c : res.cycles) uppers.push_back(c.upper.stress_Pa);
    const double med = median(uppers);
    for (const auto& c : res.cycles)
      if (std::abs(c.upper.stress_Pa / med - 1) > 0.05)
        res.warnings.push_back("cycle " + std::to_string(c.number) + " peaks at " + mpa(c.upper.stress_Pa) +
                               ", more than 5 % from the other cycles (" + mpa(med) + ")");
  }
  if (opt.expected_upper_Pa && std::abs(res.sigma_a_Pa / *opt.expected_upper_Pa - 1) > 0.05)
    res.warnings.push_back("the upper stress reads " + mpa(res.sigma_a_Pa) + ", not the expected " +
                           mpa(*opt.expected_upper_Pa));
  if (int(res.cycles.size()) > opt.evaluated_cycle)
    res.warnings.push_back(std::to_string(res.cycles.size()) + " load cycles found; cycle " +
                           std::to_string(opt.evaluated_cycle) + " is evaluated");
  if (res.E_st_Pa < 5e9 || res.E_st_Pa > 80e9)
    res.warnings.push_back("E = " + gpa(res.E_st_Pa) +
                           " lies outside 5-80 GPa, unusual for concrete: check the gauge length and the channels");
  return res;
}

std::vector<double> mean_extensometer_strain(const CompressionRecord& rec, const CyclicResult& res, double gauge) {
  std::vector<double> out(rec.t_s.size(), 0.0);
  std::size_t used = 0;
  for (std::size_t c = 0; c < res.channels.size(); ++c) {
    if (!res.channels[c].used) continue;
    ++used;
    for (std::size_t i = 0; i < out.size(); ++i) out[i] += rec.extensometer_m[c][i] / gauge;
  }
  for (double& v : out) v = used ? v / double(used) : kNaN;
  return out;
}

CrossheadFit fit_crosshead_multiplier(const CompressionRecord& rec, const CyclicResult& res, double gauge,
                                      double height, int from_cycle) {
  if (rec.crosshead_m.empty()) throw InputError(rec.origin + ": no crosshead column to fit the multiplier on");
  if (!(height > 0)) throw InputError("the specimen height must be positive for crosshead strain");
  CrossheadFit fit;
  fit.from_cycle = std::clamp(from_cycle, 1, int(res.cycles.size()));
  const auto eps = mean_extensometer_strain(rec, res, gauge);
  const double threshold = res.sigma_b_Pa + 0.1 * (res.sigma_a_Pa - res.sigma_b_Pa);
  std::vector<double> x, y;
  for (std::size_t i = res.cycles[std::size_t(fit.from_cycle - 1)].start; i <= res.cycles.back().end; ++i)
    if (rec.stress_Pa[i] >= threshold && std::isfinite(eps[i]) && std::isfinite(rec.crosshead_m[i])) {
      x.push_back(rec.crosshead_m[i] / height);
      y.push_back(eps[i]);
    }
  if (x.size() < 10) throw InputError(rec.origin + ": fewer than 10 samples to fit the crosshead multiplier on");
  fit.points = x.size();
  fit.multiplier = fit_slope(x, y);
  const double mx = std::accumulate(x.begin(), x.end(), 0.0) / double(x.size());
  const double my = std::accumulate(y.begin(), y.end(), 0.0) / double(y.size());
  fit.intercept = my - fit.multiplier * mx;
  double ss_res = 0, ss_tot = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double r = y[i] - (fit.multiplier * x[i] + fit.intercept);
    ss_res += r * r;
    ss_tot += (y[i] - my) * (y[i] - my);
  }
  fit.r2 = ss_tot > 0 ? 1 - ss_res / ss_tot : 0;
  fit.rms_strain = std::sqrt(ss_res / double(x.size()));
  if (!(fit.multiplier > 0))
    throw InputError(rec.origin + ": extensometer and crosshead strain do not rise together (multiplier " +
                     format_number(fit.multiplier) + ")");
  return fit;
}

FailureResult analyse_failure_test(const CompressionRecord& rec, std::optional<double> multiplier,
                                   std::optional<double> height) {
  const auto& s = rec.stress_Pa;
  FailureResult f;
  f.peak_index = std::size_t(std::max_element(s.begin(), s.end()) - s.begin());
  f.sigma_max_Pa = s[f.peak_index];
  f.t_peak_s = rec.t_s[f.peak_index];
  if (!(f.sigma_max_Pa > 0)) throw InputError(rec.origin + ": no compressive load in the failure test");
  const double after = *std::min_element(s.begin() + std::ptrdiff_t(f.peak_index), s.end());
  f.broke = after < 0.8 * f.sigma_max_Pa;
  if (!f.broke)
    f.warnings.push_back("the stress does not drop after its peak (lowest afterwards " +
                         format_fixed(100 * after / f.sigma_max_Pa, 0) +
                         " % of it): the record may end before failure, so sigma_max is a lower bound");
  if (f.peak_index == 0) f.warnings.push_back("the peak is the first sample: is this a test to failure?");
  if (!rec.crosshead_m.empty() && height) {
    if (!(*height > 0)) throw InputError("the specimen height must be positive for crosshead strain");
    const double u0 = rec.crosshead_m.front();
    for (double u : rec.crosshead_m) f.crosshead_strain.push_back((u - u0) / *height);
    if (multiplier) {
      for (double e : f.crosshead_strain) f.strain.push_back(*multiplier * e);
      f.strain_at_peak = f.strain[f.peak_index];
    }
  }
  return f;
}

}  // namespace mesowave::lab
