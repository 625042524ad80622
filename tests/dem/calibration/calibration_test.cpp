// The calibration algorithm (dem/calibration/calibration.hpp) on a synthetic packing
// response whose parameters are known: does it recover them, in few trials,
// and does it refuse targets no packing reaches?
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "mesowave/core/error.hpp"
#include "mesowave/dem/calibration/calibration.hpp"
#include "mesowave/dem/calibration/calibration_report.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::dem;

namespace {

// A packing's response with the structure of a real one: E_glob proportional
// to E_dem with a factor g(nu_dem), nu_glob = h(nu_dem) falling, the peak
// stress proportional-ish to T and independent of E_dem; failure trials read
// a slightly softer modulus (the microcracking below 1/3 of the peak).
struct SyntheticPacking {
  std::function<double(double)> strength = [](double T) { return 2.7 * T; };
  double g(double a) const { return 1.20 - 0.45 * a + 0.20 * a * a; }
  double h(double a) const { return 0.245 - 0.32 * a + 0.09 * a * a; }

  CalibrationTrial run(CalibrationTrial t) const {
    const auto& p = t.parameters;
    const bool failure = t.kind == CalibrationTrial::Kind::failure;
    t.E_glob_Pa = p.E_dem_Pa * g(p.nu_dem) * (failure ? 0.995 : 1.0);
    t.nu_glob = h(p.nu_dem) + (failure ? 0.002 : 0.0);
    t.peak_Pa = failure ? strength(p.T_Pa) * (1 + 0.2 * p.nu_dem) : 0;
    t.peak_reached = failure;
    return t;
  }
  CalibrationTargets targets_of(const DemParameters& truth) const {
    CalibrationTrial t;
    t.kind = CalibrationTrial::Kind::failure;
    t.parameters = truth;
    t = run(t);
    return {t.E_glob_Pa, t.nu_glob, t.peak_Pa};
  }
};

const DemParameters kPoorStart{10e9, 0.1, 10e6, 1.0};

int calibrate(CompressionCalibration& c, const SyntheticPacking& packing) {
  int trials = 0;
  while (auto t = c.next()) {
    c.record(packing.run(*t));
    ++trials;
  }
  return trials;
}

}  // namespace

TEST(CompressionCalibration, RecoversTheParametersThatMadeTheTargets) {
  const SyntheticPacking packing;
  const DemParameters truth{23.31e9, 0.32, 24.4e6, 1.0};
  const CalibrationTolerances tight{1e-5, 1e-5, 1e-5};
  CompressionCalibration c(packing.targets_of(truth), tight, kPoorStart, 30);
  const int trials = calibrate(c, packing);
  ASSERT_TRUE(c.converged());
  const DemParameters& found = c.result().parameters;
  EXPECT_NEAR(found.E_dem_Pa / truth.E_dem_Pa, 1.0, 1e-4);
  EXPECT_NEAR(found.nu_dem, truth.nu_dem, 1e-4);
  EXPECT_NEAR(found.T_Pa / truth.T_Pa, 1.0, 1e-4);
  EXPECT_LE(trials, 12);
}

TEST(CompressionCalibration, MeetsTheDefaultTolerancesInAFewTrials) {
  // The tolerances (1 % on E, 0.01 on nu, 2 % on strength) from the
  // poor start it names: a handful of runs, not a grid.
  const SyntheticPacking packing;
  CompressionCalibration c({27.42e9, 0.16, 66.0e6}, {}, kPoorStart, 12);
  const int trials = calibrate(c, packing);
  ASSERT_TRUE(c.converged());
  const CalibrationTrial& r = c.result();
  EXPECT_EQ(r.kind, CalibrationTrial::Kind::failure);
  EXPECT_LE(std::abs(r.E_glob_Pa / 27.42e9 - 1), 0.01);
  EXPECT_LE(std::abs(r.nu_glob - 0.16), 0.01);
  EXPECT_LE(std::abs(r.peak_Pa / 66e6 - 1), 0.02);
  EXPECT_LE(trials, 7);
}

