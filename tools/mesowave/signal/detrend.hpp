#pragma once
// Removing an offset or a linear drift before transforming: a DC offset puts
// its whole energy in bin 0 and a drift leaks over the low frequencies, and
// both dominate an envelope (scipy.signal.detrend's 'constant' and 'linear').
#include <span>
#include <string>
#include <string_view>

namespace mesowave::signal {

enum class Detrend {
  none,    ///< the samples as they are
  mean,    ///< subtract the mean
  linear,  ///< subtract the least-squares line a + b i through the samples
};

/// Applies `mode` in place. A record of one sample has no line: linear acts as mean.
void detrend(std::span<double> x, Detrend mode);

/// "none", "mean", "linear".
std::string_view to_string(Detrend mode);
/// Reads "none", "mean" (or "constant"), "linear"; InputError otherwise.
Detrend parse_detrend(std::string_view text);

}  // namespace mesowave::signal
