// app::Progress off a terminal (as under make or ctest: plain lines at 0, 10, 20 ... %): what
// each line claims must be true - no rate before any time has passed, and a loop that a stop
// rule ends early is not reported as 100 % done.
#include "mesowave/app/progress.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>

using namespace mesowave;

TEST(Progress, TheFirstLineSaysStartedInsteadOfARateMeasuredOverNoTime) {
  testing::internal::CaptureStderr();
  {
    app::Progress p("loop", 1000, "steps");
    p.update(0);
    p.finish();
  }
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find("loop:   0% 0/1000 steps, started\n"), std::string::npos) << err;
  EXPECT_EQ(err.find("ETA"), std::string::npos) << err;  // no ETA from zero steps
  EXPECT_NE(err.find("loop: 100% 1000/1000 steps, "), std::string::npos) << err;
  EXPECT_NE(err.find(" took 0:00\n"), std::string::npos) << err;
}

TEST(Progress, ALaterLineGivesTheRateAndAnEta) {
  testing::internal::CaptureStderr();
  {
    app::Progress p("loop", 100, "steps");
    p.update(0);
    std::this_thread::sleep_for(std::chrono::milliseconds(60));
    p.update(10);  // 10 steps in >= 60 ms: at most 167 steps/s, so 90 more take >= 0.54 s
  }
  const std::string err = testing::internal::GetCapturedStderr();
  const auto at = err.find("loop:  10% 10/100 steps, ");
  ASSERT_NE(at, std::string::npos) << err;
  const double rate = std::stod(err.substr(at + 25));
  EXPECT_GT(rate, 0.0) << err;
  EXPECT_LE(rate, 10 / 0.06) << err;
  EXPECT_NE(err.find(" steps/s, ETA ", at), std::string::npos) << err;
}

TEST(Progress, ALoopEndedByAStopRuleSaysWhereAndWhyNotOneHundredPerCent) {
  testing::internal::CaptureStderr();
  app::ProgressMark reached;
  {
    app::Progress p("mw-dem compression", 20000, "steps");
    p.update(0);
    p.update(7345);
    p.finish_early(7345, "20 % past the peak stress");
    reached = p.mark();
  }
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(err.find("100%"), std::string::npos) << err;
  EXPECT_NE(err.find("mw-dem compression:  36% 7345/20000 steps, stopped early: 20 % past the peak stress; took "),
            std::string::npos)
      << err;
  EXPECT_EQ(reached.done, 7345);  // what an interrupted run's record would say it reached
  EXPECT_EQ(reached.total, 20000);
}
