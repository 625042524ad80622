#pragma once
// Group velocity measured from signals (rod paper Section 5, Figure 9,
// Table 2): the arrival of a burst is the peak of its Hilbert envelope
// (signal::envelope), and the group velocity at the burst's centre frequency
// is a distance over the delay between two arrivals:
//   two-stations  first packet at station A and at station B, distance |AB|
//   echo          two successive packets at one sensor (the direct arrival and
//                 its echo after a round trip), distance = the round-trip path
//                 (2 L for the rod's end sensor: the rod paper's "peak to peak")
//   source        the excitation's envelope peak (burst centre) to the first
//                 packet at the sensor, distance = source-sensor path
// and from a space-time record (2D FFT): the ridge of |U(f, k)| per frequency
// gives k(f), c_phase = 2 pi f / k and c_group = d omega / dk along the ridge.
// The residual sum of squares against a theory curve over a frequency band is
// rod Table 2's figure of merit.
#include <functional>
#include <string>
#include <vector>

#include "mesowave/signal/signal.hpp"

namespace mesowave::wave {

/// A wave packet: the time of an envelope maximum (parabolic refinement) and its height.
struct Packet {
  double time_s = 0;
  double envelope = 0;
};

/// Local maxima of the Hilbert envelope of `s` (mean removed, zero padded to double
/// length) that reach `relative_threshold` of the record's largest envelope value,
/// at least `min_separation_s` apart (the higher one kept), in time order.
std::vector<Packet> envelope_packets(const signal::Signal& s, double relative_threshold, double min_separation_s);

struct GroupVelocityPoint {
  std::string run;       ///< file or label
  double f_Hz = 0;       ///< burst centre frequency
  std::string method;    ///< two-stations | echo | source | spacetime
  double t1_s = 0, t2_s = 0;
  double distance_m = 0;
  double c_group_m_s = 0;
};

/// InputError when a signal has no packet or the second arrival is not later than the first.
GroupVelocityPoint two_station_velocity(const signal::Signal& a, const signal::Signal& b, double distance_m,
                                        double f_Hz, double burst_duration_s);
GroupVelocityPoint echo_velocity(const signal::Signal& s, double path_m, double f_Hz, double burst_duration_s);
GroupVelocityPoint source_velocity(const signal::Signal& s, double distance_m, double source_time_s, double f_Hz,
                                   double burst_duration_s);

/// A space-time record u(t_i, x_j): samples[i * positions + j], uniform spacing dx.
struct SpaceTimeRecord {
  std::vector<double> samples;
  std::size_t times = 0, positions = 0;
  double dt_s = 0, dx_m = 0;
};

struct RidgePoint {
  double f_Hz = 0, k_rad_m = 0, c_phase_m_s = 0, c_group_m_s = 0;
};

/// The ridge of the forward-travelling (+x) part of the 2D spectrum, in [f_min, f_max]:
/// per frequency bin the k > 0 with the largest |U| (parabolic refinement, space
/// zero-padded `k_padding` times), kept where |U| at the ridge is at least
/// `relative_floor` of the largest ridge value; c_group the slope of a least-squares
/// line of omega against k over the point and up to three neighbours on each side
/// (as many on each side; the ridge's end points get none and are left out).
std::vector<RidgePoint> spacetime_ridge(const SpaceTimeRecord& record, double f_min_Hz, double f_max_Hz,
                                        int k_padding = 8, double relative_floor = 0.2);

struct ResidualSummary {
  double rss_m2_s2 = 0;       ///< sum of (c_measured - c_theory)^2 over the band
  double rms_m_s = 0;
  double max_abs_m_s = 0;
  std::size_t points = 0;
  std::vector<double> theory_m_s;  ///< per input point (NaN-free; 0 outside the band)
  std::vector<bool> in_band;
};

/// RSS of measured group velocities against `theory(f_Hz)` over [f_lo, f_hi] (rod Table 2).
ResidualSummary residual_sum_of_squares(const std::vector<GroupVelocityPoint>& points,
                                        const std::function<double(double)>& theory, double f_lo_Hz,
                                        double f_hi_Hz);

}  // namespace mesowave::wave

namespace mesowave::wave {

/// How `measure_run` turns one run's signals into a group velocity.
struct MeasureRequest {
  std::string method = "echo";        ///< two-stations | echo | source
  std::vector<std::string> stations;  ///< signal names: two for two-stations, one otherwise
  double distance_m = 0;              ///< 0: two-stations takes |position_B - position_A|; required otherwise
  double cycles = 5;                  ///< burst cycles (packet separation; source time n / (2 f))
};

/// The measurement for one run at burst centre frequency f: the stations looked up
/// by name (InputError naming the missing one); the source method takes the
/// envelope peak of a signal named "excitation" when the run has one, else the
/// burst centre n / (2 f).
GroupVelocityPoint measure_run(const std::vector<signal::Signal>& signals, double f_Hz, const MeasureRequest& request);

}  // namespace mesowave::wave
