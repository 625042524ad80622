#pragma once
// Reproducible white Gaussian noise for synthetic records (test data with a
// known ground truth): the same seed gives the same samples on every platform
// (core/random.hpp's Mt64Random and its Box-Muller pairs, rather than
// std::normal_distribution, whose algorithm the standard leaves open).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesowave/signal/signal.hpp"

namespace mesowave::signal {

/// n samples of zero-mean Gaussian noise with standard deviation `rms`.
std::vector<double> gaussian_noise(std::size_t n, double rms, std::uint64_t seed);

/// `record` with white Gaussian noise added at a stated SNR = 20 log10(max |x| / noise RMS), the
/// definition of the picker table (docs/upv-pickers.md): a model's noise-free record made like a
/// lab's before it is picked, so that the lab's picking chain (mw-upv --add-noise-snr-dB) meets
/// what it was made for. The noise is gaussian_noise(record.size(), max |x| 10^(-snr/20), seed).
/// InputError for a non-finite SNR or an all-zero record (no peak to state an SNR against).
Signal with_noise_at_snr(const Signal& record, double snr_dB, std::uint64_t seed);

/// The RMS that noise at `snr_dB` has against `record`: max |x| 10^(-snr/20) (same InputErrors).
double noise_rms_at_snr(const Signal& record, double snr_dB);

}  // namespace mesowave::signal
