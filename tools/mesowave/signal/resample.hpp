#pragma once
// Moving a signal onto another time base - only when asked: comparing signals
// sampled differently needs an interpolation, and which one it was belongs in
// the result ("resampled by linear interpolation").
#include <cstddef>
#include <string>
#include <string_view>

#include "mesowave/signal/signal.hpp"

namespace mesowave::signal {

enum class Interpolation {
  linear,        ///< straight lines between samples (exact for linear signals)
  cubic_spline,  ///< natural cubic spline through the samples (zero curvature at both ends)
};

std::string_view to_string(Interpolation method);
/// Reads "linear" or "cubic" ("cubic-spline"); InputError otherwise.
Interpolation parse_interpolation(std::string_view text);

/// A uniform time base t_i = t0_s + i dt_s, i < count.
struct TimeBase {
  double t0_s = 0;
  double dt_s = 0;
  std::size_t count = 0;
  double end_s() const { return t0_s + double(count == 0 ? 0 : count - 1) * dt_s; }  ///< time of the last sample
};

TimeBase time_base(const Signal& s);

/// Same sampling interval (relative difference <= 1e-9), same start (within
/// 1e-6 dt) and the same number of samples.
bool same_time_base(const TimeBase& a, const TimeBase& b);

/// "30000 samples, dt 0.1 us, t0 0 us".
std::string describe(const TimeBase& base);

/// `s` interpolated onto `target`; every target time must lie within s's
/// first and last sample (no extrapolation; 1e-9 dt of slack for rounding),
/// InputError otherwise, as for a signal of fewer than 2 samples.
Signal resample(const Signal& s, const TimeBase& target, Interpolation method);

/// The samples of `base` that lie within [begin_s, end_s] (both inclusive,
/// with 1e-9 dt of slack), as a time base; InputError naming `what` if none do.
TimeBase restrict_time_base(const TimeBase& base, double begin_s, double end_s, std::string_view what);

}  // namespace mesowave::signal
