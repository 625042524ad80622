// The thread policy (core/threads.hpp) on hand-worked machines and meshes.
#include "mesowave/core/threads.hpp"

#include "mesowave/core/error.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <atomic>
#include <cstdlib>
#include <string>
#include <thread>

using namespace mesowave;

TEST(ThreadRule, RequestedCountWins) {
  const ThreadChoice c = thread_rule(3, 2, 7.5);
  EXPECT_EQ(c.count, 3);  // even above the cores and on a busy machine: the user said so
  EXPECT_EQ(c.reason, "requested (--threads 3)");
}

TEST(ThreadRule, DefaultIsTheFreeCores) {
  EXPECT_EQ(thread_rule(0, 16, 0.0).count, 16);
  EXPECT_EQ(thread_rule(0, 16, 5.4).count, 11);   // 16 - 5.4 = 10.6 -> 11
  EXPECT_EQ(thread_rule(0, 16, 5.6).count, 10);   // 10.4 -> 10
  EXPECT_EQ(thread_rule(0, 2, 8.0).count, 1);     // oversubscribed: one thread, never zero
  EXPECT_EQ(thread_rule(-1, 4, 0.0).count, 4);    // no request
  EXPECT_EQ(thread_rule(0, 4, 1.234).reason, "3 of 4 cores (1.23 other runnable threads at the start)");
}

TEST(ThreadRule, MinimumWorkPerThread) {
  const ThreadWork mesh{12000, 4000, "elements"};
  const ThreadChoice c = thread_rule(0, 16, 0.0, mesh);
  EXPECT_EQ(c.count, 3);  // 12000 / 4000
  EXPECT_EQ(c.reason,
            "16 of 16 cores (0 other runnable threads at the start), 3 for 12000 elements (at least 4000 per thread)");
  EXPECT_EQ(thread_rule(0, 16, 0.0, {7999, 4000, "elements"}).count, 1);  // below 2 x 4000: one thread
  EXPECT_EQ(thread_rule(0, 16, 0.0, {100, 4000, "elements"}).count, 1);   // less than one thread's worth
  EXPECT_EQ(thread_rule(8, 16, 0.0, {20000, 4000, "elements"}).count, 5); // the cap applies to a request too
  // Enough work: no cap, and the reason does not mention it.
  const ThreadChoice big = thread_rule(2, 16, 0.0, {1000000, 4000, "elements"});
  EXPECT_EQ(big.count, 2);
  EXPECT_EQ(big.reason, "requested (--threads 2)");
  EXPECT_EQ(thread_rule(0, 4, 0.0, {10, 0, "elements"}).count, 4);  // no minimum given
}

TEST(ThreadRule, AppliedToOpenMP) {
  const int before = omp_get_max_threads();
  EXPECT_EQ(use_threads(2).count, 2);
  EXPECT_EQ(omp_get_max_threads(), 2);
  EXPECT_EQ(region_threads(100000, 4000), 2);
  EXPECT_EQ(region_threads(5000, 4000), 1);
  EXPECT_EQ(region_threads(10, 0), 2);
  const ThreadChoice c = use_threads(0);
  EXPECT_GE(c.count, 1);
  EXPECT_LE(c.count, omp_get_num_procs());
  EXPECT_EQ(omp_get_max_threads(), c.count);
  omp_set_num_threads(before);
}

// MESOWAVE_THREADS fixes the count of a run that does not request one (a benchmark's schedule, a
// batch job's cores); --threads still wins, and a value that is not a count is refused in one line.
TEST(ThreadRule, EnvironmentCountWhenNoneIsRequested) {
  const int before = omp_get_max_threads();
  ::setenv("MESOWAVE_THREADS", "1", 1);
  const ThreadChoice from_env = use_threads(0);
  EXPECT_EQ(from_env.count, 1);
  EXPECT_EQ(from_env.reason, "requested (MESOWAVE_THREADS=1)");
  EXPECT_EQ(omp_get_max_threads(), 1);
  EXPECT_EQ(use_threads(3).reason, "requested (--threads 3)");
  EXPECT_EQ(use_threads(0, {12000, 4000, "elements"}).count, 1);
  ::setenv("MESOWAVE_THREADS", "3", 1);
  EXPECT_EQ(use_threads(0, {8000, 4000, "elements"}).count, 2);  // the work cap applies to it too
  for (const char* bad : {"0", "two", "-1", "1.5"}) {
    ::setenv("MESOWAVE_THREADS", bad, 1);
    try {
      use_threads(0);
      ADD_FAILURE() << bad << " was taken";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()),
                std::string("MESOWAVE_THREADS (\"") + bad + "\") must be a whole number of threads, 1 or more");
    }
  }
  ::setenv("MESOWAVE_THREADS", "", 1);  // empty: as unset
  EXPECT_NE(use_threads(0).reason.find("other runnable threads"), std::string::npos);
  ::unsetenv("MESOWAVE_THREADS");
  omp_set_num_threads(before);
}

// The busy count is this instant's runnable threads, not a minute's average: a thread spinning
// beside the reader is counted (at least once of the samples' median, allowing the scheduler to
// have it momentarily off the run queue on a loaded machine), and the reader itself never is.
TEST(ThreadRule, BusyCountsTheOtherRunnableThreadsNow) {
  std::atomic<bool> stop{false};
  std::thread spinner([&] {
    while (!stop.load(std::memory_order_relaxed)) {
    }
  });
  const double with_spinner = other_runnable_threads();
  stop = true;
  spinner.join();
  EXPECT_GE(with_spinner, 1.0);
  EXPECT_GE(other_runnable_threads(1), 0.0);
}
