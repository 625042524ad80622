#pragma once
// Reproducible white Gaussian noise for synthetic records (test data with a
// known ground truth): the same seed gives the same samples on every platform
// (core/random.hpp's Mt64Random and its Box-Muller pairs, rather than
// std::normal_distribution, whose algorithm the standard leaves open).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace mesowave::signal {

/// n samples of zero-mean Gaussian noise with standard deviation `rms`.
std::vector<double> gaussian_noise(std::size_t n, double rms, std::uint64_t seed);

}  // namespace mesowave::signal
