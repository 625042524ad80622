#pragma once
// Progress of a long run (DEM, FEM, calibration) on stderr: a bar redrawn in
// place on a terminal (steps, rate, ETA); plain lines every ~10 % otherwise,
// so logs from `make -j` stay readable. Cheap enough to call every step.
#include <chrono>
#include <cstdint>
#include <string>

namespace mesowave::app {

class Progress {
public:
  /// `label` names the work ("mw-dem cube-100kHz"), `unit` the steps ("steps").
  Progress(std::string label, std::int64_t total, std::string unit = "steps", bool enabled = true);
  ~Progress();
  void update(std::int64_t done);
  void finish();

private:
  void draw(std::int64_t done, bool final);
  std::string label_, unit_;
  std::int64_t total_;
  bool enabled_, tty_, finished_ = false;
  int last_decile_ = -1;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace mesowave::app