TEST(CompressionCalibration, RefusesTargetsNoPackingReaches) {
  const CalibrationTolerances tol;
  auto message = [&](const CalibrationTargets& t) {
    return mesowave::test::input_error_of([&] {
      CompressionCalibration c(t, tol, kPoorStart, 12);
      calibrate(c, SyntheticPacking{});
    });
  };
  EXPECT_NE(message({27e9, 0.5, 66e6}).find("must lie in (0, 0.5)"), std::string::npos);
  EXPECT_NE(message({27e9, 0.62, 66e6}).find("must lie in (0, 0.5)"), std::string::npos);
  EXPECT_NE(message({27e9, -0.1, 66e6}).find("must lie in (0, 0.5)"), std::string::npos);
  EXPECT_NE(message({-27e9, 0.16, 66e6}).find("E_st"), std::string::npos);
  // The dynamic calibration's targets are E_d and nu_d, and its errors say so.
  EXPECT_NE(message({-36e9, 0.16, 66e6, "E_d", "nu_d"}).find("target E_d"), std::string::npos);
  EXPECT_NE(message({36e9, 0.62, 66e6, "E_d", "nu_d"}).find("target nu_d (0.62)"), std::string::npos);
  EXPECT_NE(message({27e9, 0.16, 0}).find("sigma_max"), std::string::npos);
  EXPECT_NE(message({27e9, 0.16, 2e9}).find("peak strain"), std::string::npos);
  // nu_glob of this packing is 0.245 at nu_dem = 0: 0.3 is out of reach.
  EXPECT_NE(message({27e9, 0.30, 66e6}).find("unreachable"), std::string::npos) << message({27e9, 0.30, 66e6});
}

TEST(CompressionCalibration, RefusesAStrengthTheBondsCannotGive) {
  // A packing whose strength saturates (every bond broken in the same way):
  // the secant asks for ever larger T until the bonds would strain by 5 %.
  SyntheticPacking packing;
  packing.strength = [](double T) { return 2.7 * T / (1 + T / 50e6); };
  CompressionCalibration c({27.42e9, 0.16, 400e6}, {}, kPoorStart, 30);
  const std::string error = mesowave::test::input_error_of([&] { calibrate(c, packing); });
  EXPECT_NE(error.find("unreachable"), std::string::npos) << error;
}

TEST(CompressionCalibration, GivesUpAfterItsTrialBudget) {
  SyntheticPacking packing;
  packing.strength = [](double T) { return 2.7 * T * (1 + 0.3 * std::sin(T / 1e6)); };  // not monotonic
  CompressionCalibration c({27.42e9, 0.16, 66e6}, {1e-9, 1e-9, 1e-9}, kPoorStart, 6);
  const std::string error = mesowave::test::input_error_of([&] { calibrate(c, packing); });
  EXPECT_NE(error.find("within 6 trials"), std::string::npos) << error;
  EXPECT_EQ(c.trials().size(), 6u);
}

namespace {

// A chain of equal spheres in tension (rod paper, Section 3): K_n = E_dem R
// (Eq. 3) and E_DEM = K_n d / (pi R^2) = E_dem d / (pi R), linear in E_dem.
double chain_modulus(double E_dem_GPa, double spacing_R) { return E_dem_GPa * spacing_R / std::numbers::pi; }

std::vector<RodTrial> calibrate_rod(RodCalibration& c, const std::function<double(double)>& response) {
  while (auto t = c.next()) {
    t->E_DEM_GPa = response(t->E_dem_GPa);
    c.record(*t);
  }
  return c.trials();
}

}  // namespace

