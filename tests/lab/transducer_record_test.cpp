// The synthetic transducer records of the picker study against closed forms:
// the pair response is the convolution of two damped resonators, its envelope
// peaks after the stated rise, the noise has the stated SNR, and a noiseless
// threshold crossing is the root of the closed-form front; the slow rise is its Hann lobe;
// the point force's records are Stokes' far field far away, and its near field has the
// signs of (3 g_i g_j - d_ij) and respects causality.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "mesowave/core/error.hpp"
#include "mesowave/lab/transducer_record.hpp"
#include "mesowave/lab/upv_waveform.hpp"

using namespace mesowave;
using namespace mesowave::lab;

namespace {
constexpr double pi = std::numbers::pi;
}  // namespace

TEST(TransducerRecord, ResponseIsTwoResonatorsConvolved) {
  // g(t) = e^{-a t} sin(w t) / w, one resonator; h = g * g by the trapezoid rule.
  const double f = 40e3, w = 2 * pi * f, a = transducer_decay_rate(f, 1.5);
  const double step = 1.0 / f / 4000;
  const auto g = [&](double t) { return std::exp(-a * t) * std::sin(w * t) / w; };
  double peak = 0;
  for (double tau : {0.3 / f, 0.9 / f, 1.5 / f, 2.7 / f}) {
    const auto n = std::size_t(std::llround(tau / step));
    double sum = 0;
    for (std::size_t i = 0; i <= n; ++i) {
      const double t = double(i) * step;
      sum += (i == 0 || i == n ? 0.5 : 1.0) * g(t) * g(tau - t);
    }
    const double h = transducer_response(tau, f, a);
    peak = std::max(peak, std::abs(h));
    // Trapezoid error ~ step^2 |(g g)''| tau / 12: below 1e-6 of the response at 4000 steps a period.
    EXPECT_NEAR(sum * step, h, 1e-6 * std::abs(h) + 1e-9 * peak) << tau * f << " periods";
  }
  EXPECT_EQ(transducer_response(-1e-6, f, a), 0.0);
  EXPECT_EQ(transducer_response(0.0, f, a), 0.0);
}

TEST(TransducerRecord, EnvelopePeaksAfterTheStatedRise) {
  for (double rise : {1.0, 1.5, 2.0}) {
    const double f = 45e3, w = 2 * pi * f, a = transducer_decay_rate(f, rise), tau_r = rise / f;
    // The closed-form envelope e^{-a tau} sqrt(1 + w^2 tau^2) is stationary at tau_r.
    const auto env = [&](double tau) { return std::exp(-a * tau) * std::sqrt(1 + w * w * tau * tau); };
    const double d = 1e-3 / f;
    EXPECT_NEAR((env(tau_r + d) - env(tau_r - d)) / (2 * d) / (env(tau_r) * f), 0.0, 1e-6) << rise;
    // On a noiseless record the largest sample is the carrier extreme nearest
    // that peak: within a quarter period of it, and since ln|z| is a parabola of
    // curvature ~ -1/tau_r^2 there, at least exp(-(T/4)^2 / (2 tau_r^2)) =
    // exp(-1 / (32 rise^2)) of the stated amplitude (0.969 for one period).
    // (The Hilbert envelope of a pulse this broad does not peak at tau_r: it
    // is not the narrow-band envelope |z|; the study measures it as it is.)
    TransducerRecordSpec spec;
    spec.frequency_Hz = f;
    spec.rise_periods = rise;
    spec.snr_dB = 300;
    spec.amplitude = 2.0;
    const auto r = transducer_record(spec);
    std::size_t k = 0;
    for (std::size_t i = 0; i < r.size(); ++i)
      if (std::abs(r.samples[i]) > std::abs(r.samples[k])) k = i;
    EXPECT_NEAR((r.time(k) - spec.onset_s) * f, rise, 0.25 + spec.sample_interval_s * f) << rise;
    EXPECT_LE(std::abs(r.samples[k]), 2.0 * (1 + 1e-12)) << rise;
    EXPECT_GE(std::abs(r.samples[k]), 2.0 * std::exp(-1.0 / (32 * rise * rise))) << rise;
  }
}

TEST(TransducerRecord, NoiseAtTheStatedSnrAndSeeded) {
  TransducerRecordSpec spec;
  spec.pretrigger_s = 2e-3;  // 20000 noise samples: the RMS to 0.5 % (1 / sqrt(2 N))
  spec.snr_dB = 26;
  spec.amplitude = 0.5;
  const auto r = transducer_record(spec);
  double m2 = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; r.time(i) < 0; ++i, ++n) m2 += r.samples[i] * r.samples[i];
  EXPECT_EQ(n, 20000u);
  EXPECT_NEAR(std::sqrt(m2 / double(n)), 0.5 * std::pow(10.0, -26.0 / 20), 4 * 0.005 * 0.5 * std::pow(10.0, -26.0 / 20));
  EXPECT_EQ(transducer_record(spec).samples, r.samples);  // same seed, same bits
  spec.seed = 2;
  EXPECT_NE(transducer_record(spec).samples, r.samples);
}

