#pragma once
// Entry points for the library's own hot loops, past the checks the public
// functions make (the caller has validated the records once).
#include <cstddef>
#include <span>
#include <string_view>

#include "mesowave/signal/envelope.hpp"
#include "mesowave/signal/spectrum.hpp"

namespace mesowave::signal::internal {

/// envelope_into without the finite-sample check.
void envelope_into_unchecked(std::span<const double> x, std::span<double> out, const HilbertOptions& options);

/// out[i] = sqrt(re[i]^2 + im[i]^2): the envelope's magnitudes, in a loop the
/// compiler vectorises (the root's argument is never negative, so errno is moot).
void magnitudes(const double* re, const double* im, double* out, std::size_t n);
/// out[k] = scale |z[k]|, the same for complex bins.
void magnitudes(const Complex* z, double scale, double* out, std::size_t n);

/// Fills `s` from the bins 0..m/2 of a record of n samples zero padded to m.
void fill_spectrum(const Complex* bins, std::size_t n, std::size_t m, double dt_s, SpectrumScaling scaling, Spectrum& s);

/// The envelope of x into `env` and its spectrum into `spectrum`, sharing the
/// forward transform when the two ask for the same detrending and FFT length.
void envelope_and_spectrum_unchecked(std::span<const double> x, std::span<double> env, const HilbertOptions& hilbert,
                                     double dt_s, const SpectrumOptions& spectrum_options, Spectrum& spectrum);

/// Sum of x in four interleaved partial sums combined in a fixed order.
double sum4(std::span<const double> x);
/// sum (a-ma)^2, sum (b-mb)^2, sum (a-ma)(b-mb), summed as sum4 does.
void centred_sums(std::span<const double> a, std::span<const double> b, double ma, double mb, double& saa,
                  double& sbb, double& sab);

/// pearson for finite records of equal, non-zero length.
double pearson_unchecked(std::span<const double> a, std::span<const double> b, std::string_view what);

}  // namespace mesowave::signal::internal
