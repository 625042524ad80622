#pragma once
// mesowave's one home for deterministic random numbers: the same (algorithm,
// seed) gives the same bits with every compiler, standard library and
// platform. The engines' outputs are fixed by their definitions; the
// distributions are written out here, because std::uniform_real_distribution,
// std::normal_distribution and friends are implementation-defined (libstdc++
// and libc++ give different numbers).
//
// Two engines, and why not one: shipped data depend on each stream, so each
// stays bit-exact.
//   - std::mt19937_64, seeded with the seed itself (the standard's seeding):
//     packings (dem::generate_packing, SizeDistribution) and signal noise
//     (signal::gaussian_noise). Its output sequence is fixed by the C++
//     standard ([rand.predef]: the 10000th draw after default construction
//     is 9981545732273789042).
//   - xoshiro256** 1.0 (Blackman and Vigna, "Scrambled linear pseudorandom
//     number generators", ACM TOMS 47 (2021)), its state the first four
//     SplitMix64 outputs from the seed, as its authors recommend: the
//     synthetic lab data (lab/synthetic_*, lab-data/*/raw).
// A new user takes Mt64Random unless it has a reason; a stream is described
// by its engine and seed alone, never by a distribution from <random>.
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <utility>

namespace mesowave {

/// SplitMix64 (Steele, Lea and Flood, OOPSLA 2014; Vigna's splitmix64.c):
/// a 64-bit counter by the golden ratio, then a bit mixer. Seeds xoshiro.
class SplitMix64 {
public:
  using result_type = std::uint64_t;
  explicit SplitMix64(std::uint64_t seed) : x_(seed) {}
  std::uint64_t operator()() {
    x_ += 0x9E3779B97F4A7C15ull;
    std::uint64_t z = x_;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  static constexpr std::uint64_t min() { return 0; }
  static constexpr std::uint64_t max() { return std::numeric_limits<std::uint64_t>::max(); }

private:
  std::uint64_t x_;
};

/// xoshiro256** 1.0 (Vigna's xoshiro256starstar.c).
class Xoshiro256StarStar {
public:
  using result_type = std::uint64_t;
  /// The state is the first four SplitMix64 outputs from `seed`.
  explicit Xoshiro256StarStar(std::uint64_t seed) {
    SplitMix64 seeder(seed);
    for (auto& s : s_) s = seeder();
  }
  /// A given state (not all zero), e.g. the reference implementation's test state.
  static Xoshiro256StarStar from_state(const std::array<std::uint64_t, 4>& state) {
    Xoshiro256StarStar x(0);
    x.s_ = state;
    return x;
  }
  const std::array<std::uint64_t, 4>& state() const { return s_; }

  std::uint64_t operator()() {
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
  static constexpr std::uint64_t min() { return 0; }
  static constexpr std::uint64_t max() { return std::numeric_limits<std::uint64_t>::max(); }

private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::array<std::uint64_t, 4> s_;
};

/// A seeded stream of numbers from a 64-bit engine, with the distributions
/// every mesowave stream uses. Each call consumes a fixed number of draws, so
/// a stream is reproducible from (engine, seed) and the sequence of calls.
template <class Engine>
class RandomStream {
public:
  explicit RandomStream(std::uint64_t seed) : engine_(seed) {}

  /// One raw 64-bit draw.
  std::uint64_t bits() { return engine_(); }
  /// Uniform in [0, 1) with 53 random bits (the top bits of one draw).
  double uniform01() { return double(bits() >> 11) * 0x1.0p-53; }
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }
  /// Uniform in (0, 1]: the midpoints of the 2^53 cells (the topmost rounds
  /// to 1), so log() never sees 0.
  double uniform_open01() { return (double(bits() >> 11) + 0.5) * 0x1.0p-53; }

  /// Approximately standard normal: the Irwin-Hall sum of twelve uniforms
  /// minus six (mean 0, variance 1, tails cut at +-6, additions only).
  double normal() {
    double sum = 0;
    for (int i = 0; i < 12; ++i) sum += uniform01();
    return sum - 6.0;
  }
  double normal(double mean, double sd) { return mean + sd * normal(); }

  /// Two independent Gaussian deviates of standard deviation `sd` (Box-Muller
  /// on two open uniforms): exact Gaussian tails, for noise.
  std::pair<double, double> gaussian_pair(double sd) {
    const double r = sd * std::sqrt(-2.0 * std::log(uniform_open01()));
    const double a = 2.0 * std::numbers::pi * uniform_open01();
    return {r * std::cos(a), r * std::sin(a)};
  }

private:
  Engine engine_;
};

/// The default stream: packings, noise, tests.
using Mt64Random = RandomStream<std::mt19937_64>;
/// The synthetic lab data's stream (lab-data/*/raw depends on its bits).
using XoshiroRandom = RandomStream<Xoshiro256StarStar>;

}  // namespace mesowave
