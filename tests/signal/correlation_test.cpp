// Pearson correlation against analytic values (self, negative, affine copy,
// phase-shifted copy, added quadrature, 10 dB noise), the per-sensor table
// and its mean (concrete paper Table 3), and every refusal.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <numbers>

#include "mesowave/core/error.hpp"
#include "mesowave/signal/correlation.hpp"
#include "mesowave/signal/hann_burst.hpp"
#include "signal/reference.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::signal;

namespace {

constexpr double pi = std::numbers::pi;

std::vector<double> tone(std::size_t n, std::size_t periods, double phase) {
  std::vector<double> x(n);
  for (std::size_t j = 0; j < n; ++j) x[j] = std::sin(2 * pi * double((periods * j) % n) / double(n) + phase);
  return x;
}

// (1 + 0.5 cos W t) sin(w t + phase) at integer periods: its envelope is the
// modulation whatever the phase (Bedrosian), so envelopes correlate at 1.
Signal modulated(const std::string& name, std::size_t n, double phase, double dt = 1e-7) {
  Signal s{name, "acceleration", "m/s^2", "z", 0.0, dt, std::vector<double>(n), std::nullopt};
  for (std::size_t j = 0; j < n; ++j)
    s.samples[j] = (1 + 0.5 * std::cos(2 * pi * double(5 * j % n) / double(n))) *
                   std::sin(2 * pi * double(150 * j % n) / double(n) + phase);
  return s;
}

}  // namespace

TEST(Pearson, SelfNegativeAndAffineCopies) {
  const auto x = test::uniform_values(1000, 1);
  std::vector<double> neg(x.size()), affine(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) neg[i] = -x[i], affine[i] = 3.0 * x[i] + 7.0;
  EXPECT_NEAR(pearson(x, x), 1.0, 1e-15);
  EXPECT_NEAR(pearson(x, neg), -1.0, 1e-15);
  EXPECT_NEAR(pearson(x, affine), 1.0, 1e-14);
}

TEST(Pearson, ShiftedCopyCorrelatesAsTheCosineOfItsPhase) {
  // Over integer periods sin(theta) and sin(theta + phi) have zero means, equal
  // variances and sum of products N/2 cos(phi): r = cos(phi). A circular shift
  // by s samples is phi = 2 pi m s / N.
  const std::size_t n = 3000, m = 7;
  const auto x = tone(n, m, 0.0);
  for (std::size_t shift : {1, 10, 100, 107, 214, 400}) {
    std::vector<double> y(n);
    for (std::size_t j = 0; j < n; ++j) y[j] = x[(j + n - shift) % n];
    EXPECT_NEAR(pearson(x, y), std::cos(2 * pi * double(m * shift) / double(n)), 1e-13) << shift;
  }
}

TEST(Pearson, AddedQuadratureLowersRAsOneOverRootOnePlusCSquared) {
  const std::size_t n = 4096;
  const auto s = tone(n, 32, 0.0), c = tone(n, 32, pi / 2);
  for (double k : {0.1, 1.0, 3.0}) {
    std::vector<double> y(n);
    for (std::size_t j = 0; j < n; ++j) y[j] = s[j] + k * c[j];
    EXPECT_NEAR(pearson(s, y), 1.0 / std::sqrt(1.0 + k * k), 1e-13) << k;
  }
}

TEST(Pearson, TenDecibelNoiseGivesTheExpectedCorrelation) {
  // y = x + sigma e with noise power sigma^2 = P/10 (10 dB): r = sqrt(P / (P + sigma^2)) = 1/sqrt(1.1),
  // up to the sampling spread of the noise's variance (sd sqrt(2/N)) and of its
  // covariance with x (sd sqrt(P/N)); to first order
  //   sd(ln r) = sqrt[(s2/(2(P+s2)))^2 2/N + (sigma^3/(P(P+s2)))^2 P/N].
  const std::size_t n = 30000;
  const HannBurst burst(100e3, 5, 1.0, 0.0);
  std::vector<double> x(n);
  for (std::size_t j = 0; j < n; ++j) x[j] = burst(double(j % 500) * 1e-7);  // a train of bursts
  double P = 0, mean = 0;
  for (double v : x) mean += v / double(n);
  for (double v : x) P += (v - mean) * (v - mean) / double(n);
  const double s2 = P / 10.0, sigma = std::sqrt(s2);
  const double expected = 1.0 / std::sqrt(1.1);
  const double sd = std::sqrt(std::pow(s2 / (2 * (P + s2)), 2) * 2.0 / double(n) +
                              std::pow(sigma * s2 / (P * (P + s2)), 2) * P / double(n));
  for (std::uint64_t seed : {2024u, 7u, 99u}) {
    const auto e = test::gaussian_noise(n, seed);
    std::vector<double> y(n);
    for (std::size_t j = 0; j < n; ++j) y[j] = x[j] + sigma * e[j];
    EXPECT_NEAR(pearson(x, y), expected, 4.0 * sd * expected) << "seed " << seed << ", sd(r) " << sd * expected;
  }
}

