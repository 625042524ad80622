#pragma once
// Analytic signal, Hilbert transform and envelope by the FFT, with exactly the
// definition of scipy.signal.hilbert (Marple 1999): with X = DFT(x) of length N,
//   z = IDFT(X h),  h_0 = 1;  h_k = 2 for 1 <= k < N/2;  h_{N/2} = 1 (N even);  h_k = 0 above,
// i.e. for odd N: h_0 = 1, h_k = 2 for 1 <= k <= (N-1)/2, 0 above. Then
// Re z = x, Im z = H{x} (the Hilbert transform) and the envelope is |z|.
//
// Edge effects: the DFT treats the record as one period of a periodic signal,
// so a burst near one end of the record leaks into the other end of its
// Hilbert transform, and a DC offset or drift (which has no analytic
// counterpart) turns into a spurious envelope. HilbertOptions::padding moves
// the wrap-around off the record (the record is zero padded, the result cut
// back to the record's length: scipy.signal.hilbert(x, M)[:N]); detrend
// removes an offset or a drift first. Tools state both in their output.
#include <span>
#include <string>
#include <vector>

#include "mesowave/signal/detrend.hpp"
#include "mesowave/signal/fft.hpp"
#include "mesowave/signal/signal.hpp"

namespace mesowave::signal {

struct HilbertOptions {
  Detrend detrend = Detrend::none;
  Padding padding{};

  /// "detrend none, padding none (FFT length 30000)": what was done to a record of n samples.
  std::string describe(std::size_t n) const;
};

/// z = x + i H{x} (after detrending), one value per sample of x.
/// InputError for an empty record or a non-finite sample.
std::vector<Complex> analytic_signal(std::span<const double> x, const HilbertOptions& options = {});

/// H{x} = Im z: the Hilbert transform (H{cos} = sin).
std::vector<double> hilbert_transform(std::span<const double> x, const HilbertOptions& options = {});

/// |z|: the envelope (instantaneous amplitude).
std::vector<double> envelope(std::span<const double> x, const HilbertOptions& options = {});

/// The same into `out` (out.size() == x.size()), allocating nothing in steady
/// state: for loops over many records.
void envelope_into(std::span<const double> x, std::span<double> out, const HilbertOptions& options = {});

/// The envelope of `s` as a signal on the same time base: same name, unit and
/// component, quantity "<quantity> envelope".
Signal envelope(const Signal& s, const HilbertOptions& options = {});

}  // namespace mesowave::signal
