// One-sided spectra against closed forms: the DFT of a sampled Hann burst
// (geometric sums), its continuous Fourier transform, tones on a bin, and
// records of 1-3 samples.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesowave/core/error.hpp"
#include "mesowave/signal/hann_burst.hpp"
#include "mesowave/signal/spectrum.hpp"
#include "signal/reference.hpp"

using namespace mesowave;
using namespace mesowave::signal;
using cplx = std::complex<double>;

namespace {

constexpr double pi = std::numbers::pi;
const cplx I(0, 1);

// The burst as 0.5 A [sin(w t) - 0.5 sin(w+ t) - 0.5 sin(w- t)], w+- = w (1 +- 1/n), for 0 <= t <= T.
struct BurstTerms {
  double a[3], c[3];
};
BurstTerms terms(const HannBurst& b) {
  const double w = 2 * pi * b.centre_frequency_hz(), n = b.cycles(), A = b.amplitude();
  return {{w, w * (1 + 1 / n), w * (1 - 1 / n)}, {0.5 * A, -0.25 * A, -0.25 * A}};
}

// DFT bin k (length M) of the samples x_j = burst(j dt), j in [j0, j1], by the
// geometric sum  sum_j r^j = r^j0 (1 - r^L) / (1 - r)  for each exponential.
cplx burst_dft_closed_form(const HannBurst& b, double dt, std::size_t j0, std::size_t j1, std::size_t k, std::size_t M) {
  const auto tm = terms(b);
  const double theta = 2 * pi * double(k) / double(M);
  const double L = double(j1 - j0 + 1);
  auto geometric = [&](double alpha) {  // sum_{j=j0}^{j1} e^{i alpha j}
    const cplx r = std::exp(I * alpha);
    if (std::abs(1.0 - r) < 1e-14) return std::exp(I * alpha * double(j0)) * L;
    return std::exp(I * alpha * double(j0)) * (1.0 - std::exp(I * alpha * L)) / (1.0 - r);
  };
  cplx X = 0;
  for (int m = 0; m < 3; ++m) {
    const double a = tm.a[m], d = b.delay_s();
    // sin(a (j dt - d)) = (e^{i a (j dt - d)} - e^{-i a (j dt - d)}) / 2i
    X += tm.c[m] * (std::exp(-I * a * d) * geometric(a * dt - theta) - std::exp(I * a * d) * geometric(-a * dt - theta)) /
         (2.0 * I);
  }
  return X;
}

// |integral_0^T burst(d + tau) e^{-i w tau} d tau|, the continuous Fourier transform's magnitude.
double burst_ft_magnitude(const HannBurst& b, double f) {
  const auto tm = terms(b);
  const double w = 2 * pi * f, T = b.duration_s();
  auto E = [&](double beta) -> cplx { return std::abs(beta) < 1e-12 ? cplx(T) : (std::exp(I * beta * T) - 1.0) / (I * beta); };
  cplx F = 0;
  for (int m = 0; m < 3; ++m) F += tm.c[m] * (E(tm.a[m] - w) - E(-tm.a[m] - w)) / (2.0 * I);
  return std::abs(F);
}

}  // namespace

TEST(Spectrum, HannBurstMatchesTheClosedFormDftBinByBin) {
  // A burst that ends exactly on the last sample: the record's end touches it.
  const double dt = 1e-7;
  const std::size_t n = 2000, cycles_end = n - 1;
  const HannBurst b(100e3, 5, 1.0, double(cycles_end - 500) * dt);  // T = 50 us = 500 dt
  const auto x = b.sample(dt, n);
  for (const auto& pad : {Padding{}, Padding{Padding::Mode::to_length, 8192}}) {
    const auto s = amplitude_spectrum(x, dt, {Detrend::none, pad, SpectrumScaling::raw});
    const std::size_t M = pad.fft_length(n);
    ASSERT_EQ(s.fft_length, M);
    ASSERT_EQ(s.amplitude.size(), M / 2 + 1);
    double peak = 0, worst = 0;
    for (std::size_t k = 0; k < s.amplitude.size(); ++k) {
      const double ref = std::abs(burst_dft_closed_form(b, dt, cycles_end - 500, cycles_end, k, M));
      peak = std::max(peak, ref);
      worst = std::max(worst, std::abs(s.amplitude[k] - ref));
      EXPECT_NEAR(s.frequency_hz[k], double(k) / (double(M) * dt), 1e-9);
    }
    EXPECT_LT(worst, 1e-10 * peak) << "M " << M;
  }
}

