// Time-of-flight pickers on synthetic records whose onset is known: a
// variance change point, sine onsets (noiseless and at 10 dB SNR), UPV-like
// records with pre-trigger noise, Hann bursts (off-grid centres, two packets,
// a burst ending on the last sample, a DC offset with a drift).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesowave/core/error.hpp"
#include "mesowave/signal/hann_burst.hpp"
#include "mesowave/signal/time_of_flight.hpp"
#include "signal/reference.hpp"

using namespace mesowave;
using namespace mesowave::signal;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double dt = 1e-7;  // 10 MHz, as the papers' records

Signal record(std::vector<double> samples, double t0 = 0.0) {
  return Signal{"B", "acceleration", "m/s^2", "z", t0, dt, std::move(samples), std::nullopt};
}

// A sine of amplitude 1 at f switched on at sample `onset` (value sin(0) = 0 there,
// so the first nonzero sample is onset + 1), plus sigma * noise.
Signal sine_onset(std::size_t n, std::size_t onset, double f, double sigma, std::uint64_t seed, double t0 = 0.0) {
  const auto e = test::gaussian_noise(n, seed);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i)
    x[i] = (i >= onset ? std::sin(2 * pi * f * double(i - onset) * dt) : 0.0) + sigma * e[i];
  return record(x, t0);
}

// Maeda's AIC by its definition, variances by two passes per split.
double aic_by_definition(const std::vector<double>& x, std::size_t k) {
  auto var = [&](std::size_t a, std::size_t b) {
    double m = 0, v = 0;
    for (std::size_t i = a; i < b; ++i) m += x[i] / double(b - a);
    for (std::size_t i = a; i < b; ++i) v += (x[i] - m) * (x[i] - m) / double(b - a);
    return v;
  };
  const double n = double(x.size());
  return double(k) * std::log(var(0, k)) + (n - double(k) - 1) * std::log(var(k, x.size()));
}

}  // namespace

TEST(Aic, CurveIsMaedasFormula) {
  const auto x = test::uniform_values(57, 5);
  const auto aic = aic_curve(x);
  ASSERT_EQ(aic.size(), 57u - 3u);
  for (std::size_t k = 2; k <= 55; ++k) EXPECT_NEAR(aic[k - 2], aic_by_definition(x, k), 1e-10) << k;
  EXPECT_THROW(aic_curve(std::vector<double>{1, 2, 3}), InputError);
  EXPECT_THROW(aic_curve(std::vector<double>(10, 4.2)), InputError);  // constant: no onset
}

TEST(Aic, FindsAVarianceChangePoint) {
  // Gaussian noise whose sd steps from 0.1 to 1 at sample 800: the split that
  // AIC (a likelihood) prefers is the change point itself.
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const auto e = test::gaussian_noise(2000, seed);
    std::vector<double> x(2000);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = (i < 800 ? 0.1 : 1.0) * e[i];
    const auto p = aic_pick(record(x));
    EXPECT_EQ(p.method, "aic");
    EXPECT_NEAR(double(p.index), 800.0, 2.0) << "seed " << seed;
    EXPECT_NEAR(p.time_s, double(p.index) * dt, 1e-18);
    EXPECT_EQ(p.quality_name, "aic_sd_s");
    EXPECT_LT(p.quality, 2 * dt) << "seed " << seed;  // a sharp minimum
  }
}

TEST(Aic, NoiselessOnsetIsExact) {
  const auto s = sine_onset(3000, 1000, 100e3, 0.0, 1);
  const auto p = aic_pick(s);
  EXPECT_EQ(p.index, 1001u);  // the first nonzero sample
  EXPECT_LT(p.quality, 1e-3 * dt);
}

