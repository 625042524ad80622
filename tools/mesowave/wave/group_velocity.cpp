#include "mesowave/wave/group_velocity.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesowave/core/check.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/signal/envelope.hpp"
#include "mesowave/signal/fft.hpp"

namespace mesowave::wave {

std::vector<Packet> envelope_packets(const signal::Signal& s, double rel, double min_sep) {
  if (s.size() < 3) throw InputError("signal " + s.name + " has fewer than 3 samples");
  const signal::HilbertOptions opt{signal::Detrend::mean, signal::Padding{signal::Padding::Mode::double_length, 0}};
  const auto e = signal::envelope(std::span<const double>(s.samples), opt);
  const double top = *std::max_element(e.begin(), e.end());
  std::vector<Packet> peaks;
  if (!(top > 0)) return peaks;
  for (std::size_t i = 1; i + 1 < e.size(); ++i) {
    if (!(e[i] >= e[i - 1] && e[i] > e[i + 1]) || e[i] < rel * top) continue;
    double t = s.time(i);
    const double denom = e[i - 1] - 2 * e[i] + e[i + 1];
    if (denom < 0) t += std::clamp(0.5 * (e[i - 1] - e[i + 1]) / denom, -0.5, 0.5) * s.dt_s;
    if (!peaks.empty() && t - peaks.back().time_s < min_sep) {
      if (e[i] > peaks.back().envelope) peaks.back() = {t, e[i]};
      continue;
    }
    peaks.push_back({t, e[i]});
  }
  return peaks;
}

namespace {
constexpr double kThreshold = 0.3;  // a packet is an envelope maximum above 30 % of the record's largest
}  // namespace

namespace {

Packet first_packet(const signal::Signal& s, double burst_duration) {
  const auto p = envelope_packets(s, kThreshold, burst_duration);
  if (p.empty()) throw InputError("signal " + s.name + " carries no wave packet (its envelope is zero)");
  return p.front();
}

GroupVelocityPoint finish(std::string method, double f, double t1, double t2, double distance) {
  if (!(t2 > t1))
    throw InputError(method + ": the second arrival (" + format_quantity(t2 / units::us, "us") +
                     ") is not later than the first (" + format_quantity(t1 / units::us, "us") + ")");
  GroupVelocityPoint p;
  p.f_Hz = f;
  p.method = std::move(method);
  p.t1_s = t1;
  p.t2_s = t2;
  p.distance_m = distance;
  p.c_group_m_s = distance / (t2 - t1);
  return p;
}

}  // namespace

GroupVelocityPoint two_station_velocity(const signal::Signal& a, const signal::Signal& b, double distance, double f,
                                        double burst_duration) {
  require_positive("station distance", distance, "m");
  return finish("two-stations", f, first_packet(a, burst_duration).time_s, first_packet(b, burst_duration).time_s,
                distance);
}

GroupVelocityPoint echo_velocity(const signal::Signal& s, double path, double f, double burst_duration) {
  require_positive("echo path", path, "m");
  const auto p = envelope_packets(s, kThreshold, burst_duration);
  if (p.size() < 2)
    throw InputError("signal " + s.name + ": the echo method needs two packets above 30 % of the largest, found " +
                     std::to_string(p.size()));
  return finish("echo", f, p[0].time_s, p[1].time_s, path);
}

GroupVelocityPoint source_velocity(const signal::Signal& s, double distance, double source_time, double f,
                                   double burst_duration) {
  require_positive("source distance", distance, "m");
  return finish("source", f, source_time, first_packet(s, burst_duration).time_s, distance);
}

std::vector<RidgePoint> spacetime_ridge(const SpaceTimeRecord& r, double f_min, double f_max, int k_padding,
                                        double floor) {
  if (r.times < 4 || r.positions < 4) throw InputError("space-time record needs at least 4 times and 4 positions");
  if (r.samples.size() != r.times * r.positions) throw InputError("space-time record size does not match its shape");
  require_positive("space-time dt", r.dt_s, "s");
  require_positive("space-time dx", r.dx_m, "m");
  const std::size_t nt = r.times, nx = r.positions;
  // Time transform per position (e^{-i omega t}), then space per frequency bin.
  std::vector<std::vector<signal::Complex>> T(nx);
  std::vector<double> column(nt);
  for (std::size_t j = 0; j < nx; ++j) {
    for (std::size_t i = 0; i < nt; ++i) column[i] = r.samples[i * nx + j];
    T[j] = signal::rfft(column);
  }
  const std::size_t nf = nt / 2 + 1;
  const std::size_t nk = std::size_t(std::max(1, k_padding)) * nx;
  const double df = 1.0 / (double(nt) * r.dt_s), dk = 2 * std::numbers::pi / (double(nk) * r.dx_m);
  struct Raw {
    double f, k, amp;
  };
  std::vector<Raw> raw;
  std::vector<signal::Complex> line(nk);
  for (std::size_t q = 1; q < nf; ++q) {
    const double f = double(q) * df;
    if (f < f_min || f > f_max) continue;
    std::fill(line.begin(), line.end(), signal::Complex(0, 0));
    for (std::size_t j = 0; j < nx; ++j) line[j] = T[j][q];
    const auto K = signal::fft(line);
    // A wave exp(i(omega t - k x)) appears at spatial bin -k: scan the negative half.
    std::size_t best = nk / 2 + 1;
    for (std::size_t m = nk / 2 + 1; m < nk; ++m)
      if (std::abs(K[m]) > std::abs(K[best])) best = m;
    double shift = 0;
    if (best > nk / 2 + 1 && best + 1 < nk) {
      const double a = std::abs(K[best - 1]), b = std::abs(K[best]), c = std::abs(K[best + 1]);
      const double den = a - 2 * b + c;
      if (den < 0) shift = std::clamp(0.5 * (a - c) / den, -0.5, 0.5);
    }
    const double k = (double(nk - best) - shift) * dk;
    raw.push_back({f, k, std::abs(K[best])});
  }
  double top = 0;
  for (const auto& p : raw) top = std::max(top, p.amp);
  std::vector<Raw> kept;
  for (const auto& p : raw)
    if (p.amp >= floor * top && p.k > 0) kept.push_back(p);
  // c_group = d omega / dk: slope of a least-squares line of omega against k over
  // the point and the same number of neighbours (up to 3) on each side along the ridge.
  std::vector<RidgePoint> out;
  for (std::size_t i = 0; i < kept.size(); ++i) {
    const std::size_t half = std::min({std::size_t(3), i, kept.size() - 1 - i});  // symmetric: no one-sided bias
    if (half == 0) continue;
    const std::size_t lo = i - half, hi = i + half;
    double sk = 0, sw = 0, skk = 0, skw = 0;
    const double m = double(hi - lo + 1);
    for (std::size_t j = lo; j <= hi; ++j) {
      const double w = 2 * std::numbers::pi * kept[j].f;
      sk += kept[j].k;
      sw += w;
      skk += kept[j].k * kept[j].k;
      skw += kept[j].k * w;
    }
    const double var = skk - sk * sk / m;
    if (!(var > 0)) continue;
    RidgePoint p;
    p.f_Hz = kept[i].f;
    p.k_rad_m = kept[i].k;
    p.c_phase_m_s = 2 * std::numbers::pi * p.f_Hz / p.k_rad_m;
    p.c_group_m_s = (skw - sk * sw / m) / var;
    out.push_back(p);
  }
  return out;
}

ResidualSummary residual_sum_of_squares(const std::vector<GroupVelocityPoint>& points,
                                        const std::function<double(double)>& theory, double lo, double hi) {
  if (!(lo <= hi)) throw InputError("frequency band: the lower end exceeds the upper end");
  ResidualSummary r;
  for (const auto& p : points) {
    const bool in = p.f_Hz >= lo * (1 - 1e-12) && p.f_Hz <= hi * (1 + 1e-12);
    r.in_band.push_back(in);
    const double c = in ? theory(p.f_Hz) : 0.0;
    r.theory_m_s.push_back(c);
    if (!in) continue;
    const double d = p.c_group_m_s - c;
    r.rss_m2_s2 += d * d;
    r.max_abs_m_s = std::max(r.max_abs_m_s, std::abs(d));
    ++r.points;
  }
  if (r.points == 0) throw InputError("no measured frequency lies in the band");
  r.rms_m_s = std::sqrt(r.rss_m2_s2 / double(r.points));
  return r;
}

}  // namespace mesowave::wave