TEST(Spectrum, DensityScalingApproachesTheContinuousFourierTransform) {
  // dt |X_k| = |F(f_k)| up to the trapezoid error of a burst that starts and
  // ends like tau^3: about (w dt)^4 / 720 = 2e-8 relatively at 10 MHz sampling.
  const double dt = 1e-7;
  const HannBurst b(100e3, 5, 1.0, 20e-6);
  const auto x = b.sample(dt, 1000);
  const auto s = amplitude_spectrum(x, dt, {Detrend::none, Padding{Padding::Mode::to_length, 16000}, SpectrumScaling::density});
  EXPECT_EQ(s.unit("m/s^2"), "m/s^2 s");
  double peak = 0;
  for (std::size_t k = 0; k < s.amplitude.size(); ++k) peak = std::max(peak, burst_ft_magnitude(b, s.frequency_hz[k]));
  EXPECT_NEAR(peak, 0.25 * b.duration_s(), 0.01 * peak);  // the main lobe: A T / 4 at f_c (Hann mean 1/2, sin 1/2)
  for (std::size_t k = 0; k < s.amplitude.size(); k += 7)
    ASSERT_NEAR(s.amplitude[k], burst_ft_magnitude(b, s.frequency_hz[k]), 1e-6 * peak) << s.frequency_hz[k];
  // The main lobe of a 5-cycle Hann burst ends at f_c (1 +- 2/5) = 60 and 140 kHz.
  const double df = s.df_hz;
  EXPECT_LT(s.amplitude[std::size_t(std::lround(60e3 / df))], 0.01 * peak);
  EXPECT_LT(s.amplitude[std::size_t(std::lround(140e3 / df))], 0.01 * peak);
  // Its maximum (f_c, shifted slightly by the negative-frequency lobe) is found.
  double f_best = 0, best = 0;
  for (double f = 80e3; f < 120e3; f += 1.0)
    if (burst_ft_magnitude(b, f) > best) best = burst_ft_magnitude(b, f), f_best = f;
  EXPECT_NEAR(peak_frequency_hz(s), f_best, 0.05 * df);
}

TEST(Spectrum, AmplitudeScalingReadsASineAmplitudeAndTheOffset) {
  for (std::size_t n : {64, 29999, 30000}) {
    const double dt = 1e-6;
    std::vector<double> x(n);
    for (std::size_t j = 0; j < n; ++j) x[j] = 0.3 + 2.5 * std::sin(2 * pi * double((13 * j) % n) / double(n));
    const auto s = amplitude_spectrum(x, dt);
    EXPECT_NEAR(s.amplitude[0], 0.3, 1e-12) << n;
    EXPECT_NEAR(s.amplitude[13], 2.5, 1e-11) << n;
    EXPECT_NEAR(s.frequency_hz[13], 13.0 / (double(n) * dt), 1e-9) << n;
    // Zero padded to 4n, the same tone sits on bin 52 and still reads 2.5.
    const auto p = amplitude_spectrum(x, dt, {Detrend::mean, Padding{Padding::Mode::to_length, 4 * n}});
    EXPECT_NEAR(p.amplitude[52], 2.5, 1e-11) << n;
    EXPECT_NEAR(p.amplitude[0], 0.0, 1e-12) << n;  // the offset removed
  }
}

TEST(Spectrum, RecordsOfOneTwoAndThreeSamples) {
  const double dt = 0.5;
  auto s1 = amplitude_spectrum(std::vector<double>{-4}, dt);
  ASSERT_EQ(s1.amplitude.size(), 1u);
  EXPECT_EQ(s1.frequency_hz[0], 0.0);
  EXPECT_DOUBLE_EQ(s1.amplitude[0], 4.0);
  auto s2 = amplitude_spectrum(std::vector<double>{3, 1}, dt);  // X = [4, 2]; DC and Nyquist not doubled
  ASSERT_EQ(s2.amplitude.size(), 2u);
  EXPECT_DOUBLE_EQ(s2.frequency_hz[1], 1.0);
  EXPECT_DOUBLE_EQ(s2.amplitude[0], 2.0);
  EXPECT_DOUBLE_EQ(s2.amplitude[1], 1.0);
  auto s3 = amplitude_spectrum(std::vector<double>{1, 0, 0}, dt);  // X = [1, 1, 1]
  ASSERT_EQ(s3.amplitude.size(), 2u);
  EXPECT_NEAR(s3.frequency_hz[1], 1.0 / 1.5, 1e-15);
  EXPECT_NEAR(s3.amplitude[0], 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(s3.amplitude[1], 2.0 / 3.0, 1e-15);
}

TEST(Spectrum, LinearDetrendRemovesAnOffsetWithADrift) {
  const double dt = 1e-7;
  const HannBurst b(300e3, 5, 1.0, 30e-6);
  const auto clean = b.sample(dt, 1500);
  auto dirty = clean;
  for (std::size_t i = 0; i < dirty.size(); ++i) dirty[i] += -2.0 + 4e3 * double(i) * dt;
  const SpectrumOptions lin{Detrend::linear, Padding{}, SpectrumScaling::amplitude};
  const auto a = amplitude_spectrum(clean, dt, lin), c = amplitude_spectrum(dirty, dt, lin);
  for (std::size_t k = 0; k < a.amplitude.size(); ++k) ASSERT_NEAR(c.amplitude[k], a.amplitude[k], 1e-12) << k;
  // The peak is where the burst is, not at DC.
  EXPECT_NEAR(peak_frequency_hz(c), 300e3, 0.5 * c.df_hz + 5e3);
}

TEST(Spectrum, BadInputsAreInputErrors) {
  EXPECT_THROW(amplitude_spectrum(std::vector<double>{}, 1e-6), InputError);
  EXPECT_THROW(amplitude_spectrum(std::vector<double>{1, 2}, 0.0), InputError);
  EXPECT_THROW(amplitude_spectrum(std::vector<double>{1, NAN}, 1e-6), InputError);
  EXPECT_THROW(parse_spectrum_scaling("dB"), InputError);
  EXPECT_THROW(amplitude_spectrum(std::vector<double>{1, 2, 3}, 1e-6, {Detrend::none, Padding{Padding::Mode::to_length, 2}}),
               InputError);
}
