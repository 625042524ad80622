// Noise at a stated SNR (signal/noise): the added noise's RMS against the
// closed form max |x| 10^(-SNR/20), the same bits for the same seed, and the
// record that has no peak to state an SNR against.
#include "mesowave/signal/noise.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mesowave/core/error.hpp"
#include "mesowave/signal/hann_burst.hpp"

using namespace mesowave;

namespace {

signal::Signal burst_record() {
  signal::Signal s;
  s.name = "model record";
  s.dt_s = 50e-9;
  s.samples = signal::HannBurst(54e3, 2, 3e-9, 12e-6).sample(s.dt_s, 20000);
  return s;
}

TEST(SignalNoise, AddedNoiseHasTheRmsOfTheStatedSnr) {
  const auto clean = burst_record();
  double peak = 0;
  for (double v : clean.samples) peak = std::max(peak, std::abs(v));
  for (double snr_dB : {20.0, 40.0}) {
    const auto noisy = signal::with_noise_at_snr(clean, snr_dB, 7);
    double sum2 = 0;
    for (std::size_t i = 0; i < clean.size(); ++i) sum2 += std::pow(noisy.samples[i] - clean.samples[i], 2);
    const double rms = std::sqrt(sum2 / double(clean.size())), expected = peak * std::pow(10.0, -snr_dB / 20);
    EXPECT_DOUBLE_EQ(signal::noise_rms_at_snr(clean, snr_dB), expected);
    // 20,000 samples: the sample RMS of unit Gaussian noise has a relative standard error
    // 1/sqrt(2n) = 0.5 %; 2 % is four of them.
    EXPECT_NEAR(rms / expected, 1.0, 0.02) << snr_dB << " dB";
    EXPECT_EQ(noisy.dt_s, clean.dt_s);
  }
}

TEST(SignalNoise, SameSeedSameBitsOtherSeedOtherNoise) {
  const auto clean = burst_record();
  EXPECT_EQ(signal::with_noise_at_snr(clean, 30, 3).samples, signal::with_noise_at_snr(clean, 30, 3).samples);
  EXPECT_NE(signal::with_noise_at_snr(clean, 30, 3).samples, signal::with_noise_at_snr(clean, 30, 4).samples);
}

TEST(SignalNoise, AnAllZeroRecordOrANonFiniteSnrIsRefused) {
  auto zero = burst_record();
  zero.samples.assign(zero.size(), 0.0);
  EXPECT_THROW(signal::with_noise_at_snr(zero, 40, 1), InputError);
  EXPECT_THROW(signal::with_noise_at_snr(burst_record(), std::nan(""), 1), InputError);
}

}  // namespace
