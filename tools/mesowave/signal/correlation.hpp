#pragma once
// Pearson's correlation coefficient between signals, per sensor and averaged
// over sensors as in the concrete paper (Section 4.3, Table 3: the mean PCC of
// the experimental and numerical signals over sensors B-G):
//   r = sum (a_i - mean a)(b_i - mean b) / sqrt(sum (a_i - mean a)^2 sum (b_i - mean b)^2).
// Both signals must share one time base; signals sampled differently are an
// error unless the caller asks for a resampling, which is then stated.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "mesowave/signal/envelope.hpp"
#include "mesowave/signal/resample.hpp"
#include "mesowave/signal/signal.hpp"
#include "mesowave/signal/spectrum.hpp"

namespace mesowave::signal {

/// r of two records of equal length. InputError (naming `what`) for empty or
/// unequal-length records, a non-finite sample, or a record of zero variance
/// (r is undefined there; a constant record correlates with nothing).
double pearson(std::span<const double> a, std::span<const double> b, std::string_view what = "records");

struct CorrelationOptions {
  /// None: the two signals must share their time base (InputError otherwise).
  /// Set: b is interpolated onto a's samples where their records overlap.
  std::optional<Interpolation> resampling;
  /// Compare only the samples within [begin_s, end_s] (after the envelopes are
  /// computed on the whole record, so the window does not add edge effects).
  std::optional<double> begin_s, end_s;
  /// How the envelopes are computed (their PCC is reported beside the signals').
  HilbertOptions envelope{};
  /// Also the spectra of both records of every sensor (over the records the
  /// envelopes were computed on); with the envelopes' detrending and FFT
  /// length they share the envelopes' forward transform.
  std::optional<SpectrumOptions> spectra;
};

struct SensorCorrelation {
  std::string sensor;
  double pcc_signal = 0;    ///< r of the two signals
  double pcc_envelope = 0;  ///< r of their envelopes
  TimeBase compared;        ///< the samples r was computed over
  std::size_t envelope_samples = 0;  ///< the record the envelopes were computed over
  bool resampled = false;   ///< whether b was interpolated onto a's samples
  Spectrum spectrum_a, spectrum_b;  ///< when CorrelationOptions::spectra asks for them
};

struct CorrelationTable {
  std::vector<SensorCorrelation> sensors;   ///< in the order of the first set
  double mean_pcc_signal = 0;               ///< mean over sensors (Table 3)
  double mean_pcc_envelope = 0;
  std::vector<std::string> only_in_a, only_in_b;  ///< sensors without a partner (not compared)
  bool excitation_left_out = false;         ///< both sets had a kExcitationName record, not compared
  std::string resampling;                   ///< "none (same time base)" or "b onto a by linear interpolation"
  std::string envelope_method;              ///< HilbertOptions::describe of the first sensor
};

/// Correlates two signals (their names may differ).
SensorCorrelation correlate(const Signal& a, const Signal& b, const CorrelationOptions& options = {});

/// Correlates sensors matched by name. `only` (if not empty) names the sensors
/// to compare, each of which must be in both sets; otherwise the sensors in
/// both sets are compared and the others listed, and a record of the load
/// (kExcitationName) is left out of the pairs and of the mean: the mean is over
/// sensors (Table 3), and two runs of one burst correlate their loads at 1. InputError if no sensor is
/// shared or a name appears twice in one set. Sensors run in parallel; the
/// result does not depend on the thread count.
CorrelationTable correlate_sensors(std::span<const Signal> a, std::span<const Signal> b,
                                   const CorrelationOptions& options = {},
                                   const std::vector<std::string>& only = {});

}  // namespace mesowave::signal
