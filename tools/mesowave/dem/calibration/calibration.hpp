#pragma once
// Flowchart step 6 of the concrete paper as an algorithm: find E_dem, nu_dem
// and T (with C = T, or a fixed ratio C / T; the friction angle given) so that
// the virtual compression test matches the lab's E_st, nu_st and sigma_max,
// using the structure of the problem instead of a grid search:
//  - elastic trials (bonds that never break, loaded to the upper modulus level
//    sigma_max / 3): the packing is a network whose stiffnesses all scale with
//    E_dem (Eq. 3), so E_glob = E_dem g(nu_dem) and nu_glob = h(nu_dem) exactly.
//    E_dem is rescaled, nu_dem found by a secant on h, started from the
//    random-packing estimate h(a) ~ (1 - a) / (4 + a) shifted through the first
//    trial (it gives 0.157 at the paper's a = 0.32, the paper's nu_glob 0.16);
//  - failure trials (the full law to failure): the forces of a quasi-static test
//    do not depend on the stiffness scale, so the peak stress depends on T and
//    nu_dem only, close to proportionally to T: T is rescaled, then found by a
//    secant on sigma_peak(T); E_dem and nu_dem are corrected from the same runs
//    (their modulus is the lab's: the secant between 10 % and 1/3 of the peak).
// The class only decides; whoever runs the trials (mw-calibrate: one mw-dem run
// each) reports their results back.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace mesowave::dem {

struct CalibrationTargets {
  double E_Pa = 0;      ///< E_st (static modulus), or E_d for the dynamic calibration
  double nu = 0;        ///< nu_st (the paper takes nu_d), or nu_d
  double sigma_Pa = 0;  ///< sigma_max (compressive strength)
  /// The paper's names of the elastic targets, as errors and the summary name them: E_st and nu_st
  /// (the static test's), or E_d and nu_d (the UPV test's: mw-calibrate --E-d-GPa --nu-d).
  std::string E_name = "E_st", nu_name = "nu_st";
};

/// The cube's targets from mw-calibrate's options: E_st and nu_st (the static test), or E_d and nu_d
/// where given (the dynamic calibration: each replaces its static twin), and sigma_max. InputError
/// naming the option (--E-st-measured-GPa, --E-d-GPa, --sigma-max-MPa) for a modulus or strength <= 0.
CalibrationTargets compression_targets(double E_st_GPa, double nu_st, double sigma_max_MPa, std::optional<double> E_d_GPa,
                                       std::optional<double> nu_d);

struct CalibrationTolerances {
  double E_relative = 0.01;      ///< 1 % on E_glob
  double nu_absolute = 0.01;     ///< 0.01 on nu_glob
  double sigma_relative = 0.02;  ///< 2 % on the peak stress
};

/// mw-calibrate's tolerances in its options' units (--tolerance-E-pct, --tolerance-nu,
/// --tolerance-sigma-pct): InputError naming the option for one <= 0.
CalibrationTolerances compression_tolerances(double E_pct, double nu, double sigma_pct);

struct DemParameters {
  double E_dem_Pa = 0;
  double nu_dem = 0;      ///< K_s / K_n
  double T_Pa = 0;        ///< normal bond strength; C = c_over_t T
  double c_over_t = 1.0;  ///< the paper: T = C
};

struct CalibrationTrial {
  enum class Kind { elastic, failure } kind = Kind::elastic;
  int number = 0;  ///< 1, 2, ...
  DemParameters parameters;
  // Results, filled by whoever ran it:
  double E_glob_Pa = 0, nu_glob = 0, peak_Pa = 0;
  bool peak_reached = false;
  double wall_s = 0;                  ///< of the steps it ran (after a shared prefix: those after it)
  std::int64_t shared_prefix_steps = 0;  ///< steps taken from an earlier trial's intact checkpoint
  int prefix_of_trial = 0;            ///< that trial's number (0: none)
  std::string model;         ///< the model that ran (linear | full)
  std::string method;        ///< dynamic (stepped) | static (mw-dem run --static)
  std::string summary_file;  ///< the run's summary (mw-dem --summary)
  std::string kind_name() const { return kind == Kind::elastic ? "elastic" : "failure"; }
};

