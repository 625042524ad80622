#pragma once
// What mw-calibrate asks of each trial and writes about a calibration: the
// mw-dem options of a trial and the results read back from its summary, a
// line per trial, the calibrated parameters as the JSON that `mw-dem run
// --from` reads, the trial log (CSV) and two figures (gnuplot scripts,
// rendered by io::run_gnuplot): the trajectory of the trials against the
// targets, and the stress-strain curves of the calibrated test with the
// target and calibrated moduli drawn.
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "mesowave/dem/calibration/calibration.hpp"
#include "mesowave/dem/contact/material.hpp"
#include "mesowave/dem/packing/packing.hpp"

namespace mesowave::dem {

/// The `mw-dem run` command of a trial: the scene's virtual test with the
/// trial's options, its summary, curves and signals trial-NN.json/.csv/.h5 in
/// `work_dir` (mw-dem records the run in the provenance database itself).
struct TrialCommand {
  std::filesystem::path mw_dem, scene, packing, work_dir;  ///< packing: "" for the scene's
  std::string db;                                          ///< "" for mw-dem's default
  int threads = 0;                                         ///< 0: mw-dem's choice
  /// trial-01.json, trial-02.csv, ... in work_dir.
  std::filesystem::path file(int trial, const std::string& extension) const;
  std::vector<std::string> argv(int trial, const std::vector<std::string>& options) const;
};

/// The cube calibration's first trial from mw-calibrate's --start-E-dem-GPa, --start-nu-dem,
/// --start-T-MPa and --C-over-T, each not given taken from the scene's material. InputError when
/// neither gives a finite T (the scene's bonds never break).
DemParameters compression_start(const CohesiveFrictionalMaterial& scene, std::optional<double> E_dem_GPa,
                                std::optional<double> nu_dem, std::optional<double> T_MPa, double c_over_t);

/// How the elastic trials run: stepped, or solved (mw-dem run --static); stepped, the moving walls'
/// speed when not the scene's (mw-dem run --velocity-mm-s). The linearised network's only rate
/// effect is inertia, held below the scene's quasi-static bound by the test itself: on the 50 mm
/// cube at 100 mm/s, four times the shipped scene's 25 mm/s, E_glob and nu_glob moved by -1.4e-5
/// (relative) and -1.1e-5 in 3.7x fewer steps (docs/calibration.md, "The elastic trials' speed").
struct ElasticTrials {
  bool static_solve = false;
  std::optional<double> velocity_mm_s;
  std::optional<std::string> preconditioner;  ///< solved trials: mw-dem's --static-preconditioner (its default: none given)
};

/// mw-calibrate's --elastic-trials static, --elastic-velocity-mm-s and --static-preconditioner,
/// checked: a speed must be positive and is for stepped trials only, a preconditioner for solved
/// ones only (InputError naming the option; mw-dem checks the preconditioner's name).
ElasticTrials elastic_trials(bool static_solve, std::optional<double> velocity_mm_s,
                             std::optional<std::string> preconditioner = std::nullopt);

/// The `mw-dem run` options of a cube trial. An elastic trial reads the
/// response where the lab reads it, between 10 % and 1/3 of the target
/// strength (EN 12390-13), on unbreakable linearised bonds, the run ending
/// just above, stepped or solved as `elastic` says (static_elastic.hpp); a failure
/// trial runs the full law with T and C = (C/T) T, always stepped at the scene's speed.
std::vector<std::string> compression_trial_options(const CalibrationTrial& trial, const CalibrationTargets& targets,
                                                   double friction_angle_deg, const ElasticTrials& elastic = {});
/// The trial with the results of its mw-dem summary (the JSON file `summary_file`).
CalibrationTrial with_results(CalibrationTrial trial, const std::filesystem::path& summary_file);
/// The rod trial with the results of its mw-dem summary (E_fit_GPa, wall_s).
RodTrial with_results(RodTrial trial, const std::filesystem::path& summary_file);
/// "trial 3 (elastic): E_dem 23.3 GPa, nu_dem 0.32 -> E_glob ..., nu_glob ... (linear model, 4.2 s)".
std::string describe(const CalibrationTrial& trial);

/// Runs a trial: its number and mw-dem options in, its summary file (trial-NN.json) out.
using TrialRunner = std::function<std::filesystem::path(int trial, const std::vector<std::string>& options)>;
/// Where trial k keeps its intact checkpoint (trial-NN-intact.h5).
using IntactCheckpointFile = std::function<std::filesystem::path(int trial)>;

/// The failure trials share their elastic prefix (engine/checkpoint.hpp, issue 19): each keeps
/// an intact checkpoint (the state before its first bond breaks, `intact_file`), and a trial
/// whose E_dem and nu_dem equal an earlier failure trial's, and whose T and C are at least its,
/// starts from the checkpoint of the strongest such trial (the latest first break). The results
/// are the same bits as a trial from step 0; the options to add to `trial`'s (none for an
/// elastic trial, or without `intact_file`).
std::vector<std::string> shared_prefix_options(const CalibrationTrial& trial, const std::vector<CalibrationTrial>& done,
                                               const IntactCheckpointFile& intact_file);

/// Runs the calibration's trials until it has its result, a line per trial on `log`
/// ("mw-calibrate: trial 3 (elastic): ...", describe()); with `intact_file` the failure
/// trials share their elastic prefix (shared_prefix_options).
void run_trials(CompressionCalibration& c, const TrialRunner& run, double friction_angle_deg, std::ostream& log,
                const ElasticTrials& elastic = {}, const IntactCheckpointFile& intact_file = {});
/// The rod's trials ("mw-calibrate rod: trial 1: E_dem 660 GPa -> E_DEM 220.6 GPa").
void run_trials(RodCalibration& c, const TrialRunner& run, std::ostream& log);

/// Where each target was read from: app::Run::origin of --E-st-measured-GPa, --nu-st and
/// --sigma-max-MPa (the file, its entry and SHA-256, or the command line). The pipeline
/// chooses the files (CC_CALIBRATION_TARGETS, pipeline/concrete-cube/step-6-calibration.mk):
/// the paper's static tests (lab-data/concrete-cube/static-test.toml: E_st_measured, nu_st,
/// sigma_max) or the lab's own step 4 (mw-compress's JSON: E_st_measured_GPa, sigma_max_MPa;
/// its records carry no lateral strain, so nu_st stays the static-test file's).
struct TargetOrigins {
  nlohmann::ordered_json E, nu, sigma_max;  ///< of the targets named CalibrationTargets::E_name, nu_name, and sigma_max
};

/// The calibrated cube: the flat keys that `mw-dem run --from` reads (E_dem_GPa,
/// nu_dem, T_MPa, C_MPa, friction_angle_deg), then the results against the targets,
/// then "targets": per target (E_st, nu_st, sigma_max; E_d, nu_d for the dynamic calibration:
/// CalibrationTargets::E_name, nu_name, which also name the flat `<name>_target` keys) its value, unit, tolerance, the
/// calibrated model's value and `origins`' record of where it was read from (nested: data for
/// the reader, never an option value of `mw-dem --from`).
/// `elastic`: how the elastic trials ran, recorded as elastic_trials ("dynamic" or "static") and,
/// when not the scene's, elastic_trials_velocity_mm_s.
nlohmann::ordered_json calibration_summary(const CompressionCalibration& c, double friction_angle_deg,
                                           const TargetOrigins& origins = {}, const ElasticTrials& elastic = {});
/// The "targets" of a calibration_summary as a table, one row per target: target, value,
/// unit, tolerance, calibrated (the model's E_glob, nu_glob, sigma_dem), read_from (the file or
/// "command line"), entry, source, cite and the first 12 hex digits of the file's SHA-256 (the
/// JSON has all 64; `mw-prov` finds the run that made a file by it).
std::string calibration_targets_csv(const nlohmann::ordered_json& summary);
/// The calibrated rod: the chain (spheres, R, d, rho_p), E_dem and K_n = E_dem R
/// (Eq. 3), E_DEM against the target, and the trials. `material` is the
/// scene's (all but E_dem).
nlohmann::ordered_json rod_calibration_summary(const RodCalibration& c, const Packing& chain,
                                               const CohesiveFrictionalMaterial& material);

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

/// The curves of a trial: its --curves CSV (stress_MPa, axial_strain,
/// lateral_strain; the summary's name with .csv) and the secant readings of
/// its summary's "test".
StressStrainCurve read_trial_curve(const std::filesystem::path& summary_file);

/// Stress against axial strain (right) and lateral strain (left, as negative
/// numbers, the usual drawing of concrete tests), with lines of the target
/// modulus E_st and of the calibrated E_glob through the lower reading.
std::string stress_strain_script(const StressStrainCurve& curve, double E_target_Pa, double nu_target,
                                 const std::filesystem::path& png, const std::string& title);

}  // namespace mesowave::dem
