// The one motion quantity of the lab, the DEM and the FEM: its names are the signal
// files' quantity attribute (docs/formats.md) and read back to the same value, its
// units are the SI units those files carry, and any other name (a signal file's
// force or strain, a capitalised name) is refused with one line naming where it came from.
#include <gtest/gtest.h>

#include "mesowave/experiment/motion_quantity.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::experiment;

TEST(MotionQuantity, NamesAndUnitsAreTheSignalFilesAttributes) {
  EXPECT_EQ(to_string(MotionQuantity::acceleration), "acceleration");
  EXPECT_EQ(to_string(MotionQuantity::velocity), "velocity");
  EXPECT_EQ(to_string(MotionQuantity::displacement), "displacement");
  EXPECT_EQ(si_unit(MotionQuantity::acceleration), "m/s^2");
  EXPECT_EQ(si_unit(MotionQuantity::velocity), "m/s");
  EXPECT_EQ(si_unit(MotionQuantity::displacement), "m");
}

TEST(MotionQuantity, EveryNameReadsBackToItsValue) {
  ASSERT_EQ(motion_quantities.size(), 3u);
  for (MotionQuantity q : motion_quantities) EXPECT_EQ(parse_motion_quantity(to_string(q), "q"), q) << to_string(q);
}

TEST(MotionQuantity, OtherNamesAreOneLineNamingTheirOrigin) {
  EXPECT_EQ(test::input_error_of([] { parse_motion_quantity("strain", "--quantity"); }),
            "--quantity (\"strain\") must be acceleration, velocity or displacement");
  for (const char* bad : {"force", "Velocity", "", "acceleration "})
    EXPECT_NE(test::input_error_of([&] { parse_motion_quantity(bad, "s.toml: [[sensor]] 1.quantity"); })
                  .find("s.toml: [[sensor]] 1.quantity (\""),
              std::string::npos)
        << bad;
}