class CompressionCalibration {
public:
  /// InputError for targets no bonded packing reaches: nu outside (0, 0.5),
  /// a non-positive modulus or strength, a peak strain sigma / E above 5 %.
  CompressionCalibration(const CalibrationTargets& targets, const CalibrationTolerances& tolerances,
                         const DemParameters& start, int max_trials);

  /// The next trial to run, or nothing once a failure trial met every target.
  /// InputError when a target turns out unreachable (nu_glob beyond what
  /// nu_dem >= 0 gives, T beyond a bond strain of 5 %) or after max_trials.
  std::optional<CalibrationTrial> next();
  void record(const CalibrationTrial& done);

  bool converged() const { return converged_; }
  const std::vector<CalibrationTrial>& trials() const { return trials_; }
  /// The parameters of the trial that met the targets.
  const CalibrationTrial& result() const;
  const CalibrationTargets& targets() const { return targets_; }
  const CalibrationTolerances& tolerances() const { return tolerances_; }

  bool meets_elastic(const CalibrationTrial& t) const;
  bool meets_all(const CalibrationTrial& t) const;

private:
  std::optional<CalibrationTrial> next_elastic();
  CalibrationTrial next_failure();
  CalibrationTrial make(CalibrationTrial::Kind kind, const DemParameters& p) const;
  std::vector<const CalibrationTrial*> of_kind(CalibrationTrial::Kind kind) const;
  /// nu_dem for the next trial from what the trials of `kind` measured.
  double next_nu_dem(const std::vector<const CalibrationTrial*>& done) const;

  CalibrationTargets targets_;
  CalibrationTolerances tolerances_;
  DemParameters start_;
  int max_trials_;
  std::vector<CalibrationTrial> trials_;
  bool elastic_done_ = false, converged_ = false;
  int pending_ = 0;  ///< a trial handed out and not yet recorded
};

// The rod paper's calibration (Table 1): the contact modulus E_dem (K_n = E_dem R
// for equal spheres, Eq. 3) so that the tension test of the chain of spheres
// gives the rod's Young modulus E. The chain's modulus E_DEM = K_n d / (pi R^2)
// is proportional to E_dem, so each next trial rescales the last one,
// E_dem <- E_dem E / E_DEM: one rescaled trial and a check. Moduli in GPa, as
// mw-dem reads and reports them (the trials' parameters pass between programs
// bit for bit). Like CompressionCalibration, the class only decides.
struct RodTrial {
  int number = 0;      ///< 1, 2, ...
  double E_dem_GPa = 0;  ///< the contact modulus tried (mw-dem --E-dem-GPa)
  // Results, filled by whoever ran it:
  double E_DEM_GPa = 0;  ///< the chain's tension modulus (mw-dem's E_fit_GPa)
  double wall_s = 0;
  std::string summary_file;
};

/// mw-calibrate rod's target E [GPa]: `E_GPa` if given, else the E of the experiment's rod
/// (experiment::rod_of: lab-data/steel-rod/experiment.toml prints the rod paper's, Section 4.1);
/// InputError when neither gives it, or both do (two targets).
double rod_target_E_GPa(std::optional<double> E_GPa, const std::filesystem::path& experiment);

class RodCalibration {
public:
  /// InputError for a non-positive target, tolerance or start, or max_trials < 1.
  RodCalibration(double E_target_GPa, double tolerance_relative, double start_E_dem_GPa, int max_trials);

  /// The next trial, or nothing once the last one met the target. InputError
  /// when max_trials ran without meeting it.
  std::optional<RodTrial> next();
  /// InputError for a trial without a positive E_DEM.
  void record(const RodTrial& done);

  bool converged() const { return converged_; }
  const std::vector<RodTrial>& trials() const { return trials_; }
  /// The trial that met the target.
  const RodTrial& result() const;
  double target_GPa() const { return target_GPa_; }

private:
  double target_GPa_, tolerance_, start_GPa_;
  int max_trials_;
  std::vector<RodTrial> trials_;
  bool converged_ = false, pending_ = false;
};

}  // namespace mesowave::dem
