#pragma once
// Interrupted runs (SIGINT, SIGTERM) stop cleanly and leave a trace. While a
// tool's body runs, app::Tool holds an InterruptGuard; while a long loop runs,
// its app::Progress holds a PollingScope. A SIGINT or SIGTERM that arrives
// while a loop polls only raises a flag (and resets the handler: a second
// signal ends the process at once); the loop's next Progress::update throws
// app::Interrupted with the step reached; app::Tool catches it (or sees the
// flag when the body returns), discards the staged outputs, records the run in
// the provenance database as interrupted - exit status 128 + the signal's
// number (130 for SIGINT, 143 for SIGTERM, the shells' convention), the error
// "interrupted by SIGTERM after 1200 of 20000 steps (mw-dem rod)" and the
// parameter "interrupted" - and returns that status. A signal outside any
// polling loop (reading inputs, a tool with no Progress) ends the process at
// once, as without the guard: nothing is written, nothing recorded.
//
// Interrupted does not derive from std::exception, so that no `catch (const
// std::exception&)` on the way out turns an interruption into a failure.
// Throw it only from the serial part of a loop: a callback run inside an
// OpenMP region must let the region end first (fem/solver.cpp keeps it and
// rethrows it after the region).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace mesowave::app {

/// Where a long loop was when it last reported (app::Progress records it).
struct ProgressMark {
  std::string label;  ///< "mw-dem rod-wave"
  std::string unit;   ///< "steps"
  std::int64_t done = 0, total = 0;
};

/// Thrown by Progress::update once a SIGINT or SIGTERM has arrived.
struct Interrupted {
  int signal = 0;
  std::optional<ProgressMark> reached;
};

/// Declares, for its lifetime, a loop that polls interrupt_signal() (Progress holds one).
class PollingScope {
public:
  PollingScope();
  ~PollingScope();
  PollingScope(const PollingScope&) = delete;
  PollingScope& operator=(const PollingScope&) = delete;
};

/// The signal that interrupted the run (SIGINT, SIGTERM), 0 if none arrived
/// since the guard was installed. Async-signal-safe to read, cheap to poll.
int interrupt_signal() noexcept;

/// Raises the flag as if `signal` had arrived (a first signal stays the one reported): a rank
/// of a distributed run that stops with the others on a signal another rank caught
/// (dem/command/run_command.cpp), so that its run too ends as interrupted.
void interrupt_as(int signal) noexcept;

/// Throws Interrupted (with the last progress mark) if a signal arrived.
void throw_if_interrupted();

/// Records where a loop stopped (a Progress records itself when it is finished
/// or destroyed, so that an interruption after the loop still names its step).
void mark_progress(const ProgressMark& mark);
/// The last mark recorded since the guard was installed.
std::optional<ProgressMark> last_progress();

/// "SIGTERM", "SIGINT", else "signal N".
std::string signal_name(int signal);

/// Installs the SIGINT and SIGTERM handlers for its lifetime (clearing the
/// flag and the progress mark) and restores the previous ones after.
class InterruptGuard {
public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

private:
  struct Saved;
  std::unique_ptr<Saved> saved_;
};

}  // namespace mesowave::app
