#pragma once
// Bar velocity from a pulse-echo record at one gauge (split Hopkinson bar,
// impact tests): a long pulse passes the gauge, reflects at the bar end (or a
// low-impedance specimen), and passes it again after a round trip of known
// length. The delay between the two pulses is picked several ways, so that the
// spread between pickers is part of the stated uncertainty:
//   edge-L        the leading edge crossing L x the pulse's extreme value
//                 (L = 0.25, 0.5, 0.75), linear between samples
//   threshold     signal::threshold_pick (onset above the preceding noise)
//   aic           signal::aic_pick (Maeda's AIC onset)
//   envelope      the Hilbert-envelope peak within each pulse
// Pulses are the stretches where |x| reaches 30 % of the record's largest |x|
// (the first two); a long flat pulse has an envelope peak at each of its edges,
// so the envelope cannot delimit pulses here.
// and the record's frequency content (energy percentiles of the first pulse's
// spectrum) says where on the Pochhammer-Chree curve the measurement sits.
#include <filesystem>
#include <string>
#include <vector>

#include "mesowave/signal/signal.hpp"
#include "mesowave/wave/pochhammer_chree.hpp"

namespace mesowave::wave {

struct BarEchoOptions {
  double path_m = 0;              ///< round-trip path between the two passes (2 x gauge-to-end distance)
  double edge_search_s = 60e-6;   ///< leading edge searched this long before each pulse
  /// If set, the first pulse is also carried over the path by the L(0,1) mode of this
  /// Pochhammer-Chree rod and scaled by the measured echo/pulse ratio: the theory's
  /// echo, picked like the measured one ("theory-" picks).
  const PochhammerChree* theory = nullptr;
  double theory_f_max_Hz = 500e3;  ///< the propagated spectrum is tapered to zero at this
};

struct BarEchoPick {
  std::string method;
  double t1_s = 0, t2_s = 0, velocity_m_s = 0;
};

struct BarEchoResult {
  std::vector<BarEchoPick> picks;
  double first_pulse_extreme = 0, second_pulse_extreme = 0;  ///< signed
  double f50_Hz = 0, f90_Hz = 0;  ///< frequencies below which 50 % / 90 % of the first pulse's energy lies
  double pulse_window_s = 0;      ///< length of the first pulse's analysis window
  /// With a theory: the bar velocity that makes the theory's echo edges fall on the
  /// measured ones, c0 x mean(theory delays) / mean(measured delays) over the three
  /// edge levels (delays scale as 1 / c0 at fixed nu and radius to well below 0.1 %
  /// here), and half the spread of the per-level ratios (relative).
  double fitted_c0_m_s = 0, fitted_c0_relative_spread = 0;
  /// With a theory: the theory's echo on the record's time base (name "theory echo").
  signal::Signal theory_echo;
};

/// A column of a CSV table as a signal: `column` names the column (or the part of its
/// header before a '/', where tables put the unit), the first column is time in s.
/// Tables often print time with few digits; the time base is rebuilt as
/// t0 + i dt, the least-squares line through all printed times, after checking
/// that every printed time agrees with it to within the printing resolution
/// (InputError otherwise).
signal::Signal signal_from_csv(const std::string& path, const std::string& column);

/// `pulse` carried a distance `distance_m` along the rod by its L(0,1) mode,
/// X(f) exp(-i k(f) distance) (a cosine taper from f_max / 2 to f_max), on a record long
/// enough that nothing wraps around: the same t0 and dt, more samples.
signal::Signal propagate_l01(const signal::Signal& pulse, const PochhammerChree& pc, double distance_m,
                             double f_max_Hz);

/// The signal `name` of a record file: a mesowave signal file (HDF5, or CSV whose
/// first column is t_s / t_ms / t_us / t_ns, read by signal::read_signals), or any
/// other CSV table through signal_from_csv.
signal::Signal read_record(const std::filesystem::path& path, const std::string& name);

/// InputError when the record does not hold two pulses.
BarEchoResult analyse_bar_echo(const signal::Signal& record, const BarEchoOptions& options);

/// The bar velocity a pulse-echo analysis reports, with its uncertainty budget.
/// The pulse front (the onset pickers) travels at the bar's low-frequency velocity;
/// the edge crossings lag more the higher the level, as dispersion widens the front,
/// so the velocity is the mean of the threshold and AIC picks only. Relative
/// standard uncertainties, combined in quadrature (GUM):
///   method    half the spread of the onset pickers' velocities over their mean,
///   sampling  half a sample on each of the two times, sqrt(1/2) dt / mean delay,
///   path      the round trip's own, u(path) / path.
struct BarEchoVelocity {
  double velocity_m_s = 0;
  double relative_uncertainty_method = 0, relative_uncertainty_sampling = 0, relative_uncertainty_path = 0;
  double velocity_uncertainty_m_s = 0;
  /// With a theory (result.fitted_c0_m_s > 0): the fitted c0's standard uncertainty,
  /// its edge-level spread combined with the sampling and path terms.
  double fitted_c0_uncertainty_m_s = 0;
};

/// InputError when `result` holds no threshold or AIC pick.
BarEchoVelocity bar_echo_velocity(const BarEchoResult& result, double dt_s, double relative_path_uncertainty);

}  // namespace mesowave::wave
