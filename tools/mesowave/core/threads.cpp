#include "mesowave/core/threads.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "mesowave/core/format.hpp"

namespace mesowave {

int threads_for_work(int count, const ThreadWork& work) {
  if (work.min_per_thread == 0) return std::max(1, count);
  const std::size_t by_work = work.items / work.min_per_thread;
  return int(std::clamp<std::size_t>(by_work, 1, std::size_t(std::max(1, count))));
}

ThreadChoice thread_rule(int requested, int cores, double load, const ThreadWork& work) {
  ThreadChoice c;
  if (requested > 0) {
    c.count = requested;
    c.reason = "requested (--threads " + std::to_string(requested) + ")";
  } else {
    c.count = std::max(1, std::min(cores, int(std::lround(double(cores) - load))));
    c.reason = std::to_string(c.count) + " of " + std::to_string(cores) + " cores (1-minute load average " +
               format_number(std::round(load * 100) / 100) + " before the run)";
  }
  const int capped = threads_for_work(c.count, work);
  if (capped < c.count) {
    c.reason += ", " + std::to_string(capped) + " for " + std::to_string(work.items) + " " + work.unit +
                " (at least " + std::to_string(work.min_per_thread) + " per thread)";
    c.count = capped;
  }
  return c;
}

ThreadChoice use_threads(int requested, const ThreadWork& work) {
  double load = 0;
  std::ifstream in("/proc/loadavg");
  if (!(in >> load)) load = 0;
  const ThreadChoice c = thread_rule(requested, omp_get_num_procs(), load, work);
  omp_set_num_threads(c.count);
  return c;
}

int region_threads(std::size_t items, std::size_t min_per_thread) {
  return threads_for_work(omp_get_max_threads(), {items, min_per_thread, ""});
}

}  // namespace mesowave
