// The calibration algorithm (dem/calibration.hpp) on a synthetic packing
// response whose parameters are known: does it recover them, in few trials,
// and does it refuse targets no packing reaches?
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "mesowave/core/error.hpp"
#include "mesowave/dem/calibration.hpp"

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
  auto message = [&](const CalibrationTargets& t) -> std::string {
    try {
      CompressionCalibration c(t, tol, kPoorStart, 12);
      calibrate(c, SyntheticPacking{});
    } catch (const InputError& e) {
      return e.what();
    }
    return "accepted";
  };
  EXPECT_NE(message({27e9, 0.5, 66e6}).find("must lie in (0, 0.5)"), std::string::npos);
  EXPECT_NE(message({27e9, 0.62, 66e6}).find("must lie in (0, 0.5)"), std::string::npos);
  EXPECT_NE(message({27e9, -0.1, 66e6}).find("must lie in (0, 0.5)"), std::string::npos);
  EXPECT_NE(message({-27e9, 0.16, 66e6}).find("E_st"), std::string::npos);
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
  try {
    calibrate(c, packing);
    FAIL() << "an unreachable strength was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unreachable"), std::string::npos) << e.what();
  }
}

TEST(CompressionCalibration, GivesUpAfterItsTrialBudget) {
  SyntheticPacking packing;
  packing.strength = [](double T) { return 2.7 * T * (1 + 0.3 * std::sin(T / 1e6)); };  // not monotonic
  CompressionCalibration c({27.42e9, 0.16, 66e6}, {1e-9, 1e-9, 1e-9}, kPoorStart, 6);
  try {
    calibrate(c, packing);
    FAIL() << "ran past its budget";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("within 6 trials"), std::string::npos) << e.what();
  }
  EXPECT_EQ(c.trials().size(), 6u);
}
