#include "mesowave/app/interrupt.hpp"

#include <signal.h>

#include <atomic>
#include <mutex>

namespace mesowave::app {
namespace {

std::atomic<int> caught{0};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs lock-free atomics");

std::mutex mark_mutex;
std::optional<ProgressMark> mark;

std::atomic<int> polling{0};  // live Progress objects: loops that will see the flag

extern "C" void on_interrupt(int signal) {
  // SA_RESETHAND has restored the default action already. With no loop to poll the flag the
  // signal takes it at once (raise: delivered when the handler returns), as without the guard.
  if (polling.load() == 0) {
    raise(signal);
    return;
  }
  int none = 0;
  caught.compare_exchange_strong(none, signal);  // the first signal is the one reported
}

constexpr int kSignals[] = {SIGINT, SIGTERM};

}  // namespace

int interrupt_signal() noexcept { return caught.load(std::memory_order_relaxed); }

void interrupt_as(int signal) noexcept {
  int none = 0;
  caught.compare_exchange_strong(none, signal);
}

void throw_if_interrupted() {
  if (const int s = interrupt_signal()) throw Interrupted{s, last_progress()};
}

PollingScope::PollingScope() { polling.fetch_add(1); }
PollingScope::~PollingScope() { polling.fetch_sub(1); }

void mark_progress(const ProgressMark& m) {
  std::lock_guard lock(mark_mutex);
  mark = m;
}

std::optional<ProgressMark> last_progress() {
  std::lock_guard lock(mark_mutex);
  return mark;
}

std::string signal_name(int signal) {
  if (signal == SIGINT) return "SIGINT";
  if (signal == SIGTERM) return "SIGTERM";
  return "signal " + std::to_string(signal);
}

struct InterruptGuard::Saved {
  struct sigaction previous[2];
};

InterruptGuard::InterruptGuard() : saved_(std::make_unique<Saved>()) {
  caught.store(0);
  {
    std::lock_guard lock(mark_mutex);
    mark.reset();
  }
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  // SA_RESETHAND: a second signal takes the default action (the process ends at once), for a
  // body that never polls; SA_RESTART: system calls in progress carry on.
  action.sa_flags = SA_RESETHAND | SA_RESTART;
  for (int i = 0; i < 2; ++i) sigaction(kSignals[i], &action, &saved_->previous[i]);
}

InterruptGuard::~InterruptGuard() {
  for (int i = 0; i < 2; ++i) sigaction(kSignals[i], &saved_->previous[i], nullptr);
}

}  // namespace mesowave::app
