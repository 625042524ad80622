#pragma once
// Flowchart steps 3 and 4 from the load frame's records (concrete paper,
// Section 3.2, Fig. 5): the stabilized secant modulus of elasticity from the
// cyclic test, the failure stress from the destructive test, and the crosshead
// correction that turns the destructive test's crosshead record into strain.
//
// Stabilized secant modulus, EN 12390-13:2013 (Polish edition PN-EN
// 12390-13:2014-02, which the paper cites as [35]). Clause 7.3.2 (method B)
// loads the specimen three times from a lower stress to the upper stress
// sigma_a = f_c/3 with holds at both levels (the paper: 0.3 MPa/s, 16.7 MPa,
// 20 s holds); clause 8.2 defines the stabilized modulus from the third loading
// cycle as the secant between the readings at the lower stress before it and at
// the upper stress of it:
//     E_C,S = (sigma_a^m - sigma_b^m) / (eps_a,3 - eps_b,2)
// with sigma^m the measured stresses, eps_a,3 the mean strain of the
// extensometers at the upper stress of cycle 3 and eps_b,2 the mean strain at
// the lower stress that ends cycle 2. (Symbols of clause 3.2: sigma_a upper,
// sigma_b lower, sigma_p preload stress. The standard's text is not freely
// available: the clause numbers and symbols were checked against the BSI
// catalogue entry and the German summary at betontechnische-daten.de, which do
// not print the formula - see docs/lab-raw-data.md.) Readings are averaged over the last
// `reading_window` seconds of each hold; where a level is not held (a turning
// point) the single extreme sample is read and the cycle says so.
//
// The same secant is reported for every cycle n (sigma_b of the reading before
// its loading, sigma_a of its hold): cycle 1 is EN 12390-13's initial modulus
// E_C,0 (method A, clause 8.1) when the record starts from a held lower level.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "mesowave/lab/compression_record.hpp"

namespace mesowave::lab {

struct Reading {
  std::size_t first = 0, last = 0;     ///< samples averaged
  double t0_s = 0, t1_s = 0;
  double stress_Pa = 0;
  std::vector<double> strain;          ///< per extensometer channel; NaN if a channel has no reading there
  bool hold = false;                   ///< a held level (false: a turning point, one sample)
  double hold_s = 0;                   ///< how long the level was held
};

struct LoadCycle {
  int number = 0;
  std::size_t start = 0, peak = 0, end = 0;  ///< samples of the excursion above the lower threshold
  std::optional<Reading> lower;        ///< the lower reading before this cycle's loading
  Reading upper;
  double loading_rate_Pa_s = 0;        ///< slope of the loading ramp between 20 and 80 % of its rise
  std::optional<double> E_Pa;          ///< secant modulus of this cycle (used channels)
  std::optional<double> E_ramp_Pa;     ///< slope of stress on mean strain over the loading ramp (20-80 % of its
                                       ///< rise): a cross-check that survives a zeroing at the ramp start
  std::string note;                    ///< why E is missing, or what is special about the readings
};

struct ChannelVerdict {
  std::string name;
  bool used = false;
  std::string reason;                  ///< why it was dropped
  double delta_strain = 0;             ///< eps_a - eps_b of the evaluated cycle (NaN if none)
};

struct CyclicOptions {
  double gauge_length_m = 0;
  int evaluated_cycle = 3;             ///< EN 12390-13: the third
  double reading_window_s = 10;
  std::size_t min_extensometers = 2;
  double channel_tolerance = 0.3;      ///< relative deviation from the channels' median that drops a channel (>= 3 channels)
  std::optional<double> expected_upper_Pa;
};

struct CyclicResult {
  std::vector<LoadCycle> cycles;
  int evaluated_cycle = 3;
  double E_st_Pa = 0;                  ///< the stabilized secant modulus E_C,S
  double sigma_a_Pa = 0, sigma_b_Pa = 0, eps_a = 0, eps_b = 0;  ///< the readings it uses (mean of used channels)
  std::vector<ChannelVerdict> channels;
  double stress_noise_Pa = 0;          ///< estimated from the record
  std::vector<std::string> warnings;
};

/// Finds the load cycles and the stabilized secant modulus. InputError when
/// the record has fewer cycles than `evaluated_cycle` (a missing cycle), when
/// fewer than `min_extensometers` channels are usable, or when the strain does
/// not rise with the stress; anything a person should look at goes to warnings.
CyclicResult analyse_cyclic_test(const CompressionRecord& record, const CyclicOptions& options);

/// Mean strain of the used channels per sample (NaN where one has no reading).
std::vector<double> mean_extensometer_strain(const CompressionRecord& record, const CyclicResult& result,
                                             double gauge_length_m);

struct CrossheadFit {
  double multiplier = 0;               ///< m in eps_extensometer = m eps_crosshead + c
  double intercept = 0;
  double r2 = 0;                       ///< coefficient of determination
  double rms_strain = 0;               ///< RMS residual [strain]
  std::size_t points = 0;
  int from_cycle = 2;
};

/// Least-squares fit of the extensometer strain against the crosshead-derived
/// strain (crosshead displacement / specimen height) over the cyclic test from
/// cycle `from_cycle` on (the first loading beds the platens in), on samples
/// above 10 % of the cycles' stress range. The paper found m = 1/4.5.
CrossheadFit fit_crosshead_multiplier(const CompressionRecord& record, const CyclicResult& result,
                                      double gauge_length_m, double specimen_height_m, int from_cycle);

struct FailureResult {
  double sigma_max_Pa = 0;
  double t_peak_s = 0;
  std::size_t peak_index = 0;
  bool broke = false;                  ///< the stress dropped below 80 % of the peak afterwards
  std::vector<double> crosshead_strain;  ///< (crosshead - its first reading) / height; empty without crosshead
  std::vector<double> strain;          ///< multiplier x crosshead strain; empty without a multiplier
  std::optional<double> strain_at_peak;
  std::vector<std::string> warnings;
};

/// Peak stress of a test to failure and, given the crosshead multiplier and the
/// specimen height, its stress-strain curve from the crosshead record.
FailureResult analyse_failure_test(const CompressionRecord& record, std::optional<double> multiplier,
                                   std::optional<double> specimen_height_m);

}  // namespace mesowave::lab