TEST(RodCalibration, TheSecantThroughTheOriginConvergesInOneStep) {
  const double E = 208.72, spacing_R = 1.03;
  RodCalibration c(E, 0.005, 100.0, 12);
  const auto trials = calibrate_rod(c, [&](double E_dem) { return chain_modulus(E_dem, spacing_R); });
  ASSERT_TRUE(c.converged());
  ASSERT_EQ(trials.size(), 2u);  // the start, then the rescaled trial that meets the target
  EXPECT_EQ(trials[0].E_dem_GPa, 100.0);
  EXPECT_NEAR(trials[0].E_DEM_GPa, 100.0 * 1.03 / std::numbers::pi, 1e-12);
  // The closed form E_dem = E pi R / d:
  EXPECT_NEAR(trials[1].E_dem_GPa, E * std::numbers::pi / spacing_R, 1e-9);
  EXPECT_NEAR(c.result().E_DEM_GPa, E, 1e-9);
  EXPECT_EQ(c.result().number, 2);
  EXPECT_FALSE(c.next());  // done stays done
}

TEST(RodCalibration, AStartThatMeetsTheTargetIsOneTrial) {
  const double start = 208.72 * std::numbers::pi / 0.95;
  RodCalibration c(208.72, 0.005, start, 12);
  EXPECT_EQ(calibrate_rod(c, [](double E_dem) { return chain_modulus(E_dem, 0.95); }).size(), 1u);
  EXPECT_EQ(c.result().E_dem_GPa, start);
}

TEST(RodCalibration, AnAffineResponseTakesAFewRescalings) {
  // E_DEM = 2 E_dem + 30 (not through the origin): the rescaling converges
  // geometrically (the error shrinks by 30 / E each step), within tolerance.
  RodCalibration c(200.0, 1e-4, 10.0, 12);
  const auto trials = calibrate_rod(c, [](double E_dem) { return 2 * E_dem + 30; });
  ASSERT_TRUE(c.converged());
  EXPECT_GT(trials.size(), 2u);
  EXPECT_LE(trials.size(), 9u);  // 7: 10, 40, 72.7, 82.9, 84.7, 84.95, 84.99 GPa
  // The fixed point of 2 E_dem + 30 = 200; E_DEM within 1e-4 puts E_dem within 1e-4 / (170 / 200).
  EXPECT_NEAR(c.result().E_dem_GPa, 85.0, 85.0 * 1.18e-4);
  for (std::size_t k = 1; k < trials.size(); ++k)
    EXPECT_LT(std::abs(trials[k].E_DEM_GPa - 200.0), std::abs(trials[k - 1].E_DEM_GPa - 200.0));
}

TEST(RodCalibration, RefusesWhatItCannotReach) {
  EXPECT_THROW(RodCalibration(0, 0.005, 100, 12), InputError);
  EXPECT_THROW(RodCalibration(208, 0, 100, 12), InputError);
  EXPECT_THROW(RodCalibration(208, 0.005, -1, 12), InputError);
  EXPECT_THROW(RodCalibration(208, 0.005, 100, 0), InputError);
  // A chain that saturates below the target: max_trials trials, then an error.
  RodCalibration c(208.72, 0.005, 100, 4);
  EXPECT_THROW(calibrate_rod(c, [](double E_dem) { return std::min(E_dem, 150.0); }), InputError);
  EXPECT_EQ(c.trials().size(), 4u);
  // A trial without a modulus, and the protocol.
  RodCalibration d(208.72, 0.005, 100, 4);
  auto t = d.next();
  ASSERT_TRUE(t);
  EXPECT_THROW(d.next(), std::logic_error);
  t->E_DEM_GPa = 0;
  EXPECT_THROW(d.record(*t), InputError);
}

// The rod's target E: --E-GPa, or the rod paper's 208.72 GPa (Section 4.1) from the steel rod's experiment.
TEST(RodCalibration, TargetFromTheOptionOrTheExperiment) {
  using mesowave::test::input_error_of;
  const std::filesystem::path rod = std::filesystem::path(MESOWAVE_SOURCE_DIR) / "lab-data/steel-rod/experiment.toml";
  EXPECT_EQ(rod_target_E_GPa(std::nullopt, rod), 208.72);
  EXPECT_EQ(rod_target_E_GPa(200.0, ""), 200.0);
  EXPECT_NE(input_error_of([&] { rod_target_E_GPa(200.0, rod); }).find("not both"), std::string::npos);
  EXPECT_NE(input_error_of([] { rod_target_E_GPa(std::nullopt, ""); }).find("--E-GPa or --experiment"), std::string::npos);
  const std::filesystem::path cube = std::filesystem::path(MESOWAVE_SOURCE_DIR) / "lab-data/concrete-cube/experiment.toml";
  EXPECT_NE(input_error_of([&] { rod_target_E_GPa(std::nullopt, cube); }).find("a rod is a cylinder specimen"), std::string::npos);
}

