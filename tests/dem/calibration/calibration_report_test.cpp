// Which earlier failure trial a calibration's trial starts from (calibration_report.hpp,
// shared_prefix_options): the state before the first break is the same for any stronger bonds
// (engine/checkpoint.hpp) and for nothing else, so the donor must have the same E_dem and nu_dem
// and a T and C at most the trial's, and of those the strongest (its bonds break last: the longest
// prefix). Checked against the choices written out by hand; the bits of such a restart are
// checked by tests/cli/mw_dem_checkpoint_test.cpp.
#include <gtest/gtest.h>

#include <fstream>

#include "mesowave/dem/calibration/calibration_report.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using namespace mesowave::dem;

namespace {

CalibrationTrial trial(int number, CalibrationTrial::Kind kind, double E_dem_GPa, double nu_dem, double T_MPa,
                       double c_over_t = 1.0) {
  CalibrationTrial t;
  t.number = number, t.kind = kind;
  t.parameters = {E_dem_GPa * 1e9, nu_dem, T_MPa * 1e6, c_over_t};
  return t;
}

constexpr auto kFailure = CalibrationTrial::Kind::failure;
constexpr auto kElastic = CalibrationTrial::Kind::elastic;

}  // namespace

TEST(SharedPrefix, AFailureTrialStartsFromTheStrongestEarlierTrialWithTheSameStiffnessAndWeakerBonds) {
  test::TempDir dir;
  const IntactCheckpointFile file = [&](int k) { return dir / ("trial-" + std::to_string(k) + "-intact.h5"); };
  const std::vector<CalibrationTrial> done = {
      trial(1, kElastic, 26.9, 0.296, 0),     // elastic: no checkpoint of bonds that break
      trial(2, kFailure, 26.9, 0.296, 24.4),  // a donor
      trial(3, kFailure, 26.9, 0.296, 30.0),  // the stronger donor
      trial(4, kFailure, 26.9, 0.296, 40.0),  // stronger than the trial: its prefix is too long
      trial(5, kFailure, 27.0, 0.296, 25.0),  // another E_dem
      trial(6, kFailure, 26.9, 0.297, 25.0),  // another nu_dem
      trial(7, kFailure, 26.9, 0.296, 31.0, 1.5),  // C = 46.5 MPa above the trial's
  };
  for (const int k : {1, 2, 3, 4, 5, 6, 7}) std::ofstream(file(k)) << "x";
  const auto next = trial(8, kFailure, 26.9, 0.296, 33.77);
  const std::vector<std::string> expected = {"--intact-checkpoint", file(8).string(), "--restart-stronger", file(3).string()};
  EXPECT_EQ(shared_prefix_options(next, done, file), expected);

  // Trial 3 left no intact checkpoint (its first bond broke before step 1000): trial 2's, then none.
  std::filesystem::remove(file(3));
  const std::vector<std::string> from_2 = {"--intact-checkpoint", file(8).string(), "--restart-stronger", file(2).string()};
  EXPECT_EQ(shared_prefix_options(next, done, file), from_2);
  std::filesystem::remove(file(2));
  const std::vector<std::string> alone = {"--intact-checkpoint", file(8).string()};
  EXPECT_EQ(shared_prefix_options(next, done, file), alone);

  // Elastic trials, and a calibration run without checkpoints, add nothing.
  EXPECT_TRUE(shared_prefix_options(trial(9, kElastic, 26.9, 0.296, 0), done, file).empty());
  EXPECT_TRUE(shared_prefix_options(next, done, {}).empty());
}