TEST(Aic, SineOnsetAtTenDecibels) {
  // 10 dB: noise power 0.5/10, sd 0.22. The sine rises above one noise sd
  // asin(0.22)/w = 0.35 us after its onset; the pick may not precede the
  // onset and should come within a few such times (1 us, a tenth of a period).
  const double sigma = std::sqrt(0.05);
  for (std::uint64_t seed = 11; seed <= 15; ++seed) {
    const auto s = sine_onset(3000, 1000, 100e3, sigma, seed);
    const auto p = aic_pick(s, {TimeWindow{50e-6, 200e-6}});
    const double late = p.time_s - 100e-6;
    EXPECT_GE(late, 0.0) << "seed " << seed;
    EXPECT_LE(late, 1e-6) << "seed " << seed;
    // A DC offset changes no variance: the same split.
    auto offset = s;
    for (auto& v : offset.samples) v += 5.0;
    EXPECT_EQ(aic_pick(offset, {TimeWindow{50e-6, 200e-6}}).index, p.index) << "seed " << seed;
  }
}

TEST(Aic, WithoutAWindowEndItStopsAtThePeak) {
  // A noiseless simulated record: zeros, a burst, zeros. Over the whole
  // record the burst's end (followed by more zeros than precede it) would be
  // the better split; the default window ends at the largest |x|.
  const HannBurst burst(100e3, 5, 1.0, 20e-6);
  const auto s = record(burst.sample(dt, 2000));
  const auto p = aic_pick(s);
  EXPECT_EQ(p.index, 201u);  // the first nonzero sample (the burst is exactly 0 at 20 us)
  EXPECT_GT(aic_pick(s, {TimeWindow{0.0, 199.9e-6}}).time_s, 69e-6);  // the whole record: its end
}

TEST(Aic, WindowTooShortOrOutsideTheRecord) {
  const auto s = sine_onset(100, 50, 100e3, 0.0, 1);
  EXPECT_THROW(aic_pick(s, {TimeWindow{1e-6, 1.2e-6}}), InputError);  // 3 samples
  EXPECT_THROW(aic_pick(s, {TimeWindow{1e-3, 2e-3}}), InputError);
  EXPECT_THROW(aic_pick(s, {TimeWindow{5e-6, 2e-6}}), InputError);
  EXPECT_THROW(aic_pick(record({1, 2, 3})), InputError);
}

TEST(Threshold, UpvRecordWithPreTriggerNoise) {
  // Trigger at t = 0, 20 us of pre-trigger noise (sd 0.01), a sine of
  // amplitude 1 from 30 us. The threshold 5 sd = 0.05 is reached at
  // 30 us + asin(0.05)/w; noise of 0.01 on a slope of w moves that by ~0.016 us.
  const double sigma = 0.01, f = 100e3, w = 2 * pi * f;
  for (std::uint64_t seed = 21; seed <= 25; ++seed) {
    const auto s = sine_onset(1200, 500, f, sigma, seed, -20e-6);  // onset at -20 + 50 = 30 us
    const auto p = threshold_pick(s);
    EXPECT_EQ(p.method, "threshold");
    EXPECT_NEAR(p.time_s, 30e-6 + std::asin(5 * sigma) / w, 0.05e-6) << "seed " << seed;
    EXPECT_EQ(p.quality_name, "snr_dB");
    EXPECT_NEAR(p.quality, 40.0, 1.0);  // 20 log10(1 / 0.01)
  }
}

TEST(Threshold, NoiselessRecordNeedsARelativeThreshold) {
  const auto s = sine_onset(2000, 500, 100e3, 0.0, 1);
  ThresholdOptions o;
  o.noise_end_s = 20e-6;
  EXPECT_THROW(threshold_pick(s, o), InputError);  // zero noise: no threshold
  o.relative = 0.1;
  const auto p = threshold_pick(s, o);
  // sin(w tau) = 0.1; linear interpolation between samples errs by < (w dt)^2 tau / 8.
  EXPECT_NEAR(p.time_s, 50e-6 + std::asin(0.1) / (2 * pi * 100e3), 1e-10);
  EXPECT_EQ(p.quality, 300.0);  // noiseless: capped
  // A record starting at 0 has no pre-trigger samples to measure noise on.
  EXPECT_THROW(threshold_pick(s), InputError);
  // Nothing crosses a threshold above the peak.
  auto quiet = sine_onset(2000, 500, 100e3, 0.01, 3);
  o.relative = 0;
  o.factor = 1000;
  EXPECT_THROW(threshold_pick(quiet, o), InputError);
}

