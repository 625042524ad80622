// FFT against the DFT by its definition (O(N^2) for small N, single bins by
// O(N) sums for the prime 29,999), round trips, padding, errors.
#include <gtest/gtest.h>

#include <cmath>
#include <thread>

#include "mesowave/core/error.hpp"
#include "mesowave/signal/fft.hpp"
#include "signal/reference.hpp"

using namespace mesowave;
using namespace mesowave::signal;
using mesowave::test::cplx;

namespace {

double max_abs_diff(const std::vector<cplx>& a, const std::vector<cplx>& b) {
  EXPECT_EQ(a.size(), b.size());
  double d = 0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

}  // namespace

TEST(Fft, RealForwardMatchesDirectDftForSmallLengths) {
  // Past n = 256, lengths with a prime factor above 13 leave FFTW: the primes 257, 263, 1009 for
  // Rader's reduction, 262 = 2 x 131 and 289 = 17^2 for Bluestein's chirp convolution.
  for (std::size_t n : {1, 2, 3, 4, 5, 6, 7, 8, 9, 15, 16, 17, 29, 64, 97, 100, 128, 243, 255, 256, 257, 262, 263, 289, 1009}) {
    const auto x = test::uniform_values(n, 100 + n);
    const auto X = rfft(x);
    auto ref = test::direct_dft(test::to_complex(x));
    ref.resize(n / 2 + 1);
    ASSERT_EQ(X.size(), n / 2 + 1) << "n = " << n;
    // Rounding of an FFT grows like eps log N |x|; |x| <= sqrt(N) here.
    EXPECT_LT(max_abs_diff(X, ref), 1e-13 * double(n)) << "n = " << n;
  }
}

TEST(Fft, ComplexForwardAndInverseMatchDirectDft) {
  for (std::size_t n : {1, 2, 3, 5, 8, 12, 31, 64}) {
    const auto re = test::uniform_values(n, 7 * n), im = test::uniform_values(n, 11 * n);
    std::vector<cplx> x(n);
    for (std::size_t i = 0; i < n; ++i) x[i] = {re[i], im[i]};
    EXPECT_LT(max_abs_diff(fft(x), test::direct_dft(x)), 1e-13 * double(n)) << n;
    auto inv = test::direct_dft(x, +1);
    for (auto& v : inv) v /= double(n);
    EXPECT_LT(max_abs_diff(ifft(x), inv), 1e-14 * double(n)) << n;
    EXPECT_LT(max_abs_diff(ifft(fft(x)), x), 1e-14 * double(n)) << n;
  }
}

TEST(Fft, ZeroPaddingIsTheDftOfThePaddedRecord) {
  const auto x = test::uniform_values(13, 5);
  auto padded = x;
  padded.resize(40, 0.0);
  auto ref = test::direct_dft(test::to_complex(padded));
  ref.resize(21);
  EXPECT_LT(max_abs_diff(rfft(x, 40), ref), 1e-12);
}

TEST(Fft, InverseRealTransformRecoversTheRecord) {
  for (std::size_t n : {1, 2, 3, 10, 11, 29999}) {
    const auto x = test::uniform_values(n, n);
    const auto y = irfft(rfft(x), n);
    double d = 0;
    for (std::size_t i = 0; i < n; ++i) d = std::max(d, std::abs(y[i] - x[i]));
    EXPECT_LT(d, 1e-14 * std::log2(double(n) + 1) + 1e-15) << "n = " << n;
  }
}

TEST(Fft, LargeAwkwardLengthsMatchDirectBinsAndParseval) {
  // 29,999 (the "large prime") is 131 x 229: Bluestein's path; 29,989 is
  // prime: Rader's. Both are checked bin by bin against the O(N) definition.
  for (std::size_t n : {29999, 29989}) {
    const auto x = test::uniform_values(n, 42);
    const auto X = rfft(x);
    ASSERT_EQ(X.size(), n / 2 + 1);
    for (std::size_t k : {std::size_t(0), std::size_t(1), std::size_t(2), std::size_t(777), std::size_t(4999),
                          n / 2 - 1, n / 2})
      EXPECT_LT(std::abs(X[k] - test::dft_bin(x, k)), 1e-10) << "n " << n << " bin " << k;  // |X| ~ 100
    // Parseval: sum x^2 = (1/N) (|X_0|^2 + 2 sum_{k>0} |X_k|^2) for odd N.
    double time_energy = 0, freq_energy = std::norm(X[0]);
    for (double v : x) time_energy += v * v;
    for (std::size_t k = 1; k < X.size(); ++k) freq_energy += 2.0 * std::norm(X[k]);
    EXPECT_NEAR(freq_energy / double(n), time_energy, 1e-12 * time_energy) << n;
  }
}

TEST(Fft, PureToneOnABinGivesHalfTheLengthThere) {
  // cos(2 pi m j / N) has X_m = N/2 and nothing elsewhere (closed form).
  for (std::size_t n : {64, 29989, 29999, 30000}) {
    const std::size_t m = 13;  // below N/2 for every N here
    std::vector<double> x(n);
    for (std::size_t j = 0; j < n; ++j) x[j] = std::cos(2.0 * std::numbers::pi * double((m * j) % n) / double(n));
    const auto X = rfft(x);
    for (std::size_t k = 0; k < X.size(); ++k)
      EXPECT_NEAR(std::abs(X[k]), k == m ? 0.5 * double(n) : 0.0, 1e-12 * double(n)) << "n " << n << " bin " << k;
  }
}

TEST(Fft, SameBitsFromConcurrentCalls) {
  const auto x = test::uniform_values(30000, 3);
  const auto serial = rfft(x);
  std::vector<cplx> a, b;
  std::thread t1([&] { a = rfft(x); });
  std::thread t2([&] { b = rfft(x); });
  t1.join();
  t2.join();
  for (std::size_t k = 0; k < serial.size(); ++k) {
    ASSERT_EQ(a[k], serial[k]);
    ASSERT_EQ(b[k], serial[k]);
  }
}

TEST(Fft, BadLengthsAreInputErrors) {
  EXPECT_THROW(rfft(std::vector<double>{}), InputError);
  EXPECT_THROW(rfft(std::vector<double>{1, 2, 3}, 2), InputError);
  EXPECT_THROW(irfft(std::vector<cplx>{1, 2}, 5), InputError);
  EXPECT_THROW(fft(std::vector<cplx>{}), InputError);
}

TEST(Fft, FastLengthsAndPadding) {
  EXPECT_EQ(fast_fft_length(1), 1u);
  EXPECT_EQ(fast_fft_length(11), 12u);
  EXPECT_EQ(fast_fft_length(29999), 30000u);  // 2^4 3 5^4
  EXPECT_EQ(fast_fft_length(30001), 30240u);  // 2^5 3^3 5 7
  EXPECT_EQ(Padding{}.fft_length(29999), 29999u);
  EXPECT_EQ(Padding::parse("double").fft_length(29999), 60000u);
  EXPECT_EQ(Padding::parse("pow2").fft_length(30000), 32768u);
  EXPECT_EQ(Padding::parse("65536").fft_length(30000), 65536u);
  EXPECT_THROW(Padding::parse("1000").fft_length(30000), InputError);
  EXPECT_THROW(Padding::parse("twice"), InputError);
  EXPECT_THROW(Padding::parse("0"), InputError);
  EXPECT_EQ(Padding::parse("pow2").name(), "pow2");
}
