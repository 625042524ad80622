// Analytic signal and envelope against scipy.signal.hilbert's definition (the
// DFT by its definition, even and odd N), closed forms (H{cos} = sin at
// integer periods; an exactly band-limited AM signal; the Bedrosian bound for
// a Hann burst), and the hard cases: lengths 1-3, a large prime, an offset
// with a drift, a burst cut off by the end of the record.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesowave/core/error.hpp"
#include "mesowave/signal/envelope.hpp"
#include "mesowave/signal/hann_burst.hpp"
#include "signal/reference.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::signal;

namespace {

constexpr double pi = std::numbers::pi;

std::vector<double> tone(std::size_t n, std::size_t periods, double phase, bool sine) {
  std::vector<double> x(n);
  for (std::size_t j = 0; j < n; ++j) {
    const double a = 2.0 * pi * double((periods * j) % n) / double(n) + phase;
    x[j] = sine ? std::sin(a) : std::cos(a);
  }
  return x;
}

HilbertOptions padded(Padding::Mode mode, Detrend d = Detrend::none) { return {d, Padding{mode, 0}}; }

}  // namespace

TEST(Envelope, AnalyticSignalMatchesScipyDefinitionForEvenAndOddLengths) {
  // 257 (prime), 262 = 2 x 131 and 289 = 17^2 take the convolution path (fft.hpp: slow_fft_length).
  for (std::size_t n : {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 29, 64, 101, 256, 257, 262, 289}) {
    const auto x = test::uniform_values(n, 1000 + n);
    const auto z = analytic_signal(x);
    const auto ref = test::scipy_hilbert_definition(x);
    ASSERT_EQ(z.size(), n);
    for (std::size_t i = 0; i < n; ++i) {
      EXPECT_NEAR(z[i].real(), ref[i].real(), 1e-13 * double(n)) << "n " << n << " i " << i;
      EXPECT_NEAR(z[i].imag(), ref[i].imag(), 1e-13 * double(n)) << "n " << n << " i " << i;
    }
  }
}

TEST(Envelope, LengthsOneToThreeByHand) {
  // N = 1 and 2: h = [1] and [1, 1], so z = x and the envelope is |x|.
  EXPECT_EQ(analytic_signal(std::vector<double>{-2.5})[0], Complex(-2.5, 0));
  const auto z2 = analytic_signal(std::vector<double>{3, -1});
  EXPECT_NEAR(std::abs(z2[0] - Complex(3, 0)), 0, 1e-15);
  EXPECT_NEAR(std::abs(z2[1] - Complex(-1, 0)), 0, 1e-15);
  // N = 3: h = [1, 2, 0], so Im z_j = (2/3) Im(X_1 e^{2 pi i j/3}); for x = [1, 0, 0], X_1 = 1 and
  // Im z = (2/3) [0, sin(2 pi/3), sin(4 pi/3)] = [0, 1/sqrt(3), -1/sqrt(3)].
  const auto h3 = hilbert_transform(std::vector<double>{1, 0, 0});
  EXPECT_NEAR(h3[0], 0.0, 1e-15);
  EXPECT_NEAR(h3[1], 1.0 / std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(h3[2], -1.0 / std::sqrt(3.0), 1e-15);
}

TEST(Envelope, HilbertOfCosineAtIntegerPeriodsIsSine) {
  for (std::size_t n : {16, 1000, 1001, 29999, 30000}) {
    for (double phase : {0.0, 0.7}) {
      const std::size_t m = n == 16 ? 3 : 101;
      const auto h = hilbert_transform(tone(n, m, phase, false));
      const auto s = tone(n, m, phase, true);
      double err = 0;
      for (std::size_t j = 0; j < n; ++j) err = std::max(err, std::abs(h[j] - s[j]));
      EXPECT_LT(err, 1e-12) << "n " << n << " phase " << phase;
    }
  }
}

TEST(Envelope, AmplitudeModulatedToneHasItsModulationAsEnvelope) {
  // x = (1 + 0.5 cos W t) cos w t with W < w, both at integer periods: the
  // spectrum of the modulation lies below w, so (Bedrosian) z = (1 + 0.5 cos W t) e^{i w t} exactly.
  const std::size_t n = 4096;
  std::vector<double> x(n), ref(n);
  for (std::size_t j = 0; j < n; ++j) {
    const double a = 1.0 + 0.5 * std::cos(2 * pi * double(7 * j % n) / double(n));
    x[j] = a * std::cos(2 * pi * double(200 * j % n) / double(n));
    ref[j] = a;
  }
  const auto e = envelope(x);
  for (std::size_t j = 0; j < n; ++j) ASSERT_NEAR(e[j], ref[j], 1e-12) << j;
}

TEST(Envelope, HannBurstEnvelopeIsItsWindowWithinTheBedrosianBound) {
  // x = w(t) sin(2 pi f_c t) with w the Hann window of T = n/f_c. Its analytic
  // signal differs from -i w e^{i 2 pi f_c t} only through W(f) at |f| > f_c,
  // so |env - w| <= integral_{|f| > f_c} |W(f)| df
  //   <= 2 int_n^inf du / (2 pi u (u^2 - 1)) = -ln(1 - 1/n^2) / (2 pi) = 0.0065 for n = 5 cycles.
  const double fc = 100e3, dt = 1e-7, delay = 100e-6;
  const HannBurst burst(fc, 5, 1.0, delay);
  const auto x = burst.sample(dt, 3000);
  const auto e = envelope(x, padded(Padding::Mode::double_length));
  const double bound = -std::log(1.0 - 1.0 / 25.0) / (2 * pi);
  double worst = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double tau = double(i) * dt - delay;
    const double w = (tau >= 0 && tau <= burst.duration_s()) ? 0.5 * (1 - std::cos(2 * pi * fc * tau / 5)) : 0.0;
    worst = std::max(worst, std::abs(e[i] - w));
  }
  EXPECT_LT(worst, bound);
}