TEST(EnvelopePeak, BurstCentreOffTheSampleGrid) {
  // The envelope of a 5-cycle (odd) Hann burst is symmetric about its centre
  // d + T/2, so its maximum is there; the parabola recovers it between samples.
  const HannBurst burst(100e3, 5, 1.0, 40.0333e-6);
  const auto s = record(burst.sample(dt, 2000));
  const auto p = envelope_peak_pick(s);
  EXPECT_EQ(p.method, "envelope-peak");
  EXPECT_NEAR(p.time_s, 40.0333e-6 + 25e-6, 0.01e-6);
  EXPECT_EQ(p.quality_name, "peak_ratio");
  EXPECT_GT(p.quality, 100.0);  // one packet, nothing competes
}

TEST(EnvelopePeak, ArrivalDifferenceGivesTheDelay) {
  // Group-velocity use: the same burst at two sensors, 37.25 us apart.
  const HannBurst near(200e3, 5, 1.0, 20e-6), far(200e3, 5, 0.6, 57.25e-6);
  const auto a = envelope_peak_pick(record(near.sample(dt, 2000)));
  const auto b = envelope_peak_pick(record(far.sample(dt, 2000)));
  EXPECT_NEAR(b.time_s - a.time_s, 37.25e-6, 0.01e-6);
}

TEST(EnvelopePeak, TwoPacketsCompete) {
  const HannBurst first(100e3, 5, 1.0, 20e-6), second(100e3, 5, 0.5, 120e-6);
  auto x = first.sample(dt, 3000);
  const auto y = second.sample(dt, 3000);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += y[i];
  const auto p = envelope_peak_pick(record(x));
  EXPECT_NEAR(p.time_s, 45e-6, 0.01e-6);
  EXPECT_NEAR(p.quality, 2.0, 0.02);  // the second packet's peak is half the first's
  // A search window picks the second one.
  const auto q = envelope_peak_pick(record(x), {TimeWindow{100e-6, 200e-6}});
  EXPECT_NEAR(q.time_s, 145e-6, 0.01e-6);
}

TEST(EnvelopePeak, BurstEndingOnTheLastSample) {
  const std::size_t n = 1500;
  const HannBurst burst(100e3, 5, 1.0, double(n - 1) * dt - 50e-6);
  const auto p = envelope_peak_pick(record(burst.sample(dt, n)));
  EXPECT_NEAR(p.time_s, double(n - 1) * dt - 25e-6, 0.01e-6);
}

TEST(EnvelopePeak, OffsetDriftAndTenDecibelNoise) {
  // 10 dB relative to the burst's power (3/16 A^2), white: the envelope's flat
  // top (above 0.9 of its peak for |t - centre| < 0.2 T = 10 us) is ragged, and
  // the maximum moves within it. Detrending removes the offset and drift.
  const HannBurst burst(100e3, 5, 1.0, 100e-6);
  const double sigma = std::sqrt(3.0 / 16.0 / 10.0);
  for (std::uint64_t seed = 31; seed <= 35; ++seed) {
    auto x = burst.sample(dt, 3000);
    const auto e = test::gaussian_noise(3000, seed);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] += sigma * e[i] + 2.0 + 1e4 * double(i) * dt;
    EnvelopePeakOptions o;
    o.hilbert.detrend = Detrend::linear;
    const auto p = envelope_peak_pick(record(x), o);
    EXPECT_NEAR(p.time_s, 125e-6, 10e-6) << "seed " << seed;
    // AIC, aimed at the first arrival and detrended, sees the burst rise out
    // of the noise before its envelope reaches 0.5 (tau = T/4 = 12.5 us).
    // Without detrending, the drift (1.4 over the window, ten noise sd) wins.
    EXPECT_LT(aic_pick(record(x), {TimeWindow{0.0, 140e-6}}).time_s, 100e-6) << "seed " << seed;
    const auto a = aic_pick(record(x), {TimeWindow{0.0, 140e-6}, Detrend::linear});
    EXPECT_GE(a.time_s, 100e-6) << "seed " << seed;
    EXPECT_LE(a.time_s, 112.5e-6) << "seed " << seed;
  }
}
