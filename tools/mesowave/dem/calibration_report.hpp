#pragma once
// What mw-calibrate writes about a calibration: the trial log (CSV) and two
// figures (gnuplot scripts, rendered by io::run_gnuplot): the trajectory of
// the trials against the targets, and the stress-strain curves of the
// calibrated test with the target and calibrated moduli drawn.
#include <filesystem>
#include <string>
#include <vector>

#include "mesowave/dem/calibration.hpp"

namespace mesowave::dem {

/// One row per trial: trial, kind, model, parameters, results (six significant digits), wall
/// time (0.1 s), summary file (which has the numbers in full).
std::string calibration_trials_csv(const std::vector<CalibrationTrial>& trials);

/// Three panels against the trial number: E_glob / E_st, nu_glob, sigma_peak /
/// sigma_max, with the tolerance bands.
std::string calibration_trajectory_script(const CompressionCalibration& c, const std::filesystem::path& png,
                                          const std::string& title);

struct StressStrainCurve {
  std::vector<double> axial, lateral, stress_Pa;  ///< compression positive, lateral extension positive
  double E_glob_Pa = 0, nu_glob = 0;
  double sigma_b_Pa = 0, sigma_a_Pa = 0, eps_b = 0, eps_a = 0;  ///< the secant's two readings
};

/// Stress against axial strain (right) and lateral strain (left, as negative
/// numbers, the usual drawing of concrete tests), with lines of the target
/// modulus E_st and of the calibrated E_glob through the lower reading.
std::string stress_strain_script(const StressStrainCurve& curve, double E_target_Pa, double nu_target,
                                 const std::filesystem::path& png, const std::string& title);

}  // namespace mesowave::dem