TEST(Pearson, RefusesWhatHasNoCoefficient) {
  const std::vector<double> a{1, 2, 3}, b{1, 2};
  EXPECT_EQ(test::input_error_of([&] { pearson(a, b, "sensor B"); }), "sensor B: unequal lengths (3 and 2 samples)");
  EXPECT_EQ(test::input_error_of([&] { pearson({}, {}, "sensor B"); }), "sensor B: cannot correlate an empty record");
  EXPECT_EQ(test::input_error_of([&] { pearson(a, std::vector<double>{1, NAN, 3}, "sensor B"); }),
            "sensor B (second): sample 1 is NaN");
  EXPECT_EQ(test::input_error_of([&] { pearson(a, std::vector<double>{2, 2, 2}, "sensor B"); }),
            "sensor B: the second record has zero variance (constant), r is undefined");
  // A constant that does not round exactly still has no variance.
  EXPECT_THROW(pearson(std::vector<double>(1000, 0.1), test::uniform_values(1000, 4)), InputError);
  // One sample has no variance; two samples always lie on a line.
  EXPECT_THROW(pearson(std::vector<double>{1}, std::vector<double>{2}), InputError);
  EXPECT_NEAR(pearson(std::vector<double>{1, 2}, std::vector<double>{5, 3}), -1.0, 1e-15);
  EXPECT_NEAR(pearson(std::vector<double>{1, 2}, std::vector<double>{3, 5}), 1.0, 1e-15);
}

TEST(Correlate, PerSensorTableAndMeanAsInTable3) {
  const std::size_t n = 3000;
  const std::vector<double> phases{0.1, 0.5, 1.2};
  std::vector<Signal> a, b;
  for (std::size_t i = 0; i < phases.size(); ++i) a.push_back(modulated(std::string(1, char('B' + i)), n, 0.0));
  for (std::size_t i = phases.size(); i-- > 0;)  // other order
    b.push_back(modulated(std::string(1, char('B' + i)), n, phases[i]));
  b.push_back(modulated("A", n, 0.0));  // the actuator, recorded only in b
  const auto table = correlate_sensors(a, b);
  ASSERT_EQ(table.sensors.size(), 3u);
  double mean = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(table.sensors[i].sensor, std::string(1, char('B' + i)));
    // Same modulation and zero-mean carriers at integer periods: r = cos(phase).
    EXPECT_NEAR(table.sensors[i].pcc_signal, std::cos(phases[i]), 1e-12);
    EXPECT_NEAR(table.sensors[i].pcc_envelope, 1.0, 1e-12);
    EXPECT_EQ(table.sensors[i].compared.count, n);
    mean += std::cos(phases[i]) / 3.0;
  }
  EXPECT_NEAR(table.mean_pcc_signal, mean, 1e-12);
  EXPECT_NEAR(table.mean_pcc_envelope, 1.0, 1e-12);
  EXPECT_TRUE(table.only_in_a.empty());
  ASSERT_EQ(table.only_in_b.size(), 1u);
  EXPECT_EQ(table.only_in_b[0], "A");
  EXPECT_EQ(table.resampling, "none (same time base)");
  EXPECT_EQ(table.envelope_method, "detrend none, padding none (FFT length 3000)");

  // Naming the sensors restricts (and orders) the table.
  const auto two = correlate_sensors(a, b, {}, {"D", "B"});
  ASSERT_EQ(two.sensors.size(), 2u);
  EXPECT_EQ(two.sensors[0].sensor, "D");
  EXPECT_NEAR(two.mean_pcc_signal, 0.5 * (std::cos(1.2) + std::cos(0.1)), 1e-12);
  EXPECT_THROW(correlate_sensors(a, b, {}, {"A"}), InputError);  // not in the first set
}

