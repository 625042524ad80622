#pragma once
// A seeded random stream whose numbers are the same on every platform and
// library version: std::mt19937_64's output sequence is fixed by the C++
// standard, but std::uniform_real_distribution and friends are not, so the
// distributions are written out here. Packings are reproducible from
// (inputs, seed) alone.
#include <cstdint>
#include <random>

namespace mesowave::dem {

class SeededRandom {
public:
  explicit SeededRandom(std::uint64_t seed) : engine_(seed) {}

  /// Uniform in [0, 1) with 53 random bits (the top bits of one draw).
  double uniform01() { return double(engine_() >> 11) * 0x1.0p-53; }
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }
  std::uint64_t bits() { return engine_(); }

private:
  std::mt19937_64 engine_;
};

}  // namespace mesowave::dem
