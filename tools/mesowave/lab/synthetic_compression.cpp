#include "mesowave/lab/synthetic_compression.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/random.hpp"
#include "mesowave/io/csv.hpp"

namespace mesowave::lab {

namespace {

// Piecewise-linear stress programme of a stress-controlled test.
struct Segment {
  double t0, t1, s0, s1;
};

double stress_at(const std::vector<Segment>& program, double t) {
  for (const auto& seg : program)
    if (t <= seg.t1) return seg.t1 > seg.t0 ? seg.s0 + (seg.s1 - seg.s0) * (t - seg.t0) / (seg.t1 - seg.t0) : seg.s1;
  return program.back().s1;
}

void append(std::vector<Segment>& program, double duration, double to) {
  const double t0 = program.empty() ? 0.0 : program.back().t1, s0 = program.empty() ? 0.0 : program.back().s1;
  program.push_back({t0, t0 + duration, s0, to});
}

double eps_c1_of(double f_c_Pa) { return 0.7 * std::pow(f_c_Pa / 1e6, 0.31) * 1e-3; }  // EN 1992-1-1 Table 3.1

}  // namespace

double sargin_strain(double sigma, double E, double f_c, double eps_c1) {
  const double k = 1.05 * E * eps_c1 / f_c;
  const double s = std::clamp(sigma / f_c, 0.0, 1.0);
  const double a = k - s * (k - 2);
  const double eta = 0.5 * (a - std::sqrt(std::max(0.0, a * a - 4 * s)));  // smaller root: ascending branch
  return eta * eps_c1;
}

SyntheticCompressionTests synthetic_compression_tests(const SyntheticCompressionSpec& spec) {
  if (!(spec.E_Pa > 0 && spec.strength_Pa > 0 && spec.upper_stress_Pa > spec.lower_stress_Pa && spec.lower_stress_Pa >= 0))
    throw InputError("synthetic compression test needs E > 0, strength > 0 and upper stress > lower stress >= 0");
  if (spec.upper_stress_Pa >= spec.strength_Pa) throw InputError("the upper stress must stay below the strength");
  if (!(spec.cyclic_rate_Pa_s > 0 && spec.failure_rate_Pa_s > 0 && spec.hold_s >= 0 && spec.cycles >= 1))
    throw InputError("rates must be positive, holds non-negative and cycles >= 1");
  if (!(spec.crosshead_multiplier > 0 && spec.crosshead_multiplier <= 1))
    throw InputError("crosshead multiplier must lie in (0, 1]");
  const double eps_c1 = eps_c1_of(spec.strength_Pa);
  const double k = 1.05 * spec.E_Pa * eps_c1 / spec.strength_Pa;
  if (k <= 1.0)
    throw InputError("E = " + format_number(spec.E_Pa / 1e9) + " GPa is too low for a strength of " +
                     format_number(spec.strength_Pa / 1e6) + " MPa (EN 1992-1-1 Eq. 3.14 needs k > 1)");

  XoshiroRandom rng(spec.seed);
  const double area = spec.side_m * spec.side_m, height = spec.side_m, L = spec.gauge_length_m;
  const double m = spec.crosshead_multiplier;
  SyntheticCompressionTests out;
  out.true_E_Pa = spec.E_Pa;
  out.true_strength_Pa = spec.strength_Pa;
  out.true_multiplier = m;
  out.eps_c1 = eps_c1;

  // ---- cyclic test ----
  std::vector<Segment> program;
  const double lo = spec.lower_stress_Pa, hi = spec.upper_stress_Pa;
  const double ramp = (hi - lo) / spec.cyclic_rate_Pa_s;
  append(program, lo / spec.cyclic_rate_Pa_s, lo);
  append(program, spec.hold_s, lo);
  for (int c = 1; c <= spec.cycles; ++c) {
    if (c == spec.skip_cycle) {
      append(program, 2 * ramp + 2 * spec.hold_s, lo);
      continue;
    }
    append(program, ramp, hi);
    append(program, spec.hold_s, hi);
    append(program, ramp, lo);
    append(program, spec.hold_s, lo);
  }
  append(program, lo / spec.cyclic_rate_Pa_s, 0.0);

  auto& cy = out.cyclic;
  cy.extensometer_m.assign(2, {});
  const double dt = 1.0 / spec.sample_rate_Hz, end = program.back().t1;
  double sigma_seen = 0;
  double stuck_value = std::numeric_limits<double>::quiet_NaN();
  for (long i = 0; double(i) * dt <= end + 1e-9; ++i) {
    const double t = double(i) * dt, sigma = stress_at(program, t);
    sigma_seen = std::max(sigma_seen, sigma);
    const double set = spec.first_loading_set * std::clamp((sigma_seen - lo) / (hi - lo), 0.0, 1.0);
    const double eps = sigma / spec.E_Pa + set;
    const double seat = spec.seating_m * (1 - std::exp(-sigma_seen / spec.seating_stress_Pa));
    cy.t_s.push_back(t);
    cy.force_N.push_back(sigma * area + spec.force_noise_N * rng.normal());
    cy.crosshead_m.push_back(height * eps / m + seat + spec.crosshead_noise_m * rng.normal());
    for (int ch = 0; ch < 2; ++ch) {
      const double bend = ch == 0 ? 1 + spec.bending : 1 - spec.bending;
      double v = L * eps * bend + spec.extensometer_noise_m * rng.normal();
      if (spec.dropout_channel == ch + 1 && t >= spec.dropout_time_s) {
        if (std::isnan(stuck_value)) stuck_value = cy.extensometer_m[ch].empty() ? v : cy.extensometer_m[ch].back();
        v = spec.dropout_stuck ? stuck_value : std::numeric_limits<double>::quiet_NaN();
      }
      cy.extensometer_m[ch].push_back(v);
    }
  }

  // ---- failure test ----
  auto& fa = out.failure;
  const double dtf = 1.0 / spec.failure_sample_rate_Hz, t_peak = spec.strength_Pa / spec.failure_rate_Pa_s;
  const double t_first = 0.37 * dtf;  // the peak falls between samples, as it does on a machine
  sigma_seen = 0;
  auto push_failure = [&](double t, double sigma, double eps) {
    sigma_seen = std::max(sigma_seen, sigma);
    const double seat = spec.seating_m * (1 - std::exp(-sigma_seen / spec.seating_stress_Pa));
    fa.t_s.push_back(t);
    fa.force_N.push_back(sigma * area + spec.force_noise_N * rng.normal());
    fa.crosshead_m.push_back(height * eps / m + seat + spec.crosshead_noise_m * rng.normal());
  };
  long i = 0;
  for (; t_first + double(i) * dtf <= t_peak; ++i) {
    const double t = t_first + double(i) * dtf, sigma = spec.failure_rate_Pa_s * t;
    push_failure(t, sigma, sargin_strain(sigma, spec.E_Pa, spec.strength_Pa, eps_c1));
  }
  // Past the peak the specimen crushes within a second: the stress falls while
  // the shortening grows.
  double eta = 1.0;
  for (double fraction : {0.97, 0.9, 0.75, 0.45, 0.15, 0.03}) {
    eta += 0.05;
    push_failure(t_first + double(i++) * dtf, fraction * spec.strength_Pa, eta * eps_c1);
  }
  return out;
}

std::string compression_record_csv(const SyntheticCompressionRecord& record) {
  std::vector<std::string> header = {"t_s", "force_kN", "crosshead_mm"};
  for (std::size_t c = 0; c < record.extensometer_m.size(); ++c) header.push_back("ext" + std::to_string(c + 1) + "_mm");
  std::vector<std::vector<std::string>> rows;
  rows.reserve(record.t_s.size());
  for (std::size_t i = 0; i < record.t_s.size(); ++i) {
    std::vector<std::string> row = {format_fixed(record.t_s[i], 3), format_fixed(record.force_N[i] / 1e3, 4),
                                    format_fixed(record.crosshead_m[i] * 1e3, 6)};
    for (const auto& ch : record.extensometer_m) row.push_back(std::isnan(ch[i]) ? "" : format_fixed(ch[i] * 1e3, 7));
    rows.push_back(std::move(row));
  }
  return io::to_csv(header, rows);
}

}  // namespace mesowave::lab