TEST(TransducerRecord, PrecursorAddsTheSameResponseEarlier) {
  TransducerRecordSpec spec;
  spec.snr_dB = 300;
  const auto main_only = transducer_record(spec);
  spec.precursor_onset_s = 35e-6;
  spec.precursor_fraction = 0.4;
  const auto both = transducer_record(spec);
  const double a = transducer_decay_rate(spec.frequency_Hz, spec.rise_periods);
  const double w = 2 * pi * spec.frequency_Hz, tau_r = spec.rise_periods / spec.frequency_Hz;
  const double peak = std::exp(-a * tau_r) * std::sqrt(1 + w * w * tau_r * tau_r) / (2 * w * w * w);
  for (std::size_t i = 0; i < both.size(); i += 97) {
    const double expected = 0.4 * transducer_response(both.time(i) - 35e-6, spec.frequency_Hz, a) / peak;
    EXPECT_NEAR(both.samples[i] - main_only.samples[i], expected, 1e-12) << both.time(i);
  }
}

TEST(TransducerRecord, BadSpecsAreRefused) {
  const auto refused = [](auto change) {
    TransducerRecordSpec s;
    change(s);
    EXPECT_THROW(transducer_record(s), InputError);
  };
  refused([](auto& s) { s.frequency_Hz = 0; });
  refused([](auto& s) { s.rise_periods = -1; });
  refused([](auto& s) { s.precursor_fraction = 1.5; });
  refused([](auto& s) { s.precursor_onset_s = 60e-6; });  // after the main onset
  refused([](auto& s) { s.onset_s = 500e-6; });           // past the record
  refused([](auto& s) { s.snr_dB = std::nan(""); });
  refused([](auto& s) { s.sample_interval_s = 0; });
}

TEST(TransducerRecord, NoiselessThresholdCrossingIsTheFrontsRoot) {
  // mw-upv's threshold (0.2 of the peak on a noiseless record) is crossed
  // where |h| / peak first reaches 0.2: found here by bisection on the closed
  // form. The picker's linear interpolation between samples errs by about
  // dt^2 |h''| / (8 |h'|) ~ 1e-3 dt at 10 MHz: 0.05 dt.
  for (double f : {30e3, 60e3})
    for (double rise : {1.0, 2.0}) {
      TransducerRecordSpec spec;
      spec.frequency_Hz = f;
      spec.rise_periods = rise;
      spec.snr_dB = 300;
      const auto r = transducer_record(spec);
      OnsetOptions o;
      o.picker = "threshold";
      const auto pick = pick_onset(r, o);
      // The threshold is 0.2 of the record's largest sample (the picker's
      // definition), a carrier peak a little below the envelope's.
      const double a = transducer_decay_rate(f, rise);
      double largest = 0;
      for (std::size_t i = 0; i < r.size(); ++i)
        largest = std::max(largest, std::abs(transducer_response(r.time(i) - spec.onset_s, f, a)));
      const double peak = largest;
      // sin x - x cos x rises monotonically up to its first extremum at x ~ pi (half a period).
      double lo = 0, hi = 0.45 / f;
      for (int it = 0; it < 100; ++it) {
        const double mid = 0.5 * (lo + hi);
        (std::abs(transducer_response(mid, f, a)) / peak < 0.2 ? lo : hi) = mid;
      }
      EXPECT_NEAR(pick.pick.time_s - spec.onset_s, lo, 0.05 * spec.sample_interval_s) << f << " Hz, rise " << rise;
    }
}

TEST(TransducerRecord, SlowRiseIsTheStatedHannLobe) {
  // The record with a slow rise minus the same record without it (same seed) is
  // fraction x sin^2(pi (t - t_0) / D) on [t_0, t_0 + D], t_0 = onset - lead / f, and 0
  // elsewhere; a fraction of 0 leaves the record as it was, bit for bit.
  TransducerRecordSpec spec;
  spec.snr_dB = 30;
  const auto plain = transducer_record(spec);
  spec.slow_rise_fraction = 0;
  EXPECT_EQ(transducer_record(spec).samples, plain.samples);
  spec.slow_rise_fraction = 0.1;
  const auto risen = transducer_record(spec);
  const double t0 = spec.onset_s - 0.35 / spec.frequency_Hz, D = 1.0 / spec.frequency_Hz;
  double largest = 0;
  for (std::size_t i = 0; i < plain.size(); ++i) {
    const double t = plain.time(i), d = risen.samples[i] - plain.samples[i];
    const double q = t >= t0 && t <= t0 + D ? std::sin(pi * (t - t0) / D) : 0.0;
    EXPECT_NEAR(d, 0.1 * q * q, 1e-12) << t * 1e6 << " us";
    largest = std::max(largest, d);
  }
  EXPECT_NEAR(largest, 0.1, 1e-3);  // its peak at t_0 + D / 2, to a sample
  spec.slow_rise_fraction = 1.5;
  EXPECT_THROW(transducer_record(spec), InputError);
}

