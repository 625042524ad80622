// app::Progress off a terminal (as under make or ctest: plain lines at 0, 10, 20 ... %): what
// each line claims must be true - no rate before any time has passed, and a loop that a stop
// rule ends early is not reported as 100 % done; a loop whose processes agree on a signal
// stops on the agreed one.
#include "mesowave/app/progress.hpp"

#include <gtest/gtest.h>
#include <signal.h>

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

// A loop whose processes agree on a signal first (mw-dem on several MPI ranks) stops on the
// agreed one: update(done, signal) throws it with where the loop was, whatever the handler saw,
// and update(done, 0) goes on even after a signal arrived (the next step's agreement takes it).
TEST(Progress, AnAgreedStopSignalIsTheOneThatStopsTheLoop) {
  const app::InterruptGuard guard;  // a flag of its own, cleared again after
  app::Progress p("mw-dem wave", 100, "steps", false);
  EXPECT_NO_THROW(p.update(3, 0));
  try {
    p.update(4, SIGTERM);
    ADD_FAILURE() << "no Interrupted";
  } catch (const app::Interrupted& i) {
    EXPECT_EQ(i.signal, SIGTERM);
    ASSERT_TRUE(i.reached);
    EXPECT_EQ(i.reached->done, 4);
  }
  EXPECT_EQ(app::interrupt_signal(), 0);  // no signal arrived here: another process caught it
  app::interrupt_as(SIGINT);              // as a rank that caught nothing takes the agreed one
  app::interrupt_as(SIGTERM);             // the first one stays
  EXPECT_EQ(app::interrupt_signal(), SIGINT);
  EXPECT_NO_THROW(p.update(5, 0));
  EXPECT_THROW(p.update(6), app::Interrupted);  // the plain update reads the flag
  { const app::InterruptGuard clear; }          // a guard clears the flag: none for the next test
}
