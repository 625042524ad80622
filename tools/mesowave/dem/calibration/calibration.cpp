#include "mesowave/dem/calibration/calibration.hpp"

#include <algorithm>
#include <cmath>

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/experiment/experiment.hpp"

namespace mesowave::dem {
namespace {

// nu_glob of a random isotropic packing against a = K_s / K_n, the estimate
// that starts the secant (only its shape matters: the first trial shifts it).
double nu_estimate(double a) { return (1 - a) / (4 + a); }
double nu_estimate_inverse(double nu) { return (1 - 4 * nu) / (1 + nu); }
double nu_estimate_slope(double a) { return -5 / ((4 + a) * (4 + a)); }

constexpr double kNuDemMax = 3.0;        // K_s up to 3 K_n
constexpr double kBondStrainMax = 0.05;  // T / E_dem: a bond strain of 5 % at breakage

std::string gpa(double pa) { return format_number(std::round(pa / 1e7) / 100) + " GPa"; }
std::string mpa(double pa) { return format_number(std::round(pa / 1e4) / 100) + " MPa"; }
std::string fixed(double v) { return format_number(std::round(v * 1e4) / 1e4); }

}  // namespace

CalibrationTargets compression_targets(double E_st_GPa, double nu_st, double sigma_max_MPa, std::optional<double> E_d_GPa,
                                       std::optional<double> nu_d) {
  return {require_positive(E_d_GPa ? "--E-d-GPa" : "--E-st-measured-GPa", E_d_GPa.value_or(E_st_GPa), "GPa") * units::GPa,
          nu_d.value_or(nu_st), require_positive("--sigma-max-MPa", sigma_max_MPa, "MPa") * units::MPa,
          E_d_GPa ? "E_d" : "E_st", nu_d ? "nu_d" : "nu_st"};
}

CalibrationTolerances compression_tolerances(double E_pct, double nu, double sigma_pct) {
  return {require_positive("--tolerance-E-pct", E_pct, "%") / 100, require_positive("--tolerance-nu", nu),
          require_positive("--tolerance-sigma-pct", sigma_pct, "%") / 100};
}

CompressionCalibration::CompressionCalibration(const CalibrationTargets& targets,
                                               const CalibrationTolerances& tolerances, const DemParameters& start,
                                               int max_trials)
    : targets_(targets), tolerances_(tolerances), start_(start), max_trials_(max_trials) {
  require_positive("target " + targets.E_name, targets.E_Pa / 1e9, "GPa");
  if (!(targets.nu > 0 && targets.nu < 0.5))
    throw InputError("target " + targets.nu_name + " (" + format_number(targets.nu) +
                     ") must lie in (0, 0.5): an isotropic elastic solid has nu < 0.5, and a bonded sphere packing "
                     "gives nu_glob > 0");
  require_positive("target sigma_max", targets.sigma_Pa / 1e6, "MPa");
  if (targets.sigma_Pa / targets.E_Pa > kBondStrainMax)
    throw InputError("target sigma_max (" + mpa(targets.sigma_Pa) + ") over " + targets.E_name + " (" + gpa(targets.E_Pa) +
                     ") is a peak strain of " + format_number(targets.sigma_Pa / targets.E_Pa) +
                     ": unreachable for a brittle bonded packing, which fails at strains of a few 1e-3");
  require_positive("tolerance on E", tolerances.E_relative);
  require_positive("tolerance on nu", tolerances.nu_absolute);
  require_positive("tolerance on sigma", tolerances.sigma_relative);
  require_positive("start E_dem", start.E_dem_Pa / 1e9, "GPa");
  require_in_range("start nu_dem", start.nu_dem, 0.0, kNuDemMax);
  require_positive("start T", start.T_Pa / 1e6, "MPa");
  require_positive("C / T", start.c_over_t);
  if (max_trials < 2) throw InputError("max trials (" + std::to_string(max_trials) + ") must be at least 2");
}

CalibrationTrial CompressionCalibration::make(CalibrationTrial::Kind kind, const DemParameters& p) const {
  CalibrationTrial t;
  t.kind = kind;
  t.number = int(trials_.size()) + 1;
  t.parameters = p;
  return t;
}

std::vector<const CalibrationTrial*> CompressionCalibration::of_kind(CalibrationTrial::Kind kind) const {
  std::vector<const CalibrationTrial*> out;
  for (const auto& t : trials_)
    if (t.kind == kind) out.push_back(&t);
  return out;
}

bool CompressionCalibration::meets_elastic(const CalibrationTrial& t) const {
  return std::abs(t.E_glob_Pa / targets_.E_Pa - 1) <= tolerances_.E_relative &&
         std::abs(t.nu_glob - targets_.nu) <= tolerances_.nu_absolute;
}

bool CompressionCalibration::meets_all(const CalibrationTrial& t) const {
  return t.kind == CalibrationTrial::Kind::failure && t.peak_reached && meets_elastic(t) &&
         std::abs(t.peak_Pa / targets_.sigma_Pa - 1) <= tolerances_.sigma_relative;
}

std::optional<CalibrationTrial> CompressionCalibration::next() {
  if (pending_) throw std::logic_error("CompressionCalibration::next before the last trial was recorded");
  if (converged_) return std::nullopt;
  std::optional<CalibrationTrial> t;
  if (!elastic_done_) {
    t = next_elastic();
    if (!t) elastic_done_ = true;
  }
  if (elastic_done_) {
    const auto failures = of_kind(CalibrationTrial::Kind::failure);
    if (!failures.empty() && meets_all(*failures.back())) {
      converged_ = true;
      return std::nullopt;
    }
    t = next_failure();
  }
  if (int(trials_.size()) >= max_trials_) {
    const CalibrationTrial& last = trials_.back();
    throw InputError("the calibration did not meet its targets within " + std::to_string(max_trials_) +
                     " trials; the last (" + last.kind_name() + ") gave E_glob " + gpa(last.E_glob_Pa) + ", nu_glob " +
                     fixed(last.nu_glob) + (last.kind == CalibrationTrial::Kind::failure ? ", peak " + mpa(last.peak_Pa) : "") +
                     " against " + gpa(targets_.E_Pa) + ", " + fixed(targets_.nu) + ", " + mpa(targets_.sigma_Pa));
  }
  pending_ = 1;
  return t;
}

void CompressionCalibration::record(const CalibrationTrial& done) {
  if (!pending_ || done.number != int(trials_.size()) + 1)
    throw std::logic_error("CompressionCalibration::record of a trial that was not handed out");
  if (!(done.E_glob_Pa > 0) || !std::isfinite(done.nu_glob))
    throw InputError("trial " + std::to_string(done.number) + " gave no modulus (E_glob " + format_number(done.E_glob_Pa) +
                     " Pa): see its summary " + done.summary_file);
  trials_.push_back(done);
  pending_ = 0;
}

const CalibrationTrial& CompressionCalibration::result() const {
  if (!converged_) throw std::logic_error("CompressionCalibration::result before convergence");
  return trials_.back();
}

double CompressionCalibration::next_nu_dem(const std::vector<const CalibrationTrial*>& done) const {
  const CalibrationTrial& last = *done.back();
  const double a1 = last.parameters.nu_dem, n1 = last.nu_glob;
  double a = -1;
  if (done.size() >= 2) {
    const CalibrationTrial& before = *done[done.size() - 2];
    const double a0 = before.parameters.nu_dem, n0 = before.nu_glob;
    if (a1 != a0 && (n1 - n0) / (a1 - a0) < 0) a = a1 + (targets_.nu - n1) * (a1 - a0) / (n1 - n0);  // secant on h
  }
  if (a < -0.5) a = nu_estimate_inverse(targets_.nu - (n1 - nu_estimate(a1)));  // the shifted estimate
  if (a < 0) {
    if (a1 == 0 && n1 < targets_.nu - tolerances_.nu_absolute)
      throw InputError("target " + targets_.nu_name + " " + fixed(targets_.nu) + " is unreachable: this packing gives nu_glob " + fixed(n1) +
                       " at nu_dem = 0 (K_s = 0), its largest");
    a = 0;
  }
  if (a > kNuDemMax) {
    if (a1 == kNuDemMax && n1 > targets_.nu + tolerances_.nu_absolute)
      throw InputError("target " + targets_.nu_name + " " + fixed(targets_.nu) + " is unreachable: this packing gives nu_glob " + fixed(n1) +
                       " at nu_dem = " + format_number(kNuDemMax) + " (K_s = 3 K_n)");
    a = kNuDemMax;
  }
  return a;
}

std::optional<CalibrationTrial> CompressionCalibration::next_elastic() {
  const auto done = of_kind(CalibrationTrial::Kind::elastic);
  if (done.empty()) return make(CalibrationTrial::Kind::elastic, start_);
  const CalibrationTrial& last = *done.back();
  if (meets_elastic(last)) return std::nullopt;
  DemParameters p = last.parameters;
  p.nu_dem = next_nu_dem(done);
  // E_glob / E_dem = g(nu_dem): interpolate g between the last two trials.
  double g = last.E_glob_Pa / last.parameters.E_dem_Pa;
  if (done.size() >= 2) {
    const CalibrationTrial& before = *done[done.size() - 2];
    const double g0 = before.E_glob_Pa / before.parameters.E_dem_Pa, a0 = before.parameters.nu_dem;
    const double a1 = last.parameters.nu_dem;
    if (a1 != a0) g += (g - g0) / (a1 - a0) * (p.nu_dem - a1);
  }
  p.E_dem_Pa = targets_.E_Pa / g;
  return make(CalibrationTrial::Kind::elastic, p);
}

CalibrationTrial CompressionCalibration::next_failure() {
  const auto failures = of_kind(CalibrationTrial::Kind::failure);
  if (failures.empty()) {
    DemParameters p = of_kind(CalibrationTrial::Kind::elastic).back()->parameters;
    p.T_Pa = start_.T_Pa;
    p.c_over_t = start_.c_over_t;
    return make(CalibrationTrial::Kind::failure, p);
  }
  const CalibrationTrial& last = *failures.back();
  if (!last.peak_reached)
    throw InputError("failure trial " + std::to_string(last.number) + " ended with the stress still rising (" +
                     mpa(last.peak_Pa) + "): lengthen the scene's [time] duration_ms");
  DemParameters p = last.parameters;
  // Strength: proportional to T first, then a secant on sigma_peak(T).
  p.T_Pa = last.parameters.T_Pa * targets_.sigma_Pa / last.peak_Pa;
  if (failures.size() >= 2) {
    const CalibrationTrial& before = *failures[failures.size() - 2];
    const double t0 = before.parameters.T_Pa, s0 = before.peak_Pa, t1 = last.parameters.T_Pa, s1 = last.peak_Pa;
    if (t1 != t0 && (s1 - s0) / (t1 - t0) > 0) {
      const double t = t1 + (targets_.sigma_Pa - s1) * (t1 - t0) / (s1 - s0);
      if (t > 0) p.T_Pa = t;
    }
  }
  // Modulus and Poisson ratio from the same run (the forces, hence the peak, do
  // not depend on E_dem), corrected only when out of tolerance: a brittle
  // packing's failure path, and so its peak, changes with any change of the run.
  if (std::abs(last.E_glob_Pa / targets_.E_Pa - 1) > tolerances_.E_relative)
    p.E_dem_Pa = last.parameters.E_dem_Pa * targets_.E_Pa / last.E_glob_Pa;
  if (std::abs(last.nu_glob - targets_.nu) > tolerances_.nu_absolute) {
    const auto elastic = of_kind(CalibrationTrial::Kind::elastic);
    double slope = nu_estimate_slope(p.nu_dem);
    if (elastic.size() >= 2) {
      const CalibrationTrial& a = *elastic[elastic.size() - 2];
      const CalibrationTrial& b = *elastic.back();
      if (b.parameters.nu_dem != a.parameters.nu_dem)
        slope = std::min(slope, (b.nu_glob - a.nu_glob) / (b.parameters.nu_dem - a.parameters.nu_dem));
    }
    p.nu_dem = std::clamp(p.nu_dem + (targets_.nu - last.nu_glob) / slope, 0.0, kNuDemMax);
  }
  if (p.T_Pa / p.E_dem_Pa > kBondStrainMax)
    throw InputError("target sigma_max " + mpa(targets_.sigma_Pa) + " is unreachable: trial " +
                     std::to_string(last.number) + " reached " + mpa(last.peak_Pa) + " with T = " + mpa(last.parameters.T_Pa) +
                     ", so the target needs T = " + mpa(p.T_Pa) + ", a bond strain T / E_dem of " +
                     format_number(p.T_Pa / p.E_dem_Pa) + " at breakage, beyond the small-strain contact law");
  return make(CalibrationTrial::Kind::failure, p);
}

double rod_target_E_GPa(std::optional<double> E_GPa, const std::filesystem::path& experiment) {
  if (E_GPa && !experiment.empty()) throw InputError("give the target E as --E-GPa or by --experiment, not both");
  if (E_GPa) return *E_GPa;
  if (experiment.empty()) throw InputError("mw-calibrate rod needs its target: --E-GPa or --experiment (the rod's E)");
  return experiment::rod_of(experiment::read_experiment_file(experiment)).E_Pa / units::GPa;
}

RodCalibration::RodCalibration(double E_target_GPa, double tolerance_relative, double start_E_dem_GPa, int max_trials)
    : target_GPa_(require_positive("target E", E_target_GPa, "GPa")),
      tolerance_(require_positive("tolerance on E_DEM", tolerance_relative)),
      start_GPa_(require_positive("start E_dem", start_E_dem_GPa, "GPa")),
      max_trials_(max_trials) {
  if (max_trials < 1) throw InputError("max trials (" + std::to_string(max_trials) + ") must be at least 1");
}

std::optional<RodTrial> RodCalibration::next() {
  if (pending_) throw std::logic_error("RodCalibration::next before the last trial was recorded");
  if (converged_) return std::nullopt;
  RodTrial t;
  t.number = int(trials_.size()) + 1;
  if (trials_.empty()) {
    t.E_dem_GPa = start_GPa_;
  } else {
    const RodTrial& last = trials_.back();
    if (std::abs(last.E_DEM_GPa / target_GPa_ - 1) <= tolerance_) {
      converged_ = true;
      return std::nullopt;
    }
    if (int(trials_.size()) >= max_trials_)
      throw InputError("the rod calibration did not reach " + format_number(target_GPa_) + " GPa within " +
                       std::to_string(max_trials_) + " trials");
    t.E_dem_GPa = last.E_dem_GPa * (target_GPa_ / last.E_DEM_GPa);  // E_DEM proportional to E_dem
  }
  pending_ = true;
  return t;
}

void RodCalibration::record(const RodTrial& done) {
  if (!pending_ || done.number != int(trials_.size()) + 1)
    throw std::logic_error("RodCalibration::record of a trial that was not handed out");
  if (!(done.E_DEM_GPa > 0) || !std::isfinite(done.E_DEM_GPa))
    throw InputError("trial " + std::to_string(done.number) + " gave no tension modulus (E_DEM " +
                     format_number(done.E_DEM_GPa) + " GPa): see its summary " + done.summary_file);
  trials_.push_back(done);
  pending_ = false;
}

const RodTrial& RodCalibration::result() const {
  if (!converged_) throw std::logic_error("RodCalibration::result before convergence");
  return trials_.back();
}

}  // namespace mesowave::dem
