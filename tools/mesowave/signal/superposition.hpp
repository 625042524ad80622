#pragma once
// One run, every burst frequency (issue 17 item 1): the generic half shared by
// the DEM (dem/engine/superposition.hpp) and the FEM (fem/superposition.hpp).
// A solver step that is linear and time-invariant in its force input records,
// for a force history f_0, f_1, ... (one value per step),
//
//   y_n = sum_{k=0..n} f_k h_{n-k}                                     (discrete convolution)
//
// where h_n is the same sensor after step n of a run with a unit force on step
// 0 alone (the impulse response). Why the impulse and not a broadband burst
// divided out in the frequency domain: the impulse IS the discrete system's
// response, so the sum is exact to round-off and needs no division by a
// spectrum that is small somewhere (a Hann burst's spectrum has zeros), no
// window and no wrap-around. Direct summation over the burst's nonzero steps in
// a fixed order: every output is its own sum, so the same bits for any thread
// count (an FFT would be cheaper only for bursts much longer than the cube's
// 200-1,000 steps).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "mesowave/signal/signal.hpp"

namespace mesowave::signal {

/// A force per step and the span of its nonzero values (the convolution sums only there).
struct ForceHistory {
  std::vector<double> force_N;   ///< f_n, n = 0 .. size - 1
  std::int64_t first = 0, last = -1;  ///< the first and last nonzero step (last < first: all zero)
  double l1_N = 0;               ///< sum_n |f_n|
};
/// f_n = force_N(n dt) for n = 0 .. steps - 1, with its nonzero span.
ForceHistory force_history(const std::function<double(double)>& force_N, double dt_s, std::int64_t steps);

/// One input of a sum: a force history and the sensor's response to a unit
/// impulse of that force (h_n after step n, at least as long as the outputs reach).
struct ConvolutionTerm {
  const ForceHistory* force = nullptr;
  std::span<const double> response;
};
/// y_m = sum over terms of sum_k f_k w_{n-k} h_{n-k}, n = m x every, m = 0 .. samples - 1,
/// w = `window` (empty: 1). The terms and steps in a fixed order; OpenMP over the outputs.
/// InputError if a response is shorter than the last output needs.
std::vector<double> convolve_sampled(const std::vector<ConvolutionTerm>& terms, std::int64_t every,
                                     std::int64_t samples, std::span<const double> window = {});

/// Superposed against direct signals, per sensor (matched by position in the lists).
struct SuperpositionError {
  std::vector<std::string> sensors;
  std::vector<double> pcc;                 ///< Pearson r of the two records
  std::vector<double> max_diff_over_peak;  ///< max |superposed - direct| / max |direct|
  double min_pcc = 1, max_diff_over_peak_all = 0;
};
/// InputError if the signals do not share names and time bases.
SuperpositionError superposition_error(const std::vector<Signal>& direct, const std::vector<Signal>& superposed);

/// The frequencies of a superposed run (--frequencies-kHz): InputError for one
/// that is not positive or given twice, or for none.
void check_frequencies(const std::vector<double>& frequencies_kHz, const std::vector<double>& check_kHz = {});

/// The frequency as file names and metric names write it: 100, 150, 212.5 (kHz).
std::string frequency_text(double frequency_hz);
/// `pattern` with every {f} replaced by frequency_text; InputError naming
/// `option` if it has no {f} (every frequency would write the same file).
std::filesystem::path frequency_path(const std::string& pattern, const std::string& option, double frequency_hz);

}  // namespace mesowave::signal
