#pragma once
// One-sided amplitude spectra with their frequency axis. With X_k the DFT of
// the n samples (zero padded to the FFT length M), f_k = k / (M dt) for
// k = 0..M/2, and the amplitude is one of
//   amplitude: A_k = c_k |X_k| / n, c_k = 2 except c_0 = 1 (and c_{M/2} = 1, M even):
//              a sine of amplitude a on a bin reads a; the signal's unit.
//   density:   |X_k| dt, the magnitude of the continuous Fourier transform
//              |integral x(t) exp(-2 pi i f t) dt| of the record; unit times s.
//   raw:       |X_k| (numpy.abs(numpy.fft.rfft(x, M))).
// Zero padding interpolates the spectrum on a finer grid (df = 1/(M dt)); the
// resolution stays 1/(n dt).
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "mesowave/signal/detrend.hpp"
#include "mesowave/signal/fft.hpp"
#include "mesowave/signal/signal.hpp"

namespace mesowave::signal {

enum class SpectrumScaling { amplitude, density, raw };

std::string_view to_string(SpectrumScaling scaling);
/// Reads "amplitude", "density" or "raw"; InputError otherwise.
SpectrumScaling parse_spectrum_scaling(std::string_view text);

struct SpectrumOptions {
  Detrend detrend = Detrend::none;
  Padding padding{};
  SpectrumScaling scaling = SpectrumScaling::amplitude;
};

struct Spectrum {
  std::vector<double> frequency_hz;  ///< f_k = k df
  std::vector<double> amplitude;     ///< per the scaling, one value per frequency
  double df_hz = 0;                  ///< bin spacing 1 / (M dt)
  std::size_t samples = 0;           ///< n, the record length
  std::size_t fft_length = 0;        ///< M
  SpectrumScaling scaling = SpectrumScaling::amplitude;

  /// The unit of `amplitude` for samples in `signal_unit` ("m/s^2" -> "m/s^2 s" for density).
  std::string unit(std::string_view signal_unit) const;
};

/// Spectrum of `x` sampled every `dt_s`. InputError for an empty record, a
/// non-finite sample or a non-positive dt.
Spectrum amplitude_spectrum(std::span<const double> x, double dt_s, const SpectrumOptions& options = {});
Spectrum amplitude_spectrum(const Signal& s, const SpectrumOptions& options = {});

/// The same into `out`, reusing its storage: for loops over many records.
void amplitude_spectrum(std::span<const double> x, double dt_s, const SpectrumOptions& options, Spectrum& out);

/// Frequency of the largest amplitude above `min_frequency_hz`, refined by a
/// parabola through the peak bin and its neighbours (on the log amplitude,
/// exact for a Gaussian peak); the bin's own frequency at the ends.
double peak_frequency_hz(const Spectrum& spectrum, double min_frequency_hz = 0.0);

}  // namespace mesowave::signal