TEST(TransducerRecord, PointForceFarFieldIsTheLoadsRate) {
  // Far from the force (r = 20 m), the transverse record is F'(t - r/beta) normalised, and
  // the axial one F'(t - r/alpha): Stokes' far field (Aki & Richards Eq. 4.23). What is left:
  // the near field, at most ~ 2 alpha / (w r) = 4.9e-4 of the far field (axial; beta / (w r)
  // transverse), the record's peak taken at 50 ns samples, (w dt)^2 / 2 = 7e-4 under F''s, and
  // the reference's 1 ns grid, w x 0.5 ns = 3.8e-4: 1.6e-3 in all, under the bound 2e-3.
  const double f = 120e3, alpha = 3703.0, beta = 2355.0, r = 20.0;
  const auto rate = burst_wavelet(f, 2, true, 1e-9);
  double rate_peak = 0;
  for (double v : rate.samples) rate_peak = std::max(rate_peak, std::abs(v));
  for (bool axial : {false, true}) {
    PointForceRecordSpec spec;
    spec.distance_m = r;
    spec.p_speed_m_s = alpha;
    spec.s_speed_m_s = beta;
    spec.axial = axial;
    spec.snr_dB = std::numeric_limits<double>::infinity();
    spec.duration_s = 8.6e-3;
    const auto rec = point_force_record(spec);
    const double arrival = r / (axial ? alpha : beta);
    double worst = 0;
    for (std::size_t i = 0; i < rec.size(); ++i) {
      const double tau = rec.time(i) - arrival;
      const auto k = std::llround(tau / 1e-9);
      const double expected = k > 0 && std::size_t(k) < rate.size() ? rate.samples[std::size_t(k)] / rate_peak : 0.0;
      if (!axial || tau > -1e-6) worst = std::max(worst, std::abs(rec.samples[i] - expected));
    }
    EXPECT_LT(worst, 2e-3) << (axial ? "axial" : "transverse");
  }
}

TEST(TransducerRecord, PointForceNearFieldIsTheIntegralInClosedForm) {
  // Before r/alpha the records are exactly 0 (causality). Between r/alpha and r/beta the
  // transverse record is the near field alone, -1/r^3 d/dt int_{r/alpha}^{t} tau F(t - tau) dtau,
  // which integration by parts turns into -1/r^3 (t_a F(u) + int_0^u F), u = t - t_a (F(0) = 0),
  // with the Hann burst's integral in closed form:
  //   int_0^u F = (1 - cos w u) / (2 w) - [(1 - cos (1 + 1/n) w u) / ((1 + 1/n) w)
  //                                        + (1 - cos (1 - 1/n) w u) / ((1 - 1/n) w)] / 4.
  // The record (Simpson's rule on tau F'(t - tau)) is normalised by its peak: the ratio to the
  // closed form must be one positive constant (to Simpson's ~1e-6 and the sampling).
  PointForceRecordSpec spec;
  spec.p_speed_m_s = 3703.0;
  spec.s_speed_m_s = 2355.0;
  spec.snr_dB = std::numeric_limits<double>::infinity();
  const auto transverse = point_force_record(spec);
  spec.axial = true;
  const auto axial = point_force_record(spec);
  const double r = 0.05, ta = r / 3703.0, tb = r / 2355.0, w = 2 * pi * 120e3, n = 2;
  const auto F = [&](double u) { return std::sin(w * u) * 0.5 * (1 - std::cos(w * u / n)); };
  const auto G = [&](double u) {
    return (1 - std::cos(w * u)) / (2 * w) - ((1 - std::cos((1 + 1 / n) * w * u)) / ((1 + 1 / n) * w) +
                                              (1 - std::cos((1 - 1 / n) * w * u)) / ((1 - 1 / n) * w)) / 4;
  };
  std::vector<std::pair<double, double>> pairs;  // (record, closed form)
  double largest = 0;
  for (std::size_t i = 0; i < transverse.size(); ++i) {
    const double t = transverse.time(i);
    if (t < ta) {
      EXPECT_EQ(transverse.samples[i], 0.0) << t * 1e6;
      EXPECT_EQ(axial.samples[i], 0.0) << t * 1e6;
    } else if (t < tb) {
      const double closed = -(ta * F(t - ta) + G(t - ta)) / (r * r * r);
      pairs.push_back({transverse.samples[i], closed});
      largest = std::max(largest, std::abs(closed));
    }
  }
  double lo = 1e300, hi = -1e300;
  for (const auto& [rec, closed] : pairs)
    if (std::abs(closed) > 0.01 * largest) lo = std::min(lo, rec / closed), hi = std::max(hi, rec / closed);
  ASSERT_GT(pairs.size(), 100u);
  EXPECT_GT(lo, 0.0);
  EXPECT_NEAR(hi / lo, 1.0, 1e-4);
  spec.s_speed_m_s = 4000;  // beta > alpha
  EXPECT_THROW(point_force_record(spec), InputError);
}