// One name per paper quantity: a calibration to the UPV test's E_d and nu_d says so in its summary
// (E_d_target_GPa, targets.E_d), never under the static test's names.
TEST(CompressionCalibration, TheDynamicCalibrationsSummaryNamesItsTargetsEdAndNud) {
  const SyntheticPacking packing;
  CompressionCalibration c({36.67e9, 0.1618, 66e6, "E_d", "nu_d"}, {}, kPoorStart, 12);
  calibrate(c, packing);
  ASSERT_TRUE(c.converged());
  const auto j = calibration_summary(c, 18);
  EXPECT_EQ(j.at("E_d_target_GPa").get<double>(), 36.67);
  EXPECT_EQ(j.at("nu_d_target").get<double>(), 0.1618);
  EXPECT_FALSE(j.contains("E_st_target_GPa"));
  EXPECT_TRUE(j.at("targets").contains("E_d") && j.at("targets").contains("nu_d"));
  EXPECT_FALSE(j.at("targets").contains("E_st"));
}

namespace {
// An elastic and a failure trial of one parameter set (the options mw-calibrate gives each).
std::pair<CalibrationTrial, CalibrationTrial> elastic_and_failure_trials() {
  CalibrationTrial elastic, failure;
  elastic.kind = CalibrationTrial::Kind::elastic;
  failure.kind = CalibrationTrial::Kind::failure;
  elastic.parameters = failure.parameters = {26.9e9, 0.296, 33.8e6, 1.0};
  return {elastic, failure};
}
}  // namespace

TEST(CompressionCalibration, TheElasticTrialsRunAtTheirOwnSpeedAndTheFailureTrialsAtTheScenes) {
  // mw-calibrate --elastic-velocity-mm-s 100: the elastic trials' mw-dem runs get --velocity-mm-s 100,
  // the failure trials none (the strength depends on the rate; docs/calibration.md), and the summary
  // says how the elastic trials ran.
  const auto [elastic, failure] = elastic_and_failure_trials();
  const CalibrationTargets targets{27.42e9, 0.16, 66e6};
  const ElasticTrials fast = elastic_trials(false, 100.0);
  const auto has_speed = [](const std::vector<std::string>& o) {
    const auto at = std::find(o.begin(), o.end(), "--velocity-mm-s");
    return at != o.end() && at + 1 != o.end() && *(at + 1) == "100";
  };
  EXPECT_TRUE(has_speed(compression_trial_options(elastic, targets, 18, fast)));
  EXPECT_FALSE(has_speed(compression_trial_options(failure, targets, 18, fast)));
  const auto scene_speed = compression_trial_options(elastic, targets, 18);
  EXPECT_EQ(std::find(scene_speed.begin(), scene_speed.end(), "--velocity-mm-s"), scene_speed.end());

  const SyntheticPacking packing;
  CompressionCalibration c(packing.targets_of({26.9e9, 0.296, 33.8e6, 1.0}), {}, kPoorStart, 12);
  calibrate(c, packing);
  const auto j = calibration_summary(c, 18, {}, fast);
  EXPECT_EQ(j.at("elastic_trials").get<std::string>(), "dynamic");
  EXPECT_EQ(j.at("elastic_trials_velocity_mm_s").get<double>(), 100.0);
  EXPECT_FALSE(calibration_summary(c, 18).contains("elastic_trials_velocity_mm_s"));

  // One line naming the option: a speed that is not positive, or one given to solved trials.
  EXPECT_NE(test::input_error_of([] { elastic_trials(false, 0.0); }).find("--elastic-velocity-mm-s"), std::string::npos);
  const std::string both = test::input_error_of([] { elastic_trials(true, 100.0); });
  EXPECT_NE(both.find("--elastic-velocity-mm-s"), std::string::npos);
  EXPECT_NE(both.find("static"), std::string::npos);
}

