#pragma once
// The random numbers behind the synthetic raw data: our own generator, so the
// same seed gives the same data with any compiler and standard library
// (std::normal_distribution and friends are implementation-defined and differ
// between libstdc++ and libc++).
//
// xoshiro256** (Blackman and Vigna, "Scrambled linear pseudorandom number
// generators", ACM TOMS 47 (2021)), seeded through SplitMix64 as its authors
// recommend. Normal deviates are the Irwin-Hall sum of twelve uniforms minus
// six: mean 0, variance 1, tails cut at +-6, made of additions only.
#include <cstdint>

namespace mesowave::lab {

class SyntheticRng {
public:
  explicit SyntheticRng(std::uint64_t seed) {
    std::uint64_t x = seed;
    for (auto& s : s_) {
      x += 0x9E3779B97F4A7C15ull;  // SplitMix64
      std::uint64_t z = x;
      z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
      z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
      s = z ^ (z >> 31);
    }
  }

  std::uint64_t next() {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }

  /// Uniform in [0, 1) with 53 random bits.
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Standard normal (Irwin-Hall, 12 terms).
  double normal() {
    double sum = 0;
    for (int i = 0; i < 12; ++i) sum += uniform();
    return sum - 6.0;
  }
  double normal(double mean, double sd) { return mean + sd * normal(); }

private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t s_[4];
};

}  // namespace mesowave::lab
