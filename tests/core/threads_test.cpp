// The thread policy (core/threads.hpp) on hand-worked machines and meshes.
#include "mesowave/core/threads.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <atomic>
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