namespace mesowave::wave {

GroupVelocityPoint measure_run(const std::vector<signal::Signal>& signals, double f, const MeasureRequest& req) {
  require_positive("burst frequency", f, "Hz");
  require_positive("burst cycles", req.cycles);
  const auto find = [&](const std::string& name) -> const signal::Signal& {
    for (const auto& s : signals)
      if (s.name == name) return s;
    std::string names;
    for (const auto& s : signals) names += (names.empty() ? "" : ", ") + s.name;
    throw InputError("no signal named " + name + " (the run has: " + names + ")");
  };
  const double burst = req.cycles / f;
  if (req.method == "two-stations") {
    if (req.stations.size() != 2) throw InputError("two-stations needs exactly two --station names");
    const auto& a = find(req.stations[0]);
    const auto& b = find(req.stations[1]);
    double d = req.distance_m;
    if (d == 0) {
      if (!a.position_m || !b.position_m)
        throw InputError("the stations carry no positions: give the distance between them");
      const auto& pa = *a.position_m;
      const auto& pb = *b.position_m;
      d = std::hypot(pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]);
    }
    return two_station_velocity(a, b, d, f, burst);
  }
  if (req.stations.size() != 1) throw InputError(req.method + " needs exactly one --station name");
  if (!(req.distance_m > 0)) throw InputError(req.method + " needs the path length (--distance-mm)");
  const auto& s = find(req.stations[0]);
  if (req.method == "echo") return echo_velocity(s, req.distance_m, f, burst);
  if (req.method == "source") {
    double t0 = burst / 2;
    for (const auto& x : signals)
      if (x.name == signal::kExcitationName) t0 = envelope_packets(x, kThreshold, burst).at(0).time_s;
    return source_velocity(s, req.distance_m, t0, f, burst);
  }
  throw InputError("method " + req.method + " must be two-stations, echo or source");
}

}  // namespace mesowave::wave