TEST(Envelope, OffsetAndDriftAreRemovedExactlyByLinearDetrend) {
  const HannBurst burst(200e3, 5, 2.0, 40e-6);
  const auto clean = burst.sample(1e-7, 2000);
  auto dirty = clean;
  for (std::size_t i = 0; i < dirty.size(); ++i) dirty[i] += 3.0 + 1.5e3 * double(i) * 1e-7;  // 3 + 1500 t
  const auto e_clean = envelope(clean, padded(Padding::Mode::double_length, Detrend::linear));
  const auto e_dirty = envelope(dirty, padded(Padding::Mode::double_length, Detrend::linear));
  // Detrending is linear and annihilates a + b t, so both records become the same one.
  for (std::size_t i = 0; i < clean.size(); ++i) ASSERT_NEAR(e_dirty[i], e_clean[i], 1e-11) << i;
  // Without detrending the offset dominates: the envelope far from the burst is about |3 + 1500 t|.
  const auto e_raw = envelope(dirty, padded(Padding::Mode::double_length));
  EXPECT_GT(e_raw[1900], 2.0);
  // Mean removal leaves the drift, which ruins the envelope (documented edge effect).
  const auto e_mean = envelope(dirty, padded(Padding::Mode::double_length, Detrend::mean));
  EXPECT_GT(std::abs(e_mean[1990] - e_clean[1990]), 0.1);
}

TEST(Envelope, BurstCutOffByTheEndOfTheRecordWrapsWithoutPadding) {
  // Half a burst: the record ends at the burst's centre. The DFT's periodic
  // extension puts that jump next to the record's start.
  const double dt = 1e-7;
  const std::size_t n = 3000;
  const HannBurst burst(100e3, 5, 1.0, double(n - 1) * dt - 25e-6);
  const auto x = burst.sample(dt, n);
  auto early_max = [](const std::vector<double>& e) {
    double m = 0;
    for (std::size_t i = 0; i < 300; ++i) m = std::max(m, e[i]);
    return m;
  };
  const auto e_none = envelope(x);
  const auto e_pad = envelope(x, padded(Padding::Mode::double_length));
  // Without padding the first 30 us see the half burst: an artefact of order its amplitude.
  EXPECT_GT(early_max(e_none), 0.3);
  // Zero padded, the start sees only the aperiodic Hilbert tail of the cut
  // burst, about A / (pi w_c d) = 1 / (pi 2 pi 1e5 245e-6) = 0.002 at d >= 245 us.
  EXPECT_LT(early_max(e_pad), 0.002);
  // Both agree where the burst is: the padding changes the edges only.
  EXPECT_NEAR(e_none[n - 100], e_pad[n - 100], 0.01);
}

TEST(Envelope, PaddedResultIsScipyWithLongerFftCutBack) {
  // scipy.signal.hilbert(x, M)[:N]: the definition applied to the zero padded record.
  const auto x = test::uniform_values(21, 9);
  auto padded_x = x;
  padded_x.resize(50, 0.0);
  const auto ref = test::scipy_hilbert_definition(padded_x);
  const auto z = analytic_signal(x, {Detrend::none, Padding{Padding::Mode::to_length, 50}});
  ASSERT_EQ(z.size(), 21u);
  for (std::size_t i = 0; i < z.size(); ++i) EXPECT_NEAR(std::abs(z[i] - ref[i]), 0.0, 1e-13) << i;
}

TEST(Envelope, SignalOverloadKeepsTheTimeBaseAndNamesTheQuantity) {
  Signal s{"B", "acceleration", "m/s^2", "z", -1e-5, 1e-7, tone(1000, 20, 0, false), std::nullopt};
  const auto e = envelope(s);
  EXPECT_EQ(e.name, "B");
  EXPECT_EQ(e.quantity, "acceleration envelope");
  EXPECT_EQ(e.unit, "m/s^2");
  EXPECT_EQ(e.t0_s, s.t0_s);
  EXPECT_EQ(e.dt_s, s.dt_s);
  EXPECT_NEAR(e.samples[500], 1.0, 1e-12);
  EXPECT_EQ(HilbertOptions{}.describe(1000), "detrend none, padding none (FFT length 1000)");
}

TEST(Envelope, BadRecordsAreInputErrors) {
  EXPECT_THROW(envelope(std::vector<double>{}), InputError);
  EXPECT_THROW(envelope(std::vector<double>{1, NAN, 2}), InputError);
  EXPECT_THROW(envelope(std::vector<double>{1, INFINITY}), InputError);
  Signal s{"B", "", "", "", 0, 0, {1, 2, 3}, std::nullopt};
  EXPECT_THROW(envelope(s), InputError);  // dt = 0
  const Signal t{"C", "", "", "", 0, 1e-6, {1, 2, NAN}, std::nullopt};
  EXPECT_EQ(mesowave::test::input_error_of([&] { envelope(t); }), "signal C: sample 2 (t = 2 us) is NaN");
}
