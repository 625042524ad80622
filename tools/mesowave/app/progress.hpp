#pragma once
// Progress of a long run (DEM, FEM, calibration) on stderr: a bar redrawn in
// place on a terminal (steps, rate, ETA); plain lines every ~10 % otherwise,
// so logs from `make -j` stay readable. Cheap enough to call every step.
//
// update() is also where a long loop notices an interruption: once SIGINT or
// SIGTERM has arrived (app/interrupt.hpp), it throws app::Interrupted with the
// step reached, whether the bar is shown or not. Call it from the loop's serial
// part, never inside an OpenMP region.
#include <chrono>
#include <cstdint>
#include <string>

#include "mesowave/app/interrupt.hpp"

namespace mesowave::app {

class Progress {
public:
  /// `label` names the work ("mw-dem cube-100kHz"), `unit` the steps ("steps");
  /// `resumed_at`: the steps an earlier run did (a restart), which the rate and ETA leave out.
  Progress(std::string label, std::int64_t total, std::string unit = "steps", bool enabled = true,
           std::int64_t resumed_at = 0);
  ~Progress();
  /// Shows `done` of `total`; throws app::Interrupted if a signal arrived.
  void update(std::int64_t done) { update(done, interrupt_signal()); }
  /// The same, but throws on `stop_signal` (nonzero) instead of reading the flag: a loop whose
  /// processes agree on a signal first, so that all stop after the same step.
  void update(std::int64_t done, int stop_signal);
  /// The work is complete: the last line shows `total` and the time taken.
  void finish();
  /// The loop ended at `done` before `total` because `why` (a test's stop rule, say): the last
  /// line says so instead of claiming 100 %.
  void finish_early(std::int64_t done, const std::string& why);
  /// Where the loop is: label, unit, the last `done` given, total.
  ProgressMark mark() const;

private:
  void draw(std::int64_t done, bool final, const std::string& stopped_because = {});
  PollingScope polling_;  // a signal while this loop runs waits for its update()
  std::string label_, unit_;
  std::int64_t total_, done_ = 0, resumed_at_ = 0;
  bool enabled_, tty_, finished_ = false;
  int last_decile_ = -1;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace mesowave::app
