#pragma once
// Time-of-flight pickers for UPV waveforms and simulated signals. Each returns
// the arrival time and a quality measure (larger snr or ratio = more
// trustworthy; smaller spread = better resolved):
//
//  threshold      first sample whose deviation from the pre-trigger mean reaches
//                 max(factor x noise RMS, relative x peak), refined linearly between
//                 samples. Quality: snr_dB = 20 log10(peak / noise RMS) (capped at
//                 300 dB for a noiseless record).
//  aic            Maeda's (1985) Akaike information criterion picker: the onset
//                 splits the window x[1..N] where
//                   AIC(k) = k log var(x[1..k]) + (N - k - 1) log var(x[k+1..N])
//                 is smallest; the pick is the first sample after the split
//                 (0-based index k). Quality: aic_sd_s, the spread of the onset
//                 under the Akaike weights w_k ~ exp(-(AIC(k) - AIC_min) / 2)
//                 (St-Onge 2011), in seconds: ~0 for a sharp onset.
//  envelope-peak  the maximum of the Hilbert envelope, refined by a parabola
//                 through the peak sample and its neighbours (the group arrival
//                 of a narrow-band burst). Quality: peak_ratio, the peak over the
//                 highest other local maximum outside the peak's half-maximum
//                 lobe (capped at 1e6): ~1 means two packets compete.
//
// Search windows restrict where a pick may fall. Times are the signal's own
// (t0_s + i dt_s): for a UPV record, the trigger is at t = 0 and the samples
// before it are the pre-trigger noise.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "mesowave/signal/envelope.hpp"
#include "mesowave/signal/signal.hpp"

namespace mesowave::signal {

struct TimeWindow {
  std::optional<double> begin_s, end_s;  ///< unset: the start / end of the record
};

struct Pick {
  std::string method;        ///< "threshold" | "aic" | "envelope-peak"
  double time_s = 0;         ///< the arrival time
  std::size_t index = 0;     ///< the sample at (or just after) time_s
  double quality = 0;        ///< see quality_name; always finite
  std::string quality_name;  ///< "snr_dB" | "aic_sd_s" | "peak_ratio"
};

struct ThresholdOptions {
  std::optional<double> noise_begin_s;  ///< default: the first sample
  /// End of the pre-trigger noise window (exclusive). Default: t = 0 if the
  /// record starts before 0; otherwise it must be given (InputError).
  std::optional<double> noise_end_s;
  double factor = 5.0;    ///< threshold = factor x noise RMS ...
  double relative = 0.0;  ///< ... or this fraction of the peak |x - noise mean|, whichever is larger
  TimeWindow search;      ///< default: from the end of the noise window to the end of the record
};

struct AicOptions {
  /// The window AIC splits. It must hold one onset: without an end, it ends
  /// at the largest |x| after its start (the usual practice for AE and UPV
  /// picks), so that the end of a packet is not taken for a second split.
  TimeWindow search;
  /// Applied to the window first. A drift inflates the variance of long
  /// segments and drags the split away from the onset; an offset changes nothing.
  Detrend detrend = Detrend::none;
};

struct EnvelopePeakOptions {
  TimeWindow search;
  /// The envelope is computed over the whole record; padding keeps a burst
  /// near one end from wrapping onto the other.
  HilbertOptions hilbert{Detrend::mean, Padding{Padding::Mode::double_length, 0}};
};

Pick threshold_pick(const Signal& s, const ThresholdOptions& options = {});
Pick aic_pick(const Signal& s, const AicOptions& options = {});
Pick envelope_peak_pick(const Signal& s, const EnvelopePeakOptions& options = {});

/// Maeda's AIC over a whole record of N >= 4 samples: element j is AIC at the
/// split before sample k = j + 2 (k = 2 .. N-2, so that both parts hold two
/// samples or more). Variances are floored at 1e-30 of the record's variance
/// (a noiseless simulated record is exactly zero before its arrival).
/// InputError for fewer than 4 samples or a constant record.
std::vector<double> aic_curve(std::span<const double> x);

}  // namespace mesowave::signal