TEST(Correlate, TheLoadsRecordIsLeftOutOfTheMeanUnlessNamed) {
  // Two runs of one burst (FEM against FEM) both carry the load's record: it
  // would correlate at 1 and lift the mean over sensors above Table 3's.
  const std::size_t n = 3000;
  std::vector<Signal> a{modulated("B", n, 0.0), modulated(kExcitationName, n, 0.0)};
  std::vector<Signal> b{modulated(kExcitationName, n, 0.0), modulated("B", n, 1.0)};
  const auto table = correlate_sensors(a, b);
  ASSERT_EQ(table.sensors.size(), 1u);
  EXPECT_EQ(table.sensors[0].sensor, "B");
  EXPECT_NEAR(table.mean_pcc_signal, std::cos(1.0), 1e-12);
  EXPECT_TRUE(table.excitation_left_out);
  EXPECT_TRUE(table.only_in_a.empty() && table.only_in_b.empty());

  const auto named = correlate_sensors(a, b, {}, {"B", kExcitationName});
  ASSERT_EQ(named.sensors.size(), 2u);
  EXPECT_NEAR(named.mean_pcc_signal, 0.5 * (std::cos(1.0) + 1.0), 1e-12);
  EXPECT_FALSE(named.excitation_left_out);
}

TEST(Correlate, SpectraOfBothSetsComeWithTheTable) {
  std::vector<Signal> a{modulated("B", 3000, 0.0), modulated("C", 2999, 0.0)};
  std::vector<Signal> b{modulated("B", 3000, 0.3), modulated("C", 2999, 0.6)};
  for (auto pad : {Padding{}, Padding{Padding::Mode::to_length, 8192}}) {
    CorrelationOptions opt;
    opt.spectra = SpectrumOptions{Detrend::none, pad, SpectrumScaling::amplitude};
    const auto table = correlate_sensors(a, b, opt);
    for (std::size_t i = 0; i < 2; ++i) {
      // Shared with the envelope's transform or not, the same numbers as a spectrum on its own.
      const auto ref_a = amplitude_spectrum(a[i], *opt.spectra), ref_b = amplitude_spectrum(b[i], *opt.spectra);
      EXPECT_EQ(table.sensors[i].spectrum_a.amplitude, ref_a.amplitude) << i;
      EXPECT_EQ(table.sensors[i].spectrum_b.amplitude, ref_b.amplitude) << i;
      EXPECT_EQ(table.sensors[i].spectrum_b.fft_length, pad.fft_length(a[i].size()));
    }
    // The tone of `modulated` (150 periods in the record) sits at bin 150 unpadded.
    if (pad.mode == Padding::Mode::none) {
      EXPECT_NEAR(peak_frequency_hz(table.sensors[0].spectrum_a), 150.0 / 300e-6, 1.0);
    }
  }
}

TEST(Correlate, SameBitsWhateverTheThreadCount) {
  std::vector<Signal> a, b;
  for (int i = 0; i < 8; ++i) {
    a.push_back(modulated("S" + std::to_string(i), 3001, 0.0));
    auto s = modulated("S" + std::to_string(i), 3001, 0.1 * i);
    const auto noise = test::gaussian_noise(3001, 77 + i);
    for (std::size_t j = 0; j < s.samples.size(); ++j) s.samples[j] += 0.2 * noise[j];
    b.push_back(s);
  }
  omp_set_num_threads(1);
  const auto one = correlate_sensors(a, b);
  omp_set_num_threads(2);
  const auto two = correlate_sensors(a, b);
  for (std::size_t i = 0; i < one.sensors.size(); ++i) {
    EXPECT_EQ(one.sensors[i].pcc_signal, two.sensors[i].pcc_signal);
    EXPECT_EQ(one.sensors[i].pcc_envelope, two.sensors[i].pcc_envelope);
  }
  EXPECT_EQ(one.mean_pcc_signal, two.mean_pcc_signal);
}

