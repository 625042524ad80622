#pragma once
// The one thread policy of every solver (DEM, FEM, packing). A time step (or
// a relaxation iteration) ends at a barrier: on a machine already busy with
// other work a descheduled thread stalls the others at every barrier, and a
// parallel region costs a few microseconds that a small model does not repay.
// So the rule is:
//   1. `requested` threads if > 0 (--threads N), else MESOWAVE_THREADS=N from
//      the environment if set (so a benchmark, or a scheduler that gives each
//      job its cores, can fix the count of every tool a pipeline starts without
//      editing a make rule; docs/benchmarks.md, "The schedule on 2 cores");
//   2. else the cores the machine is not busy with: cores minus the threads
//      of other work that want a core NOW, at least 1 (measured on 2 cores at
//      load 8: two threads ran 2-3x slower than one). "Now" is the kernel's
//      runnable count (procs_running of /proc/stat, this thread excluded), the
//      median of a few samples 10 ms apart so that a process starting or
//      ending at that instant does not decide. Not the 1-minute load average:
//      it still holds the run that just finished, so in a serial pipeline every
//      run saw load 1.00 from its predecessor and took one thread on a
//      2-core machine (issue 17: all 26 DEM and FEM runs of make reproduce);
//   3. at most one thread per `min_per_thread` units of work (elements,
//      spheres), so below 2 x min_per_thread one thread is used.
// Every solver gives the same bits for any thread count, so the rule moves
// only the wall time. Each run reports the count and `reason`.
#include <cstddef>
#include <optional>
#include <string>

namespace mesowave {

/// What the rule decided, and why (for the run summary).
struct ThreadChoice {
  int count = 1;
  std::string reason;
};

/// The work a run parallelises: `items` units (named `unit`, e.g. "elements"),
/// each thread worth it from `min_per_thread` units on. min_per_thread = 0:
/// no minimum.
struct ThreadWork {
  std::size_t items = 0;
  std::size_t min_per_thread = 0;
  std::string unit = "items";
};

/// The rule itself, for a machine with `cores` cores on which `busy` threads of other work are runnable.
/// `requested_by`: who asked for `requested` threads, for the reason ("" = "--threads N").
ThreadChoice thread_rule(int requested, int cores, double busy, const ThreadWork& work = {},
                         const std::string& requested_by = "");

/// MESOWAVE_THREADS from the environment: 0 when unset or empty; InputError (one line) when it
/// is not a whole number of 1 or more.
int environment_threads();

/// The runnable threads other than the caller, now: the median over `samples` readings 10 ms apart of
/// procs_running - 1 from /proc/stat (0 where it cannot be read).
double other_runnable_threads(int samples = 5);

/// At most `count` threads, and at most one per work.min_per_thread items (at least 1).
int threads_for_work(int count, const ThreadWork& work);

/// The rule on this machine (`requested`, else environment_threads(), else OpenMP's core count
/// less other_runnable_threads), applied: OpenMP's next parallel regions use the chosen count.
ThreadChoice use_threads(int requested, const ThreadWork& work = {});

/// The last choice use_threads made in this process, if it made one: app::Tool records its count
/// with the run (metric `threads`), since a wall time means little without it.
std::optional<ThreadChoice> threads_chosen();

/// Threads for one parallel region over `items` units: OpenMP's current
/// maximum (what use_threads set), capped by the work.
int region_threads(std::size_t items, std::size_t min_per_thread);

}  // namespace mesowave
