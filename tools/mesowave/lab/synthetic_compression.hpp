#pragma once
// Synthetic load-frame records with a stated ground truth: the two compression
// tests of the concrete paper, Section 3.2 (Fig. 5), on a 150 mm cube.
//
// Cyclic test (EN 12390-13 method B, as the paper ran it): stress-controlled
// ramps at `rate` between a lower stress and the upper stress (16.7 MPa), each
// level held `hold` seconds, `cycles` loading cycles. The specimen is linear
// elastic with modulus E in every cycle except the first loading, which adds a
// permanent set (bedding-in of the specimen, the reason the standard reads the
// stabilized modulus on the third cycle). Two extensometers on opposite faces
// read the mean strain times (1 +- bending) plus noise; the crosshead reads the
// specimen shortening divided by the crosshead multiplier m (machine and platen
// compliance: crosshead strain = extensometer strain / m) plus an irreversible
// seating of the platens during the first loading, plus noise.
//
// Failure test: stress-controlled at `failure_rate` to the strength f_c,
// crosshead only (the paper's destructive test ran without extensometers). The
// specimen follows EN 1992-1-1 Eq. (3.14),
//     sigma / f_c = (k eta - eta^2) / (1 + (k - 2) eta),  eta = eps / eps_c1,
//     k = 1.05 E eps_c1 / f_c,  eps_c1 = 0.7 f_c^0.31 permille (Table 3.1, f_c in MPa),
// whose secant to 0.4 f_c is close to E and whose peak is exactly f_c at
// eps_c1 (the realistic softening near failure); after the peak the specimen
// crushes within a second: the stress falls to nothing while the shortening grows.
//
// Hard cases for tests: a cycle left out (the machine holds at the lower
// stress instead), and an extensometer channel that drops out (empty fields or
// a stuck value) from a given time on.
#include <cstdint>
#include <string>
#include <vector>

namespace mesowave::lab {

struct SyntheticCompressionSpec {
  double E_Pa = 27.42e9;
  double strength_Pa = 66.0e6;
  double upper_stress_Pa = 16.7e6;
  double lower_stress_Pa = 0.5e6;       ///< sigma_p of method B (assumed: the paper does not print it)
  double cyclic_rate_Pa_s = 0.3e6;
  double failure_rate_Pa_s = 0.6e6;
  double hold_s = 20;
  int cycles = 3;
  double side_m = 0.150;                ///< cube: loaded area side^2, height = side
  double gauge_length_m = 0.075;
  double crosshead_multiplier = 1.0 / 4.5;
  double sample_rate_Hz = 5;            ///< cyclic test
  double failure_sample_rate_Hz = 10;
  double bending = 0.03;                ///< extensometers read (1 +- bending) x the mean strain
  double first_loading_set = 20e-6;     ///< permanent strain of the first loading
  double seating_m = 0.02e-3;           ///< irreversible platen seating in the crosshead record
  double seating_stress_Pa = 1.0e6;     ///< seating is (1 - exp(-sigma/this)) complete
  double force_noise_N = 50;
  double extensometer_noise_m = 0.1e-6;
  double crosshead_noise_m = 0.5e-6;
  int skip_cycle = 0;                   ///< 1-based cycle replaced by a hold at the lower stress (0: none)
  int dropout_channel = 0;              ///< 1 or 2: that extensometer drops out (0: none)
  double dropout_time_s = 0;
  bool dropout_stuck = false;           ///< stuck at its last value instead of empty fields
  std::uint64_t seed = 1;
};

struct SyntheticCompressionRecord {
  std::vector<double> t_s, force_N, crosshead_m;
  std::vector<std::vector<double>> extensometer_m;  ///< per channel; NaN where a channel dropped out (empty field)
};

struct SyntheticCompressionTests {
  SyntheticCompressionRecord cyclic, failure;
  double true_E_Pa = 0, true_strength_Pa = 0, true_multiplier = 0;
  double eps_c1 = 0;                   ///< strain at the peak of the failure curve
};

SyntheticCompressionTests synthetic_compression_tests(const SyntheticCompressionSpec& spec);

/// The record as a machine export: t_s, force_kN, crosshead_mm and ext1_mm,
/// ext2_mm... (omitted for the failure test); empty fields where a channel has
/// no reading.
std::string compression_record_csv(const SyntheticCompressionRecord& record);

/// EN 1992-1-1 Eq. (3.14) strain on the ascending branch for stress sigma <= f_c.
double sargin_strain(double sigma, double E, double f_c, double eps_c1);

}  // namespace mesowave::lab