TEST(CompressionCalibration, SolvedElasticTrialsPassTheirPreconditionerToMwDem) {
  // mw-calibrate --elastic-trials static --static-preconditioner amg: each elastic trial's mw-dem run
  // gets --static --static-preconditioner amg (mw-dem checks the name), a failure trial neither, and
  // the summary records it; a preconditioner for stepped trials is refused in one line.
  const auto [elastic, failure] = elastic_and_failure_trials();
  const CalibrationTargets targets{27.42e9, 0.16, 66e6};
  const ElasticTrials amg = elastic_trials(true, std::nullopt, "amg");
  const auto preconditioner = [](const std::vector<std::string>& o) {
    const auto at = std::find(o.begin(), o.end(), "--static-preconditioner");
    return at != o.end() && at + 1 != o.end() ? *(at + 1) : std::string();
  };
  const auto options = compression_trial_options(elastic, targets, 18, amg);
  EXPECT_NE(std::find(options.begin(), options.end(), "--static"), options.end());
  EXPECT_EQ(preconditioner(options), "amg");
  EXPECT_EQ(preconditioner(compression_trial_options(failure, targets, 18, amg)), "");
  EXPECT_EQ(preconditioner(compression_trial_options(elastic, targets, 18, elastic_trials(true, std::nullopt))), "");

  const SyntheticPacking packing;
  CompressionCalibration c(packing.targets_of({26.9e9, 0.296, 33.8e6, 1.0}), {}, kPoorStart, 12);
  calibrate(c, packing);
  EXPECT_EQ(calibration_summary(c, 18, {}, amg).at("elastic_trials_preconditioner").get<std::string>(), "amg");
  EXPECT_FALSE(calibration_summary(c, 18, {}, elastic_trials(true, std::nullopt)).contains("elastic_trials_preconditioner"));

  const std::string stepped = test::input_error_of([] { elastic_trials(false, std::nullopt, "amg"); });
  EXPECT_NE(stepped.find("--static-preconditioner amg"), std::string::npos);
  EXPECT_NE(stepped.find("--elastic-trials static"), std::string::npos);
}

TEST(CompressionCalibration, TheFirstTrialTakesTheStartOptionsElseTheScenesMaterial) {
  CohesiveFrictionalMaterial scene;
  scene.E_dem_Pa = 23.31e9, scene.stiffness_ratio = 0.32, scene.tensile_strength_Pa = 24.4e6;
  const DemParameters from_scene = compression_start(scene, std::nullopt, std::nullopt, std::nullopt, 1.0);
  EXPECT_EQ(from_scene.E_dem_Pa, 23.31e9);
  EXPECT_EQ(from_scene.nu_dem, 0.32);
  EXPECT_EQ(from_scene.T_Pa, 24.4e6);
  const DemParameters given = compression_start(scene, 10.0, 0.1, 12.5, 2.0);  // GPa, -, MPa
  EXPECT_EQ(given.E_dem_Pa, 10e9);
  EXPECT_EQ(given.nu_dem, 0.1);
  EXPECT_EQ(given.T_Pa, 12.5e6);
  EXPECT_EQ(given.c_over_t, 2.0);
  // Bonds that never break (no T in the scene) and no --start-T-MPa: nothing to calibrate T from.
  scene.tensile_strength_Pa = std::numeric_limits<double>::infinity();
  EXPECT_NE(test::input_error_of([&] { compression_start(scene, std::nullopt, std::nullopt, std::nullopt, 1.0); })
                .find("--start-T-MPa"),
            std::string::npos);
  EXPECT_EQ(compression_start(scene, std::nullopt, std::nullopt, 30.0, 1.0).T_Pa, 30e6);
}