TEST(Correlate, DifferentTimeBasesNeedAnExplicitResampling) {
  // The same smooth burst sampled at 10 MHz and at 4 MHz from another start.
  const HannBurst burst(100e3, 5, 1.0, 20e-6);
  Signal fine{"B", "velocity", "m/s", "", 0.0, 1e-7, burst.sample(1e-7, 1000), std::nullopt};
  Signal coarse{"B", "velocity", "m/s", "", -5e-6, 2.5e-7, burst.sample(2.5e-7, 440, -5e-6), std::nullopt};
  EXPECT_EQ(test::input_error_of([&] { correlate(fine, coarse); }),
            "sensor B: different time bases (1000 samples, dt 0.1 us, t0 0 us vs 440 samples, dt 0.25 us, t0 -5 us); "
            "ask for a resampling (mw-pcc --resample linear|cubic) to interpolate one onto the other");
  CorrelationOptions opt;
  opt.resampling = Interpolation::cubic_spline;
  const auto c = correlate(fine, coarse, opt);
  EXPECT_TRUE(c.resampled);
  EXPECT_EQ(c.compared.count, 1000u);  // the coarse record covers the fine one
  // At 40 samples per period the spline errs by ~(5/384) (w h)^4 = 5e-6 of the amplitude: r = 1 to ~1e-10.
  EXPECT_NEAR(c.pcc_signal, 1.0, 1e-8);
  opt.resampling = Interpolation::linear;
  const std::vector<Signal> A{fine}, B{coarse};
  const auto table = correlate_sensors(A, B, opt);
  EXPECT_EQ(table.resampling, "second set onto the first's samples by linear interpolation (1 of 1 sensors)");
  // Linear interpolation at 40 samples per period loses (w h)^2 / 8 = 3e-3 of the amplitude at worst: r still > 0.999.
  EXPECT_GT(table.sensors[0].pcc_signal, 0.999);
  EXPECT_LT(table.sensors[0].pcc_signal, 1.0 - 1e-8);  // and is measurably not exact
}

TEST(Correlate, UnequalLengthOnOneSamplingIsNamed) {
  Signal a = modulated("C", 3000, 0), b = modulated("C", 3000, 0.3);
  b.samples.resize(2990);
  EXPECT_EQ(test::input_error_of([&] { correlate(a, b); }),
            "sensor C: unequal lengths (3000 and 2990 samples on the same sampling); cut both to a common window or "
            "resample explicitly");
  // With a resampling allowed the overlap is compared.
  CorrelationOptions opt;
  opt.resampling = Interpolation::linear;
  EXPECT_EQ(correlate(a, b, opt).compared.count, 2990u);
}

TEST(Correlate, WindowRestrictsTheComparedSamples) {
  Signal a = modulated("B", 3000, 0), b = modulated("B", 3000, 0.4);
  CorrelationOptions opt;
  opt.begin_s = 50e-6;
  opt.end_s = 100e-6;
  const auto c = correlate(a, b, opt);
  EXPECT_EQ(c.compared.count, 501u);  // 50 .. 100 us at 0.1 us, both ends included
  EXPECT_NEAR(c.compared.t0_s, 50e-6, 1e-15);
  opt.begin_s = 1.0;
  opt.end_s = 2.0;
  EXPECT_THROW(correlate(a, b, opt), InputError);
}

TEST(Correlate, SetsThatCannotBeMatched) {
  const std::vector<Signal> a{modulated("B", 100, 0)}, b{modulated("C", 100, 0)};
  EXPECT_EQ(test::input_error_of([&] { correlate_sensors(a, b); }), "the two sets share no sensor name, nothing to correlate");
  const std::vector<Signal> twice{modulated("B", 100, 0), modulated("B", 100, 1)};
  EXPECT_EQ(test::input_error_of([&] { correlate_sensors(twice, a); }), "sensor 'B' appears twice in the first set");
  // A zero-variance sensor is named even when other sensors are fine.
  std::vector<Signal> flat{modulated("B", 100, 0), modulated("C", 100, 0)};
  flat[1].samples.assign(100, 0.0);
  const std::vector<Signal> ok{modulated("B", 100, 0), modulated("C", 100, 0)};
  EXPECT_EQ(test::input_error_of([&] { correlate_sensors(flat, ok); }),
            "sensor C: the first record has zero variance (constant), r is undefined");
}
