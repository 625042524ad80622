#include "mesowave/core/threads.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"

namespace mesowave {

namespace {
std::optional<ThreadChoice> last_choice;  // use_threads runs on the main thread, before any region
}  // namespace

int threads_for_work(int count, const ThreadWork& work) {
  if (work.min_per_thread == 0) return std::max(1, count);
  const std::size_t by_work = work.items / work.min_per_thread;
  return int(std::clamp<std::size_t>(by_work, 1, std::size_t(std::max(1, count))));
}

ThreadChoice thread_rule(int requested, int cores, double busy, const ThreadWork& work,
                         const std::string& requested_by) {
  ThreadChoice c;
  if (requested > 0) {
    c.count = requested;
    c.reason = "requested (" + (requested_by.empty() ? "--threads " + std::to_string(requested) : requested_by) + ")";
  } else {
    c.count = std::max(1, std::min(cores, int(std::lround(double(cores) - busy))));
    c.reason = std::to_string(c.count) + " of " + std::to_string(cores) + " cores (" +
               format_number(std::round(busy * 100) / 100) + " other runnable threads at the start)";
  }
  const int capped = threads_for_work(c.count, work);
  if (capped < c.count) {
    c.reason += ", " + std::to_string(capped) + " for " + std::to_string(work.items) + " " + work.unit +
                " (at least " + std::to_string(work.min_per_thread) + " per thread)";
    c.count = capped;
  }
  return c;
}

double other_runnable_threads(int samples) {
  std::vector<double> others;
  for (int i = 0; i < samples; ++i) {
    if (i > 0) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    std::ifstream in("/proc/stat");
    std::string key;
    long long value = 0;
    while (in >> key) {
      if (key == "procs_running" && (in >> value)) {
        others.push_back(double(std::max(0LL, value - 1)));
        break;
      }
      in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
    }
  }
  if (others.empty()) return 0;
  std::sort(others.begin(), others.end());
  const std::size_t n = others.size();
  return n % 2 ? others[n / 2] : (others[n / 2 - 1] + others[n / 2]) / 2;
}

int environment_threads() {
  const char* text = std::getenv("MESOWAVE_THREADS");
  if (text == nullptr || *text == '\0') return 0;
  const std::string value = text;
  if (value.size() > 6 || value.find_first_not_of("0123456789") != std::string::npos || std::stoi(value) < 1)
    throw InputError("MESOWAVE_THREADS (\"" + value + "\") must be a whole number of threads, 1 or more");
  return std::stoi(value);
}

ThreadChoice use_threads(int requested, const ThreadWork& work) {
  const int from_environment = requested > 0 ? 0 : environment_threads();
  const int asked = requested > 0 ? requested : from_environment;
  const double busy = asked > 0 ? 0 : other_runnable_threads();
  const ThreadChoice c =
      thread_rule(asked, omp_get_num_procs(), busy, work,
                  from_environment > 0 ? "MESOWAVE_THREADS=" + std::to_string(from_environment) : "");
  omp_set_num_threads(c.count);
  last_choice = c;
  return c;
}

std::optional<ThreadChoice> threads_chosen() { return last_choice; }

int region_threads(std::size_t items, std::size_t min_per_thread) {
  return threads_for_work(omp_get_max_threads(), {items, min_per_thread, ""});
}

}  // namespace mesowave
